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

"""Column layouts of the package's computes (1-based, as c_ID[k] in a dump header), so that
dumps written with `c_ID[*]` or any subset of c_ID[k] can be read by name. Checked against the
computes' own dumps by tests/analysis/dump_layouts.py (CTest analysis.dump_layouts): a
column added, removed or moved on either side fails it."""

# compute nscd/contacts (one row per contact point)
CONTACT_POINTS = {name: k + 1 for k, name in enumerate(
    "id_i id_j px py pz nx ny nz fn ft fx fy fz gap status".split())}

# compute nscd/contacts pairs (one row per contacting pair)
CONTACT_PAIRS = {name: k + 1 for k, name in enumerate(
    "id_i id_j xi yi zi xj yj zj fn fx fy fz points nx ny nz".split())}

# compute fabric/atom (per-atom array)
FABRIC = {name: k + 1 for k, name in enumerate("fxx fyy fzz fxy fxz fyz nc".split())}

# compute wire/local (one row per wire element)
WIRE_ELEMENTS = {name: k + 1 for k, name in enumerate("id1 id2 strain tension energy".split())}

# compute wire/contacts (one row per wire contact point): the element's two node IDs
# (wire-wall/plate: the node, then 0); the other body (grain ID, -k for the k-th boundary
# fix, or the other element's first node for wire-wire); kind (1 wire-grain, 2 wire-wire,
# 3 wire-boundary); contact point; unit normal from the other body to the wire; normal
# force (>= 0); tangential force vector; overlap; status (0 stick, 1 slide). The force on
# the wire is fn * n + ft.
WIRE_CONTACTS = {name: k + 1 for k, name in enumerate(
    "id1 id2 other kind px py pz nx ny nz fn ftx fty ftz overlap status".split())}

WIRE_GRAIN, WIRE_WIRE, WIRE_BOUNDARY = 1, 2, 3

# compute nscd/stress/atom (per-atom array), tension positive
STRESS = {name: k + 1 for k, name in enumerate("sxx syy szz sxy sxz syz".split())}

# compute nscd/crush/atom (per-atom array): largest contact force, size, F/d^2, index
CRUSH = {name: k + 1 for k, name in enumerate("fmax d sigma index".split())}
