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

# fix nscd's write_problem and benchmarks/solver/replay_problem: a small pile of random
# grains poured for 300 steps writes the contact problem of step 300; solved again alone by
# replay_problem with fix nscd's options it must take the sweeps fix nscd took at that step
# (thermo f_nscd[1]) and reach its residual (f_nscd[2]) to 6 printed digits: the file
# holds the whole problem, and the replay is the same computation. Also: a bad file is
# refused naming what could not be read.
#
#   replay_problem_check.sh LMP REPLAY_PROBLEM WORK
set -euo pipefail
lmp=$1 replay=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cat > in.pour <<'DECK'
units           lj
atom_style      spheropolyhedron
atom_modify     map array
boundary        f f f
region          box block -2 2 -2 2 -1 10 units box
create_box      1 box
shapes          random 6 seed 5 vertices 8 12 size 0.8 1.0 radius 0.05
region          sites block -1.4 1.4 -1.4 1.4 0.6 6 units box
create_atoms    1 random 30 77 sites overlap 1.3 maxtry 1000
shapes          assign all shape random 1 6 11 density 1 orient random 13
pair_style      nscd
pair_coeff      * * 0.5
neighbor        0.3 bin
neigh_modify    every 1 delay 0 check yes
timestep        0.005
fix             floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5
fix             side all nscd/wall cylinder 0 0 0 0 0 1 1.9 friction 0.5
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd write_problem 300 step300.problem
thermo_style    custom step f_nscd[1] f_nscd[2] atoms
thermo_modify   format float %.6e
thermo          300
run             300
DECK
"$lmp" -in in.pour -log log.pour > /dev/null
grep -q "step 300: contact problem written to step300.problem" log.pour || { echo "FAIL: no write_problem message"; exit 1; }
read -r sweeps residual < <(awk '$1 == 300 && NF == 4 {print $2, $3}' log.pour | tail -1)
out=$("$replay" step300.problem --repeat 1)
echo "fix nscd at step 300: $sweeps sweeps, residual $residual"
echo "$out"
replayed_sweeps=$(echo "$out" | sed -n 's/.*: \([0-9]*\) sweeps, residual.*/\1/p')
replayed_residual=$(echo "$out" | sed -n 's/.*sweeps, residual \([0-9.e+-]*\).*/\1/p')
[ "$(printf '%.0f' "$sweeps")" = "$replayed_sweeps" ] || { echo "FAIL: sweeps $sweeps in LAMMPS, $replayed_sweeps replayed"; exit 1; }
/usr/bin/python3 -c "import sys; a, b = float('$residual'), float('$replayed_residual'); sys.exit(0 if abs(a - b) <= 1e-5 * abs(a) + 1e-300 else 1)" \
  || { echo "FAIL: residual $residual in LAMMPS, $replayed_residual replayed"; exit 1; }
[ "$(printf '%.0f' "$sweeps")" -gt 4 ] || { echo "FAIL: step 300 too easy ($sweeps sweeps) to test the replay"; exit 1; }
head -c 2000 step300.problem > damaged.problem
if "$replay" damaged.problem > damaged.out 2>&1; then echo "FAIL: a truncated file was read"; exit 1; fi
grep -q "truncated or damaged" damaged.out || { echo "FAIL: no clear refusal"; cat damaged.out; exit 1; }
echo "replay_problem_check: OK"
