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

# Configures the project once more with the tests on and the benchmarks off, in a scratch
# build tree (configure and generate only): it must succeed, leave out the one test that
# runs a benchmark's executable (lammps.replay_problem) and keep the others.
#   without_benchmarks.sh SOURCE_DIR LAMMPS_TREE SCRATCH_DIR
set -euo pipefail
src=$1; tree=$2; work=$3
rm -rf "$work"
cmake -S "$src" -B "$work" -DLAMMPS_SOURCE_DIR="$tree" \
      -DNSCD_BUILD_TESTS=ON -DNSCD_BUILD_BENCHMARKS=OFF > "$work.log" 2>&1 ||
  { tail -20 "$work.log"; echo "the configure with -DNSCD_BUILD_BENCHMARKS=OFF failed"; exit 1; }
tests=$work/tests/lammps/CTestTestfile.cmake
grep -q "lammps.test_nscd" "$tests" || { echo "no LAMMPS tests registered in $tests"; exit 1; }
! grep -q "lammps.replay_problem" "$tests" ||
  { echo "lammps.replay_problem registered without the benchmarks"; exit 1; }
[ ! -d "$work/benchmarks" ] || { echo "benchmarks configured although off"; exit 1; }
rm -rf "$work" "$work.log"
echo "configures with the tests and without the benchmarks"
