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

# A large column (issue 28, item 4): examples/column/in.column at radius R = 9 (three times
# the papers' column radius: ~450 grains and a double loop of ~565 nodes per layer, 2 lattice
# cells a layer), LAYERS layers in all (default 10: ~4500 grains and ~5600 wire nodes), on NP
# ranks (default 2), stopped once STOP layers (default 2) have been deposited or after
# MAX_SECONDS of wall time (default 780), whichever comes first. Prints the layers done, the
# steps, the time per step, the mean sweeps per step, LAMMPS' "Per MPI rank memory" line of
# the last run, each rank's peak resident memory (VmHWM) and, on several ranks, fix nscd's and
# fix wire's counts of messages and bytes between ranks over the last run that ended.
#
#   benchmarks/large_column/run.sh                     # 2 ranks, the first 2 layers
#   STOP=4 MAX_SECONDS=3600 benchmarks/large_column/run.sh
# Writes benchmarks/large_column/work/ (log.large, screen.txt). LMP and MPIEXEC choose
# the programs; extra arguments go to lmp (e.g. -var balance shift).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=$(realpath "${LMP:-$here/../../build/lmp}")
mpiexec=${MPIEXEC:-mpiexec}
np=${NP:-2}
layers=${LAYERS:-10}
stop=${STOP:-2}
max_seconds=${MAX_SECONDS:-780}
mkdir -p "$here/work"
cd "$here/work"
rm -f log.large
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
start=$SECONDS
"$mpiexec" -np "$np" \
  "$lmp" -in "$here/../../examples/column/in.column" -log log.large -var name large -var R 9 -var cells 2 \
  -var layers "$layers" -var dump_every 1000000 "$@" > screen.txt 2>&1 &
run=$!
# The lmp processes of this run (descendants of its mpiexec) and their peak resident memory
# (VmHWM, kB) as the kernel keeps it, read every 5 s: the run is stopped, not ended.
descendants() { local c; for c in $(ps -o pid= --ppid "$1"); do echo "$c"; descendants "$c"; done; }
declare -A peak
read_peaks() {
  local p kb
  for p in $(descendants "$run"); do
    [ "$(cat /proc/"$p"/comm 2> /dev/null)" = lmp ] || continue
    kb=$(awk '/^VmHWM/ {print $2}' /proc/"$p"/status 2> /dev/null) || continue
    [ -n "$kb" ] && peak[$p]=$kb
  done
}
# the deck goes on to its later layers and phases: stop it (this run only, by its process ID)
while kill -0 "$run" 2> /dev/null; do
  read_peaks
  if grep -q "^layer $stop of $layers" log.large 2> /dev/null || (( SECONDS - start > max_seconds )); then
    kill "$run"
    break
  fi
  sleep 5
done
wait "$run" || true
wall=$(( SECONDS - start ))
done_layers=$(grep -c "^layer [0-9]* of $layers" log.large || true)
echo "benchmarks/large_column: R 9, $layers layers in the deck, $np ranks: $done_layers layers deposited in $wall s wall"
grep "^layer [0-9]* of" log.large || true
/usr/bin/python3 - log.large <<'PY'
import re, sys
# per run of the deck (LAMMPS' "Loop time" line, fix nscd's end-of-run line): atoms, steps,
# wall time, time per step, mean sweeps per step
text = open(sys.argv[1]).read()
loops = re.findall(r"^Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms", text, re.M)
sweeps = re.findall(r"^fix nscd \S+: (\d+) steps, sweeps per step (\S+) on average", text, re.M)
loops = [(float(t), int(n), int(a)) for t, n, a in loops if int(n) > 0]
print("atoms  steps  wall s  ms/step  sweeps/step")
for (t, n, a), (_, sw) in zip(loops, sweeps):
    print(f"{a:5d}  {n:5d}  {t:6.1f}  {1000 * t / n:7.0f}  {float(sw):11.1f}")
total, steps = sum(t for t, _, _ in loops), sum(n for _, n, _ in loops)
if steps: print(f"all runs: {steps} steps, {total:.0f} s, {1000 * total / steps:.0f} ms per step")
memory = re.findall(r"^Per MPI rank memory.*$", text, re.M)
if memory: print("last run: " + memory[-1])
PY
echo "peak resident memory per lmp process (kB, up to the last reading before the stop): ${peak[*]}"
# fix nscd's and fix wire's counts of their communication between ranks over the last run
# that ended (on more than one rank: messages and bytes per sweep exchange, per substep, ...)
grep "^fix nscd [^ ]*: \(between\|per \|warm start over\)" log.large | tail -4 || true
grep "^fix wire [^ ]*: \(between\|per substep\|friction memories with\)" log.large | tail -3 || true
