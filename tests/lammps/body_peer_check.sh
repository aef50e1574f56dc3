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

# benchmarks/peer's chain on spinning grains: our 216 grains (in.setup) given an angular
# velocity, written for LAMMPS' BODY package by nscd_to_body, read and moved by BODY for 100
# steps of free fall, and turned back by body_to_nscd.py, which must put every vertex of our
# shapes where BODY has it (to 1e-9; the grains turn by 0.37 rad). Catches a converter whose
# file BODY refuses or misreads, and a wrong orientation mapping.
#
#   body_peer_check.sh LMP NSCD_TO_BODY SOURCE_DIR WORK
set -euo pipefail
lmp=$1 tobody=$2 src=$3 work=$4
peer=$src/benchmarks/peer
mkdir -p "$work"
cd "$peer"
"$lmp" -in in.setup -var dir "$work" -log "$work/setup.log" > /dev/null
cat > "$work/in.spin" <<'DECK'
units           lj
atom_style      spheropolyhedron
atom_modify     map array
boundary        f f f
shapes          read ${dir}/peer.shapes
read_data       ${dir}/peer.data
set             group all omega 1.0 2.0 3.0
write_data      ${dir}/spin.data
DECK
"$lmp" -in "$work/in.spin" -var dir "$work" -log "$work/spin.log" > /dev/null
"$tobody" "$work/peer.shapes" "$work/spin.data" "$work/spin.body"
nmax=$(head -1 "$work/spin.body" | awk '{print $9}' | tr -d ,)
"$lmp" -in in.body -var dir "$work" -var data "$work/spin.body" -var name spin -var nmax "$nmax" \
  -var dt 1e-3 -var time 0.1 -log "$work/body.log" > /dev/null
out=$(/usr/bin/python3 body_to_nscd.py "$work/spin.data" "$work/spin.dump" "$work/spin_end.data" \
  "$work/peer.shapes" "$work/spin.vertices")
echo "$out"
distance=$(sed -n 's/.*vertices: //p' <<<"$out")
/usr/bin/python3 -c "import sys; d = float('$distance'); sys.exit(0 if d < 1e-9 else 'vertices differ by %g' % d)"
# BODY turned them: the orientation at the end differs from the start
moved=$(awk '/ITEM: TIMESTEP/ {n++} n == 2 && NF == 8 && $1 == 1 {print $5}' "$work/spin.dump")
first=$(awk '/ITEM: TIMESTEP/ {n++} n == 1 && NF == 8 && $1 == 1 {print $5}' "$work/spin.dump")
[ "$moved" != "$first" ] || { echo "BODY did not turn grain 1 (qw $first)"; exit 1; }
echo "ok: BODY read our grains, turned them, and our vertices match BODY's ($distance)"
