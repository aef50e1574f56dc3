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

# tools/nscd_analysis installs as a Python package offline (pip with Debian's setuptools, no
# index, no build isolation) and its entry point `nscd-analysis` runs the installed code: a
# figure from a log (timeseries), from a folder outside the source tree. The package is
# copied first so that the build leaves nothing in tools/.
#
#   install_package.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
python=${NSCD_PYTHON:-/usr/bin/python3}
rm -rf "$work" && mkdir -p "$work/source" && cd "$work"
cp -r "$src/tools/pyproject.toml" "$src/tools/nscd_analysis" source/
"$python" -m pip install --quiet --root-user-action=ignore --no-build-isolation --no-deps --no-index --prefix "$work/prefix" ./source
command=$(find "$work/prefix" -path '*/bin/nscd-analysis' -type f)
site=$(dirname "$(find "$work/prefix" -path '*-packages/nscd_analysis/__init__.py')")
[ -x "$command" ] && [ -n "$site" ] || { echo "pip installed no nscd-analysis command or package"; exit 1; }
export PYTHONPATH=$(dirname "$site")
where=$("$python" -c 'import nscd_analysis; print(nscd_analysis.__file__)')
case $where in "$work/prefix/"*) ;; *) echo "imported $where, not the installed package"; exit 1;; esac
cat > log.small <<'LOG'
   Step          v_height
         0   1.5
       100   1.25
Loop time of 0.1 on 1 procs for 100 steps with 2 atoms
LOG
"$command" timeseries log.small --plot Step:v_height -o series
tr -d "\r" < series.csv | grep -qx "100,1.25" || { echo "series.csv lacks the row 100,1.25:"; cat series.csv; exit 1; }
test -s series.png
"$python" -m nscd_analysis --help > /dev/null
echo "nscd-analysis installed with pip in $work/prefix and ran from there"
