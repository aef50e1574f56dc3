/* -*- c++ -*- ----------------------------------------------------------
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

// Closest points between two segments (internal to lib/geometry).
#pragma once

#include "math/types.h"

namespace nscd {
namespace geometry_detail {

struct SegmentClosest {
  double s = 0.0;          // parameter on segment a (0 at a0, 1 at a1)
  double t = 0.0;          // parameter on segment b
  Vec3 point_a, point_b;   // the closest points
  // Segments parallel within the angular tolerance: then every s in [s_lo, s_hi] is
  // equally close (s is its middle); otherwise s_lo == s_hi == s.
  bool parallel = false;
  double s_lo = 0.0, s_hi = 0.0;
};

// Exact closest points of segments a0-a1 and b0-b1. Zero-length segments (shorter than
// length_tolerance) are points. Parallel overlapping segments get the middle of the
// overlap, so the answer moves continuously as they slide.
SegmentClosest closest_points_on_segments(const Vec3 &a0, const Vec3 &a1, const Vec3 &b0,
                                          const Vec3 &b1, double length_tolerance);

// Parameter of the point of segment a0-a1 closest to p (0 for a zero-length segment).
double closest_parameter_on_segment(const Vec3 &a0, const Vec3 &a1, const Vec3 &p);

// A unit vector perpendicular to v (deterministic; v need not be normalised, v != 0).
Vec3 any_perpendicular(const Vec3 &v);

}    // namespace geometry_detail
}    // namespace nscd
