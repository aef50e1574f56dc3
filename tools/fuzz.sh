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

# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for the given time,
# one after the other (doc/robustness.md):
#   tools/fuzz.sh [SECONDS_PER_TARGET]      (default 60)
# TARGETS (default: all) picks some, e.g. TARGETS="restart_solver polyline" tools/fuzz.sh 600.
# BUILD_DIR (default build-fuzz) keeps the growing corpus between runs in
# BUILD_DIR/fuzz-corpus/<target>; crashes land in BUILD_DIR/fuzz-artifacts/<target>/.
# Keep a crash as a regression input: copy it to tests/fuzz/regressions/<target>/ (the
# CTest tests fuzz_replay_* replay that folder), then fix the code.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
build=${BUILD_DIR:-$here/build-fuzz}
all_targets="shape_text shape_serial restart_solver restart_wire restart_wall restart_plate restart_pair polyline grain_record"
targets=${TARGETS:-$all_targets}

nice -n 10 cmake -S "$here" -B "$build" -DNSCD_WITH_LAMMPS=OFF -DNSCD_BUILD_BENCHMARKS=OFF \
  -DNSCD_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
nice -n 10 cmake --build "$build" -j1 --target shape_serialize fuzz_seeds $(for t in $targets; do echo fuzz_$t; done)

# Seed corpora: the example libraries and the format page's example (text), their
# serialised forms (serial), the blocks, files and records fuzz_seeds writes (the other
# targets), and every kept regression input.
seeds=$build/fuzz-seeds
rm -rf "$seeds"
mkdir -p "$seeds/shape_text" "$seeds/shape_serial"
for file in "$here"/examples/*/*.shapes; do
  name=$(basename "$(dirname "$file")")_$(basename "$file")
  cp "$file" "$seeds/shape_text/$name"
  "$build/tests/fuzz/shape_serialize" "$file" > "$seeds/shape_serial/$name"
done
cp "$here/doc/shape_library_example.shapes" "$seeds/shape_text/format_page_example"    # the format page's example
"$build/tests/fuzz/shape_serialize" "$seeds/shape_text/format_page_example" > "$seeds/shape_serial/format_page_example"
"$build/tests/fuzz/fuzz_seeds" "$seeds"
for target in $all_targets; do
  mkdir -p "$seeds/$target"
  cp "$here"/tests/fuzz/regressions/$target/* "$seeds/$target/"
done

status=0
for target in $targets; do
  corpus=$build/fuzz-corpus/$target
  artifacts=$build/fuzz-artifacts/$target
  mkdir -p "$corpus" "$artifacts"
  dict=()
  [ "$target" = shape_text ] && dict=(-dict="$here/tests/fuzz/shape_text.dict")
  echo "== fuzz_$target for $seconds s (corpus $corpus)"
  stamp=$build/fuzz-$target.start
  touch "$stamp"
  # One process (libFuzzer's default: one job, one worker), niced: the machine is shared.
  if ! nice -n 10 "$build/tests/fuzz/fuzz_$target" "$corpus" "$seeds/$target" "${dict[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$artifacts/" 2>"$build/fuzz-$target.log"; then
    status=1
  fi
  grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units|SUMMARY|property violated|ERROR" "$build/fuzz-$target.log" || true
  # only what this run found (older finds stay until copied to tests/fuzz/regressions)
  crashes=$(find "$artifacts" -type f -newer "$stamp" | wc -l)
  echo "fuzz_$target: $crashes new crash/timeout input(s) in $artifacts (log $build/fuzz-$target.log)"
  [ "$crashes" -eq 0 ] || status=1
done
exit $status
