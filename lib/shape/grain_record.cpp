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

#include "shape/grain_record.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace nscd {
namespace {

std::string number(double x)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", x);
  return text;
}

}    // namespace

CheckedGrain check_grain_record(const ShapeLibrary &library, const GrainRecord &record, QuaternionLength length)
{
  if (record.shape < 0 || record.shape > library.size())
    throw ShapeError("shape id " + std::to_string(record.shape) + " is outside 0.." + std::to_string(library.size()) +
                     ": 'shapes read FILE' before read_data, or 0 for a point");
  if (!(record.mass > 0.0) || !std::isfinite(record.mass))
    throw ShapeError("mass " + number(record.mass) + " must be a finite number > 0");
  const std::array<double, 4> &q = record.quat;
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const std::string quat = "quaternion (" + number(q[0]) + " " + number(q[1]) + " " + number(q[2]) + " " +
      number(q[3]) + ")";
  if (!(norm > 1e-10) || !std::isfinite(norm))
    throw ShapeError(quat + " has no usable length (" + number(norm) + "); use 1 0 0 0 for no rotation");
  if (length == QuaternionLength::unit && std::abs(norm - 1.0) > 1e-6)
    throw ShapeError(quat + " has length " + number(norm) + ", not 1 as stored orientations have");
  CheckedGrain out;
  for (int k = 0; k < 4; k++) out.quat[k] = q[k] / norm;
  if (record.shape == 0) return out;
  const Spheropolyhedron &shape = library.shape(record.shape);
  out.inertia = grain_inertia_from_mass(shape, record.mass).inertia;    // throws for masses without finite moments
  out.bounding_radius = shape.bounding_radius;
  return out;
}

}    // namespace nscd
