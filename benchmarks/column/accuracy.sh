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

# Accuracy beside the speed: the column's outcome with each speed-up that changes the
# trajectory, against today's settings, over seeds (issue "The papers' column at full size
# in minutes"). Each setting runs examples/column/in.column at the papers' layer size (R 3,
# cells 2, elements 0.2) with LAYERS layers for every seed, one rank per run, JOBS runs at a
# time; then accuracy.py tabulates height and retained fraction kept through the walls and
# the relaxation, wire stretch energy, and the plate's sink at fixed loads, with mean and
# scatter over the seeds.
#
#   benchmarks/column/accuracy.sh                  # settings below, seeds 1 2 3, 6 layers
#   SEEDS="1 2 3 4" LAYERS=8 JOBS=2 benchmarks/column/accuracy.sh
#   SETTINGS="today new" benchmarks/column/accuracy.sh
#
# Settings (each a set of -var's on top of the common ones):
#   today      the substeps and fixed phases of main before 26 Nov 2026 (substeps 247, settle fixed)
#   new        the defaults (automatic substeps; phases end at rest)
#   fast       the defaults with the fewest stable substeps (83 for the papers' wire)
#   relax01    fast, and relaxations ending at an rms speed of 0.01 (v_relax; as loose as a
#              layer's v_rest: the deck's first state-based version)
#   substeps   the fewest stable substeps (83) only, settle fixed: the stable rule alone
#   settle     phases ending at rest only (substeps 247): the state-based phases alone
#   inertia10  the defaults with fix wire inertia 10
#   dt01       the defaults with an NSCD step of 0.01 (twice the deck's)
# Writes benchmarks/column/work/accuracy/<setting>.<seed>.log and accuracy.csv.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${LMP:-$here/../../build/lmp}
seeds=${SEEDS:-1 2 3}
layers=${LAYERS:-6}
jobs=${JOBS:-2}
settings=${SETTINGS:-today new inertia10}
work=${WORK:-$here/work/accuracy}
mkdir -p "$work"
cd "$work"
# LAMMPS reads its input as it goes (and again at every jump): the runs read a copy
cp "$here/../../examples/column/in.column" in.column
common=(-var layers "$layers" -var R 3 -var cells 2 -var layer_steps 800 -var wire_steps 200 -var relax_max 10
        -var load_rate 10 -var load_max 10 -var dump_every 1000000 -var thermo_every 100)
options_of() {
  case $1 in
    today) echo "-var substeps 247 -var settle fixed" ;;
    new) echo "" ;;
    fast) echo "-var substeps stable" ;;
    relax01) echo "-var substeps stable -var v_relax 0.01" ;;
    substeps) echo "-var substeps stable -var settle fixed" ;;
    settle) echo "-var substeps 247" ;;
    inertia10) echo "-var inertia 10" ;;
    dt01) echo "-var dt 0.01" ;;
    *) echo "accuracy.sh: unknown setting $1" >&2; exit 1 ;;
  esac
}
run_one() {    # setting seed
  local options
  options=$(options_of "$1")
  # shellcheck disable=SC2086
  /usr/bin/time -f "%e s wall, %U s user" -o "$1.$2.time" nice -n 5 "$lmp" -in in.column \
    -log "$1.$2.log" -screen none -var name "$1.$2" -var seed "$2" "${common[@]}" $options > /dev/null 2>&1 \
    || echo "accuracy.sh: $1 seed $2 failed (see $work/$1.$2.log)" >&2
}
for setting in $settings; do
  for seed in $seeds; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 5; done
    grep -q "s user" "$setting.$seed.time" 2>/dev/null && continue    # done before: kept
    run_one "$setting" "$seed" &
  done
done
wait
/usr/bin/python3 "$here/accuracy.py" --work "$work" --settings $settings --seeds $seeds --csv accuracy.csv
