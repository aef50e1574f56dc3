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

// Exact mass properties (unit density) of spheres, spherocylinders and dilated convex
// polyhedra, as raw moments so that pieces can be summed.
//
// The dilated polyhedron P + B(r) is cut into disjoint pieces whose moments have closed
// forms: the core polyhedron, one prism per face (face x [0, r] along its normal), one
// cylindrical wedge per edge (opening = exterior dihedral angle) and one spherical sector
// per vertex (over the vertex's normal cone). See doc/Howto_nscd_shapes_physics.rst.
#pragma once

#include "math/types.h"
#include "shape/spheropolyhedron.h"

#include <array>
#include <vector>

namespace nscd {

// Raw moments of a solid at unit density: volume = integral of 1, first = integral of x,
// second = integral of x x^T.
struct MassMoments {
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();

  MassMoments &operator+=(const MassMoments &other)
  {
    volume += other.volume;
    first += other.first;
    second += other.second;
    return *this;
  }
  Vec3 centre() const { return first / volume; }
  // Inertia tensor about the centre of mass.
  Mat3 inertia_about_centre() const;
};

MassMoments ball_moments(const Vec3 &centre, double radius);
MassMoments spherocylinder_moments(const Vec3 &a, const Vec3 &b, double radius);

// Polyhedron core only (tetrahedra from the origin to each face's fan triangles).
// Faces must be convex, counter-clockwise seen from outside.
MassMoments polyhedron_moments(const std::vector<Vec3> &vertices, const std::vector<Face> &faces);

// Core + face prisms + edge wedges + vertex sectors; exact for any radius >= 0.
// `edges[i]` is bounded by faces `edge_faces[i]`.
MassMoments dilated_polyhedron_moments(const std::vector<Vec3> &vertices,
                                       const std::vector<Face> &faces,
                                       const std::vector<std::array<int, 2>> &edges,
                                       const std::vector<std::array<int, 2>> &edge_faces,
                                       double radius);

// Solid angle of the normal cone at each vertex (2 pi minus the face angles there); the
// angles add up to 4 pi on a closed convex polyhedron.
std::vector<double> vertex_normal_cone_angles(const std::vector<Vec3> &vertices,
                                              const std::vector<Face> &faces);

// Integral of mean curvature M = sum over edges of length * exterior angle / 2, so that
// the dilated volume is V + A r + M r^2 + 4/3 pi r^3 (Steiner).
double mean_curvature_integral(const std::vector<Vec3> &vertices, const std::vector<Face> &faces,
                               const std::vector<std::array<int, 2>> &edges,
                               const std::vector<std::array<int, 2>> &edge_faces);

double polygon_area(const std::vector<Vec3> &vertices, const Face &face);

}    // namespace nscd
