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

// Helpers shared by the shape tests: reproducible random numbers and geometric oracles
// that do not use the code under test.
#pragma once

#include "math/types.h"
#include "shape/spheropolyhedron.h"

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace nscd::test {

constexpr double kPi = 3.14159265358979323846;

// Uniform in [0, 1) from the raw 64-bit engine output (same on every platform).
inline double uniform01(std::mt19937_64 &rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

inline Vec3 random_in_ball(std::mt19937_64 &rng)
{
  for (;;) {
    const Vec3 p(2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1);
    if (p.squaredNorm() <= 1.0) return p;
  }
}

inline Quat random_rotation(std::mt19937_64 &rng)
{
  Eigen::Vector4d q;
  do {
    q = Eigen::Vector4d(2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1,
                        2 * uniform01(rng) - 1);
  } while (q.norm() < 0.1 || q.norm() > 1.0);
  q.normalize();
  return Quat(q[0], q[1], q[2], q[3]);
}

inline std::vector<Vec3> box_corners(double a, double b, double c, const Vec3 &shift = Vec3::Zero())
{
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(shift + Vec3((i & 1 ? 0.5 : -0.5) * a, (i & 2 ? 0.5 : -0.5) * b, (i & 4 ? 0.5 : -0.5) * c));
  return corners;
}

inline double distance_to_segment(const Vec3 &x, const Vec3 &a, const Vec3 &b)
{
  const Vec3 ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * ab)).norm();
}

// Distance from x to the core polyhedron (0 inside), brute force over faces, using only
// the face lists (not the mass-property code).
inline double distance_to_core(const Spheropolyhedron &s, const Vec3 &x)
{
  bool inside = true;
  for (const auto &f : s.faces) inside = inside && f.normal.dot(x) <= f.offset;
  if (inside) return 0.0;
  double best = HUGE_VAL;
  for (const auto &f : s.faces) {
    const double height = f.normal.dot(x) - f.offset;
    if (height <= 0) continue;    // the closest point lies on a face that x is outside of
    const Vec3 foot = x - height * f.normal;
    bool in_polygon = true;
    const size_t n = f.vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec3 &a = s.vertices[f.vertices[i]], &b = s.vertices[f.vertices[(i + 1) % n]];
      in_polygon = in_polygon && (b - a).cross(foot - a).dot(f.normal) >= 0;
    }
    if (in_polygon) {
      best = std::min(best, height);
      continue;
    }
    for (size_t i = 0; i < n; ++i)
      best = std::min(best, distance_to_segment(x, s.vertices[f.vertices[i]], s.vertices[f.vertices[(i + 1) % n]]));
  }
  return best;
}

}    // namespace nscd::test
