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

# Builds LAMMPS with this package as a shared library (liblammps.so) in a build tree of its
# own and puts LAMMPS' `lammps` Python module beside it, so that Python drives LAMMPS
# in-process (examples/python/):
#
#   tools/build_python.sh [-D options for CMake]
#   PYTHONPATH=build-python/python /usr/bin/python3 -c 'import lammps; lammps.lammps()'
#
# A cold LAMMPS build (position-independent code: the objects of build/ do not serve), about
# as long as the first build of build/. The module is LAMMPS' own python/lammps of the same
# source tree; it finds liblammps.so in its folder. Environment: BUILD_DIR (default
# <repo>/build-python), JOBS (default: number of cores).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build-python}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

if [ ! -f "$build/CMakeCache.txt" ] || [ $# -gt 0 ]; then
  cmake -S "$here" -B "$build" -DBUILD_SHARED_LIBS=ON -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
        -DNSCD_BUILD_TESTS=OFF -DNSCD_BUILD_BENCHMARKS=OFF "$@"
fi
cmake --build "$build" --target lammps -j "$jobs"

tree=$(sed -n 's/^LAMMPS_SOURCE_DIR:PATH=//p' "$build/CMakeCache.txt")
library=$(find "$build" -maxdepth 2 -name 'liblammps.so*' -type f | sort | head -1)
if [ -z "$library" ] || [ ! -d "$tree/python/lammps" ]; then
  echo "build_python.sh: no liblammps.so in $build or no python/lammps in '$tree'" >&2
  exit 1
fi
module=$build/python/lammps
rm -rf "$module"
mkdir -p "$module"
cp -r "$tree/python/lammps/." "$module/"
ln -s "$library" "$module/liblammps.so"
echo "build_python.sh: the lammps module is in $build/python:"
echo "  PYTHONPATH=$build/python /usr/bin/python3 examples/python/column.py"
