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

# examples/python/column.py through LAMMPS' Python module built with this package
# (build/python, cmake/LammpsWithPackage.cmake): a small wired column built and run in-process; its height and
# fabric angle written as PNG and CSV. The column must stand (height above one grain
# layer, 0.8), the fabric angle must be measured in some r bin, and the module must be the
# build's, with fix nscd. Exits 77 (CTest: skipped) when the module is not built.
#
#   column_example.sh MODULE_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
module=$1 src=$2 work=$3
python=${NSCD_PYTHON:-/usr/bin/python3}
if [ ! -f "$module/lammps/__init__.py" ] || [ ! -e "$module/lammps/liblammps.so" ]; then
  echo "SKIPPED: no lammps Python module with liblammps.so in $module: configure with -DNSCD_LAMMPS_SHARED=ON (the default)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work" && cd "$work"
export PYTHONPATH=$module:$src/tools
"$python" "$src/examples/python/column.py" -o column --layers 2 | tee column.out
test -s column.png
"$python" - <<'PY'
import csv
rows = list(csv.reader(open("column.csv")))
blank = rows.index([])
heights = [float(r[1]) for r in rows[1:blank]]
angles = [r for r in rows[blank + 2:] if r[3] not in ("", "nan")]
assert len(heights) > 20, f"{len(heights)} height readings"
assert heights[-1] > 0.8, f"the column fell: height {heights[-1]}"
assert angles, "no r bin with a fabric angle"
print(f"column.py: {len(heights)} height readings, final height {heights[-1]:.3f}; "
      f"fabric angle in {len(angles)} r bins")
PY
