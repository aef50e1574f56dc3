#!/bin/bash
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

# Growth of the sweeps per step from 20 to 40 grain layers under the 1000x plate (issue 14:
# <= 1.5x), over several random columns: each seed builds its own settled 20- and 40-layer
# columns (in.column_settle, until the plate sinks slower than 1e-3), then every method runs
# STEPS steps of in.column on each; growth.py prints per seed and method the sweeps per step
# and the ratio 40 / 20, and the ratio of the sweeps summed over all seeds.
#
#   benchmarks/hard/growth.sh     (LMP, WORK=/tmp/nscd_growth, SEEDS="4711:99 12:13 21:22 34:35",
#                                  STEPS=100, TOLERANCE=1e-4, RAMP=0, METHODS="nesterov|gs|nesterov coarse yes")
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${LMP:-../../build/lmp}")
WORK=${WORK:-/tmp/nscd_growth}
STEPS=${STEPS:-100}
TOLERANCE=${TOLERANCE:-1e-4}
RAMP=${RAMP:-0}
IFS='|' read -r -a METHODS <<< "${METHODS:-nesterov|gs|nesterov coarse yes}"
mkdir -p "$WORK"
for pair in ${SEEDS:-4711:99 12:13 21:22 34:35}; do
  seed=${pair%:*} orient=${pair#*:}
  for layers in 20 40; do
    restart="$WORK/column${layers}_s$seed.restart"
    [ -f "$restart" ] || "$LMP" -in in.column_settle -var layers $layers -var dir "$WORK" \
      -var seed $seed -var orient $orient -var tag _s$seed -log "$restart.log" > /dev/null
    for method in "${METHODS[@]}"; do
      log="$WORK/column${layers}_s$seed.${method// /_}.ramp$RAMP.log"
      command="$LMP -in in.column -var layers $layers -var tag _s$seed -var steps $STEPS -var tolerance $TOLERANCE -var max_sweeps 5000 -var solver \"method $method\" -var ramp $RAMP"
      echo "seed $seed, $layers layers, method $method"
      eval "$command -var dir $WORK -log $log" > /dev/null
      echo "# command: (cd benchmarks/hard && ${command/$LMP/../../build/lmp} -var dir WORK)" >> "$log"
    done
  done
done
/usr/bin/python3 growth.py "$WORK" "$RAMP"
