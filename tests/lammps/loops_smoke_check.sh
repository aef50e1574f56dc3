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

# Smoke test of benchmarks/loops (Guerra & Holmes' column of grains and elastic loops): a
# small column (80 grains, two loops 1.2 grain diameters apart) through the whole protocol with
# short phases, then checks on its end state (check_loops.py): the rings intact (every
# element within 1 % of its rest length, every node within 5 % of the ring radius from the
# axis), no grain through the floor or out of the box, the column's height kept.
#
#   loops_smoke_check.sh LMP CODE(nscd|peer) SCRATCH
# Exit 77 (CTest SKIP) for the peer when lmp has no pair_style granular
# (build with -DNSCD_WITH_GRANULAR=ON).
set -euo pipefail
lmp=$1 code=$2 scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
# (the list first, then grep: grep -q stops reading early and lmp's SIGPIPE fails the pipe)
if [ "$code" = peer ] && ! grep -qw granular <<<"$("$lmp" -h)"; then
  echo "lmp has no pair_style granular (configure with -DNSCD_WITH_GRANULAR=ON): skipped"
  exit 77
fi
rm -rf "$scratch"
mkdir -p "$scratch"
dt=1e-4
[ "$code" = peer ] && dt=5e-6
/usr/bin/python3 "$top/benchmarks/loops/loops.py" run --lmp "$lmp" --dir "$scratch" --code "$code" \
  --grains 80 --spacing 1.2 --mu 0.5 --seed 3 --dt-nscd $dt --dt-peer $dt \
  --t-settle 0.2 --t-hold 0.01 --t-free 0.02
run=$(ls -d "$scratch"/${code}_*)
/usr/bin/python3 "$here/check_loops.py" "$run" "$code"
