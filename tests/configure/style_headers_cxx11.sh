#!/usr/bin/env bash
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

# LAMMPS core files (force.cpp, modify.cpp, ...) include every style header through the
# generated style_*.h, and LAMMPS still accepts C++11 (-DCMAKE_CXX_STANDARD=11 with
# LAMMPS_CXX11). So the style headers, included together as the core includes them, must
# compile as strict C++11 (the compiler's message names the header and line).
#   style_headers_cxx11.sh PACKAGE_SRC_DIR LAMMPS_TREE CXX [MPI compile flags...]
set -euo pipefail
pkg=$1; tree=$2; cxx=$3; shift 3
includes=()
for header in "$pkg"/*.h; do
  grep -Eq "^(Atom|Pair|Fix|Bond|Angle|Compute|Command|Dump)Style\(" "$header" &&
    includes+=("#include \"$(basename "$header")\"")
done
[ ${#includes[@]} -gt 0 ] || { echo "no style header in $pkg"; exit 1; }
printf '%s\n' "${includes[@]}" |
  "$cxx" -std=c++11 -pedantic-errors -DLAMMPS_CXX11 "$@" -fsyntax-only -I"$tree/src" -I"$pkg" -x c++ -
echo "${#includes[@]} style headers compile as C++11"
