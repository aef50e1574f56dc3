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

// Distance between the convex hulls of two point sets (GJK; internal to lib/geometry).
#pragma once

#include "math/types.h"

namespace nscd {
namespace geometry_detail {

struct GjkResult {
  bool overlap = false;     // hulls intersect (or touch within round-off)
  double distance = 0.0;    // distance between the hulls (0 when overlap)
  Vec3 point_a, point_b;    // closest points (meaningful only when !overlap)
};

// Gilbert-Johnson-Keerthi distance of conv(a[0..na)) and conv(b[0..nb)). Exact for
// polytopes up to round-off: it stops when the support point brings no progress.
// length_scale (the size of the shapes) sets the round-off tolerance.
GjkResult gjk_distance(const Vec3 *a, int na, const Vec3 *b, int nb, double length_scale);

}    // namespace geometry_detail
}    // namespace nscd
