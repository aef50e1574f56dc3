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

# Memory per rank after read_restart (issue 28): in.bed_memory's restart of the settled bed
# replicated to 100800 grains (written once per WORK on WRITE_NP ranks), read on 1 and on 4 ranks
# with `run 0`. Prints per rank count LAMMPS' "Per MPI rank memory" line (min/avg/max) and
# each rank's peak resident memory (/usr/bin/time %M, kB).
#
#   benchmarks/scaling/memory.sh   (LMP=build/lmp, WORK=/tmp/scaling, RX=10, RY=10, WRITE_NP=4)
# The peak resident memory includes LAMMPS' read buffer: rank 0 reads the file one writer's
# chunk at a time and broadcasts it to every rank, so a file written on 1 rank puts all of
# it on every reader at once; LAMMPS' line counts the arrays held after the read.
set -e
cd "$(dirname "$0")"
LMP=$(realpath "${LMP:-../../build/lmp}")
WORK=${WORK:-/tmp/scaling}
RX=${RX:-10}
RY=${RY:-10}
WRITE_NP=${WRITE_NP:-4}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$WORK"
[ -f "$WORK/bed.restart" ] || "$LMP" -in in.bed_settle -var dir "$WORK" -log "$WORK/bed_settle.log" > /dev/null
[ -f "$WORK/bed_memory.restart" ] ||
  mpiexec --oversubscribe -np "$WRITE_NP" "$LMP" -in in.bed_memory -var dir "$WORK" -var phase write -var rx "$RX" -var ry "$RY" -log "$WORK/bed_memory_write.log" > /dev/null
for np in 1 4; do
  rm -f "$WORK"/bed_memory_np$np.rss.*
  mpiexec --oversubscribe -np "$np" bash -c 'exec /usr/bin/time -f "%M" -o "$0.rss.$OMPI_COMM_WORLD_RANK" "$@"' \
    "$WORK/bed_memory_np$np" "$LMP" -in in.bed_memory -var dir "$WORK" -var phase read -log "$WORK/bed_memory_np$np.log" > /dev/null
  echo "read on $np ranks: $(grep -m1 '^Per MPI rank memory' "$WORK/bed_memory_np$np.log" | sed 's/.*= //'); peak rss_kb per rank $(cat "$WORK"/bed_memory_np$np.rss.* | tr '\n' ' ')"
done
