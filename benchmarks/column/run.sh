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

# The papers' size: a wire column of 25 layers (radius 3 ~ 6 largest grain radii; 2 lattice
# cells = 50 grains per layer, ~1250 grains, 25 double loops) through every phase of
# examples/column/in.column on NP ranks, then the per-phase table (steps, wall time, ms per
# step, mean sweeps, unconverged fraction) of examples/column/summary.py. Not run by ctest.
#
#   benchmarks/column/run.sh                 # 2 ranks, all phases (hours on 2 cores)
#   NP=1 LAYERS=5 benchmarks/column/run.sh   # a shorter look at the same scene
#   benchmarks/column/run.sh -var start 3    # extra lmp arguments (here: go on from phase 2's restart)
# Writes benchmarks/column/work/ (log.bench, bench.*). LMP and MPIEXEC choose the programs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${LMP:-$here/../../build/lmp}
np=${NP:-2}
mpiexec=${MPIEXEC:-mpiexec}
layers=${LAYERS:-25}
mkdir -p "$here/work"
cd "$here/work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
start=$SECONDS
"$mpiexec" -np "$np" "$lmp" -in "$here/../../examples/column/in.column" -log log.bench \
  -var name bench -var layers "$layers" -var R 3 -var cells 2 -var dump_every 10000 "$@" > screen.txt
echo "benchmarks/column: $layers layers on $np ranks, $(( SECONDS - start )) s wall"
/usr/bin/python3 "$here/../../examples/column/summary.py" log.bench --csv summary.csv
