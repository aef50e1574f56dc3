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

# Validation (issue 26): the papers' headline at the smallest size that shows it. A column of
# 3 thick layers (R 2, 3 lattice cells per layer, ~116 grains, the box window) through the
# deposit, the wall removal and a short relaxation (examples/column/in.column -var last 4),
# with closed rings (-var loop ring -var k_rot 1 -var mu_pw 1: the setting that stands at the
# papers' size, doc/validation.md) and without wire, for SEEDS; check_rings.py then asserts
# the contrast the seeds show (thresholds and the measurements behind them in that script).
#   column_rings.sh LMP COLUMN_DECK SCRATCH_DIR [SEEDS...]   (default seeds: 1 2)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=$1; deck=$2; work=$3
shift 3
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2)
rm -rf "$work"; mkdir -p "$work"; cp "$deck" "$work/in.column"
cd "$work"
scene=(-var layers 3 -var R 2 -var window box -var cells 3 -var element 0.3
       -var layer_steps 400 -var wire_steps 100 -var relax_chunk 250 -var relax_max 2
       -var wall_speed 0.3 -var wall_travel 0.6 -var last 4
       -var dump_every 1000000 -var thermo_every 100)
logs=()
for s in "${seeds[@]}"; do
  "$lmp" -in in.column -log "log.ring$s" -var name "ring$s" -var seed "$s" \
         -var loop ring -var k_rot 1 -var mu_pw 1 "${scene[@]}" > /dev/null
  "$lmp" -in in.column -log "log.bare$s" -var name "bare$s" -var seed "$s" -var wire no "${scene[@]}" > /dev/null
  logs+=("log.ring$s" "log.bare$s")
done
/usr/bin/python3 "$here/check_rings.py" "${logs[@]}"
