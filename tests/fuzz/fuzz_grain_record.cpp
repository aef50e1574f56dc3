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

// Fuzz target: the check of the atom style's data-file and restart readers
// (lib/shape/grain_record.h check_grain_record), with a library of a cube and a rod
// (a spherocylinder). The input is a sequence of records: shape id (int32), mass, qw qx qy qz
// (doubles) and a byte choosing data-file (any quaternion length) or restart (unit) rules.
// A refusal (ShapeError) is fine; anything else is a bug: a crash, another exception, a
// sanitizer report, or an accepted grain whose orientation is not a unit quaternion or whose
// moments are not finite and positive.
#include "fuzz_util.h"
#include "shape/grain_record.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

using namespace nscd;
using nscd_fuzz::violated;

namespace {

const ShapeLibrary &library()
{
  static const ShapeLibrary shapes = []() {
    ShapeLibrary l;
    std::istringstream text("shape cube\nradius 0\nvertices 8\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n"
                            "1 1 1\nend\nshape rod\nradius 0.1\nvertices 2\n0 0 0\n0 0 3\nend\n");
    l.read(text, "fuzz");
    return l;
  }();
  return shapes;
}

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  constexpr std::size_t kRecord = 4 + 5 * 8 + 1;
  for (std::size_t at = 0; at + kRecord <= size; at += kRecord) {
    GrainRecord r;
    std::memcpy(&r.shape, data + at, 4);
    std::memcpy(&r.mass, data + at + 4, 8);
    std::memcpy(r.quat.data(), data + at + 12, 32);
    const QuaternionLength length = data[at + 44] & 1 ? QuaternionLength::unit : QuaternionLength::any;
    CheckedGrain g;
    try {
      g = check_grain_record(library(), r, length);
    } catch (const ShapeError &) {
      continue;
    }
    double norm = 0.0;
    for (double q : g.quat) norm += q * q;
    if (!(std::abs(norm - 1.0) <= 1e-12)) violated("an accepted orientation is not a unit quaternion");
    if (!g.inertia.allFinite() || (r.shape > 0 && !(g.inertia.minCoeff() > 0.0)))
      violated("accepted moments are not finite and positive");
    if (r.shape == 0 && g.inertia.norm() != 0.0) violated("a point has moments of inertia");
    if (!(r.mass > 0.0) || !std::isfinite(r.mass)) violated("an accepted mass is not finite and positive");
  }
  return 0;
}
