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

# Builds the package into another LAMMPS release and runs the tests there, in its own build
# tree (build-lammps-<name>/), next to the default build.
#
#   tools/test_lammps_release.sh 4Jul2026            # fetched by tools/fetch_lammps.sh (Debian sid)
#   tools/test_lammps_release.sh /path/to/lammps     # any LAMMPS tree, 2 Aug 2023 or newer
#   tools/test_lammps_release.sh 4Jul2026 -L unit    # extra arguments go to ctest
#
# Exit status: that of ctest; 3 if the release cannot be had (sid's archive moves).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
what=${1:?usage: test_lammps_release.sh RELEASE|LAMMPS_TREE [ctest options]}
shift
if [ -d "$what" ]; then
  tree=$(cd "$what" && pwd)
else
  tree=$(bash "$here/tools/fetch_lammps.sh" "${NSCD_CACHE:-$HOME/.cache/nscd-lammps}" "$what") || {
    echo "test_lammps_release.sh: LAMMPS $what cannot be had here; nothing tested" >&2; exit 3; }
fi
name=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$tree/src/version.h" | tr -d ' ')
build=${BUILD_DIR:-$here/build-lammps-$name}
echo "test_lammps_release.sh: LAMMPS $name from $tree, build tree $build"
BUILD_DIR=$build "$here/tools/build.sh" -DLAMMPS_SOURCE_DIR="$tree"
ctest --test-dir "$build" --output-on-failure -j "${JOBS:-$(nproc 2>/dev/null || echo 2)}" "$@"
