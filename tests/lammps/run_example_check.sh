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

# Runs an example deck in a scratch copy of its folder and checks what it wrote.
#   run_example_check.sh LMP EXAMPLE_DIR SCRATCH_DIR [LAUNCHER ...]
# LAUNCHER (e.g. mpiexec -np 2) runs LMP under MPI.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=$1; src=$2; work=$3
shift 3
launch=("$@")
rm -rf "$work"; mkdir -p "$work"; cp "$src"/in.* "$work"/
cd "$work"
deck=$(ls in.* | head -n 1)
name=$(basename "$src")
case "$name" in
  pile)    # the first 300 steps only: the whole pour is a run of minutes
    "$lmp" -in "$deck" -log log.lammps -var steps 300 > screen.txt
    grep -q "^Loop time" log.lammps
    grep -q "Created 384 atoms" log.lammps || { echo "expected 384 grains"; exit 1; }
    [ -s grains.0.vtk ] && [ -s pile.data ] && [ -s pile.shapes ]
    polys=$(awk '/^POLYGONS/ {print $2}' grains.0.vtk)
    [ "$polys" -gt 384 ] || { echo "grains.0.vtk has only '$polys' polygons"; exit 1; }
    ! grep -q "ERROR\|Lost atoms" log.lammps
    ;;
  column)  # a 2-layer column through all five phases: double loops, no wire, closed rings (< 1 min);
           # and its deposit at another dt
    small=(-var layers 2 -var R 2 -var element 0.3 -var layer_steps 300 -var wire_steps 100
           -var relax_chunk 200 -var relax_max 5 -var wall_speed 0.3 -var wall_travel 0.6
           -var seat_steps 100 -var load_chunk 100 -var load_max 3 -var load_rate 20
           -var thermo_every 100 -var dump_every 100000)
    "${launch[@]}" "$lmp" -in "$deck" -log log.column "${small[@]}" > screen.txt
    "${launch[@]}" "$lmp" -in "$deck" -log log.bare "${small[@]}" -var wire no -var name bare > screen_bare.txt
    "${launch[@]}" "$lmp" -in "$deck" -log log.ring "${small[@]}" -var loop ring -var name ring > screen_ring.txt
    "${launch[@]}" "$lmp" -in "$deck" -log log.prestrain "${small[@]}" -var loop ring -var prestrain 0.01 -var last 1 \
      -var name prestrain > screen_prestrain.txt
    # -var dt 0.01: the step counts are counted at dt 0.005, so the deposit of 2 x (300 + 100)
    # steps runs in 2 x (150 + 50) = 400 steps of 0.01, the same time
    "${launch[@]}" "$lmp" -in "$deck" -log log.dt "${small[@]}" -var settle fixed -var dt 0.01 -var last 1 \
      -var name dt > screen_dt.txt
    grep -q "^phase 1 done: .*, step 400$" log.dt ||
      { echo "column: -var dt 0.01 should run the deposit in 400 steps: $(grep '^phase 1 done' log.dt)"; exit 1; }
    for kind in grains.*.vtk fabric.*.dump pairs.*.dump wire.*.dump nodes.*.dump phase5.restart; do
      ls column.$kind > /dev/null || { echo "column: no column.$kind written"; exit 1; }
    done
    /usr/bin/python3 "$here/check_column.py" log.column log.bare log.ring log.prestrain 0.01
    ;;
  string)  # 3 layers of the single string through all five phases, briefly (< 1 min): one
           # molecule, one chain (elements = nodes - 1), every element laid at its rest length
    small=(-var layers 3 -var R 2 -var element 0.3 -var layer_steps 200 -var wire_steps 100
           -var relax_chunk 100 -var relax_max 2 -var wall_speed 0.3 -var wall_travel 0.3
           -var seat_steps 100 -var seat_max 1 -var load_chunk 100 -var load_max 1 -var load_rate 20
           -var thermo_every 100 -var dump_every 100000 -var column_deck "$src/../column/in.column")
    "${launch[@]}" "$lmp" -in "$deck" -log log.string "${small[@]}" > screen.txt
    grep -q "^phase 5 done" log.string || { echo "string: phase 5 not reached"; exit 1; }
    ! grep -q "ERROR\|Lost atoms\|from rest length" log.string
    [ "$(grep -c '^create_wire: .*continuing molecule 1 from its end node' log.string)" -eq 4 ] ||
      { echo "string: expected 2 risers and 2 loops continued"; exit 1; }
    awk '/^create_wire: / { for (k = 1; k <= NF; k++) { if ($k == "nodes") n += $(k-1); if ($k == "elements") e += $(k-1) }
                            if ($0 !~ /molecule 1\)/) bad = 1 }
         END { if (bad || e != n - 1) { printf "string: %d nodes, %d elements, molecules %s\n", n, e, bad ? "several" : "1"; exit 1 } }' log.string
    ;;
  *)       # validation decks: they print "check NAME: passed" or exit with status 1
    cp "$src"/*.shapes . 2>/dev/null || true
    "${launch[@]}" "$lmp" -in "$deck" -log log.lammps > screen.txt
    grep -q "^check .*: passed" log.lammps
    ;;
esac
echo "example $name: ok"
