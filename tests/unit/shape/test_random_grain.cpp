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

// Random ballast grains: reproducibility, the drawn sizes, vertex counts and axis ratios,
// and parameter validation.
#include "shape/random_grain.h"
#include "shape_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace nscd;
using namespace nscd::test;

namespace {

double equivalent_diameter(const Spheropolyhedron &s) { return std::cbrt(6 * s.volume / kPi); }

// Extent of the core along body axis k.
double extent(const Spheropolyhedron &s, int k)
{
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto &v : s.vertices) {
    lo = std::min(lo, v[k]);
    hi = std::max(hi, v[k]);
  }
  return hi - lo;
}

}    // namespace

TEST(RandomGrain, SameSeedSameGrainsDifferentSeedDifferentGrains)
{
  RandomGrainParams params;
  params.radius = 0.02;
  ShapeLibrary a, b, c;
  add_random_grains(a, params, 6, 2026);
  add_random_grains(b, params, 6, 2026);
  add_random_grains(c, params, 6, 2027);
  EXPECT_EQ(a.serialize(), b.serialize());
  EXPECT_NE(a.shape(1).vertices[0], c.shape(1).vertices[0]);
  EXPECT_EQ(a.name(3), "grain_2026_3");
}

TEST(RandomGrain, GrainDependsOnlyOnSeedAndIndex)
{
  RandomGrainParams params;
  ShapeLibrary few, many;
  add_random_grains(few, params, 3, 11);
  add_random_grains(many, params, 10, 11);
  for (int id = 1; id <= 3; ++id) EXPECT_EQ(few.shape(id).vertices, many.shape(id).vertices);
}

TEST(RandomGrain, SizesVertexCountsAndRadiusFollowTheParameters)
{
  RandomGrainParams params;
  params.min_vertices = 8;
  params.max_vertices = 14;
  params.min_diameter = 0.5;
  params.max_diameter = 1.5;
  params.radius = 0.05;
  ShapeLibrary library;
  const int n = 300;
  EXPECT_EQ(add_random_grains(library, params, n, 5), 1);
  double mean = 0;
  std::vector<int> vertex_histogram(params.max_vertices + 1, 0);
  for (int id = 1; id <= n; ++id) {
    const auto &s = library.shape(id);
    EXPECT_EQ(s.radius, params.radius);
    const double d = equivalent_diameter(s);
    EXPECT_GE(d, params.min_diameter * (1 - 1e-12));
    EXPECT_LE(d, params.max_diameter * (1 + 1e-12));
    mean += d / n;
    // Points on a strictly convex surface are all hull vertices.
    ASSERT_GE(static_cast<int>(s.vertices.size()), params.min_vertices);
    ASSERT_LE(static_cast<int>(s.vertices.size()), params.max_vertices);
    vertex_histogram[s.vertices.size()]++;
  }
  // Uniform diameters: mean 1, standard error (1/sqrt(12))/sqrt(n).
  EXPECT_NEAR(mean, 1.0, 4 / std::sqrt(12.0 * n));
  for (int k = params.min_vertices; k <= params.max_vertices; ++k) EXPECT_GT(vertex_histogram[k], 0) << k;
}

TEST(RandomGrain, VolumeIsTheDrawnEquivalentSphereExactly)
{
  // With min = max diameter every grain has exactly that equivalent diameter.
  RandomGrainParams params;
  params.min_diameter = params.max_diameter = 2.0;
  params.radius = 0.3;
  for (int index = 0; index < 10; ++index) {
    const auto s = random_grain(params, 99, index);
    EXPECT_NEAR(s.volume, kPi / 6 * 8, 1e-13 * s.volume);
  }
}

TEST(RandomGrain, ShapeFollowsTheAxisRatios)
{
  // Many points: the hull approaches the ellipsoid, extents approach 2 : 2 b/a : 2 c/a.
  RandomGrainParams params;
  params.min_vertices = params.max_vertices = 400;
  params.ratio_b = 0.7;
  params.ratio_c = 0.4;
  const auto s = random_grain(params, 1, 0);
  const double a = extent(s, 0);
  EXPECT_NEAR(extent(s, 1) / a, 0.7, 0.03);
  EXPECT_NEAR(extent(s, 2) / a, 0.4, 0.03);
}

TEST(RandomGrain, RatioSpreadVariesTheGrainShapes)
{
  RandomGrainParams params;
  params.min_vertices = params.max_vertices = 200;
  params.ratio_b = 0.8;
  params.ratio_c = 0.5;
  params.ratio_spread = 0.3;
  double lo = HUGE_VAL, hi = 0;
  for (int index = 0; index < 40; ++index) {
    const auto s = random_grain(params, 3, index);
    const double ratio = extent(s, 2) / extent(s, 0);
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  EXPECT_LT(lo, 0.45);    // without spread every ratio would be close to 0.5
  EXPECT_GT(hi, 0.55);
  EXPECT_GT(lo, 0.5 * 0.7 - 0.05);
}

TEST(RandomGrain, FourVertexGrainsAreNotSlivers)
{
  RandomGrainParams params;
  params.min_vertices = params.max_vertices = 4;
  for (int index = 0; index < 50; ++index) {
    const auto s = random_grain(params, 8, index);
    EXPECT_EQ(s.vertices.size(), 4u);
    EXPECT_GT(s.principal_inertia[0], 0.02 * s.principal_inertia[2]);
  }
}

TEST(RandomGrain, BadParametersAreRejected)
{
  auto error_for = [](auto change) {
    RandomGrainParams params;
    change(params);
    try {
      ShapeLibrary library;
      add_random_grains(library, params, 1, 1);
    } catch (const ShapeError &e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto contains = [](const std::string &message, const std::string &part) {
    return message.find(part) != std::string::npos;
  };
  EXPECT_TRUE(contains(error_for([](auto &p) { p.min_vertices = 3; }), "min vertices 3 is below 4"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.max_vertices = 10; }), "max vertices 10 is below min vertices 12"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.max_vertices = 20000; }), "above 10000"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.min_diameter = 0; }), "min diameter 0 is not a positive number"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.min_diameter = NAN; }), "min diameter nan"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.max_diameter = 0.5; }), "max diameter 0.5 is below min diameter 1"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.ratio_b = 1.2; }), "axis ratio b/a 1.2 is outside (0, 1]"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.ratio_c = 0; }), "axis ratio c/a 0 is outside (0, 1]"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.ratio_spread = 1; }), "spread 1 is outside [0, 1)"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.radius = -1; }), "rounding radius -1 is invalid"));
  EXPECT_TRUE(contains(error_for([](auto &p) { p.radius = 0.5; }), "give r < DMIN / 2"));
  ShapeLibrary library;
  try {
    add_random_grains(library, RandomGrainParams(), 0, 1);
    ADD_FAILURE();
  } catch (const ShapeError &e) {
    EXPECT_TRUE(contains(e.what(), "count 0 must be at least 1"));
  }
}
