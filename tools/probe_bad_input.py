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

"""Feeds bad input to every style of the package through lmp decks and sorts the outcomes.

    tools/probe_bad_input.py [--lmp build/lmp] [--ranks 1] [--only SUBSTRING] [--markdown FILE]

Each case is a small deck with one bad value (or a bad combination). Outcomes:
  clear     the run stops with an ERROR (or, where a warning is the answer, prints a WARNING)
            whose text names the bad value or keyword (the substrings listed with the case)
  unclear   it stops with an ERROR that does not name them
  crash     it ends without an ERROR line (signal, abort, uncaught exception)
  hang      no end within the time limit
  silent    it runs to the end without the error or warning it should give
  handled   a case that must run (an edge value that is fine) ran and passed its check
  wrong     such a case ran but failed its check
Exit status 1 if any case is unclear, crash, hang, silent or wrong. doc/robustness.md has the table.

Message length (LAMMPS' rule of at most two printed lines, doc/build.md): every ERROR line a
case prints, and the WARNING a warning case expects, must hold a message (the text between
'ERROR: ' or 'WARNING: ' and LAMMPS' ' (src/...:N)') of at most MAX_MESSAGE characters plus
the length of the values the case names (its substrings): the format string's limit, with room
for what fills it. A longer one is listed as `long` and fails the run (--max-length 0: off).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

CUBE = "shape cube\nradius 0\nvertices 8\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\nend\n"


def cube_scaled(s, name="cube", radius="0"):
    pts = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    body = "\n".join(f"{x * s:g} {y * s:g} {z * s:g}" for x, y, z in pts)
    return f"shape {name}\nradius {radius}\nvertices 8\n{body}\nend\n"


# Damages a restart file in place, as a deck's `shell` command runs it: FILE FIX_ID STYLE WHAT
# finds the global block of that fix (its ID and style as counted strings, LAMMPS' size, then
# the package's mark) and overwrites a field; "truncate" cuts the file in half.
DAMAGE_SCRIPT = r"""
import struct, sys
path, fix_id, style, what = sys.argv[1:5]
data = bytearray(open(path, "rb").read())
if what == "truncate":
    open(path, "wb").write(data[: len(data) // 2]); sys.exit(0)
def counted(t): return struct.pack("i", len(t) + 1) + t.encode() + b"\0"
marker = counted(fix_id) + counted(style)
at = data.find(marker)
while at >= 0 and struct.unpack_from("i", data, at + len(marker) + 4)[0] != 0x4E534344:
    at = data.find(marker, at + 1)
block = at + len(marker) + 4
fields = {"mark": ("i", 0, 7), "count": ("q", 16, 10**9), "size": ("q", 8, 4),
          "kind": ("d", 16, 2.0), "format": ("i", 4, 999), "dt": ("d", 24, 5e-315),
          "wire_count": ("q", 24, 10**9), "wire_dt": ("d", 16, 5e-315)}
if what == "atom_nan":
    # fix nscd's impulses travel with the atoms: an atom's values {size, format 1, count k,
    # k records of 6 doubles (two tags, a feature, the impulse)}; NaN into the first impulse
    for k in range(1, 64):
        at = data.find(struct.pack("3d", 3 + 6 * k, 1.0, k))
        if at >= 0: break
    else: sys.exit("damage.py: no atom holds a warm-start record")
    struct.pack_into("d", data, at + 24 + 24, float("nan"))
    open(path, "wb").write(data); sys.exit(0)
form, offset, value = fields[what]
struct.pack_into(form, data, block + offset, value)
open(path, "wb").write(data)
"""

# Files a case may use, written into its working folder.
FILES = {
    "cube.shapes": CUBE,
    "cube_again.shapes": CUBE,
    "tiny.shapes": cube_scaled(1e-100),
    "small70.shapes": cube_scaled(1e-70),
    "tetra90.shapes": "shape t\nradius 0\nvertices 4\n0 0 0\n1e-90 0 0\n0 1e-90 0\n0 0 1e-90\nend\n",
    "huge200.shapes": cube_scaled(1e200),
    "huge150.shapes": cube_scaled(1e150),
    "far.shapes": "shape h\nradius 0\nvertices 4\n0 0 0\n1e300 0 0\n0 1 0\n0 0 1\nend\n",
    "round.shapes": "shape r\nradius 1e300\nvertices 1\n0 0 0\nend\n",
    "negative_radius.shapes": "shape r\nradius -0.5\nvertices 1\n0 0 0\nend\n",
    "nan_radius.shapes": "shape r\nradius nan\nvertices 1\n0 0 0\nend\n",
    "empty.shapes": "",
    "nul.shapes": "shape c\nradius 0\x00\nvertices 1\n0 0 0\nend\n",
    "twice.shapes": CUBE + CUBE,
    "short.shapes": "shape c\nradius 0\nvertices 8\n0 0 0\n1 0 0\n0 1 0\nend\n",
    "no_end.shapes": "shape c\nradius 0.1\nvertices 1\n0 0 0\n",
    "word.shapes": "shape c\nradius 0\nvertices 4\n0 0 0\n1 abc 0\n0 1 0\n0 0 1\nend\n",
    "line.shapes": "shape c\nradius 0\nvertices 3\n0 0 0\n1 0 0\n2 0 0\nend\n",
    "flat.shapes": "shape c\nradius 0\nvertices 4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\nend\n",
    "path.txt": "0 0 1\n1 0 1\n1 1 1\n",
    "nan_path.txt": "0 -2 1\nnan -1 1\n1 -2 1\n",
    "inf_path.txt": "0 -2 1\ninf -1 1\n1 -2 1\n",
    "huge_path.txt": "0 -2 1\n1e400 -1 1\n1 -2 1\n",
    "header_path.txt": "x y z\n0 -2 1\n1 -2 1\n",
    "bad_shape.data": "bad shape id\n\n1 atoms\n1 atom types\n\n-5 5 xlo xhi\n-5 5 ylo yhi\n-5 5 zlo zhi\n\n"
                      "Atoms # spheropolyhedron\n\n1 1 7 1.0 0 0 0.5 1 0 0 0\n",
    "bad_mass.data": "bad mass\n\n1 atoms\n1 atom types\n\n-5 5 xlo xhi\n-5 5 ylo yhi\n-5 5 zlo zhi\n\n"
                     "Atoms # spheropolyhedron\n\n1 1 1 -1.0 0 0 0.5 1 0 0 0\n",
    "bad_quat.data": "bad quaternion\n\n1 atoms\n1 atom types\n\n-5 5 xlo xhi\n-5 5 ylo yhi\n-5 5 zlo zhi\n\n"
                     "Atoms # spheropolyhedron\n\n1 1 1 1.0 0 0 0.5 0 0 0 0\n",
    "damage.py": DAMAGE_SCRIPT,
}

BASE = [
    "units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
    "shapes read cube.shapes", "region box block -5 5 -5 5 -5 5", "create_box 2 box",
    "create_atoms 1 single 0 0 0.5", "create_atoms 1 single 2 0 0.5",
    "shapes assign all shape 1 density 1", "pair_style nscd", "pair_coeff * * 0.5",
    "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes", "timestep 0.001",
    "fix floor all nscd/wall plane 0 0 0 0 0 1", "fix g all gravity 1.0 vector 0 0 -1",
    "fix solver all nscd", "run 10",
]

WIRE = [
    "units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
    "boundary f f f", "shapes read cube.shapes", "region box block -5 5 -5 5 -1 5",
    "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 "
    "extra/special/per/atom 6",
    "create_atoms 1 single 0 0 0.5", "shapes assign all shape 1 density 1",
    "bond_style wire", "bond_coeff 1 100 0.2", "angle_style wire", "angle_coeff 1 0.01",
    "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 angle 1 mass 0.01 radius 0.02",
    "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
    "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
    "fix g all gravity 1.0 vector 0 0 -1",
    "group wire type 2",
    "fix w wire wire radius 0.02 k_n 200 gamma_n 2 k_t 150 gamma_t 1 mu_s 0.5 mu_d 0.4",
    "group grains type 1", "fix solver grains nscd", "run 10",
]


# The wire scene written to a restart file, damaged by damage.py, and read back with the fixes
# defined again: `damaged(fix, style, what)`.
def damaged(fix_id, style, what):
    lines = deck(WIRE, {"create_wire": "create_wire 2 line -0.8 0 1.0201 0.8 0 1.0201 bond 1 angle 1 mass 0.01 radius 0.02",
                        "fix g ": "fix g all gravity 1.0 vector 0.1 0 -1"},
                 add=["fix plate all nscd/plate 3 mass 1"], run="run 60")
    again = [l for l in lines if l.startswith(("neighbor", "neigh_modify", "timestep", "fix ", "group "))]
    return lines + ["write_restart r.restart", "clear",
                    f"shell /usr/bin/python3 damage.py r.restart {fix_id} {style} {what}",
                    "read_restart r.restart"] + again + ["run 1"]


def deck(base, replace=None, add=(), drop=(), run=None):
    """base with lines starting with a key of `replace` replaced, `add` before the last line
    (the run), lines starting with an entry of `drop` removed, and the run line replaced."""
    out = []
    for line in base[:-1]:
        if any(line.startswith(d) for d in drop):
            continue
        for key, new in (replace or {}).items():
            if line.startswith(key):
                line = new
                break
        out.append(line)
    return out + list(add) + [run or base[-1]]


def shapes_deck(*lines):
    return ["units lj", "atom_style spheropolyhedron", "region box block -5 5 -5 5 -5 5",
            "create_box 1 box", *lines]


EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples")

# (name, deck lines, expected outcome, substrings the message must hold)
#   expected outcome: "error", "warning" or "ok"
CASES = [
    # --- shape library files (shapes read)
    ("cube x 1e-100", shapes_deck("shapes read tiny.shapes"), "error", ["below the supported"]),
    ("cube x 1e-70", shapes_deck("shapes read small70.shapes"), "error", ["below the supported"]),
    ("tetrahedron of side 1e-90", shapes_deck("shapes read tetra90.shapes"), "error", ["below the supported"]),
    ("cube side 1e200", shapes_deck("shapes read huge200.shapes"), "error", ["1e+200"]),
    ("cube side 1e150", shapes_deck("shapes read huge150.shapes"), "error", ["1e+150"]),
    ("vertex at 1e300", shapes_deck("shapes read far.shapes"), "error", ["1e+300"]),
    ("radius 1e300", shapes_deck("shapes read round.shapes"), "error", ["1e+300"]),
    ("radius -0.5", shapes_deck("shapes read negative_radius.shapes"), "error", ["-0.5"]),
    ("radius nan", shapes_deck("shapes read nan_radius.shapes"), "error", ["nan"]),
    ("a directory as the file", shapes_deck("shapes read ."), "error", ["directory"]),
    ("a missing file", shapes_deck("shapes read nowhere.shapes"), "error", ["nowhere.shapes"]),
    ("an empty file", shapes_deck("shapes read empty.shapes"), "error", ["empty.shapes"]),
    ("a NUL byte", shapes_deck("shapes read nul.shapes"), "error", ["0x00"]),
    ("a name taken by an earlier file", shapes_deck("shapes read cube.shapes", "shapes read cube_again.shapes"),
     "error", ["cube", "already"]),
    ("one name twice in a file", shapes_deck("shapes read twice.shapes"), "error", ["cube"]),
    ("fewer vertices than announced", shapes_deck("shapes read short.shapes"), "error", ["short.shapes"]),
    ("no 'end'", shapes_deck("shapes read no_end.shapes"), "error", ["end"]),
    ("a word for a coordinate", shapes_deck("shapes read word.shapes"), "error", ["abc"]),
    ("collinear points, radius 0", shapes_deck("shapes read line.shapes"), "error", ["line.shapes"]),
    ("coplanar points, radius 0", shapes_deck("shapes read flat.shapes"), "error", ["flat.shapes"]),
    # --- shapes random / write / assign
    ("shapes write of an empty library", shapes_deck("shapes write out.shapes"), "error", ["empty"]),
    ("shapes random 100000000", shapes_deck("shapes random 100000000 seed 1"), "error", ["100000000"]),
    ("shapes random 0", shapes_deck("shapes random 0 seed 1"), "error", ["0"]),
    ("shapes random -5", shapes_deck("shapes random -5 seed 1"), "error", ["-5"]),
    ("vertices 4 99999999999", shapes_deck("shapes random 2 seed 1 vertices 4 99999999999"), "error", ["99999999999"]),
    ("vertices 3 10", shapes_deck("shapes random 2 seed 1 vertices 3 10"), "error", ["3"]),
    ("vertices 10 5", shapes_deck("shapes random 2 seed 1 vertices 10 5"), "error", ["10", "5"]),
    ("size 1e300 1e300", shapes_deck("shapes random 2 seed 1 size 1e300 1e300"), "error", ["1e+300"]),
    ("size 2 1", shapes_deck("shapes random 2 seed 1 size 2 1"), "error", ["2", "1"]),
    ("size -1 1", shapes_deck("shapes random 2 seed 1 size -1 1"), "error", ["-1"]),
    ("axes 2 0.5", shapes_deck("shapes random 2 seed 1 axes 2 0.5"), "error", ["2"]),
    ("random radius -0.1", shapes_deck("shapes random 2 seed 1 radius -0.1"), "error", ["-0.1"]),
    ("shapes random without seed", shapes_deck("shapes random 2"), "error", ["seed"]),
    ("the same seed twice", shapes_deck("shapes random 2 seed 9", "shapes random 2 seed 9"), "error", ["seed"]),
    ("shapes bogus", shapes_deck("shapes bogus"), "error", ["bogus"]),
    ("assign shape 99", deck(BASE, {"shapes assign": "shapes assign all shape 99 density 1"}), "error", ["99"]),
    ("assign shape random 3 1", deck(BASE, {"shapes assign": "shapes assign all shape random 3 1 5"}), "error", ["IMIN"]),
    ("density 1e400", deck(BASE, {"shapes assign": "shapes assign all shape 1 density 1e400"}), "error", ["1e400"]),
    ("density 1e-320", deck(BASE, {"shapes assign": "shapes assign all shape 1 density 1e-320"}), "error", ["1e-320"]),
    ("density 0", deck(BASE, {"shapes assign": "shapes assign all shape 1 density 0"}), "error", ["density"]),
    ("density -1", deck(BASE, {"shapes assign": "shapes assign all shape 1 density -1"}), "error", ["-1"]),
    ("mass 1e400", deck(BASE, {"shapes assign": "shapes assign all shape 1 mass 1e400"}), "error", ["1e400"]),
    ("orient quat 0 0 0 0", deck(BASE, {"shapes assign": "shapes assign all shape 1 density 1 orient quat 0 0 0 0"}),
     "error", ["quat"]),
    ("assign bogus keyword", deck(BASE, {"shapes assign": "shapes assign all shape 1 bogus 1"}), "error", ["bogus"]),
    # documented: atoms keep their mass (1 from create_atoms)
    ("shapes assign without density or mass", deck(BASE, {"shapes assign": "shapes assign all shape 1"}), "ok", []),
    # --- pair_style nscd
    ("activation/fraction 1e6", deck(BASE, {"pair_style": "pair_style nscd activation/fraction 1e6"}), "error", ["1000000"]),
    ("activation -1", deck(BASE, {"pair_style": "pair_style nscd activation -1"}), "error", ["-1"]),
    ("activation 100", deck(BASE, {"pair_style": "pair_style nscd activation 100"}), "error", ["activation 100"]),
    ("reach -1", deck(BASE, {"pair_style": "pair_style nscd reach -1"}), "error", ["-1"]),
    ("reach 1e6", deck(BASE, {"pair_style": "pair_style nscd reach 1e6"}), "error", ["reach"]),
    ("pair_style nscd bogus", deck(BASE, {"pair_style": "pair_style nscd bogus 1"}), "error", ["bogus"]),
    ("friction -0.5", deck(BASE, {"pair_coeff": "pair_coeff * * -0.5"}), "error", ["-0.5"]),
    ("restitution 2", deck(BASE, {"pair_coeff": "pair_coeff * * 0.5 restitution 2"}), "error", ["2"]),
    ("a type pair without pair_coeff", deck(BASE, {"pair_coeff": "pair_coeff 1 1 0.5"}), "error", ["pair coeffs"]),    # LAMMPS' own check
    ("newton off", deck(BASE, {"atom_modify": "atom_modify map array\nnewton off on"}), "error", ["newton"]),
    ("a periodic box narrower than a grain",
     deck(BASE, {"boundary": "boundary p p f", "region": "region box block -0.6 0.6 -5 5 -1 5",
                 "create_atoms 1 single 2": "create_atoms 1 single 0 0 2.5"}), "error", ["wide"]),
    # --- fix nscd
    ("timestep 0", deck(BASE, {"timestep": "timestep 0"}), "error", ["timestep 0"]),
    ("timestep -0.001", deck(BASE, {"timestep": "timestep -0.001"}), "error", ["-0.001"]),
    ("tolerance -1", deck(BASE, {"fix solver": "fix solver all nscd tolerance -1"}), "error", ["-1"]),
    ("tolerance 0", deck(BASE, {"fix solver": "fix solver all nscd tolerance 0"}), "error", ["tolerance"]),
    ("max_sweeps 0", deck(BASE, {"fix solver": "fix solver all nscd max_sweeps 0"}), "error", ["max_sweeps"]),
    ("theta 0", deck(BASE, {"fix solver": "fix solver all nscd theta 0"}), "error", ["theta"]),
    ("theta 1.5", deck(BASE, {"fix solver": "fix solver all nscd theta 1.5"}), "error", ["1.5"]),
    ("relaxation 2", deck(BASE, {"fix solver": "fix solver all nscd relaxation 2"}), "error", ["2"]),
    ("order bogus", deck(BASE, {"fix solver": "fix solver all nscd order bogus"}), "error", ["bogus"]),
    ("check 0", deck(BASE, {"fix solver": "fix solver all nscd check 0"}), "error", ["check"]),
    ("skip_separating maybe", deck(BASE, {"fix solver": "fix solver all nscd skip_separating maybe"}), "error", ["maybe"]),
    ("slip_guess maybe", deck(BASE, {"fix solver": "fix solver all nscd slip_guess maybe"}), "error", ["maybe"]),
    ("exchange 0", deck(BASE, {"fix solver": "fix solver all nscd exchange 0"}), "error", ["exchange"]),
    ("fix nscd bogus keyword", deck(BASE, {"fix solver": "fix solver all nscd bogus 1"}), "error", ["bogus"]),
    ("a value missing at the end", deck(BASE, {"fix solver": "fix solver all nscd tolerance"}), "error", ["tolerance"]),
    ("fix nve as well", deck(BASE, add=["fix twice all nve"]), "error", ["nve"]),
    ("two fix nscd", deck(BASE, add=["fix solver2 all nscd"]), "error", ["nscd"]),
    ("minimize", deck(BASE, run="minimize 1e-4 1e-6 10 100"), "error", ["minimize"]),
    ("run_style respa", deck(BASE, add=["run_style respa 2 2"]), "error", ["respa"]),
    ("grains placed inside each other", deck(BASE, {"create_atoms 1 single 2": "create_atoms 1 single 0 0 0.5"}),
     "warning", ["overlap"]),
    ("walls without fix nscd", deck(BASE, drop=["fix solver"]), "error", ["fix nscd"]),
    # --- fix nscd/wall
    ("wall normal 0 0 0", deck(BASE, {"fix floor": "fix floor all nscd/wall plane 0 0 0 0 0 0"}), "error", ["normal"]),
    ("cylinder radius -1", deck(BASE, add=["fix c all nscd/wall cylinder 0 0 0 0 0 1 -1"]), "error", ["-1"]),
    ("cylinder axis 0 0 0", deck(BASE, add=["fix c all nscd/wall cylinder 0 0 0 0 0 0 4"]), "error", ["axis"]),
    ("wall friction -1", deck(BASE, {"fix floor": "fix floor all nscd/wall plane 0 0 0 0 0 1 friction -1"}), "error", ["-1"]),
    ("wall restitution 1.5", deck(BASE, {"fix floor": "fix floor all nscd/wall plane 0 0 0 0 0 1 restitution 1.5"}),
     "error", ["1.5"]),
    ("wall kind sphere", deck(BASE, {"fix floor": "fix floor all nscd/wall sphere 0 0 0 1"}), "error", ["sphere"]),
    ("wall velocity inf", deck(BASE, {"fix floor": "fix floor all nscd/wall plane 0 0 0 0 0 1 velocity 0 0 1e400"}),
     "error", ["1e400"]),
    ("grains behind a wall", deck(BASE, add=["fix top all nscd/wall plane 0 0 0.2 0 0 -1"]), "error", ["top", "outside"]),
    # --- fix nscd/plate
    ("plate mass 0", deck(BASE, add=["fix plate all nscd/plate 3 mass 0"]), "error", ["mass"]),
    ("plate mass -1", deck(BASE, add=["fix plate all nscd/plate 3 mass -1"]), "error", ["-1"]),
    ("plate rate 1e400", deck(BASE, add=["fix plate all nscd/plate 3 mass 1 rate 1e400"]), "error", ["1e400"]),
    ("plate rate 1e300", deck(BASE, add=["fix plate all nscd/plate 3 mass 1 rate 1e300"]), "error", ["finite", "plate"]),
    ("plate below the grains", deck(BASE, add=["fix plate all nscd/plate 0.5 mass 1"]), "error", ["plate"]),
    ("plate without mass", deck(BASE, add=["fix plate all nscd/plate 3"]), "error", ["mass"]),
    # --- computes and dumps
    ("nscd/column radius -1", deck(BASE, add=["compute col all nscd/column 0 0 -1"]), "error", ["-1"]),
    ("nscd/column percentile 0", deck(BASE, add=["compute col all nscd/column 0 0 2 percentile 0"]), "error", ["percentile"]),
    ("nscd/column percentile 150", deck(BASE, add=["compute col all nscd/column 0 0 2 percentile 150"]), "error", ["150"]),
    ("nscd/contacts bogus", deck(BASE, add=["compute c all nscd/contacts bogus"]), "error", ["bogus"]),
    ("fabric/atom contacts bogus", deck(BASE, add=["compute f all fabric/atom contacts bogus"]), "error", ["bogus"]),
    ("fabric/atom wire yes", deck(BASE, add=["compute f all fabric/atom wire yes"]), "error", ["wire"]),
    ("dump grains/vtk every 0", deck(BASE, add=["dump d all grains/vtk 0 g.*.vtk"]), "error", ["0"]),
    ("dump grains/vtk without *", deck(BASE, add=["dump d all grains/vtk 5 g.vtk"]), "error", ["*"]),
    # --- wire
    ("fix wire bogus keyword", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 bogus 1"}), "error", ["bogus"]),
    ("fix wire keyword without value", deck(WIRE, {"fix w ": "fix w wire wire radius"}), "error", ["radius"]),
    ("fix wire radius -1", deck(WIRE, {"fix w ": "fix w wire wire radius -1"}), "error", ["-1"]),
    ("fix wire mu_d > mu_s", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 200 mu_s 0.3 mu_d 0.5"}),
     "error", ["mu_d"]),
    ("fix wire safety 2", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 safety 2"}), "error", ["2"]),
    ("fix wire substeps 0", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 substeps 0"}), "error", ["substeps"]),
    ("fix wire with minimize", deck(WIRE, run="minimize 1e-4 1e-6 10 100"), "error", ["minimize"]),
    ("bond_coeff k_elo -1", deck(WIRE, {"bond_coeff": "bond_coeff 1 -1 0.2"}), "error", ["-1"]),
    ("bond_coeff r0 0", deck(WIRE, {"bond_coeff": "bond_coeff 1 100 0"}), "error", ["0"]),
    ("angle_coeff -1", deck(WIRE, {"angle_coeff": "angle_coeff 1 -1"}), "error", ["-1"]),
    ("create_wire outside the box", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 9 -2 0.3 bond 1 mass 0.01 radius 0.02"}),
     "error", ["outside"]),
    ("create_wire through a grain", deck(WIRE, {"create_wire": "create_wire 2 line -3 0 0.5 3 0 0.5 bond 1 mass 0.01 radius 0.02"}),
     "error", ["overlap"]),
    ("create_wire elements shorter than 2 r_w", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 mass 0.01 radius 0.5"}),
     "error", ["diameter"]),
    ("create_wire without bond", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 mass 0.01 radius 0.02"}),
     "error", ["bond"]),
    ("create_wire mass 0", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 mass 0 radius 0.02"}),
     "error", ["mass"]),
    ("create_wire type 7", deck(WIRE, {"create_wire": "create_wire 7 line -3 -2 0.3 3 -2 0.3 bond 1 mass 0.01 radius 0.02"}),
     "error", ["7"]),
    ("create_wire polyline missing file", deck(WIRE, {"create_wire": "create_wire 2 polyline nowhere.txt bond 1 mass 0.01 radius 0.02 strained yes"}),
     "error", ["nowhere.txt"]),
    ("create_wire loop gap 400", deck(WIRE, {"create_wire": "create_wire 2 loop 0 0 0.3 2 gap 400 bond 1 mass 0.01 radius 0.02"}),
     "error", ["400"]),
    ("create_wire bogus path", deck(WIRE, {"create_wire": "create_wire 2 spiral 0 0 0.3 bond 1 mass 0.01"}),
     "error", ["spiral"]),
    ("create_wire drop with nothing below", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 mass 0.01 radius 0.02 drop yes"}),
     "error", ["drop", "nothing below"]),
    ("create_wire drop onto a grain", deck(WIRE, {"create_wire": "create_wire 2 line -3 0 3 3 0 3 bond 1 mass 0.01 radius 0.02 drop yes"}),
     "ok", []),
    ("create_wire drop maybe", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 mass 0.01 radius 0.02 drop maybe"}),
     "error", ["maybe"]),
    ("create_wire drop with from", deck(WIRE, add=["create_wire 2 line 3 -2 0.3 3 2 0.3 from last drop yes"]),
     "error", ["drop", "from"]),
    # --- create_grains (doc/create_grains.rst)
    ("create_grains type 7", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 7 g shape 1 1 density 1 seed 5 lattice 1.5"]), "error", ['7']),
    ("create_grains no such region", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 nowhere shape 1 1 density 1 seed 5 lattice 1.5"]), "error", ['nowhere']),
    ("create_grains seed 0", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density 1 seed 0 lattice 1.5"]), "error", ['seed', '0']),
    ("create_grains density -1", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density -1 seed 5 lattice 1.5"]), "error", ['density', '-1']),
    ("create_grains lattice 0", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density 1 seed 5 lattice 0"]), "error", ['lattice', '0']),
    ("create_grains shape 1 9 (library of 1)", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 9 density 1 seed 5 lattice 1.5"]), "error", ['9']),
    ("create_grains random 0 10", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density 1 seed 5 random 0 10"]), "error", ['random', '0']),
    ("create_grains without layout", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density 1 seed 5"]), "error", ['lattice', 'random']),
    ("create_grains region outside the box", deck(BASE, add=["region far block 3 8 -2 2 2 4 units box", "create_grains 1 far shape 1 1 density 1 seed 5 lattice 1.5"]), "error", ['outside']),
    ("create_grains bogus keyword", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density 1 seed 5 lattice 1.5 color red"]), "error", ['color']),
    ("create_grains gap -1", deck(BASE, add=["region g block -2 2 -2 2 2 4 units box", "create_grains 1 g shape 1 1 density 1 seed 5 lattice 1.5 gap -1"]), "error", ['gap', '-1']),
    # --- issue 25: numbers given to keywords
    ("tolerance nan", deck(BASE, {"fix solver": "fix solver all nscd tolerance nan"}), "error", ["tolerance", "nan"]),
    ("max_sweeps 2.5", deck(BASE, {"fix solver": "fix solver all nscd max_sweeps 2.5"}), "error", ["max_sweeps", "2.5"]),
    ("friction nan", deck(BASE, {"pair_coeff": "pair_coeff * * nan"}), "error", ["friction", "nan"]),
    ("activation inf", deck(BASE, {"pair_style": "pair_style nscd activation inf"}), "error", ["activation", "inf"]),
    ("wall point nan", deck(BASE, {"fix floor": "fix floor all nscd/wall plane 0 0 nan 0 0 1"}), "error", ["point", "nan"]),
    ("plate mass inf", deck(BASE, add=["fix plate all nscd/plate 3 mass inf"]), "error", ["mass", "inf"]),
    ("fix wire k_n nan", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n nan"}), "error", ["k_n", "nan"]),
    ("fix wire substeps 2.5", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 200 substeps 2.5"}), "error", ["substeps", "2.5"]),
    ("fix wire substeps 1000000000", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 200 substeps 1000000000"}),
     "error", ["substeps 1000000000"]),
    ("fix wire substeps far above stability", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 200 substeps 5000"}),
     "warning", ["substeps 5000"]),
    ("fix wire dt_sp 0", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 200 dt_sp 0"}), "error", ["dt_sp", "auto"]),
    ("fix wire contacts_per_node 0", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 200 contacts_per_node 0"}),
     "error", ["contacts_per_node"]),
    ("create_wire radius inf", deck(WIRE, {"create_wire": "create_wire 2 loop 0 0 1 inf bond 1 mass 0.01 radius 0.02"}),
     "error", ["radius", "inf"]),
    ("create_wire nodes 7.5", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 mass 0.01 radius 0.02 nodes 7.5"}),
     "error", ["nodes", "7.5"]),
    ("shapes random 2.5", shapes_deck("shapes random 2.5 seed 1"), "error", ["count", "2.5"]),
    ("shapes assign density nan", deck(BASE, {"shapes assign": "shapes assign all shape 1 density nan"}), "error", ["density", "nan"]),
    # --- pair_style nscd: one distance twice
    ("activation and activation/fraction", deck(BASE, {"pair_style": "pair_style nscd activation 0.1 activation/fraction 0.2"}),
     "error", ["activation 0.1", "activation/fraction 0.2"]),
    ("reach and reach/fraction", deck(BASE, {"pair_style": "pair_style nscd reach 0.1 reach/fraction 1"}),
     "error", ["reach 0.1", "reach/fraction 1"]),
    # --- values a run cannot take
    ("a cylinder narrower than the grain", deck(BASE, {"fix floor": "fix floor all nscd/wall cylinder 0 0 0 0 0 1 0.3"},
                                                drop=["create_atoms 1 single 2"]), "warning", ["radius 0.3"]),
    ("grain mass 1e-300", deck(BASE, {"shapes assign": "shapes assign all shape 1 mass 1e-300"}), "error", ["1e-300"]),
    ("plate mass 1e-300", deck(BASE, add=["fix plate all nscd/plate 3 mass 1e-300"]), "error", ["mass", "1e-300"]),
    ("plate rate 1e12", deck(BASE, {"create_atoms 1 single 2": "create_atoms 1 single 0 0 1.5"},
                             add=["fix plate all nscd/plate 2.5 mass 1 rate 1e12"], run="run 20"), "error", ["rate 1e+12"]),
    ("plate rate 1e9", deck(BASE, {"create_atoms 1 single 2": "create_atoms 1 single 0 0 1.5"},
                            add=["fix plate all nscd/plate 2.5 mass 1 rate 1e9"], run="run 20"), "error", ["rate 1e+09"]),
    ("overlap_speed 1e6", deck(BASE, {"fix solver": "fix solver all nscd overlap_speed 1e6",
                                      "create_atoms 1 single 2": "create_atoms 1 single 0.5 0 0.5"}, run="run 100"),
     "error", ["overlap_speed 1000000"]),
    # --- fix wire without contacts, wire inside a grain
    ("fix wire without k_n among grains", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02"}), "error", ["k_n"]),
    ("fix wire k_n 0 among grains", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 0"}), "warning", ["k_n 0"]),
    ("compute wire/contacts with k_n 0", deck(WIRE, {"fix w ": "fix w wire wire radius 0.02 k_n 0"},
                                              add=["compute wc all wire/contacts"]), "error", ["wire/contacts", "k_n 0"]),
    ("a wire inside a grain", deck(WIRE, {"create_wire": "create_wire 2 line -3 0 0.5 3 0 0.5 bond 1 angle 1 mass 0.01 "
                                                         "radius 0.02 overlap ignore"}), "warning", ["inside grain ID 1"]),
    ("create_wire takes fix wire's radius", deck(WIRE, {"create_wire": "group wire type 2\nfix w0 wire wire radius 0.02 k_n 200\n"
                                                                       "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 angle 1 mass 0.01",
                                                        "fix w ": "unfix w0\ngroup wire type 2\nfix w wire wire radius 0.02 k_n 200"}),
     "ok", []),
    # --- create_wire: polyline lines, overlapping wires
    ("polyline line nan", deck(WIRE, {"create_wire": "create_wire 2 polyline nan_path.txt bond 1 mass 0.01 radius 0.02 strained yes"}),
     "error", [":2:", "nan"]),
    ("polyline line inf", deck(WIRE, {"create_wire": "create_wire 2 polyline inf_path.txt bond 1 mass 0.01 radius 0.02 strained yes"}),
     "error", [":2:", "inf"]),
    ("polyline line 1e400", deck(WIRE, {"create_wire": "create_wire 2 polyline huge_path.txt bond 1 mass 0.01 radius 0.02 strained yes"}),
     "error", [":2:", "1e400"]),
    ("polyline header line", deck(WIRE, {"create_wire": "create_wire 2 polyline header_path.txt bond 1 mass 0.01 radius 0.02 strained yes"}),
     "error", [":1:", "'x'"]),
    ("helix pitch below the diameter", deck(WIRE, {"create_wire": "create_wire 2 loop 0 0 2 2.5 turns 2 pitch 0.01 bond 1 mass 0.01 radius 0.02"}),
     "error", ["pitch 0.01", "diameter"]),
    ("a loop across its periodic image", deck(WIRE, {"boundary": "boundary p p f",
                                                     "create_wire": "create_wire 2 loop 0 0 2 4.995 bond 1 mass 0.01 radius 0.02 strained yes"}),
     "error", ["periodic image"]),    # (the message names no value)
    ("a second wire through the first", deck(WIRE, {"create_wire": "create_wire 2 line -3 -2 0.3 3 -2 0.3 bond 1 angle 1 mass 0.01 "
                                                                   "radius 0.02\ncreate_wire 2 line 2 -4 0.3 2 3 0.3 bond 1 mass 0.01 radius 0.02"}),
     "error", ["overlaps the wire element"]),
    # --- data files
    ("data file shape id 7", shapes_deck("clear", "atom_style spheropolyhedron", "shapes read cube.shapes", "read_data bad_shape.data"),
     "error", ["shape id 7"]),
    ("data file mass -1", shapes_deck("clear", "atom_style spheropolyhedron", "shapes read cube.shapes", "read_data bad_mass.data"),
     "error", ["mass -1"]),
    ("data file quaternion 0 0 0 0", shapes_deck("clear", "atom_style spheropolyhedron", "shapes read cube.shapes", "read_data bad_quat.data"),
     "error", ["quaternion"]),
    # --- damaged and cut restart files (damage.py, through `shell`)
    ("restart: fix nscd count too large", damaged("solver", "nscd", "count"), "error", ["fix nscd solver", "counts 1000000000"]),
    ("restart: fix nscd foreign mark", damaged("solver", "nscd", "mark"), "error", ["fix nscd solver", "mark"]),
    ("restart: fix nscd NaN impulse", damaged("solver", "nscd", "atom_nan"), "error", ["fix nscd solver", "nan"]),
    ("restart: fix nscd size", damaged("solver", "nscd", "size"), "error", ["fix nscd solver", "bytes"]),
    ("restart: fix nscd denormal timestep", damaged("solver", "nscd", "dt"), "error", ["fix nscd solver", "timestep is 5.00000000228"]),
    ("restart: fix wire count too large", damaged("w", "wire", "wire_count"), "error", ["fix wire w", "counts 1000000000"]),
    ("restart: fix wire denormal substep", damaged("w", "wire", "wire_dt"), "error", ["fix wire w", "substep is 5.00000000228"]),
    ("restart: fix wire foreign mark", damaged("w", "wire", "mark"), "error", ["fix wire w", "mark"]),
    ("restart: wall kind 2", damaged("floor", "nscd/wall", "kind"), "error", ["fix nscd/wall floor", "kind is 2"]),
    ("restart: wall format 999", damaged("floor", "nscd/wall", "format"), "error", ["fix nscd/wall floor", "format 999"]),
    ("restart: plate foreign mark", damaged("plate", "nscd/plate", "mark"), "error", ["fix nscd/plate plate", "mark"]),
    ("restart: plate format 999", damaged("plate", "nscd/plate", "format"), "error", ["fix nscd/plate plate", "format 999"]),
    ("restart: file cut in half", damaged("solver", "nscd", "truncate"), "error", ["restart file"]),    # LAMMPS' own
    # --- examples/column without the restart it continues from
    ("examples/column -var start 5 without phase 4", ["variable start index 5", f"include {EXAMPLES}/column/in.column"],
     "error", ["column.phase4.restart"]),
]


MAX_MESSAGE = 120    # as tools/lammps_style.py's limit on format strings


def message_text(line):
    """The message of an ERROR or WARNING line, without LAMMPS' prefix and its ' (src/...:N)'."""
    text = re.sub(r"^.*?(ERROR|WARNING)( on proc \d+)?: ", "", line.strip())
    return re.sub(r"\s+\((src|lib)/[^)]*:\d+\)\s*$", "", text)


def over_length(line, words, limit):
    """How many characters the message of `line` exceeds `limit` plus its named values by (<= 0: fine)."""
    text = message_text(line)
    allowance = limit + sum(len(w) for w in words if w in text)
    return len(text) - allowance


def long_messages(text, expect, words, limit):
    """The ERROR lines (and for a warning case the named WARNING line) of a case's output that
    are too long, as (excess, message)."""
    if limit <= 0:
        return []
    ours = re.compile(r"^\s*(ERROR|WARNING)( on proc \d+)?: ")    # LAMMPS' lines, not MPI's ORTE_ERROR_LOG
    lines = [l for l in text.splitlines() if ours.match(l) and l.lstrip().startswith("ERROR")]
    if expect == "warning":
        lines += [l for l in text.splitlines() if ours.match(l) and "WARNING" in l and all(w in l for w in words)][:1]
    found = {}
    for l in lines:
        excess = over_length(l, words, limit)
        if excess > 0:
            found[message_text(l)] = excess
    return [(excess, message) for message, excess in found.items()]


def run_case(lmp, ranks, name, lines, expect, words, timeout):
    with tempfile.TemporaryDirectory(prefix="probe_") as d:
        for f, text in FILES.items():
            with open(os.path.join(d, f), "w") as out:
                out.write(text)
        with open(os.path.join(d, "in.probe"), "w") as out:
            out.write("\n".join(lines) + "\n")
        cmd = [lmp, "-in", "in.probe", "-log", "none", "-echo", "none"]
        if ranks > 1:
            cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_btl_vader_single_copy_mechanism="none")
        try:
            p = subprocess.run(cmd, cwd=d, capture_output=True, text=True, errors="replace",
                               timeout=timeout, env=env)
        except subprocess.TimeoutExpired:
            return "hang", "", ""
    text = p.stdout + p.stderr
    outcome, message = sort_outcome(p.returncode, text, expect, words)
    return outcome, message, text


def sort_outcome(returncode, text, expect, words):
    errors = [l for l in text.splitlines() if "ERROR" in l]
    warnings = [l for l in text.splitlines() if "WARNING" in l]
    named = lambda found: any(all(w in l for w in words) for l in found)
    if expect == "ok":
        return ("handled" if returncode == 0 else ("wrong" if errors else "crash")), (errors or [""])[0]
    if errors:
        if expect == "error":
            return ("clear" if named(errors) else "unclear"), errors[0]
        return "unclear", errors[0]    # a warning was the answer, an error stops the run
    if returncode != 0:
        return "crash", (text.strip().splitlines() or ["(no output)"])[-1]
    if expect == "warning" and named(warnings):
        return "clear", [l for l in warnings if all(w in l for w in words)][0]
    return "silent", (warnings or [""])[0]


def main():
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmp", default=os.path.join(here, "build", "lmp"))
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--only", default="")
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--markdown", help="write the per-case table here")
    ap.add_argument("--max-length", type=int, default=MAX_MESSAGE,
                    help="longest message beyond its named values (0: no length check)")
    args = ap.parse_args()
    lmp = os.path.abspath(args.lmp)     # the cases run in scratch folders: a relative path would miss
    counts, rows, too_long = {}, [], []
    for name, lines, expect, words in CASES:
        if args.only and args.only not in name:
            continue
        outcome, message, text = run_case(lmp, args.ranks, name, lines, expect, words, args.timeout)
        counts[outcome] = counts.get(outcome, 0) + 1
        too_long += [(name, excess, long_one)
                     for excess, long_one in long_messages(text, expect, words, args.max_length)]
        message = re.sub(r"\s+\(src/[^)]*\)", "", message.replace("|", "/")).strip()
        rows.append((name, outcome, message))
        print(f"{outcome:8s} {name}: {message}", flush=True)
    total = sum(counts.values())
    summary = ", ".join(f"{k} {counts.get(k, 0)}" for k in
                        ("clear", "handled", "unclear", "crash", "hang", "silent", "wrong"))
    for name, excess, long_one in too_long:
        print(f"long     {name}: {len(long_one)} characters, {excess} beyond {args.max_length} and its named values: "
              f"{long_one}")
    summary += f"; {len(too_long)} message(s) too long" if args.max_length > 0 else ""
    print(f"probe_bad_input: {total} cases on {args.ranks} rank(s): {summary}")
    if args.markdown:
        with open(args.markdown, "w") as out:
            out.write(f"{total} cases on {args.ranks} rank(s): {summary}\n\n| case | outcome | message |\n|---|---|---|\n")
            for name, outcome, message in rows:
                out.write(f"| {name} | {outcome} | `{message[:160]}` |\n")
    bad = sum(counts.get(k, 0) for k in ("unclear", "crash", "hang", "silent", "wrong")) + len(too_long)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
