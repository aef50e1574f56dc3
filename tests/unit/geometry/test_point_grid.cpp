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

// PointGrid against a brute-force scan: every query returns exactly the points within
// the radius, each once.
#include "geometry/point_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using nscd::PointGrid;
using nscd::Vec3;

namespace {
std::vector<int> near_by_grid(const PointGrid &grid, const Vec3 &c, double r)
{
  std::vector<int> found;
  grid.for_each_near(c, r, [&](int i) { found.push_back(i); });
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<int> near_by_scan(const std::vector<Vec3> &points, const Vec3 &c, double r)
{
  std::vector<int> found;
  for (int i = 0; i < (int) points.size(); i++)
    if ((points[i] - c).squaredNorm() <= r * r) found.push_back(i);
  return found;
}
}    // namespace

TEST(PointGrid, MatchesBruteForceOnRandomClouds)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 7.0), radius(0.0, 4.0), cell(0.05, 3.0);
  long total = 0;
  for (int trial = 0; trial < 200; trial++) {
    std::vector<Vec3> points(1 + trial % 150);
    for (Vec3 &p : points) p = Vec3(u(rng), u(rng), 0.1 * u(rng));    // flat clouds too
    PointGrid grid;
    grid.build(points, cell(rng));
    for (int q = 0; q < 20; q++) {
      const Vec3 c(u(rng), u(rng), u(rng));
      const double r = radius(rng);
      const std::vector<int> expected = near_by_scan(points, c, r);
      ASSERT_EQ(near_by_grid(grid, c, r), expected) << "trial " << trial << " query " << q;
      total += (long) expected.size();
    }
  }
  EXPECT_GT(total, 10000);    // the queries did find points
}

TEST(PointGrid, CoincidentPointsAndQueriesOutsideTheCloud)
{
  const std::vector<Vec3> points(5, Vec3(1, 2, 3));
  PointGrid grid;
  grid.build(points, 0.5);
  EXPECT_EQ(near_by_grid(grid, Vec3(1, 2, 3), 0.0).size(), 5u);
  EXPECT_TRUE(near_by_grid(grid, Vec3(10, 2, 3), 8.9).empty());
  EXPECT_EQ(near_by_grid(grid, Vec3(10, 2, 3), 9.0).size(), 5u);
}

TEST(PointGrid, HugeSpanKeepsKeysDistinct)
{
  // 1e9 cells along x: the grid enlarges its cells instead of letting keys collide.
  std::vector<Vec3> points;
  for (int i = 0; i < 100; i++) points.push_back(Vec3(1e7 * i, 0.01 * i, 0.0));
  PointGrid grid;
  grid.build(points, 0.01);
  for (int i = 0; i < 100; i++) EXPECT_EQ(near_by_grid(grid, points[i], 0.5), std::vector<int>{i});
}

TEST(PointGrid, RejectsBadInput)
{
  PointGrid grid;
  EXPECT_THROW(grid.build({Vec3::Zero()}, 0.0), std::invalid_argument);
  EXPECT_THROW(grid.build({Vec3(NAN, 0, 0)}, 1.0), std::invalid_argument);
  grid.build({}, 1.0);
  EXPECT_TRUE(near_by_grid(grid, Vec3::Zero(), 1e9).empty());
}
