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

# Builds LAMMPS with the package (installing what is missing) and runs an example.
#   tools/run_example.sh                    the papers' column, small (see below): ~6 min CPU
#   tools/run_example.sh column [ARGS...]   the same; ARGS (e.g. -var layers 25) replace the small size
#   tools/run_example.sh NAME [ARGS...]     examples/NAME/in.NAME, ARGS passed to lmp
# The small column: 5 layers of random grains (lattice sites inside the loop), each with a
# double wire loop of radius 2.5,
# through all phases of examples/column/in.column (deposit, relax, wall removal, relax,
# plate loading to failure), then the same without wire (the control). Outputs go to
# examples/column/run/ (column.* with the wire, nowire.* without); the phase tables are
# printed at the end.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
example=${1:-column}
[ $# -gt 0 ] && shift
[ -f "$here/examples/$example/in.$example" ] || {
  echo "run_example.sh: no examples/$example/in.$example (examples: $(ls "$here/examples" | tr '\n' ' '))" >&2
  exit 2
}
"$here/tools/build.sh"

if [ "$example" != column ]; then
  cd "$here/examples/$example"
  "$build/lmp" -in "in.$example" "$@"
  echo "run_example.sh: output is in examples/$example (see its README.md)"
  exit 0
fi

source "$here/tools/small_column.sh"    # the small column's -vars: small_column
small=("${small_column[@]}")
[ $# -gt 0 ] && small=("$@")
out="$here/examples/column/run"
mkdir -p "$out"
cd "$out"
start=$SECONDS
"$build/lmp" -in ../in.column -log log.column "${small[@]}" > screen.column.txt
"$build/lmp" -in ../in.column -log log.nowire -var name nowire -var wire no "${small[@]}" > screen.nowire.txt
for name in column nowire; do
  echo "== $name ($( [ $name = column ] && echo 'with wire' || echo 'no wire, the control'))"
  /usr/bin/python3 ../summary.py "log.$name"
done
echo "run_example.sh: $(( SECONDS - start )) s; output is in $out"
echo "  log.column, log.nowire: thermo (phase, height, retained fraction, wire energies, plate force, sweeps)"
echo "  column.grains.*.vtk: grain surfaces for ParaView; column.{fabric,pairs,wire,nodes}.*.dump: for"
echo "  tools/nscd-analysis and tools/column_figures.sh (see examples/column/README.md)"
