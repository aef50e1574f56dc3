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

# compute wire/contacts through dump local into tools/nscd-analysis wire-contacts
# (doc/analysis.md): lmp runs tests/analysis/in.wire_contacts on NP ranks (a wire resting
# on a floor), and the tool, reading the dump, must find one row per node (31, each once
# over the ranks) with every force on the wire within 30 degrees of the vertical.
#
#   wire_contacts_dump.sh LMP SOURCE_DIR WORK_DIR NP
set -euo pipefail
lmp=$1 src=$2 work=$3 np=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
mpiexec --oversubscribe -n "$np" "$lmp" -in "$src/tests/analysis/in.wire_contacts" -log log.lammps -screen none
/usr/bin/python3 "$src/tools/nscd-analysis" wire-contacts wcontacts.1500.dump --kind 3 --bins 6 -o fig6 | tee tool.out
grep -q "31 contacts, fraction within 30 deg of the vertical 1.000" tool.out || {
  echo "expected 31 wire-floor contacts, all vertical"; exit 1; }
rows=$(awk '/ITEM: NUMBER OF ENTRIES/{getline; print}' wcontacts.1500.dump)
[ "$rows" = 31 ] || { echo "dump holds $rows rows, expected 31"; exit 1; }
# each node once: the first column (the node) has 31 distinct values
distinct=$(awk 'f && NF == 16 {print $1} /ITEM: ENTRIES/ {f = 1}' wcontacts.1500.dump | sort -u | wc -l)
[ "$distinct" = 31 ] || { echo "$distinct distinct nodes in the rows, expected 31"; exit 1; }
test -s fig6.png && test -s fig6.csv
echo "wire-contacts read compute wire/contacts' dump on $np rank(s)"
