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

# fix nscd across MPI ranks. Pours and settles the same grains on 1, 2 and 4 ranks (in.pour)
# and compares the piles at rest with the 1-rank pile (check.py; extra 1-rank pours with
# other initial velocities show how much two pours differ anyway). Then continues the
# settled 1-rank pile on 1, 2 and 4 ranks (in.continue): the same problem, differing only
# in the decomposition, for the extra sweeps and the time per step, with and without
# Open MPI's mpi_yield_when_idle (4 ranks on 2 cores busy-poll otherwise).
#
#   benchmarks/mpi/run.sh [small] [lmp arguments for in.pour, e.g. -var tolerance 1e-5]
#     (default) 200 grains; about 12 minutes on 2 cores (1 more per extra seed)
#     small     80 grains, the pours only (the CTest mpi.pile_on_1_2_4_ranks)
#
# Environment: LMP (default build/lmp), MPIRUN (mpirun), WORK (default benchmarks/mpi/work
# or work_small), SEEDS (velocity seeds of the extra 1-rank pours; default "2", small: none).
# Prints markdown tables (also to WORK/results.md); exits 1 if a pile breaks a tolerance.
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${LMP:-$here/../../build/lmp}
mpirun=${MPIRUN:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

mode=full; [ "${1:-}" = small ] && { mode=small; shift; }
if [ $mode = small ]; then
  size=(-var nx 4 -var nz 5 -var pour 1500 -var window 250 "$@")
  work=${WORK:-$here/work_small}; seeds=${SEEDS:-}
  # 80 grains: 1-rank pours differing only in their initial velocities scatter by up to
  # 4 % in height and 40 % in mean contact force (locked-in side-wall stress), see doc/mpi.md
  export HEIGHT_TOL=${HEIGHT_TOL:-0.08} FORCE_TOL=${FORCE_TOL:-0.5}
else
  size=(-var nx 5 -var nz 8 -var pour 2000 -var window 500 "$@")
  work=${WORK:-$here/work}; seeds=${SEEDS:-2}
  # 200 grains: 1-rank pours scatter by up to 3.4 % in height and 7.5 % in force
  export HEIGHT_TOL=${HEIGHT_TOL:-0.05} FORCE_TOL=${FORCE_TOL:-0.15}
fi
mkdir -p "$work"

# run FOLDER RANKS YIELD DECK [lmp arguments]: one run in its own folder under $work. A
# failed run (e.g. lost atoms) leaves its log; check.py then reports it.
run() {
  local dir=$work/$1 np=$2 yield=$3 deck=$4; shift 4
  rm -rf "$dir" && mkdir -p "$dir"
  echo "run.sh: $(basename "$dir") ($np ranks, mpi_yield_when_idle $yield)" >&2
  (cd "$dir" && OMPI_MCA_mpi_yield_when_idle=$yield \
     "$mpirun" -np "$np" "$lmp" -in "$here/$deck" -log log.lammps -screen none "$@") ||
    echo "run.sh: $(basename "$dir") failed, see $dir/log.lammps" >&2
}

run pour.np1 1 1 in.pour "${size[@]}"
for s in $seeds; do run pour.np1_seed$s 1 1 in.pour "${size[@]}" -var seed "$s"; done
run pour.np2 2 1 in.pour "${size[@]}"
run pour.np4 4 1 in.pour "${size[@]}"
extra=(); for s in $seeds; do extra+=("$work/pour.np1_seed$s"); done

status=0
{
  echo "# benchmarks/mpi/run.sh $mode $* on $(hostname), $(nproc) cores, $(date -u +%F)"
  echo
  python3 "$here/check.py" pour "$work/pour.np1" "${extra[@]}" "$work/pour.np2" "$work/pour.np4"
} | tee "$work/results.md"
status=${PIPESTATUS[0]}
[ $mode = small ] && exit "$status"

restart=$work/pour.np1/settled.restart
run continue.np1 1 1 in.continue -var restart "$restart"
for np in 2 4; do run continue.np${np}_yield1 "$np" 1 in.continue -var restart "$restart"; done
# Without yielding, 4 ranks on 2 cores busy-poll: 40-180x slower, so 100 steps at rest only.
for np in 2 4; do run continue.np${np}_yield0 "$np" 0 in.continue -var restart "$restart" -var phases 1 -var steps 100; done
python3 "$here/check.py" continue "$work"/continue.np1 "$work"/continue.np{2,4}_yield{1,0} |
  tee -a "$work/results.md"
exit "$status"
