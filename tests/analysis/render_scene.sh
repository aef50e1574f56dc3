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

# Renders a small scene to PNG the way a user makes the papers' Fig. 2 (doc/analysis.md):
# lmp runs tests/analysis/in.render (dump grains/vtk, compute nscd/contacts pairs,
# compute wire/local, node positions), tools/nscd-analysis turns the dumps into .vtp files,
# pvbatch renders tools/nscd_render.py's three views under Xvfb, and check_png.py wants
# each picture drawn (> 2 % of the pixels off the background, some in colour) and < 300 KB.
# Exits 77 (CTest: skipped) when pvbatch, ParaView's Python or xvfb-run is missing.
#
#   render_scene.sh LMP SOURCE_DIR WORK_DIR      (PVBATCH=... names another pvbatch)
set -euo pipefail
lmp=$1 src=$2 work=$3
pvbatch=${PVBATCH:-pvbatch}
skip() { echo "SKIPPED: $*; install with: apt-get install paraview python3-paraview xvfb xauth"; exit 77; }
command -v "$pvbatch" >/dev/null || skip "no $pvbatch"
command -v xvfb-run >/dev/null || skip "no xvfb-run"
[ -d /usr/lib/python3/dist-packages/paraview ] || skip "no ParaView Python module (python3-paraview)"

rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$lmp" -in "$src/tests/analysis/in.render" -var dir "$src/tests/analysis" -log log.render -screen none
/usr/bin/python3 "$src/tools/nscd-analysis" vtk-network pairs.300.dump -o network
/usr/bin/python3 "$src/tools/nscd-analysis" vtk-wire --elements wire.300.dump --nodes nodes.300.dump -o wire
render() {
  xvfb-run -a -s "-screen 0 1280x1024x24" "$pvbatch" "$src/tools/nscd_render.py" --grains grains.300.vtk \
    --wire wire.300.vtp --network network.300.vtp --min-force 0.01 --out fig2 --size 400 400 > render.log 2>&1
}
# pvbatch has been seen to abort while creating its X window (vtkXOpenGLRenderWindow::
# CreateAWindow), on a fresh machine's first X start and twice in a row on a loaded one:
# up to four tries, a few seconds apart. What is tested is our pipeline, not the X server.
ok=0
for try in 1 2 3 4; do
  if render; then ok=1; break; fi
  echo "pvbatch failed (try $try):"; tail -3 render.log; sleep $((2 * try))
done
[ $ok = 1 ] || { cat render.log; exit 1; }
# pvbatch exits 0 after pipeline errors: they must not happen
if grep -q " ERR| " render.log; then grep " ERR| " render.log | head -5; exit 1; fi
/usr/bin/python3 "$src/tests/analysis/check_png.py" 0.02 fig2_column.png fig2_network_side.png fig2_network_top.png
