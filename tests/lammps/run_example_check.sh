#!/usr/bin/env bash
# Runs an example deck in a scratch copy of its folder and checks what it wrote.
#   run_example_check.sh LMP EXAMPLE_DIR SCRATCH_DIR
set -euo pipefail
lmp=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cp "$src"/in.* "$work"/
cd "$work"
deck=$(ls in.* | head -n 1)
"$lmp" -in "$deck" -log log.lammps > screen.txt
name=$(basename "$src")
case "$name" in
  pile)
    grep -q "^Loop time" log.lammps
    atoms=$(awk '/^ *[0-9]+ +[0-9]+ +[0-9.e+-]+ *$/ {n=$2} END {print n}' log.lammps)
    [ "$atoms" = 384 ] || { echo "expected 384 grains in thermo output, got '$atoms'"; exit 1; }
    [ -s grains.0.vtk ] && [ -s pile.data ] && [ -s pile.shapes ]
    polys=$(awk '/^POLYGONS/ {print $2}' grains.0.vtk)
    [ "$polys" -gt 384 ] || { echo "grains.0.vtk has only '$polys' polygons"; exit 1; }
    ;;
esac
echo "example $name: ok"
