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

#include "geometry/segment_closest.h"

#include <algorithm>
#include <cmath>

namespace nscd {
namespace geometry_detail {
namespace {

// Two directions with sin(angle) below this are parallel: the closest points are then
// ill-conditioned and we take the middle of the overlap instead.
constexpr double kParallelSine = 1e-9;

double clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }

// Fills the result for segments found parallel: overlap of b's projection onto a.
void closest_on_parallel(const Vec3 &a0, const Vec3 &da, const Vec3 &b0, const Vec3 &db,
                         SegmentClosest &out)
{
  const double aa = da.squaredNorm();
  const double sb0 = (b0 - a0).dot(da) / aa;
  const double sb1 = (b0 + db - a0).dot(da) / aa;
  const double lo = std::max(0.0, std::min(sb0, sb1));
  const double hi = std::min(1.0, std::max(sb0, sb1));
  if (lo <= hi) {
    out.s_lo = lo;
    out.s_hi = hi;
    out.s = 0.5 * (lo + hi);
  } else {
    // No overlap: the ends facing each other are closest.
    out.s = std::max(sb0, sb1) < 0.0 ? 0.0 : 1.0;
    out.s_lo = out.s_hi = out.s;
  }
  out.point_a = a0 + out.s * da;
  out.t = closest_parameter_on_segment(b0, b0 + db, out.point_a);
  out.point_b = b0 + out.t * db;
  out.parallel = true;
}

}    // namespace

double closest_parameter_on_segment(const Vec3 &a0, const Vec3 &a1, const Vec3 &p)
{
  const Vec3 d = a1 - a0;
  const double dd = d.squaredNorm();
  if (dd == 0.0) return 0.0;
  return clamp01((p - a0).dot(d) / dd);
}

Vec3 any_perpendicular(const Vec3 &v)
{
  // Cross with the coordinate axis least aligned with v: never close to parallel.
  int axis = 0;
  if (std::abs(v.y()) < std::abs(v[axis])) axis = 1;
  if (std::abs(v.z()) < std::abs(v[axis])) axis = 2;
  return v.cross(Vec3::Unit(axis)).normalized();
}

SegmentClosest closest_points_on_segments(const Vec3 &a0, const Vec3 &a1, const Vec3 &b0,
                                          const Vec3 &b1, double length_tolerance)
{
  SegmentClosest out;
  const Vec3 da = a1 - a0, db = b1 - b0, r = a0 - b0;
  const double aa = da.squaredNorm(), bb = db.squaredNorm();
  const double tol2 = length_tolerance * length_tolerance;
  const bool a_is_point = aa <= tol2, b_is_point = bb <= tol2;

  if (a_is_point && b_is_point) {
    out.s = out.t = 0.0;
  } else if (a_is_point) {
    out.s = 0.0;
    out.t = closest_parameter_on_segment(b0, b1, a0);
  } else if (b_is_point) {
    out.t = 0.0;
    out.s = closest_parameter_on_segment(a0, a1, b0);
  } else {
    const double ab = da.dot(db), ar = da.dot(r), br = db.dot(r);
    const double denom = aa * bb - ab * ab;    // = |da x db|^2 >= 0
    if (denom <= kParallelSine * kParallelSine * aa * bb) {
      closest_on_parallel(a0, da, b0, db, out);
      return out;
    }
    // Closest points of the infinite lines, then clamp one and re-project the other.
    out.s = clamp01((ab * br - ar * bb) / denom);
    out.t = (ab * out.s + br) / bb;
    if (out.t < 0.0) {
      out.t = 0.0;
      out.s = clamp01(-ar / aa);
    } else if (out.t > 1.0) {
      out.t = 1.0;
      out.s = clamp01((ab - ar) / aa);
    }
  }
  out.s_lo = out.s_hi = out.s;
  out.point_a = a0 + out.s * da;
  out.point_b = b0 + out.t * db;
  return out;
}

}    // namespace geometry_detail
}    // namespace nscd
