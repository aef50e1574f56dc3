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

# Runs example decks on 1 and 4 MPI ranks and keeps LAMMPS' log of each run beside the deck,
# named as LAMMPS' own examples name theirs: examples/NAME/log.DDMonYY.NAME.g++.N. The runs
# happen in a scratch copy of the folder (build/example_logs/NAME.N), so no other output
# lands in examples/.
#
#   tools/example_logs.sh [NAME ...]      (default: every example with a deck)
#
# The long scenes run at the small size of their README: column (tools/run_example.sh's
# settings, the wired column only), silo (its README's small size), string (3 layers), pile
# (its 4000 steps). Environment: BUILD_DIR (default <repo>/build), RANKS (default "1 4").
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
ranks=${RANKS:-1 4}
stamp=$(date +%d%b%y)
[ -x "$build/lmp" ] || { echo "example_logs.sh: no $build/lmp (run tools/build.sh)" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_mpi_yield_when_idle=1

source "$here/tools/small_column.sh"    # tools/run_example.sh's small column: small_column
deck_vars() {   # the -vars an example runs with here
  case "$1" in
    column) printf '%s\n' "${small_column[@]}" ;;
    silo)   printf '%s\n' -var layers 5 -var R 2.5 -var cells 2 -var layer_steps 500 -var relax_chunk 250 \
                          -var load_rate 20 -var load_max 20 ;;
    string) printf '%s\n' -var layers 3 -var R 2.5 -var dump_every 1000000 -var load_rate 20 -var load_max 20 ;;
  esac
}

# silo and string include ../column/in.column: a copy sits there beside the scratch folders
mkdir -p "$build/example_logs/column"
cp "$here/examples/column/in.column" "$build/example_logs/column/"

names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for d in "$here"/examples/*/; do d=$(basename "$d"); [ -f "$here/examples/$d/in.$d" ] && names+=("$d"); done
fi
for name in "${names[@]}"; do
  src=$here/examples/$name
  [ -f "$src/in.$name" ] || { echo "example_logs.sh: no examples/$name/in.$name" >&2; exit 2; }
  mapfile -t vars < <(deck_vars "$name")
  for n in $ranks; do
    work=$build/example_logs/$name.$n
    rm -rf "$work"; mkdir -p "$work"; cp "$src"/in.* "$work"/; cp "$src"/*.shapes "$work"/ 2>/dev/null || true
    log=log.$stamp.$name.g++.$n
    start=$SECONDS
    (cd "$work" && if [ "$n" -eq 1 ]; then "$build/lmp" -in "in.$name" -log "$log" "${vars[@]}"
                   else mpiexec -np "$n" "$build/lmp" -in "in.$name" -log "$log" "${vars[@]}"; fi > screen.txt) ||
      { echo "example_logs.sh: $name on $n rank(s) failed; see $work/screen.txt" >&2; exit 1; }
    rm -f "$src"/log.*."$name".g++."$n"
    cp "$work/$log" "$src/$log"
    echo "examples/$name/$log ($(( SECONDS - start )) s)"
  done
done
