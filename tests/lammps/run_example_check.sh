#!/usr/bin/env bash
# Runs an example deck in a scratch copy of its folder and checks what it wrote.
#   run_example_check.sh LMP EXAMPLE_DIR SCRATCH_DIR [LAUNCHER ...]
# LAUNCHER (e.g. mpiexec -np 2) runs LMP under MPI.
set -euo pipefail
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
  *)       # validation decks: they print "check NAME: passed" or exit with status 1
    cp "$src"/*.shapes . 2>/dev/null || true
    "${launch[@]}" "$lmp" -in "$deck" -log log.lammps > screen.txt
    grep -q "^check .*: passed" log.lammps
    ;;
esac
echo "example $name: ok"
