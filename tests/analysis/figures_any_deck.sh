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

# tools/column_figures.sh on a deck that is not examples/column (doc/analysis.md): lmp runs
# tests/analysis/in.figures_deck (files pile.KIND.<step>.*, its log split in log.pile.1 and
# log.pile.2, thermo columns step v_stage v_load f_nscd[1] only, no wire, no silo), then the
# figure tool is given the prefix, both logs, the phase and load columns, R and an r/z range.
# Wants: every figure the output allows made (Fig. 3, 4, 5 of the column, the series panel of
# v_load, Fig. 2 when pvbatch and xvfb-run are there), the others (Fig. 6 without wire
# contacts, the silo's figures, the v_height panel) skipped with a warning naming what is
# missing, Fig. 5's curves labelled by load; and nscd-analysis phases over both logs showing
# the 0-step stage 2.
#
#   figures_any_deck.sh LMP SOURCE_DIR WORK_DIR
set -euo pipefail
lmp=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$lmp" -in "$src/tests/analysis/in.figures_deck" -log log.pile.1 -screen none
fail() { echo "FAIL: $*"; exit 1; }

status=0
bash "$src/tools/column_figures.sh" --column . --column-prefix pile --column-log log.pile.1 --column-log log.pile.2 \
  --phase-column v_stage --load-phase 3 --load-column v_load --R 2 --rmax 2.2 --zmin 0 \
  --series Step:v_load --series Step:v_height out > figures.log 2>&1 || status=$?
grep -v "WARN|\|^\s*$" figures.log
[ $status = 0 ] || fail "column_figures.sh exited $status"

expected=(fig3_column fig4 fig5_column series_column)
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
  expected+=(fig2_step2000_column fig2_step2000_network_side fig2_step2800_network_top)
else
  grep -q "WARNING: fig2 skipped: pvbatch or xvfb-run missing" figures.log || fail "Fig. 2 not reported skipped"
fi
for f in "${expected[@]}"; do
  [ -s "out/$f.png" ] || fail "out/$f.png not made"
done
/usr/bin/python3 "$src/tests/analysis/check_png.py" 0.02 out/fig3_column.png out/fig4.png out/fig5_column.png
for what in "fig6 skipped: no pile.wcontacts" "fig3_silo skipped: no --silo" "fig5_silo skipped: no --silo" \
            "series_silo skipped" "panel Step:v_height skipped: the log has no v_height"; do
  grep -q "WARNING: $what" figures.log || fail "no warning '$what'"
done
[ ! -e out/fig6.png ] || fail "fig6.png made without wire contacts"
# the rest step is the last dump before stage 3 (the loading) starts, found across both logs
grep -q "column at rest: step 2000, under load: step 2800" figures.log || fail "rest/loaded steps"
grep -q "^load 0 (step 2000)," out/fig5_column.csv || fail "Fig. 5 not labelled by load at rest"
grep -q "^load 20 (step 2800)," out/fig5_column.csv || fail "Fig. 5 not labelled by load under load"

/usr/bin/python3 "$src/tools/nscd-analysis" phases log.pile.1 log.pile.2 --phase-column v_stage | tee phases.txt
grep -q "^1,,2000," phases.txt || fail "stage 1 (2000 steps) missing"
grep -q "^2,,0," phases.txt || fail "the 0-step stage 2 dropped"
grep -q "^3,,800," phases.txt || fail "stage 3 (800 steps, second log) missing"
echo "figures_any_deck: OK"
