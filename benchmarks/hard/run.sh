#!/bin/bash
# Hard-case benchmark of fix nscd's solver methods: every scene (in.tower20, in.pyramid10,
# in.column with 20 and 40 layers under a plate of mass ratio 1000, in.pile with mu = 1) with
# plain Gauss-Seidel and the accelerated methods at several tolerances; report.py turns the
# logs into the table of doc/BENCHMARKS.md and doc/img/hard_speed_error.png.
#
#   benchmarks/hard/run.sh            (LMP=path/to/lmp, WORK=scratch dir, STEPS=30, TOLERANCES="1e-3 1e-4", MAX_SWEEPS=5000)
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

run() {    # name deck tolerance method [vars...]
  local name=$1 deck=$2 tolerance=$3 method=$4
  shift 4
  local log="$WORK/$name.${method// /_}.$tolerance.log"
  local command="$LMP -in $deck -var steps $STEPS -var tolerance $tolerance -var max_sweeps $MAX_SWEEPS -var solver \"$method\" $*"
  echo "$name | $method | $tolerance"
  ( cd "$PWD" && eval "$command -var dir $WORK -log $log" > /dev/null )
  echo "# command: (cd benchmarks/hard && ${command/$LMP/../../build/lmp} -var dir WORK)" >> "$log"
}
for tolerance in ${TOLERANCES:-1e-3 1e-4}; do
  for method in "method gs" "method nesterov" "method nesterov coarse yes"; do
    run tower20 in.tower20 $tolerance "$method"
    run pyramid10 in.pyramid10 $tolerance "$method"
    run column20 in.column $tolerance "$method" -var layers 20
    run column40 in.column $tolerance "$method" -var layers 40
    run pile in.pile $tolerance "$method"
  done
done
/usr/bin/python3 report.py "$WORK" ../../doc/BENCHMARKS.md ../../doc/img/hard_speed_error.png
