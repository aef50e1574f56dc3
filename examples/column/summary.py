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

"""Kept for old commands: the per-phase table is `tools/nscd-analysis phases LOG...`
(doc/analysis.md); this forwards its arguments there."""
import os
import sys

tools = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, tools)
from nscd_analysis.cli import main  # noqa: E402

sys.exit(main(["phases"] + sys.argv[1:]))
