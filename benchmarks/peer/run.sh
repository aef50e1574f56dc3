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

# The in-LAMMPS peer side by side (issue 14, item 5): the same random grains, the same pile,
# run by fix nscd and by LAMMPS' BODY package (pair body/rounded/polyhedron) in the same lmp.
#
#   benchmarks/peer/run.sh [stage ...]     (LMP=build/lmp, TOBODY=build/tools/body/nscd_to_body,
#                                           WORK=/tmp/peer; stages default: setup pour bodypour)
# Stages:
#   setup    in.setup: 216 grains on a lattice -> peer.shapes, peer.data; peer.body for BODY
#   pour     fix nscd pours them for POUR_TIME (3) time units, frictionless, at dt 0.005:
#            default, and with overlap_speed 0.2
#   bodypour BODY pours them at BODY_DT (1e-3) for POUR_TIME time units
#   scan     BODY pours them at DTS (default "4e-3 2e-3") for POUR_TIME: its largest usable dt
#   stiff    the pour to STIFF_TIME (1.5): fix nscd (default, overlap_speed 0.2), BODY with
#            k_n = 1e4 at dt 1e-3 and k_n = 1e5 (c_n 158, c_t 39.5: the same damping ratios) at dt 5e-4
#   settle   fix nscd, overlap_speed 0.2, 2 x 6 time units -> settled.data (a settled pile), settled.body
#   settled  the settled pile for TIME (1) time unit: fix nscd at dt 0.005, BODY at BODY_DT
#            (BODY crashes on it: doc/BENCHMARKS.md)
# Every BODY end state is turned into our data file (body_to_nscd.py, which checks the
# vertices against BODY's) and measured by in.overlap with our contact geometry (overlaps.py
# splits grain-grain from grain-wall). Each run's log is WORK/<name>.log; the summary lines
# are collected in WORK/summary.txt.
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${LMP:-../../build/lmp}")
TOBODY=$(realpath "${TOBODY:-../../build/tools/body/nscd_to_body}")
WORK=${WORK:-/tmp/peer}
PY=/usr/bin/python3
mkdir -p "$WORK"
summary() { echo "$*" | tee -a "$WORK/summary.txt"; }

loop_time() { grep "^Loop time" "$1" | tail -1 | awk '{print $4}'; }

nscd_run() {    # name [lmp vars]: fix nscd, then the overlap of its end state
  local name=$1; shift
  "$LMP" -in in.nscd -var dir "$WORK" -var out "$WORK/$name.data" "$@" -log "$WORK/$name.log" > /dev/null
  measure "$name" "$(grep '^peer nscd' "$WORK/$name.log")"
}

body_run() {    # name data.body [lmp vars]: BODY, then our data file of its end and the overlap
  local name=$1 body=$2; shift 2
  local nmax; nmax=$(head -1 "$body" | awk '{print $9}' | tr -d ,)
  "$LMP" -in in.body -var dir "$WORK" -var data "$body" -var name "$name" -var nmax "$nmax" "$@" \
    -log "$WORK/$name.log" > /dev/null || { summary "$name: BODY run failed (see $WORK/$name.log)"; return; }
  local initial=$WORK/peer.data
  [ "$body" = "$WORK/settled.body" ] && initial=$WORK/settled.data
  $PY body_to_nscd.py "$initial" "$WORK/$name.dump" "$WORK/$name.data" "$WORK/peer.shapes" "$WORK/$name.vertices" \
    > "$WORK/$name.convert"
  measure "$name" "$(grep '^peer body' "$WORK/$name.log"); $(tail -1 "$WORK/$name.convert")"
}

measure() {    # name text: in.overlap on WORK/name.data
  local name=$1 text=$2
  "$LMP" -in in.overlap -var dir "$WORK" -var data "$WORK/$name.data" -log "$WORK/$name.overlap.log" > /dev/null
  summary "$name: loop time $(loop_time "$WORK/$name.log") s; $text"
  summary "  $($PY overlaps.py "$WORK/$name.data.contacts" | cut -d: -f2-)"
}

for stage in ${@:-setup pour bodypour}; do
  case $stage in
  setup)
    "$LMP" -in in.setup -var dir "$WORK" -log "$WORK/setup.log" > /dev/null
    "$TOBODY" "$WORK/peer.shapes" "$WORK/peer.data" "$WORK/peer.body" ;;
  pour)
    nscd_run nscd_pour -var time "${POUR_TIME:-3}"
    nscd_run nscd_pour_push -var time "${POUR_TIME:-3}" -var solver "overlap_speed 0.2" ;;
  bodypour)
    body_run body_pour "$WORK/peer.body" -var dt "${BODY_DT:-1e-3}" -var time "${POUR_TIME:-3}" ${BODY_VARS:-} ;;
  scan)
    for dt in ${DTS:-4e-3 2e-3}; do
      body_run "body_scan_dt$dt" "$WORK/peer.body" -var dt "$dt" -var time "${POUR_TIME:-3}" -var thermo_every 0.05 ${BODY_VARS:-}
    done ;;
  stiff)
    t=${STIFF_TIME:-1.5}
    nscd_run "nscd_pour_t$t" -var time "$t"
    nscd_run "nscd_pour_push_t$t" -var time "$t" -var solver "overlap_speed 0.2"
    body_run "body_pour_k1e4_t$t" "$WORK/peer.body" -var dt 1e-3 -var time "$t"
    body_run "body_pour_k1e5_t$t" "$WORK/peer.body" -var dt 5e-4 -var time "$t" -var kn 1e5 -var cn 158 -var ct 39.5 ;;
  settle)
    nscd_run nscd_settle1 -var time 6 -var solver "overlap_speed 0.2"
    nscd_run nscd_settle2 -var time 6 -var solver "overlap_speed 0.2" -var data "$WORK/nscd_settle1.data"
    cp "$WORK/nscd_settle2.data" "$WORK/settled.data"
    "$TOBODY" "$WORK/peer.shapes" "$WORK/settled.data" "$WORK/settled.body" ;;
  settled)
    nscd_run nscd_settled -var data "$WORK/settled.data" -var time "${TIME:-1}"
    body_run body_settled "$WORK/settled.body" -var dt "${BODY_DT:-1e-3}" -var time "${TIME:-1}" ${BODY_VARS:-} ;;
  *) echo "unknown stage $stage"; exit 2 ;;
  esac
done
