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

# Sphinx configuration of the package's documentation: the command and style reference pages
# and the Howto pages of the models (doc/Howto_nscd_*.rst) in reStructuredText as LAMMPS' own
# manual writes them (doc/*.rst, ASCII only), the build, MPI, analysis and dated measurement
# pages in Markdown through MyST (doc/*.md).
# Built by the CTest test docs.sphinx with warnings as errors:
#   /usr/bin/python3 -m sphinx -W --keep-going -b html doc build/doc-html
# (Debian: python3-sphinx, python3-myst-parser; tools/build.sh installs them.)

import re

from pygments.lexer import RegexLexer
from pygments.token import Comment, Keyword, Name, Number, String, Text, Whitespace

project = "NSCD and elastic wires for LAMMPS"
author = "the NSCD package authors"

extensions = ["myst_parser", "sphinx.ext.extlinks"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]

# Links to a section of another Markdown page (`page.md#a-heading`) resolve through the
# headings' anchors, as GitHub makes them. Those anchors exist for Markdown headings only: a
# section of a reStructuredText page (a Howto page) is linked by its label, {ref}`text
# <label>` from Markdown, :ref:`text <label>` from reStructuredText, the label being the
# `.. _label:` line before the section.
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath"]

html_theme = "alabaster"
html_title = project

# :lammps:`fix <fix>` links a command of LAMMPS' own manual, as :doc:`fix <fix>` does inside it.
extlinks = {"lammps": ("https://docs.lammps.org/%s.html", "%s")}


class LammpsInputLexer(RegexLexer):
    """Input lines of LAMMPS for `.. code-block:: LAMMPS` (the name LAMMPS' manual uses):
    the command, comments, variables, strings and numbers; anything else is plain text, so
    no line fails to lex."""

    name = "LAMMPS"
    aliases = ["LAMMPS", "lammps"]
    flags = re.MULTILINE
    tokens = {
        "root": [
            (r"^[ \t]*[a-z_][a-z_/]*", Keyword),
            (r"[ \t]+|\n", Whitespace),
            (r"#.*$", Comment),
            (r"\$\{[^}\n]*\}|\$\([^)\n]*\)|\$[A-Za-z]|\b[vcf]_\w+(\[[^\]\n]*\])?", Name.Variable),
            (r'"[^"\n]*"|\'[^\'\n]*\'', String),
            (r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\b", Number),
            (r"[^\s#\"'$]+|.", Text),
        ]
    }


def setup(app):
    app.add_lexer("LAMMPS", LammpsInputLexer)
