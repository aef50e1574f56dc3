#!/usr/bin/python3
# ----------------------------------------------------------------------
# NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
# spheropolyhedra coupled to elastic wires.
#
# Copyright (2026) the NSCD package developers. This software is
# distributed under the GNU General Public License, version 2, the
# licence of LAMMPS. See the LICENSE file in the top-level directory
# of the package.
# ----------------------------------------------------------------------
# Contributing author: the NSCD package developers
# ----------------------------------------------------------------------

"""A small wired column built, run and measured in-process through LAMMPS' Python module,
as in a notebook: layers of random grains poured into a square box on two staggered
lattices, a double wire loop laid on each, the side walls pulled away; the column's height
is read after every chunk of steps, and at the end the fabric of every grain is taken from
compute fabric/atom as a numpy array and reduced to the angle of its largest principal
direction against r with nscd_analysis (the papers' Fig. 4). Writes PREFIX.png (height vs
step, fabric angle vs r) and PREFIX.csv.

Needs the lammps module built with this package (build/python, made by tools/build.sh) and
nscd_analysis (pip-installed, doc/analysis.md, or tools/ on PYTHONPATH):

    PYTHONPATH=build/python:tools /usr/bin/python3 examples/python/column.py -o column

Defaults: 2 layers of R = 2.5 (about 40 grains), about half a minute on one core.
"""
import argparse
import csv
import sys

import numpy as np

try:
    import lammps
except ImportError:
    sys.exit("column.py: no lammps module: build it with tools/build.sh and put build/python on PYTHONPATH")
try:
    from nscd_analysis import cylinder, fabric, fields
    from nscd_analysis.dumps import Snapshot
    from nscd_analysis.layouts import FABRIC
except ImportError:
    sys.exit("column.py: no nscd_analysis: pip install -e tools (doc/analysis.md), or put tools/ on PYTHONPATH")


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("-o", "--out", default="column", help="prefix of the PNG and CSV written")
    p.add_argument("--layers", type=int, default=2, help="grain layers, each with a double wire loop")
    p.add_argument("--radius", type=float, default=2.5, help="loop radius R (the column's radius)")
    p.add_argument("--seed", type=int, default=2026, help="grain shapes, placement and orientations")
    p.add_argument("--layer-steps", type=int, default=600, help="steps for a layer to fall and settle")
    p.add_argument("--wire-steps", type=int, default=200, help="steps after laying a loop")
    p.add_argument("--wall-steps", type=int, default=400, help="steps pulling the side walls away")
    p.add_argument("--chunk", type=int, default=50, help="steps between height readings")
    p.add_argument("--rbins", type=int, default=4, help="r bins of the fabric angle")
    return p.parse_args()


def setup(lmp, a):
    """The box, the grain shapes, the wire's styles, the walls, gravity and the integrators
    (the settings of examples/column/in.column)."""
    half = a.radius + 0.4
    top = 3 * a.layers * 1.6 + 10
    lmp.commands_string(f"""
        units           lj
        atom_style      hybrid spheropolyhedron angle
        atom_modify     map array
        boundary        f f f
        newton          on
        region          box block -{half + 2} {half + 2} -{half + 2} {half + 2} -1 {top} units box
        create_box      2 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 &
                        extra/special/per/atom 6
        shapes          random 24 seed {a.seed} vertices 10 20 size 0.8 1.0 axes 0.8 0.6 radius 0.05
        bond_style      wire
        bond_coeff      1 5000 0.2
        angle_style     wire
        angle_coeff     1 0.01
        special_bonds   lj 0 0 0
        group           grains type 1
        group           wire type 2
        pair_style      nscd
        pair_coeff      * * 0.5
        neighbor        0.3 bin
        neigh_modify    every 1 delay 0 check yes
        timestep        0.005
        fix             floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5
        fix             xlo all nscd/wall plane -{half} 0 0 1 0 0
        fix             xhi all nscd/wall plane {half} 0 0 -1 0 0
        fix             ylo all nscd/wall plane 0 -{half} 0 0 1 0
        fix             yhi all nscd/wall plane 0 {half} 0 0 -1 0
        fix             gravity all gravity 1.0 vector 0 0 -1
        fix             w wire wire radius 0.05 k_n 2000 gamma_n 2 k_t 1500 gamma_t 1 mu_s 0.5 mu_ww_s 0.3
        fix             nscd grains nscd tolerance 1e-4 max_sweeps 500
        compute         col grains nscd/column 0 0 {a.radius} floor 0.0
        compute         all_top grains nscd/column 0 0 1e6
        compute         wire_z wire reduce max z
        compute         fab grains fabric/atom
        variable        height equal c_col[1]
        variable        grains equal count(grains)
        thermo          {a.chunk}
    """)


def run_in_chunks(lmp, steps, chunk, history, phase):
    """Runs `steps` steps, appending (step, column height, phase) after each chunk."""
    done = 0
    while done < steps:
        n = min(chunk, steps - done)
        lmp.command(f"run {n} post no")
        done += n
        history.append((int(lmp.get_thermo("step")), lmp.extract_variable("height"), phase))


def top_of_deposit(lmp):
    """Highest grain surface or wire node (compute nscd/column's top and a reduce over z)."""
    lmp.command("run 0 post no")
    grains = lmp.extract_compute("all_top", lammps.LMP_STYLE_GLOBAL, lammps.LMP_TYPE_VECTOR)[4]
    wire = lmp.extract_compute("wire_z", lammps.LMP_STYLE_GLOBAL, lammps.LMP_TYPE_SCALAR)
    return max(grains, wire + 0.05)


def build_column(lmp, a, history):
    fill = a.radius + 0.4 - 0.7
    for layer in range(1, a.layers + 1):
        z0 = top_of_deposit(lmp) + 0.9
        lmp.commands_string(f"""
            region   window block -{fill} {fill} -{fill} {fill} {z0} {z0 + 1.6 - 1e-6} units box
            create_grains 1 window shape 1 24 density 1.0 seed {100 * a.seed + layer} lattice 1.6
            region   window delete
            group    grains type 1
        """)
        run_in_chunks(lmp, a.layer_steps, a.chunk, history, f"layer {layer}")
        zw = top_of_deposit(lmp) + 0.05 + 0.05
        lmp.commands_string(f"""
            create_wire 2 loop 0 0 {zw} {a.radius} turns 2 pitch 0.12 gap 20 start {137 * layer} &
                        bond 1 angle 1 mass 0.005 radius 0.05 overlap 0.1
            group    wire type 2
        """)
        run_in_chunks(lmp, a.wire_steps, a.chunk, history, f"loop {layer}")


def remove_walls(lmp, a, history):
    """Side walls pulled outward at 0.1 for wall-steps steps, then removed, and as many
    steps again for the column to settle."""
    for name, v in (("xlo", "-0.1 0 0"), ("xhi", "0.1 0 0"), ("ylo", "0 -0.1 0"), ("yhi", "0 0.1 0")):
        lmp.command(f"fix_modify {name} velocity {v}")
    run_in_chunks(lmp, a.wall_steps, a.chunk, history, "walls")
    for name in ("xlo", "xhi", "ylo", "yhi"):
        lmp.command(f"unfix {name}")
    run_in_chunks(lmp, a.wall_steps, a.chunk, history, "free")


def fabric_snapshot(lmp):
    """The grains' positions and compute fabric/atom's columns, as a nscd_analysis Snapshot
    (the arrays LAMMPS holds, no dump file)."""
    lmp.command("run 0 post no")
    nlocal = lmp.extract_global("nlocal")
    types = lmp.numpy.extract_atom("type")[:nlocal]
    x = lmp.numpy.extract_atom("x")[:nlocal]
    fab = lmp.numpy.extract_compute("fab", lammps.LMP_STYLE_ATOM, lammps.LMP_TYPE_ARRAY)[:nlocal]
    grains = types == 1
    names = ["x", "y", "z"] + sorted(FABRIC, key=FABRIC.get)
    data = np.column_stack([x[grains], fab[grains]])
    return Snapshot(int(lmp.get_thermo("step")), None, names, data, "compute fab")


def write_outputs(a, history, r_edges, count, mean, sem):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    steps = np.array([h[0] for h in history])
    heights = np.array([h[1] for h in history])
    walls = steps[[h[2] == "walls" for h in history]]
    centres = cylinder.centres(r_edges)
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 3.8))
    left.axvspan(walls.min() - a.chunk, walls.max(), color="0.9", label="side walls pulled away")
    left.plot(steps, heights, "o-", ms=3)
    left.legend(fontsize=8)
    left.set_xlabel("step")
    left.set_ylabel("column height (compute nscd/column)")
    right.errorbar(centres / a.radius, mean, yerr=sem, marker="o", ms=4, capsize=2)
    right.axhline(0.0, color="0.6", lw=0.8)
    right.set_xlabel("r / R")
    right.set_ylabel("angle of the largest fabric direction (rad)")
    fig.tight_layout()
    fig.savefig(a.out + ".png", dpi=100)
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["step", "height", "phase"])
        w.writerows(history)
        w.writerow([])
        w.writerow(["r_lo", "r_hi", "grains", "mean_angle_rad", "sem_rad"])
        w.writerows(zip(r_edges[:-1], r_edges[1:], count, mean, sem))
    return a.out + ".png", a.out + ".csv"


def main():
    a = arguments()
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        if not lmp.has_style("fix", "nscd"):
            sys.exit("column.py: this lammps module has no fix nscd: build it with tools/build.sh")
        history = []
        setup(lmp, a)
        build_column(lmp, a, history)
        remove_walls(lmp, a, history)
        r, _, blocks, angle = fabric.per_grain(fabric_snapshot(lmp), (0.0, 0.0))
        r_edges = cylinder.edges(r, count=a.rbins)
        count, mean, sem, _ = fields.angle_profile(r, blocks, angle, r_edges)
        deposit = [h for h in history if h[2] != "walls" and h[2] != "free"][-1]
        print(f"{len(r)} grains with contacts (of {int(lmp.extract_variable('grains'))}); height {deposit[1]:.3f} "
              f"after the deposit (step {deposit[0]}), {history[-1][1]:.3f} after the walls "
              f"(step {history[-1][0]}): {100 * history[-1][1] / deposit[1]:.0f} %")
        print(*write_outputs(a, history, r_edges, count, mean, sem))
    finally:
        lmp.close()


if __name__ == "__main__":
    main()
