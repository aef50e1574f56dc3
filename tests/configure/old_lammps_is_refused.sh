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

# Configures the project against a LAMMPS tree that says it is 29 Sep 2021 (a copy of the
# default tree's cmake/ and src/version.h, nothing else) and checks that the configure step
# stops with the message naming the minimum release, before any LAMMPS source is read.
#   old_lammps_is_refused.sh SOURCE_DIR LAMMPS_TREE SCRATCH_DIR
set -euo pipefail
src=$1; tree=$2; work=$3
rm -rf "$work"
mkdir -p "$work/old/src"
cp -r "$tree/cmake" "$work/old/"
sed 's/^#define LAMMPS_VERSION .*/#define LAMMPS_VERSION "29 Sep 2021"/' "$tree/src/version.h" > "$work/old/src/version.h"
if cmake -S "$src" -B "$work/build" -DLAMMPS_SOURCE_DIR="$work/old" > "$work/log" 2>&1; then
  echo "a 29 Sep 2021 tree was accepted"; exit 1
fi
flat=$(tr -s ' \n' '  ' < "$work/log")    # CMake wraps its messages
grep -q "LAMMPS 29 Sep 2021" <<<"$flat" && grep -q "needs LAMMPS 2 Aug 2023 or newer" <<<"$flat" ||
  { echo "the refusal does not name the releases:"; tail -20 "$work/log"; exit 1; }
rm -rf "$work"
echo "LAMMPS 29 Sep 2021 is refused, naming 2 Aug 2023"
