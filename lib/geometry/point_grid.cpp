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

#include "geometry/point_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nscd {

namespace {
constexpr int kBits = 20;    // per axis in a cell key: up to about 1e6 cells along an axis
}

void PointGrid::build(const std::vector<Vec3> &points, double cell)
{
  if (!(cell > 0.0) || !std::isfinite(cell))
    throw std::invalid_argument("PointGrid: cell size must be finite and > 0");
  points_ = points;
  entries_.clear();
  if (points_.empty()) return;
  Vec3 lo = points_[0], hi = points_[0];
  for (const Vec3 &p : points_) {
    if (!p.allFinite()) throw std::invalid_argument("PointGrid: a point is not finite");
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Cells along the longest axis stay below 2^kBits, so keys never collide.
  cell_ = std::max(cell, (hi - lo).maxCoeff() / double((1 << kBits) - 2));
  origin_ = lo;
  cells_ = ((hi - lo) / cell_).array().floor().cast<int>() + 1;
  entries_.reserve(points_.size());
  for (int i = 0; i < (int) points_.size(); i++) {
    const Eigen::Array3i c = cell_of(points_[i]);
    entries_.push_back({key_of(c.x(), c.y(), c.z()), i});
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry &a, const Entry &b) {
    return a.cell != b.cell ? a.cell < b.cell : a.index < b.index;
  });
}

Eigen::Array3i PointGrid::cell_of(const Vec3 &p) const
{
  Eigen::Array3i c;
  for (int d = 0; d < 3; d++) {
    const double u = std::floor((p[d] - origin_[d]) / cell_);
    c[d] = (int) std::clamp(u, 0.0, (double) cells_[d] - 1);
  }
  return c;
}

std::uint64_t PointGrid::key_of(int x, int y, int z)
{
  return ((std::uint64_t) x << (2 * kBits)) | ((std::uint64_t) y << kBits) | (std::uint64_t) z;
}

std::pair<std::size_t, std::size_t> PointGrid::bucket(std::uint64_t key) const
{
  const auto first = std::lower_bound(entries_.begin(), entries_.end(), key,
                                      [](const Entry &e, std::uint64_t k) { return e.cell < k; });
  auto last = first;
  while (last != entries_.end() && last->cell == key) ++last;
  return {(std::size_t) (first - entries_.begin()), (std::size_t) (last - entries_.begin())};
}

}    // namespace nscd
