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

# Speed against error of fix nscd on the settled 384-grain pile of examples/pile.
#   benchmarks/pile/run.sh [steps per tolerance, default 200]
# Pours the pile once (examples/pile/in.pile, 4000 steps; cached as pile.restart), then
# for each tolerance runs the same steps from the same state and prints one table row.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${LMP:-$here/../../build/lmp}
steps=${1:-200}
work=${WORK:-$here/work}
mkdir -p "$work" && cd "$work"
if [ ! -f pile.restart ]; then
  cp "$here/../../examples/pile/in.pile" .
  "$lmp" -in in.pile -log pour.log -screen none -var steps 4000
  [ -f pile.restart ] || { echo "pour did not write pile.restart" >&2; exit 1; }
fi
for scene in settled loaded; do
  echo
  echo "$scene pile, $steps steps per row:"
  echo "| tolerance | sweeps/step (mean) | residual reached (mean) | converged steps | max predicted overlap | min gap | seconds/step |"
  echo "|---|---|---|---|---|---|---|"
  for tol in 1e-2 1e-3 1e-4 1e-5 1e-6; do
    "$lmp" -in "$here/in.$scene" -log "$scene.$tol.log" -screen none -var tolerance $tol -var steps $steps
    seconds=$(awk '/^Loop time of/ {print $4 / $9}' "$scene.$tol.log")
    grep "^result" "$scene.$tol.log" | awk -v s="$seconds" '{printf "| %s | %s | %s | %s | %s | %s | %.4f |\n", $3, $5, $7, $13, $9, $11, s}'
  done
done
