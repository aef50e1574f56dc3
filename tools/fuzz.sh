#!/usr/bin/env bash
# Builds the libFuzzer targets of lib/shape with clang (ASan + UBSan) and runs each for
# the given time, one after the other (doc/robustness.md):
#   tools/fuzz.sh [SECONDS_PER_TARGET]      (default 60)
# BUILD_DIR (default build-fuzz) keeps the growing corpus between runs in
# BUILD_DIR/fuzz-corpus/<target>; crashes land in BUILD_DIR/fuzz-artifacts/<target>/.
# Keep a crash as a regression input: copy it to tests/fuzz/regressions/<target>/ (the
# CTest tests fuzz_replay_* replay that folder), then fix the code.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
build=${BUILD_DIR:-$here/build-fuzz}

nice -n 10 cmake -S "$here" -B "$build" -DNSCD_WITH_LAMMPS=OFF -DNSCD_BUILD_BENCHMARKS=OFF \
  -DNSCD_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
nice -n 10 cmake --build "$build" -j1 --target fuzz_shape_text fuzz_shape_serial shape_serialize

# Seed corpora: the example libraries and the format page's example (text), their
# serialised forms (serial), and every kept regression input.
text_seeds=$build/fuzz-seeds/shape_text
serial_seeds=$build/fuzz-seeds/shape_serial
rm -rf "$build/fuzz-seeds"
mkdir -p "$text_seeds" "$serial_seeds"
for file in "$here"/examples/*/*.shapes; do
  name=$(basename "$(dirname "$file")")_$(basename "$file")
  cp "$file" "$text_seeds/$name"
  "$build/tests/fuzz/shape_serialize" "$file" > "$serial_seeds/$name"
done
awk '/^## Example/{f=1} f&&/^```$/{n++; next} f&&n==1' "$here/doc/shape_library_format.md" > "$text_seeds/format_page_example"
"$build/tests/fuzz/shape_serialize" "$text_seeds/format_page_example" > "$serial_seeds/format_page_example"
cp "$here"/tests/fuzz/regressions/shape_text/* "$text_seeds/"
cp "$here"/tests/fuzz/regressions/shape_serial/* "$serial_seeds/"

status=0
for target in shape_text shape_serial; do
  corpus=$build/fuzz-corpus/$target
  artifacts=$build/fuzz-artifacts/$target
  mkdir -p "$corpus" "$artifacts"
  dict=()
  [ "$target" = shape_text ] && dict=(-dict="$here/tests/fuzz/shape_text.dict")
  echo "== fuzz_$target for $seconds s (corpus $corpus)"
  # One process (libFuzzer's default: one job, one worker), niced: the machine is shared.
  if ! nice -n 10 "$build/tests/fuzz/fuzz_$target" "$corpus" "$build/fuzz-seeds/$target" "${dict[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$artifacts/" 2>"$build/fuzz-$target.log"; then
    status=1
  fi
  grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units|SUMMARY|property violated|ERROR" "$build/fuzz-$target.log" || true
  crashes=$(find "$artifacts" -type f | wc -l)
  echo "fuzz_$target: $crashes crash/timeout input(s) in $artifacts (log $build/fuzz-$target.log)"
  [ "$crashes" -eq 0 ] || status=1
done
exit $status
