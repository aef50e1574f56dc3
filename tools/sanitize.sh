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

# Builds with AddressSanitizer + UndefinedBehaviorSanitizer in a separate build directory
# and runs the tests there; any sanitizer report fails the run (doc/robustness.md).
#
#   tools/sanitize.sh [ctest options, e.g. -R Shape]            lib/ and its unit tests
#                                                                (and the fuzz replays)
#   tools/sanitize.sh --lammps [ctest options]                  LAMMPS with the package:
#                                                                the single-rank LAMMPS tests
#
# BUILD_DIR (default build-sanitize, or build-sanitize-lammps), CXX (default g++; clang++
# works too), JOBS (build jobs, default 1: the machine is shared).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
lammps=OFF
if [ "${1:-}" = "--lammps" ]; then lammps=ON; shift; fi
if [ $lammps = ON ]; then build=${BUILD_DIR:-$here/build-sanitize-lammps}; else build=${BUILD_DIR:-$here/build-sanitize}; fi
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"

nice -n 10 cmake -S "$here" -B "$build" -DNSCD_WITH_LAMMPS=$lammps -DNSCD_BUILD_BENCHMARKS=OFF \
  -DCMAKE_CXX_COMPILER="${CXX:-g++}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
nice -n 10 cmake --build "$build" -j "${JOBS:-1}"

# Leaks are errors too; a UBSan finding stops the test with a stack trace.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
if [ $lammps = OFF ]; then
  nice -n 10 ctest --test-dir "$build" -L unit --output-on-failure "$@"
  exit
fi
# Memory errors and undefined behaviour are checked; leaks are not: LAMMPS itself leaks the
# command object when a command stops with an error (Input::execute_command creates it with
# new and the exception skips the delete; the bad-input tests do that on purpose), and Open
# MPI's plugins are unloaded before the leak check, leaving allocations without a module.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
# The LAMMPS tests on one rank (the .npN runs go through mpiexec: see doc/robustness.md).
nice -n 10 ctest --test-dir "$build" -L lammps -E '\.np[0-9]+$|^robustness' --output-on-failure "$@"
