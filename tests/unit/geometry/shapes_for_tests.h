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

// Shapes and placements shared by the geometry tests.
#pragma once

#include "geometry/contact.h"
#include "shape/spheropolyhedron.h"

#include <cmath>
#include <random>
#include <vector>

namespace nscd::test {

inline Spheropolyhedron make_box(double hx, double hy, double hz, double radius)
{
  std::vector<Vec3> corners;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) corners.emplace_back(sx * hx, sy * hy, sz * hz);
  return make_spheropolyhedron(corners, radius);
}

inline Spheropolyhedron make_sphere(double radius) { return make_spheropolyhedron({Vec3::Zero()}, radius); }

inline Spheropolyhedron make_capsule(double half_length, double radius)
{
  return make_spheropolyhedron({Vec3(-half_length, 0, 0), Vec3(half_length, 0, 0)}, radius);
}

// A grain like the ones the simulations use: hull of random points on an ellipsoid.
inline Spheropolyhedron make_random_grain(std::mt19937_64 &rng, int points, double radius)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vec3> cloud;
  for (int k = 0; k < points; ++k) {
    Vec3 p(normal(rng), normal(rng), normal(rng));
    p.normalize();
    cloud.emplace_back(1.0 * p.x(), 0.8 * p.y(), 0.6 * p.z());
  }
  return make_spheropolyhedron(cloud, radius);
}

// Pose that puts the shape's input coordinates (the points given to
// make_spheropolyhedron) at `position`, rotated by `rotation`.
inline Pose place(const Spheropolyhedron &shape, const Vec3 &position, const Quat &rotation = Quat::Identity())
{
  Pose pose;
  pose.position = position + rotation * shape.input_centroid;
  pose.orientation = rotation * shape.input_rotation;
  return pose;
}

inline Quat rotation_about(const Vec3 &axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

inline Quat random_rotation(std::mt19937_64 &rng)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  Quat q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized();
}

inline double min_gap(const ContactSet &set)
{
  double g = INFINITY;
  for (const auto &p : set) g = std::min(g, p.gap);
  return g;
}

}    // namespace nscd::test
