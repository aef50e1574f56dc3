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

"""Checks on the end of a benchmarks/loops run (tests/lammps/loops_smoke_check.sh):

* every ring intact: each element (neighbouring nodes by atom ID, the last back to the
  first) within 1 % of the rest length, each node within 5 % of the ring radius from the axis;
* no grain more than 2 % of a diameter through the floor, none outside the box;
* the loops hold the grains by contact: no grain sinks into a loop by more than 10 % of the
  loop's radius (nscd: grain centre to element axis against d/2 + r_w; peer: to bead
  centres against d/2 + the bead radius); a loop too soft to hold lets them sink;
* the loops kept the grains in: no grain's surface more than a quarter diameter outside the
  second cylinder (the loops' outer surface) at the end;
* the column kept at least 80 % of its held height (the phases are short: a fall of more
  would be grains thrown, not a slump).

  check_loops.py RUNDIR nscd|peer
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "benchmarks", "loops"))
import loops  # noqa: E402  (the scene's constants and the height measure of the benchmark)


R_WIRE = {"nscd": 0.00065, "peer": 0.00075}   # in.nscd's r_w; in.peer's bead radius h/2


def deepest_sink(grains, nodes, code):
    """The deepest overlap of a grain with a loop, in units of the loop's radius: the wire's
    elements (spherocylinders) for nscd, the beads (spheres) for the peer."""
    r_w = R_WIRE[code]
    n = loops.N_BEADS
    deepest = 0.0
    for k in range(len(nodes) // n):
        a = nodes[k * n:(k + 1) * n]
        b = np.roll(a, -1, axis=0) if code == "nscd" else a      # a bead is a zero-length segment
        ab = b - a
        for g in grains:
            t = np.clip(np.einsum("ij,ij->i", g - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-30), 0, 1)
            dist = np.linalg.norm(a + t[:, None] * ab - g, axis=1).min()
            deepest = max(deepest, (0.5 * loops.D + r_w - dist) / r_w)
    return deepest


def main():
    rundir, code = sys.argv[1], sys.argv[2]
    failures = []
    grains = loops.read_dump(os.path.join(rundir, "%s.end.dump" % code))
    nodes = loops.read_dump(os.path.join(rundir, "%s.loops.dump" % code))
    nodes = nodes[nodes[:, 0].argsort()]
    l0 = 2 * loops.R_LOOP * math.sin(math.pi / loops.N_BEADS)
    if len(nodes) == 0 or len(nodes) % loops.N_BEADS:
        failures.append("%d loop nodes: not whole rings of %d" % (len(nodes), loops.N_BEADS))
    worst_strain = worst_radius = 0.0
    for k in range(len(nodes) // loops.N_BEADS):
        ring = nodes[k * loops.N_BEADS:(k + 1) * loops.N_BEADS, 1:4]
        lengths = [math.dist(ring[i], ring[(i + 1) % len(ring)]) for i in range(len(ring))]
        worst_strain = max(worst_strain, max(abs(l / l0 - 1) for l in lengths))
        radii = [math.hypot(p[0], p[1]) for p in ring]
        worst_radius = max(worst_radius, max(abs(r / loops.R_LOOP - 1) for r in radii))
    if worst_strain > 0.01:
        failures.append("an element strained by %.3g (> 1 %%): a ring broke or blew up" % worst_strain)
    if worst_radius > 0.05:
        failures.append("a node %.3g of the ring radius off it (> 5 %%)" % worst_radius)
    z_low = grains[:, 3].min() - 0.5 * loops.D
    if z_low < -0.02 * loops.D:
        failures.append("a grain %.3g m through the floor" % -z_low)
    if abs(grains[:, 1:3]).max() > 0.2:
        failures.append("a grain outside the box")
    sink = deepest_sink(grains[:, 1:4], nodes[:, 1:4], code)
    if sink > 0.1:
        failures.append("a grain sinks %.3g loop radii into a loop (> 0.1)" % sink)
    reach = (np.hypot(grains[:, 1], grains[:, 2]) + 0.5 * loops.D).max()
    if reach > loops.R_OUT + 0.25 * loops.D:
        failures.append("a grain reaches %.4f m from the axis (loops' outside %.4f m)" % (reach, loops.R_OUT))
    held = loops.column_height(loops.read_dump(os.path.join(rundir, "%s.held.dump" % code)))
    end = loops.column_height(grains)
    if end < 0.8 * held:
        failures.append("the column fell from %.4f to %.4f m" % (held, end))
    print("check_loops %s: %d rings, largest element strain %.2e, largest node radius error %.2e, "
          "deepest grain in a loop %.2e loop radii, lowest grain %.2e m above the floor, grains reach %.4f m from the axis, height %.4f -> %.4f m"
          % (code, len(nodes) // loops.N_BEADS, worst_strain, worst_radius, sink, z_low, reach, held, end))
    for f in failures:
        print("check_loops %s: FAILED: %s" % (code, f))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
