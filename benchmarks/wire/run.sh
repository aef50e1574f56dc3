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

# Speed of fix wire on a column of 340 grains with 2360 wire nodes in 4 double loops
# (in.settle, in.column), resting and sliding, on 1 and 2 MPI ranks: fix wire's own timing
# (ns per node per substep, its split, bytes sent per substep) next to the error measures
# of the run (kinetic energy, the floor's load against the weight).
#
#   benchmarks/wire/run.sh [steps per phase, default 100]
#
# Environment: LMP (default build/lmp), MPIRUN (default mpirun), WORK (default
# benchmarks/wire/work), SETTLE (settling steps, default 13000; the settled column is
# cached as $WORK/column_settled.data), SKIN (fix wire's contact skin, default 0.05),
# LMP_BEFORE (optional: a build of another commit to time on the same column; its fix
# wire time is estimated as its Modify time minus this build's Modify time plus this
# build's fix wire time, fix nscd and the rest being the same work).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
absolute() {    # a path given relative to the caller's folder (the runs cd to WORK); a bare name stays
  case $1 in */*) echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" ;; *) echo "$1" ;; esac
}
lmp=$(absolute "${LMP:-$here/../../build/lmp}")
mpirun=${MPIRUN:-mpirun}
steps=${1:-100}
work=${WORK:-$here/work}
skin=${SKIN:-0.05}
mkdir -p "$work" && cd "$work"
if [ ! -f column_settled.data ]; then
  /usr/bin/python3 "$here/make_column.py" > column.data
  "$lmp" -in "$here/in.settle" -var dir "$here/" -var steps "${SETTLE:-13000}" -var wire_skin "skin $skin" \
    -log settle.log -screen none
fi

run() {    # label, log name, fix wire's skin option, launcher words...
  local label=$1 log=$2 skin_option=$3
  shift 3
  "$@" -in "$here/in.column" -var dir "$here/" -var rest "$steps" -var slide "$steps" -var wire_skin "$skin_option" \
    -log "$log" -screen none
  echo "== $label"
  awk '/benchmark phase:/ {phase = $3}
       /^fix wire w: time per part/ {rows = 9}
       rows > 0 {print phase ": " $0; rows--; next}
       /^fix wire w:/ {print phase ": " $0}
       /^Loop time/ {loop = $4} /^Modify/ {print phase ": Modify " $5 " s (average over ranks) of loop " loop " s"}' "$log"
  awk '/^ +Step/ {getline; first = $0} /^Loop time/ {print "   thermo at the end of the phase: " last} /^ +[0-9]+ / {last = $0}' "$log"
}

run "1 rank" one_rank.log "skin $skin" "$lmp"
run "2 ranks" two_ranks.log "skin $skin" $mpirun -np 2 "$lmp"
if [ -n "${LMP_BEFORE:-}" ]; then    # (a fix wire without the skin option)
  run "1 rank, LMP_BEFORE" before.log "" "$(absolute "$LMP_BEFORE")"
fi
echo
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
