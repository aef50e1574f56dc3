#!/usr/bin/env bash
# Builds LAMMPS with the package (installing what is missing) and runs the main example.
#   tools/run_example.sh [example folder name, default: pile]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
example=${1:-pile}
"$here/tools/build.sh"
cd "$here/examples/$example"
"$build/lmp" -in in.$example
echo "run_example.sh: output is in examples/$example (see its README.md)"
