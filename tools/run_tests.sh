#!/usr/bin/env bash
# Builds everything (installing what is missing) and runs the whole test suite with CTest.
#   tools/run_tests.sh [ctest options, e.g. -R shape]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
"$here/tools/build.sh"
ctest --test-dir "$build" --output-on-failure -j "${JOBS:-$(nproc 2>/dev/null || echo 2)}" "$@"
