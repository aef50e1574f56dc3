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

# Sphinx configuration of the package's documentation (doc/*.md, Markdown through MyST).
# Built by the CTest test docs.sphinx with warnings as errors:
#   /usr/bin/python3 -m sphinx -W --keep-going -b html doc build/doc-html
# (Debian: python3-sphinx, python3-myst-parser; tools/build.sh installs them.)

project = "NSCD and elastic wires for LAMMPS"
author = "the NSCD package authors"

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]

# Links to a section of another page (`page.md#a-heading`) resolve through the headings'
# anchors, as GitHub makes them.
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath"]

html_theme = "alabaster"
html_title = project
