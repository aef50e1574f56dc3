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

// Convex hull of a 3-D point cloud as polygonal faces (qhull underneath).
// Internal to lib/shape: Spheropolyhedron users do not need it.
#pragma once

#include "math/types.h"

#include <array>
#include <vector>

namespace nscd {

struct HullPolygon {
  std::vector<int> vertices;    // indices into the input points, counter-clockwise seen from outside
};

struct HullTopology {
  std::vector<int> vertices;                // input indices of the hull vertices, ascending
  std::vector<HullPolygon> faces;           // coplanar facets merged; canonical order
  std::vector<std::array<int, 2>> edges;    // input indices, first < second, sorted
};

// Hull of points spanning 3-D space (the caller has checked that they are not flat).
// Facets coplanar to within merge_distance (a length; 0 = round-off only) are merged into
// one polygon. Each face starts at its smallest vertex
// index and faces are sorted, so the result only depends on the input order, not on
// qhull's internals. Throws ShapeError if qhull fails.
HullTopology convex_hull_3d(const std::vector<Vec3> &points, double merge_distance);

}    // namespace nscd
