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

# CPU seconds (user+sys) to compile the LAMMPS core files that include style_*.h, ccache off.
# Measures what the slim style headers save (doc/README: LAMMPS versions).
# usage: tools/core_compile_time.sh BUILD_DIR   (a build configured with
#        -DCMAKE_EXPORT_COMPILE_COMMANDS=ON against LAMMPS 4 Feb 2025)
build=$1
src=$(grep -o '"file": "[^"]*lammps-4Feb2025/src/[a-z_]*\.cpp"' $build/compile_commands.json | sed 's/"file": "//; s/"$//')
total=0
for f in $src; do
  grep -q '#include "style_' "$f" || continue
  cmd=$(/usr/bin/python3 -c "
import json,sys
for e in json.load(open('$build/compile_commands.json')):
    if e['file']=='$f': print(e['directory']); print(e['command']); break")
  dir=$(echo "$cmd" | head -1); c=$(echo "$cmd" | tail -1 | sed "s| -o [^ ]*| -o /tmp/core_obj.o|")
  t=$( { cd $dir && CCACHE_DISABLE=1 /usr/bin/time -f "%U %S" bash -c "$c" ; } 2>&1 | tail -1 | awk '{print $1+$2}')
  echo "$(basename $f) $t"
  total=$(echo "$total + $t" | bc)
done
echo "TOTAL $total"
