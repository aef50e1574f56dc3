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

# Scaling of fix nscd (issue 14, item 6): a settled periodic bed of 1008 random grains
# (in.bed_settle, built once per WORK), replicated to ~10^4 and ~10^5 grains (in.bed_run), run
# on 1, 2, 4 and 8 MPI ranks. Prints one line per run (also to WORK/summary.txt): grains, ranks,
# ms per step (Loop time of the measured run / steps), mean sweeps, residual, overlap,
# floor error, and the peak resident memory of each rank (/usr/bin/time %M, kB); then LAMMPS'
# "Per MPI rank memory" line and fix nscd's count of its communication between ranks over the
# measured run (messages and bytes per sweep exchange and per step, warm-start hand-over).
#
#   benchmarks/scaling/run.sh [case ...]   (LMP=build/lmp, WORK=/tmp/scaling, STEPS=30, WARM=10)
# Cases (default: the first seven): 1e3, 1e4, 1e5 (1 rank), 1e3x2, 1e4x2 (2 ranks), 1e3x4,
# 1e4x4 (4 ranks), 1e4x8 (8 ranks; the 10^4 bed is a 10 x 1 strip, split in x only), sq, sqx4,
# sqx8 (a 3 x 3 square of 9072 grains on 1, 4 = 2 x 2 and 8 = 4 x 2 ranks); 4 and 8 ranks are
# oversubscribed on a 2-core machine: their sweeps and messages count, their times do not.
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${LMP:-../../build/lmp}")
WORK=${WORK:-/tmp/scaling}
STEPS=${STEPS:-30}
WARM=${WARM:-10}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$WORK"
[ -f "$WORK/bed.restart" ] || "$LMP" -in in.bed_settle -var dir "$WORK" -log "$WORK/bed_settle.log" > /dev/null

run() {    # name ranks rx ry [lmp vars]
  local name=$1 np=$2 rx=$3 ry=$4; shift 4
  local log=$WORK/$name.log
  rm -f "$WORK/$name".rss.*
  # each rank under /usr/bin/time, writing its peak resident memory to name.rss.<rank>
  mpiexec --oversubscribe -np "$np" bash -c 'exec /usr/bin/time -f "rss_kb %M" -o "$0.rss.$OMPI_COMM_WORLD_RANK" "$@"' \
    "$WORK/$name" "$LMP" -in in.bed_run -var dir "$WORK" -var rx "$rx" -var ry "$ry" -var steps "$STEPS" -var warm "$WARM" "$@" -log "$log" > /dev/null
  local loop ms rss
  loop=$(grep "^Loop time" "$log" | tail -1 | awk '{print $4}')
  ms=$(awk -v t="$loop" -v n="$STEPS" 'BEGIN {printf "%.1f", 1000 * t / n}')
  rss=$(cat "$WORK/$name".rss.* | awk '{printf "%s%d", (NR > 1 ? " " : ""), $2}')
  # the measured run's breakdown: contact detection (Pair) and fix nscd (Modify), ms per step
  local pair modify
  pair=$(grep "^Pair  " "$log" | tail -1 | awk -v n="$STEPS" '{printf "%.1f", 1000 * $5 / n}')
  modify=$(grep "^Modify" "$log" | tail -1 | awk -v n="$STEPS" '{printf "%.1f", 1000 * $5 / n}')
  local first; first=$(grep -A2 "^ *Step" "$log" | awk "NR == 3 {print \$2}")
  echo "$name: ms/step $ms (pair $pair, fix $modify); rss_kb per rank $rss; first step sweeps $first; $(grep '^scaling:' "$log" | sed 's/^scaling: //')" | tee -a "$WORK/summary.txt"
  # the measured run's memory line and fix nscd's counts (the last of each in the log)
  { grep "^Per MPI rank memory" "$log" | tail -1
    grep "^fix nscd solve: per \|^fix nscd solve: warm start over" "$log" | tail -3; } | sed 's/^/  /' | tee -a "$WORK/summary.txt"
  echo "  command: (cd benchmarks/scaling && mpiexec -np $np ../../build/lmp -in in.bed_run -var dir WORK -var rx $rx -var ry $ry -var steps $STEPS -var warm $WARM $*)" | tee -a "$WORK/summary.txt"
}

for c in ${@:-1e3 1e4 1e5 1e3x2 1e4x2 1e3x4 1e4x4}; do
  case $c in
  1e3) run 1e3_np1 1 1 1 ;;
  1e4) run 1e4_np1 1 10 1 ;;
  1e5) run 1e5_np1 1 10 10 ;;
  1e3x2) run 1e3_np2 2 1 1 ;;
  1e4x2) run 1e4_np2 2 10 1 ;;
  1e3x4) run 1e3_np4 4 1 1 ;;
  1e4x4) run 1e4_np4 4 10 1 ;;
  1e4x8) run 1e4_np8 8 10 1 ;;
  sq) run sq_np1 1 3 3 ;;          # a square bed of 9072 grains, split in x and y
  sqx4) run sq_np4 4 3 3 ;;
  sqx8) run sq_np8 8 3 3 ;;
  *) echo "unknown case $c"; exit 2 ;;
  esac
done
# per-step and per-sweep cost of every run in WORK (fit.py)
logs=$(ls "$WORK"/1e*_np*.log "$WORK"/sq_np*.log 2> /dev/null)
/usr/bin/python3 fit.py $logs | tee -a "$WORK/summary.txt"
