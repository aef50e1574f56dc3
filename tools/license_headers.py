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

"""The licence and author header every source file of the package starts with, in
LAMMPS' form (a licence block, then a contributing-author block; C++ headers open with
"-*- c++ -*-"), written as a C++ comment or as '#' lines for scripts.

    license_headers.py [--add] [REPO]

Source files: C++ (.cpp, .h), Python (.py) and shell (.sh) files and '#!' scripts under
src/ lib/ tests/ benchmarks/ tools/ examples/, and doc/conf.py. Build files (CMake) and
input decks carry no header, as in LAMMPS.

Without --add: prints each source file that does not start with the header (after its
'#!' line) and exits 1 if any does not, or if LICENSE is not the GPL version 2.
With --add: puts the header on top of each source file that lacks it.
"""
import argparse
import os
import pathlib
import sys

LICENCE = [
    "NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid",
    "spheropolyhedra coupled to elastic wires.",
    "",
    "Copyright (2026) the NSCD package developers. This software is",
    "distributed under the GNU General Public License, version 2, the",
    "licence of LAMMPS. See the LICENSE file in the top-level directory",
    "of the package.",
]
AUTHORS = ["Contributing author: the NSCD package developers"]

SOURCE_DIRS = ["src", "lib", "tests", "benchmarks", "tools", "examples"]
SOURCE_SUFFIXES = {".cpp", ".h", ".py", ".sh"}
EXTRA_FILES = ["doc/conf.py"]
GPL2_OPENING = "GNU GENERAL PUBLIC LICENSE\n                       Version 2, June 1991"


def c_block(lines, opening="/* " + "-" * 70):
    body = ["   " + line if line else "" for line in lines]
    return "\n".join([opening, *body, "-" * 73 + " */"]) + "\n"


def header_for(path):
    """The header text a file of this kind starts with (after a '#!' line)."""
    if path.suffix in (".cpp", ".h"):
        opening = "/* -*- c++ -*- " + "-" * 58 if path.suffix == ".h" else "/* " + "-" * 70
        return c_block(LICENCE, opening) + "\n" + c_block(AUTHORS) + "\n"
    rule = "# " + "-" * 70
    body = ["# " + line if line else "#" for line in LICENCE]
    return "\n".join([rule, *body, rule, "# " + AUTHORS[0], rule]) + "\n\n"


def is_source(path):
    if path.suffix in SOURCE_SUFFIXES:
        return True
    if path.suffix or not path.is_file():
        return False
    with open(path, "rb") as f:
        return f.read(2) == b"#!"


def source_files(repo):
    found = [repo / name for name in EXTRA_FILES if (repo / name).is_file()]
    for top in SOURCE_DIRS:
        for folder, subdirs, files in os.walk(repo / top):
            subdirs[:] = sorted(d for d in subdirs if not d.startswith((".", "__pycache__")))
            found += [pathlib.Path(folder) / f for f in sorted(files) if is_source(pathlib.Path(folder) / f)]
    return found


def split_shebang(text):
    if text.startswith("#!"):
        first, _, rest = text.partition("\n")
        return first + "\n", rest
    return "", text


def has_header(path):
    _, rest = split_shebang(path.read_text())
    return rest.startswith(header_for(path))


def add_header(path):
    shebang, rest = split_shebang(path.read_text())
    path.write_text(shebang + header_for(path) + rest)


def licence_problem(repo):
    licence = repo / "LICENSE"
    if not licence.is_file():
        return "LICENSE: missing (the GPL version 2: /usr/share/common-licenses/GPL-2)"
    if not licence.read_text().lstrip().startswith(GPL2_OPENING):
        return "LICENSE: not the GNU General Public License version 2"
    return ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("repo", nargs="?", default=pathlib.Path(__file__).resolve().parent.parent,
                        type=pathlib.Path, help="top-level directory of the package")
    parser.add_argument("--add", action="store_true", help="add the header where it is missing")
    args = parser.parse_args()
    files = source_files(args.repo)
    lacking = [f for f in files if not has_header(f)]
    if args.add:
        for path in lacking:
            add_header(path)
        print(f"header added to {len(lacking)} of {len(files)} source files")
        return 0
    for path in lacking:
        print(f"{path.relative_to(args.repo)}: does not start with the licence header "
              f"(tools/license_headers.py --add writes it)")
    problem = licence_problem(args.repo)
    if problem:
        print(problem)
    print(f"{len(files)} source files, {len(lacking)} without the licence header")
    return 1 if lacking or problem else 0


if __name__ == "__main__":
    sys.exit(main())
