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

"""Analysis of LAMMPS dumps and logs of the NSCD package: the papers' figures (fabric field,
principal fabric angle vs r, Fn(r), wire-grain force orientations, time series) and VTK
files for ParaView. Command line: tools/nscd-analysis (see doc/analysis.md).

Needs numpy, scipy and matplotlib (Debian's python3-numpy, python3-scipy,
python3-matplotlib; run with /usr/bin/python3)."""
