#!/usr/bin/env bash
# Builds lib/ and its unit tests with AddressSanitizer + UndefinedBehaviorSanitizer in a
# separate build directory and runs the unit tests (and the fuzz-regression replays);
# any sanitizer report fails the run (doc/robustness.md):
#   tools/sanitize.sh [ctest options, e.g. -R Shape]
# BUILD_DIR (default build-sanitize), CXX (default g++; clang++ works too), JOBS (build
# jobs, default 1: the machine is shared).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build-sanitize}
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"

nice -n 10 cmake -S "$here" -B "$build" -DNSCD_WITH_LAMMPS=OFF -DNSCD_BUILD_BENCHMARKS=OFF \
  -DCMAKE_CXX_COMPILER="${CXX:-g++}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
nice -n 10 cmake --build "$build" -j "${JOBS:-1}"

# Leaks are errors too; a UBSan finding stops the test with a stack trace.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
nice -n 10 ctest --test-dir "$build" -L unit --output-on-failure "$@"
