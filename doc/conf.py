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
