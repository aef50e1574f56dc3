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

# One expensive step of a column under the 1000x plate, solved alone with each method and
# setting: seed 34's 20-layer column of growth.sh (at rest, ramp 0) lets go of its plate
# around step 1613, where every method needs thousands of sweeps (doc/BENCHMARKS.md, growth
# section). Runs the column from growth.sh's restart to the step before (default method,
# tolerance 1e-4, as growth.sh), saves that state, then solves the next step from it with
# each setting and prints sweeps, residual reached and the plate force, and the same step
# solved to 1e-7 (the reference: what the step's forces are).
#
#   benchmarks/hard/bad_step.sh     (LMP, WORK=/tmp/nscd_growth with column20_s34.restart
#                                    from growth.sh, STEP=1613, MAX_SWEEPS=20000)
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${LMP:-../../build/lmp}")
WORK=${WORK:-/tmp/nscd_growth}
STEP=${STEP:-1613}
MAX_SWEEPS=${MAX_SWEEPS:-20000}
column="-var layers 20 -var tag _s34 -var dir $WORK"
[ -f "$WORK/column20_s34.restart" ] || SEEDS="34:35" METHODS=nesterov WORK="$WORK" ./growth.sh > /dev/null
start=$("$LMP" -in in.column $column -var steps 0 -log none | awk '/^ +Step/{getline; print $1; exit}')
before="$WORK/bad_step.$((STEP - 1)).restart"
printf 'include in.column\nwrite_restart %s\n' "$before" > "$WORK/bad_step.before.in"
"$LMP" -in "$WORK/bad_step.before.in" $column -var steps $((STEP - 1 - start)) -var tolerance 1e-4 \
  -var max_sweeps 5000 -var solver "method nesterov" -log "$WORK/bad_step.before.log" > /dev/null
printf "step %d of seed 34's 20-layer column, solved alone from the state after step %d\n\n" "$STEP" $((STEP - 1))
echo "| setting | tolerance | sweeps | residual reached | plate force | plate velocity |"
echo "|---|---|---|---|---|---|"
solve() {    # label tolerance solver [vars...]
  local label=$1 tolerance=$2 solver=$3
  shift 3
  "$LMP" -in in.column $column -var from "$before" -var steps 1 -var tolerance $tolerance \
    -var max_sweeps $MAX_SWEEPS -var solver "$solver" "$@" -log "$WORK/bad_step.log" > /dev/null
  awk -v label="$label" -v tol=$tolerance '/^Loop time/{on=0} /^ +Step/{on=1; next} on && !/^WARNING/ {row=$0}
    END {split(row, f); printf "| %s | %s | %d | %.2e | %.1f | %.4f |\n", label, tol, f[2], f[3], f[8], f[9]}' \
    "$WORK/bad_step.log"
}
solve "\`method nesterov\` (default)" 1e-4 "method nesterov"
solve "\`method gs\`" 1e-4 "method gs"
solve "\`method nncg\`" 1e-4 "method nncg"
solve "\`method nesterov coarse yes\`" 1e-4 "method nesterov coarse yes"
solve "\`method nesterov theta 0.5\`" 1e-4 "method nesterov theta 0.5"
solve "\`method nesterov\`, reference" 1e-7 "method nesterov"
echo
awk '/^ +Step/{getline; print "plate weight " $10 "; grains and plate " $6; exit}' "$WORK/bad_step.log"
