#!/usr/bin/env python3
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

"""Every command page of doc/ (the pages of the table of contents captioned "Commands" in
doc/index.md) has the sections of a LAMMPS reference page: Syntax, Examples, Description,
Restart, Restrictions, Related commands, Default (as '## ' headings), in that order (other
sections may stand between them). Prints what is missing or out of order and exits 1 if
anything is.

    check_layout.py DOC_DIR
"""
import pathlib
import re
import sys

SECTIONS = ["Syntax", "Examples", "Description", "Restart", "Restrictions", "Related commands", "Default"]


def command_pages(doc):
    index = (doc / "index.md").read_text()
    for block in re.findall(r"```\{toctree\}\n(.*?)```", index, re.S):
        lines = [line.strip() for line in block.splitlines() if line.strip()]
        if ":caption: Commands" in lines:
            return [line for line in lines if not line.startswith(":")]
    sys.exit(f"{doc / 'index.md'}: no toctree captioned 'Commands'")


def headings(page):
    """The '## ' headings of a page, outside code blocks."""
    found, fence = [], False
    for line in page.read_text().splitlines():
        if line.startswith("```"):
            fence = not fence
        elif not fence and line.startswith("## "):
            found.append(line[3:].strip())
    return found


def layout_problems(page):
    found = headings(page)
    missing = [s for s in SECTIONS if s not in found]
    if missing:
        return "no section " + ", ".join(missing)
    present = [h for h in found if h in SECTIONS]
    if present != SECTIONS:
        return "sections out of order: " + ", ".join(present)
    return ""


def main():
    doc = pathlib.Path(sys.argv[1])
    pages = command_pages(doc)
    bad = 0
    for name in pages:
        problem = layout_problems(doc / f"{name}.md")
        if problem:
            bad += 1
            print(f"doc/{name}.md: {problem}")
    print(f"{len(pages)} command pages, {bad} not in the layout of a LAMMPS reference page")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
