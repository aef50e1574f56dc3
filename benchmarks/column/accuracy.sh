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
#   SCENE=small SETTINGS="new fast" CROSS="new fast" SEEDS="2026 2027 2028" JOBS=1 benchmarks/column/accuracy.sh
#
# SCENE: papers (the default: the papers' layers as above) or small (tools/run_example.sh's
# column, 5 layers of R 2.5, loaded to 400 unless it fails first: the README's numbers).
# CROSS="A B": then also phase 5 alone from each seed's phase-4 restart of A loaded with B's
# options and of B with A's (logs A-then-B.SEED.log): whether a setting's failure load comes
# from the column it built or from the loading.
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
#   anderson   the defaults with fix nscd method anderson
# Writes benchmarks/column/work/accuracy/<setting>.<seed>.log and accuracy.csv (SCENE small:
# work/accuracy.small/).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${LMP:-$here/../../build/lmp}
seeds=${SEEDS:-1 2 3}
layers=${LAYERS:-6}
jobs=${JOBS:-2}
settings=${SETTINGS:-today new inertia10}
scene=${SCENE:-papers}
cross=${CROSS:-}
work=${WORK:-$here/work/accuracy}
[ "$scene" = papers ] || work=${WORK:-$here/work/accuracy.$scene}
mkdir -p "$work"
cd "$work"
# LAMMPS reads its input as it goes (and again at every jump): the runs read a copy
cp "$here/../../examples/column/in.column" in.column
case $scene in
  papers) common=(-var layers "$layers" -var R 3 -var cells 2 -var layer_steps 800 -var wire_steps 200 -var relax_max 10
                  -var load_rate 10 -var load_max 10 -var dump_every 1000000 -var thermo_every 100) ;;
  small) # shellcheck source=SCRIPTDIR/../../tools/small_column.sh
         source "$here/../../tools/small_column.sh"    # the README's column: small_column
         common=("${small_column[@]}" -var dump_every 1000000) ;;
  *) echo "accuracy.sh: SCENE $scene: use papers or small" >&2; exit 1 ;;
esac
options_of() {   # the -var's of a setting, one argument per line
  case $1 in
    today) printf '%s\n' -var substeps 247 -var settle fixed ;;
    new) ;;
    fast) printf '%s\n' -var substeps stable ;;
    relax01) printf '%s\n' -var substeps stable -var v_relax 0.01 ;;
    substeps) printf '%s\n' -var substeps stable -var settle fixed ;;
    settle) printf '%s\n' -var substeps 247 ;;
    inertia10) printf '%s\n' -var inertia 10 ;;
    dt01) printf '%s\n' -var dt 0.01 ;;
    anderson) printf '%s\n' -var solver_options "method anderson" ;;
    *) echo "accuracy.sh: unknown setting $1" >&2; exit 1 ;;
  esac
}
run_one() {    # name seed options...
  local name=$1 seed=$2
  shift 2
  /usr/bin/time -f "%e s wall, %U s user" -o "$name.$seed.time" nice -n 5 "$lmp" -in in.column \
    -log "$name.$seed.log" -screen none -var name "$name.$seed" -var seed "$seed" "${common[@]}" "$@" > /dev/null 2>&1 \
    || echo "accuracy.sh: $name seed $seed failed (see $work/$name.$seed.log)" >&2
}
queue() {      # name seed options...: run in the background once fewer than JOBS run; skip if done
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 5; done
  grep -q "s user" "$1.$2.time" 2>/dev/null && return    # done before: kept
  run_one "$@" &
}
for setting in $settings; do options_of "$setting" > /dev/null; done    # an unknown one stops here
for setting in $settings; do
  mapfile -t options < <(options_of "$setting")
  for seed in $seeds; do
    queue "$setting" "$seed" "${options[@]}"
  done
done
wait
crossed=()
if [ -n "$cross" ]; then
  read -r a b <<< "$cross"
  [ -n "$b" ] || { echo "accuracy.sh: CROSS '$cross': give two settings" >&2; exit 1; }
  for pair in "$a $b" "$b $a"; do
    read -r built loaded <<< "$pair"
    crossed+=("$built-then-$loaded")
    mapfile -t options < <(options_of "$loaded")
    for seed in $seeds; do
      # the deck reads NAME.phase4.restart for -var start 5: the built column under the new name
      ln -sf "$built.$seed.phase4.restart" "$built-then-$loaded.$seed.phase4.restart"
      queue "$built-then-$loaded" "$seed" -var start 5 "${options[@]}"
    done
  done
  wait
fi
# shellcheck disable=SC2086
/usr/bin/python3 "$here/accuracy.py" --work "$work" --settings $settings "${crossed[@]}" --seeds $seeds --csv accuracy.csv
