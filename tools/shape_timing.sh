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

# Times the shape-library reader on large inputs (doc/robustness.md, "Speed"):
#   one shape of 10^5 random points, one of 10^6 points, 10^5 one-vertex shapes.
#   tools/shape_timing.sh [BUILD_DIR]   (default build-lib; lib/ must be built there)
# Compiles a small driver against BUILD_DIR/lib/libnscd_core.a and prints the wall time
# of ShapeLibrary::read_file for each file (median of REPEAT runs, default 3; a file whose
# runs take more than LIMIT seconds, default 600, is reported without a time).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$here/build-lib}" && pwd)
repeat=${REPEAT:-3}
limit=${LIMIT:-600}    # seconds per file, all repeats together
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 - "$work" <<'PY'
import random, sys
work = sys.argv[1]
rng = random.Random(1)
def cloud(path, n):
    with open(path, "w") as f:
        f.write(f"shape cloud\nradius 0\nvertices {n}\n")
        for _ in range(n):
            f.write(f"{rng.uniform(-1, 1):.17g} {rng.uniform(-1, 1):.17g} {rng.uniform(-1, 1):.17g}\n")
        f.write("end\n")
cloud(f"{work}/points_1e5.shapes", 100000)
cloud(f"{work}/points_1e6.shapes", 1000000)
with open(f"{work}/spheres_1e5.shapes", "w") as f:
    for k in range(100000):
        f.write(f"shape s{k}\nradius 0.5\nvertices 1\n{k} 0 0\nend\n")
PY

cat > "$work/driver.cpp" <<'CPP'
#include "shape/shape_library.h"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
int main(int argc, char **argv)
{
  const int repeat = std::atoi(argv[1]);
  for (int a = 2; a < argc; ++a) {
    std::vector<double> seconds;
    int shapes = 0;
    for (int r = 0; r < repeat; ++r) {
      const auto start = std::chrono::steady_clock::now();
      nscd::ShapeLibrary library;
      library.read_file(argv[a]);
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      shapes = library.size();
    }
    std::sort(seconds.begin(), seconds.end());
    std::printf("%-24s %6d shape(s)  median %.3f s  (min %.3f, max %.3f, %d runs)\n",
                argv[a] + std::string(argv[a]).rfind('/') + 1, shapes, seconds[seconds.size() / 2],
                seconds.front(), seconds.back(), repeat);
  }
}
CPP
g++ -O2 -std=c++17 -I"$here/lib" -I/usr/include/eigen3 "$work/driver.cpp" "$build/lib/libnscd_core.a" \
    -lqhull_r -o "$work/driver"
cd "$work"
for file in points_1e5.shapes points_1e6.shapes spheres_1e5.shapes; do
  timeout "$limit" "$work/driver" "$repeat" "$file" || echo "$file: no result within $limit s (exit $?)"
done
