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

# LAMMPS' `lammps` Python module with this package, for Python driving LAMMPS in-process
# (examples/python/). The default build makes it (cmake/LammpsWithPackage.cmake: LAMMPS as
# liblammps.so, its python/lammps package beside it in <build>/python), so this is
# tools/build.sh, switching a tree configured with -DNSCD_LAMMPS_SHARED=OFF back on:
#
#   tools/build_python.sh [-D options for CMake]
#   PYTHONPATH=build/python /usr/bin/python3 -c 'import lammps; lammps.lammps()'
#
# Environment: as tools/build.sh (BUILD_DIR, default <repo>/build; JOBS).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
args=("$@")
if grep -q "^NSCD_LAMMPS_SHARED:BOOL=OFF" "$build/CMakeCache.txt" 2>/dev/null; then
  args+=(-DNSCD_LAMMPS_SHARED=ON)
fi
"$here/tools/build.sh" "${args[@]}"
if [ ! -f "$build/python/lammps/__init__.py" ] || [ ! -e "$build/python/lammps/liblammps.so" ]; then
  echo "build_python.sh: no lammps module with liblammps.so in $build/python" >&2
  exit 1
fi
echo "build_python.sh: the lammps module is in $build/python:"
echo "  PYTHONPATH=$build/python:$here/tools /usr/bin/python3 examples/python/column.py"
