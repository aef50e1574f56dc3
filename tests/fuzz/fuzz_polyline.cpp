/* ----------------------------------------------------------------------
   NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
   spheropolyhedra coupled to elastic wires.

   Copyright (2026) the NSCD package developers. This software is
   distributed under the GNU General Public License, version 2, the
   licence of LAMMPS. See the LICENSE file in the top-level directory
   of the package.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: the NSCD package developers
------------------------------------------------------------------------- */

// Fuzz target: the polyline file reader of create_wire (lib/wire/wire_path.h
// read_polyline), then the layout of the accepted path and its self-overlap check
// (lib/wire/wire_overlap.h), as create_wire runs them. The first input byte sets the node
// count aimed at (2 to 257, a chord of length/(n-1)), the rest is the file. A refusal
// (WirePathError) is fine; anything else is a bug: a crash, another exception, a sanitizer
// report, an accepted point that is not finite, a layout whose nodes are not finite or
// whose elements are not of the chord's length.
#include "fuzz_util.h"
#include "wire/wire_overlap.h"
#include "wire/wire_path.h"

#include <cmath>
#include <cstdint>
#include <string>

using namespace nscd;
using namespace nscd::wire;
using nscd_fuzz::violated;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  if (size < 1) return 0;
  const int nodes = 2 + data[0];
  const std::string text(reinterpret_cast<const char *>(data + 1), size - 1);
  PolylinePath path;
  try {
    path = read_polyline(text, "fuzz.txt");
  } catch (const WirePathError &) {
    return 0;
  }
  for (const Vec3 &p : path.points)
    if (!p.allFinite()) violated("an accepted point is not finite");
  WireLayout layout;
  try {
    double length = 0.0;
    for (size_t k = 0; k + 1 < path.points.size(); k++) length += (path.points[k + 1] - path.points[k]).norm();
    layout = lay_polyline(path, length / (nodes - 1));
  } catch (const WirePathError &) {
    return 0;    // too few points, coinciding points, a path too long for doubles
  }
  for (const Vec3 &x : layout.nodes)
    if (!x.allFinite()) violated("a laid node is not finite");
  if (layout.nodes.size() < 2) violated("an accepted layout has fewer than 2 nodes");
  for (const WireElement &e : layout.topology.elements) {
    const double l = (layout.nodes[e.b] - layout.nodes[e.a]).norm();
    if (!(std::abs(l - layout.chord) <= 1e-6 * layout.chord)) violated("an element is not of the chord's length");
  }
  const ElementOverlap o = deepest_overlap_within({layout.nodes, layout.topology.elements}, 0.25 * layout.chord, {});
  if (!(o.depth >= 0.0) || !std::isfinite(o.depth)) violated("overlap depth is not a finite number >= 0");
  return 0;
}
