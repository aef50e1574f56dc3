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

// Broad phase: points bucketed on a uniform grid, for "which points lie within r of c"
// queries (the wire's contact search: element centres and grain centres).
#pragma once

#include "math/types.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace nscd {

class PointGrid {
 public:
  // Buckets `points` in cubic cells of edge `cell` (> 0; enlarged if the points span more
  // than 2^20 cells along an axis). Keeps a copy of the points.
  void build(const std::vector<Vec3> &points, double cell);

  // Calls visit(index) for every point with |point - centre| <= radius, each exactly once.
  template <class Visit> void for_each_near(const Vec3 &centre, double radius, Visit &&visit) const;

  std::size_t size() const { return points_.size(); }

 private:
  struct Entry {
    std::uint64_t cell;
    int index;
  };
  std::vector<Vec3> points_;
  std::vector<Entry> entries_;    // sorted by cell, then index
  Vec3 origin_ = Vec3::Zero();    // lower corner of cell (0, 0, 0)
  Eigen::Array3i cells_ = Eigen::Array3i::Zero();    // cells per axis holding points
  double cell_ = 1.0;

  // cell of p, clamped to the occupied range (no point lies outside it)
  Eigen::Array3i cell_of(const Vec3 &p) const;
  static std::uint64_t key_of(int x, int y, int z);
  std::pair<std::size_t, std::size_t> bucket(std::uint64_t key) const;    // [first, last)
};

template <class Visit>
void PointGrid::for_each_near(const Vec3 &centre, double radius, Visit &&visit) const
{
  if (points_.empty()) return;
  const double r2 = radius * radius;
  auto test = [&](int i) {
    if ((points_[i] - centre).squaredNorm() <= r2) visit(i);
  };
  const Eigen::Array3i lo = cell_of(centre - Vec3::Constant(radius));
  const Eigen::Array3i hi = cell_of(centre + Vec3::Constant(radius));
  const Eigen::Array3d span = (hi - lo + 1).cast<double>();
  if (span.prod() > (double) entries_.size()) {    // more cells than points: scan the points
    for (int i = 0; i < (int) points_.size(); i++) test(i);
    return;
  }
  for (int x = lo.x(); x <= hi.x(); x++)
    for (int y = lo.y(); y <= hi.y(); y++)
      for (int z = lo.z(); z <= hi.z(); z++) {
        const auto [first, last] = bucket(key_of(x, y, z));
        for (std::size_t e = first; e < last; e++) test(entries_[e].index);
      }
}

}    // namespace nscd
