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

"""The documentation's layout, as LAMMPS' own manual has it (doc/src/Modify_requirements.rst of
the LAMMPS tree):

1. every command page of doc/ (the pages of the table of contents captioned "Commands" in
   doc/index.md) is reStructuredText, doc/<page>.rst, in ASCII only, with an `.. index::` line, a
   title "... command" underlined with '=', and the sections of a LAMMPS reference page,
   underlined with '"': Syntax, Examples, Description, the restart section, Restrictions,
   Related commands, Default, in that order (other sections may stand between them). The
   restart section is the one LAMMPS gives the style's kind: "Restart, fix_modify, output, run
   start/stop, minimize info" (fixes), "Output info" (computes), "Mixing, shift, table, tail
   correction, restart, rRESPA info" (pair styles) or "Restart info" (the others); the other
   .rst pages of doc/ (the package page) are ASCII too;
2. every Howto page of the models (the pages named Howto_* in the table of contents captioned
   "Howto and models", as LAMMPS' doc/src/Howto_*.rst) is reStructuredText, doc/<page>.rst, in
   ASCII only, titled with a line underlined with '=', and holds no Markdown left over from a
   conversion (a ``` fence, a [text](page.md) link); the Syntax/Examples layout of a command
   page does not apply to it. The build, MPI, analysis and dated measurement pages stay Markdown;
3. every pointer to a page of doc/ ("doc/fix_wire.rst", "../../doc/fix_nscd_plate.rst#failure")
   in src/ lib/ tests/ tools/ examples/ benchmarks/ README.md and doc/ names a page that exists,
   and so does every relative link of a Markdown page of doc/ ("[text](Howto_nscd_units.rst)"),
   so a message, comment or link cannot point to a page that was renamed or removed (a link to
   a section of a reStructuredText page goes by the section's label, {ref}`text <label>`:
   "page.rst#anchor" does not resolve). The logs of the examples (examples/*/log.*) are left
   out: they are the record of a run, deck echo included, as LAMMPS' own example logs are.

Prints what is wrong and exits 1 if anything is.

    check_layout.py DOC_DIR
"""
import pathlib
import re
import sys

SECTIONS = ["Syntax", "Examples", "Description", "Restart", "Restrictions", "Related commands", "Default"]
RESTART_SECTIONS = {
    "Restart, fix_modify, output, run start/stop, minimize info",
    "Output info",
    "Mixing, shift, table, tail correction, restart, rRESPA info",
    "Restart info",
}
POINTER_DIRS = ["src", "lib", "tests", "tools", "examples", "benchmarks", "doc"]
POINTER_FILES = ["README.md"]
POINTER = re.compile(r"\bdoc/([A-Za-z0-9_]+\.(?:md|rst))\b")
RELATIVE_LINK = re.compile(r"\]\(([A-Za-z0-9_]+\.(?:md|rst))(#[^)]*)?\)")
MARKDOWN_LEFTOVER = re.compile(r"^\s*```|\]\([^)\s]*\.(?:md|rst)(?:#[^)]*)?\)")
TEXT_SUFFIXES = {".cpp", ".h", ".py", ".sh", ".md", ".rst", ".txt", ".cmake", ""}


def toctree_pages(doc, caption):
    index = (doc / "index.md").read_text()
    for block in re.findall(r"```\{toctree\}\n(.*?)```", index, re.S):
        lines = [line.strip() for line in block.splitlines() if line.strip()]
        if f":caption: {caption}" in lines:
            return [line for line in lines if not line.startswith(":")]
    sys.exit(f"{doc / 'index.md'}: no toctree captioned '{caption}'")


def command_pages(doc):
    return toctree_pages(doc, "Commands")


def howto_pages(doc):
    return [name for name in toctree_pages(doc, "Howto and models") if name.startswith("Howto_")]


def sections(text):
    """(title, underline character) of every section heading of an rst text, in order."""
    lines = text.splitlines()
    found = []
    for k in range(len(lines) - 1):
        title, under = lines[k].rstrip(), lines[k + 1].rstrip()
        if (title and not title.startswith(" ") and len(under) >= len(title) and len(set(under)) == 1
                and under[0] in "=\"^-~*#+'" and (k == 0 or not lines[k - 1].strip())):
            found.append((title, under[0]))
    return found


def non_ascii(page):
    """A problem per line of the page that holds a byte outside ASCII."""
    return [f"line {number}: not ASCII: {line.decode('utf-8', 'replace').strip()[:70]}"
            for number, line in enumerate(page.read_bytes().splitlines(), 1) if any(b > 127 for b in line)]


def layout_problems(page):
    problems = non_ascii(page)
    text = page.read_bytes().decode("utf-8", "replace")
    if not re.search(r"^\.\. index:: ", text, re.M):
        problems.append("no '.. index::' line")
    found = sections(text)
    if not found or found[0][1] != "=" or not found[0][0].endswith(" command"):
        problems.append("the title is not '... command' underlined with '='")
    top = ["Restart" if title in RESTART_SECTIONS else title for title, mark in found if mark == '"']
    missing = [s for s in SECTIONS if s not in top]
    if missing:
        problems.append("no section " + ", ".join(missing))
    else:
        present = [t for t in top if t in SECTIONS]
        if present != SECTIONS:
            problems.append("sections out of order: " + ", ".join(present))
    return problems


def howto_problems(page):
    """What keeps a Howto page from being ASCII reStructuredText with a title."""
    problems = non_ascii(page)
    lines = page.read_bytes().decode("utf-8", "replace").splitlines()
    found = sections("\n".join(lines))
    if not found or found[0][1] != "=":
        problems.append("the title is not underlined with '='")
    problems += [f"line {number}: Markdown left in the page: {line.strip()[:70]}"
                 for number, line in enumerate(lines, 1) if MARKDOWN_LEFTOVER.search(line)]
    return problems


def dangling_pointers(repo):
    """file:line: doc/<page> for every pointer to a page of doc/ that does not exist."""
    doc = repo / "doc"
    files = [repo / name for name in POINTER_FILES]
    for folder in POINTER_DIRS:
        files += [p for p in sorted((repo / folder).rglob("*")) if p.is_file()]
    problems = []
    for path in files:
        rel = path.relative_to(repo)
        if path.suffix not in TEXT_SUFFIXES or (rel.parts[0] == "examples" and path.name.startswith("log.")):
            continue
        try:
            text = path.read_text()
        except (UnicodeDecodeError, OSError):
            continue
        relative = rel.parts[0] == "doc" and path.suffix == ".md"
        for number, line in enumerate(text.splitlines(), 1):
            for page in POINTER.findall(line):
                if not (doc / page).is_file():
                    problems.append(f"{rel}:{number}: points to doc/{page}, which does not exist")
            for page, anchor in RELATIVE_LINK.findall(line) if relative else []:
                if not (path.parent / page).is_file():
                    problems.append(f"{rel}:{number}: links {page}, which does not exist")
                elif anchor and page.endswith(".rst"):
                    problems.append(f"{rel}:{number}: links {page}{anchor}: a section of a reStructuredText "
                                    "page is linked by its label, {ref}`text <label>`")
    return problems


def main():
    doc = pathlib.Path(sys.argv[1])
    pages = command_pages(doc)
    bad = 0
    for name in pages:
        page = doc / f"{name}.rst"
        if not page.is_file():
            bad += 1
            print(f"doc/{name}.rst: missing (command pages are reStructuredText)")
            continue
        for problem in layout_problems(page):
            print(f"doc/{name}.rst: {problem}")
        bad += bool(layout_problems(page))
    print(f"{len(pages)} command pages, {bad} not in the layout of a LAMMPS reference page")
    howtos = howto_pages(doc)
    bad_howtos = 0
    for name in howtos:
        page = doc / f"{name}.rst"
        problems = howto_problems(page) if page.is_file() else ["missing (Howto pages are reStructuredText)"]
        for problem in problems:
            print(f"doc/{name}.rst: {problem}")
        bad_howtos += bool(problems)
    print(f"{len(howtos)} Howto pages, {bad_howtos} not ASCII reStructuredText with a title")
    bad += bad_howtos
    others = [page for page in sorted(doc.glob("*.rst")) if page.stem not in pages + howtos]
    for page in others:
        for problem in non_ascii(page):
            bad += 1
            print(f"doc/{page.name}: {problem}")
    dangling = dangling_pointers(doc.resolve().parent)
    for problem in dangling:
        print(problem)
    print(f"{len(dangling)} pointers to pages of doc/ that do not exist")
    return 1 if bad or dangling else 0


if __name__ == "__main__":
    sys.exit(main())
