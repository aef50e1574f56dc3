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

# Hard-case benchmark of fix nscd's solver, speed against error: every scene (in.tower20,
# in.pyramid10, in.column with 20 and 40 layers under a plate of mass ratio 1000, in.pile with
# mu = 1) with plain Gauss-Seidel and the accelerated methods at several tolerances, then the
# default method with one setting changed at a time (theta, max_sweeps, dt, a tighter
# tolerance); report.py turns the logs into the table of doc/BENCHMARKS.md and the Pareto
# plots doc/img/hard_speed_error.png.
#
#   benchmarks/hard/run.sh            (LMP=path/to/lmp, WORK=scratch dir, STEPS=30, TOLERANCES="1e-3 1e-4",
#                                      MAX_SWEEPS=5000, VARIANTS=yes)
#
# The settled column and pile are built once per WORK directory (in.*_settle).
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${LMP:-../../build/lmp}")
WORK=${WORK:-/tmp/nscd_hard}
STEPS=${STEPS:-30}
MAX_SWEEPS=${MAX_SWEEPS:-5000}
mkdir -p "$WORK"

settle() {    # deck restart [vars...]
  local deck=$1 restart=$2
  shift 2
  [ -f "$WORK/$restart" ] && return
  echo "building $restart ($deck)"
  "$LMP" -in "$deck" -var dir "$WORK" "$@" -log "$WORK/$restart.log" > /dev/null
}
settle in.column_settle column20.restart -var layers 20
settle in.column_settle column40.restart -var layers 40
settle in.pile_settle pile.restart

run() {    # name deck tolerance solver [vars...]: solver = fix nscd keywords
  local name=$1 deck=$2 tolerance=$3 method=$4
  shift 4
  local tag="${method// /_}" steps=$STEPS
  local args=("$@") k
  for ((k = 0; k + 2 < ${#args[@]}; k++)); do    # -var dt X: the same simulated time at dt X
    if [ "${args[k]} ${args[k+1]}" = "-var dt" ]; then
      tag="$tag+dt${args[k+2]}"
      steps=$(/usr/bin/python3 -c "print(round($STEPS * 0.005 / ${args[k+2]}))")
    fi
  done
  local log="$WORK/$name.$tag.$tolerance.log"
  local command="$LMP -in $deck -var steps $steps -var tolerance $tolerance -var max_sweeps $MAX_SWEEPS -var solver \"$method\" $*"
  echo "$name | $method $* | $tolerance"
  ( cd "$PWD" && eval "$command -var dir $WORK -log $log" > /dev/null )
  echo "# command: (cd benchmarks/hard && ${command/$LMP/../../build/lmp} -var dir WORK)" >> "$log"
}
scenes() {    # tolerance solver [vars...]: every scene
  run tower20 in.tower20 "$@"
  run pyramid10 in.pyramid10 "$@"
  run column20 in.column "$1" "$2" -var layers 20 "${@:3}"
  run column40 in.column "$1" "$2" -var layers 40 "${@:3}"
  run pile in.pile "$@"
}
for tolerance in ${TOLERANCES:-1e-3 1e-4}; do
  for method in "method gs" "method nesterov" "method nesterov coarse yes"; do
    scenes $tolerance "$method"
  done
done
if [ "${VARIANTS:-yes}" = yes ]; then    # the default method, one setting changed at a time
  scenes 1e-4 "method nesterov theta 0.5"
  scenes 1e-4 "method nesterov max_sweeps 100"
  scenes 1e-4 "method nesterov" -var dt 0.0025
  scenes 1e-5 "method nesterov"
fi
/usr/bin/python3 report.py "$WORK" ../../doc/BENCHMARKS.md ../../doc/img/hard_speed_error.png
