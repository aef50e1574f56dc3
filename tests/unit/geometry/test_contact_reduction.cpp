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

// Point reduction when a patch has more candidates than ContactSet::kMaxPoints: depth
// first. A point that is touching or penetrating must never be dropped in favour of a
// shallower one: the NSCD solver only stops the overlap of the points it is given from
// growing, so a dropped penetrating point sinks further (the resting-pile bug: a grain on
// a plane wall kept 4 shallow far vertices for patch area and let its penetrating
// vertices sink from 0.005 to 0.03 over 1300 steps).
#include "geometry/contact.h"
#include "geometry/feature_key.h"
#include "shapes_for_tests.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace nscd {
namespace {

using test::place;
using test::rotation_about;

const double kPi = std::acos(-1.0);

bool has_key(const ContactSet &set, std::uint64_t key)
{
  return std::any_of(set.begin(), set.end(), [&](const ContactPoint &p) { return p.key == key; });
}

// Keys of the set are distinct.
void expect_unique_keys(const ContactSet &set)
{
  std::vector<std::uint64_t> keys;
  for (const auto &p : set) keys.push_back(p.key);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::unique(keys.begin(), keys.end()), keys.end());
}

// A grain whose bottom is a regular m-gon (radius 1) with its vertices lifted by
// `lift[k]`, closed by a smaller square top: m + 4 vertices, all of them hull vertices.
Spheropolyhedron bumpy_bottom_grain(const std::vector<double> &lift, double radius)
{
  const int m = static_cast<int>(lift.size());
  std::vector<Vec3> pts;
  for (int k = 0; k < m; ++k) {
    const double a = 2 * kPi * k / m;
    pts.emplace_back(std::cos(a), std::sin(a), lift[k]);
  }
  for (int k = 0; k < 4; ++k) {
    const double a = 2 * kPi * k / 4 + 0.3;
    pts.emplace_back(0.4 * std::cos(a), 0.4 * std::sin(a), 0.5);
  }
  return make_spheropolyhedron(pts, radius);
}

// Gap of every core vertex above the plane z = 0 (vertex k has key vertex k / wall).
std::vector<double> vertex_gaps(const Spheropolyhedron &shape, const Pose &pose)
{
  std::vector<double> gaps;
  for (const Vec3 &v : shape.vertices) gaps.push_back(pose.to_world(v).z() - shape.radius);
  return gaps;
}

std::uint64_t wall_key(int vertex) { return make_key(vertex_feature(vertex), wall_feature()); }

// The regression: 8 core vertices at small gaps of both signs within the activation
// distance, against a plane. All 8 fit: all are reported, and so every one with gap <= 0.
TEST(ContactReduction, PlaneKeepsEveryVertexOfAnEightVertexBand)
{
  const double r = 0.05, activation = 0.1;
  const auto grain = bumpy_bottom_grain({0.0, 0.08, -0.004, 0.06, 0.002, 0.09, -0.003, 0.07}, r);
  const Pose pose = place(grain, Vec3(0, 0, r - 0.005));
  ContactWorkspace ws;
  const ContactSet set = contact_grain_plane(grain, pose, PlaneWall{Vec3::Zero(), Vec3::UnitZ()}, activation, ws);
  const auto gaps = vertex_gaps(grain, pose);
  int in_band = 0, penetrating = 0;
  for (size_t k = 0; k < gaps.size(); ++k) {
    if (gaps[k] > activation) continue;
    ++in_band;
    penetrating += gaps[k] <= 0.0;
    EXPECT_TRUE(has_key(set, wall_key(static_cast<int>(k)))) << "vertex " << k << " gap " << gaps[k];
  }
  ASSERT_EQ(in_band, 8);
  EXPECT_GE(penetrating, 3);
  EXPECT_EQ(set.count, 8);
  expect_unique_keys(set);
}

// 12 vertices in the band, 5 of them penetrating and clustered on one side, the shallow
// ones spread around: the area rule alone would keep shallow far vertices; depth first
// keeps the 5 penetrating ones and fills the other 3 slots for coverage.
TEST(ContactReduction, PlaneKeepsPenetratingVerticesOverShallowFarOnes)
{
  const double r = 0.05, activation = 0.1;
  const auto grain = bumpy_bottom_grain({-0.004, -0.003, -0.002, 0.09, 0.08, 0.07, 0.06, 0.075, 0.088, 0.07, -0.002, -0.003}, r);
  const Pose pose = place(grain, Vec3(0, 0, r), rotation_about(Vec3(1, 2, 0), 1e-4));
  ContactWorkspace ws;
  const ContactSet set = contact_grain_plane(grain, pose, PlaneWall{Vec3::Zero(), Vec3::UnitZ()}, activation, ws);
  ASSERT_EQ(set.count, ContactSet::kMaxPoints);
  const auto gaps = vertex_gaps(grain, pose);
  int penetrating = 0, in_band = 0;
  for (size_t k = 0; k < gaps.size(); ++k) {
    in_band += gaps[k] <= activation;
    if (gaps[k] > 0.0) continue;
    ++penetrating;
    EXPECT_TRUE(has_key(set, wall_key(static_cast<int>(k)))) << "vertex " << k << " gap " << gaps[k];
  }
  EXPECT_EQ(in_band, 12);
  EXPECT_EQ(penetrating, 5);
  // The penetrating vertices sit around +x; the 3 shallow ones kept span the patch and
  // reach its far side.
  double min_x = 1e9, max_x = -1e9;
  for (const auto &p : set) {
    min_x = std::min(min_x, p.point.x());
    max_x = std::max(max_x, p.point.x());
  }
  EXPECT_LT(min_x, -0.8);
  EXPECT_GT(max_x, 0.9);
  expect_unique_keys(set);
}

// Random grains (12-20 vertices, r = 0.05) resting on a plane: a face turned down, tilted
// by up to 0.03 rad, lowest vertex 0 to 0.01 into the wall; activation 0.1 (the LAMMPS
// case) and 0.4 (often more vertices than the capacity in the band, so the reduction runs).
// No vertex with gap <= 0 is ever missing; when the band fits, every vertex in it is
// reported; otherwise the set is full.
TEST(ContactReduction, RandomGrainsRestingOnAPlaneNeverDropAPenetratingVertex)
{
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> count(12, 20);
  const double r = 0.05;
  const PlaneWall floor{Vec3::Zero(), Vec3::UnitZ()};
  ContactWorkspace ws;
  int reduced = 0, cases = 0;
  for (int g = 0; g < 60; ++g) {
    const auto grain = test::make_random_grain(rng, count(rng), r);
    const double activation = g % 2 ? 0.4 : 0.1;
    for (int trial = 0; trial < 40; ++trial, ++cases) {
      const Vec3 &down = grain.faces[static_cast<size_t>(unit(rng) * grain.faces.size()) % grain.faces.size()].normal;
      const Vec3 axis = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, 0.0).normalized();
      Pose pose;
      pose.orientation = Quat(Eigen::AngleAxisd(0.03 * unit(rng), axis)) * Quat::FromTwoVectors(down, -Vec3::UnitZ());
      double lowest = 1e300;
      for (const Vec3 &v : grain.vertices) lowest = std::min(lowest, (pose.orientation * v).z());
      pose.position = Vec3(unit(rng), unit(rng), -lowest + r - 0.01 * unit(rng));
      const ContactSet set = contact_grain_plane(grain, pose, floor, activation, ws);
      const auto gaps = vertex_gaps(grain, pose);
      int in_band = 0, penetrating = 0;
      for (double gap : gaps) {
        in_band += gap <= activation;
        penetrating += gap <= 0.0;
      }
      ASSERT_LE(penetrating, ContactSet::kMaxPoints) << "grain " << g << " trial " << trial;
      EXPECT_EQ(set.count, std::min(in_band, ContactSet::kMaxPoints));
      reduced += in_band > ContactSet::kMaxPoints;
      for (size_t k = 0; k < gaps.size(); ++k) {
        const bool kept = has_key(set, wall_key(static_cast<int>(k)));
        if (gaps[k] <= 0.0 || in_band <= ContactSet::kMaxPoints) {
          EXPECT_EQ(kept, gaps[k] <= activation) << "grain " << g << " trial " << trial << " vertex " << k << " gap " << gaps[k];
        }
      }
      for (const auto &p : set) EXPECT_LE(p.gap, activation);
      expect_unique_keys(set);
    }
  }
  // The sweep must exercise the reduction, not only the cases that fit.
  EXPECT_GT(reduced, cases / 12) << "of " << cases;
}

// The same resting sweep inside a cylinder: the wall is curved, the rule the same.
TEST(ContactReduction, RandomGrainsAgainstACylinderNeverDropAPenetratingVertex)
{
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = 0.05, activation = 0.1, R = 4.0;
  const CylinderWall silo{Vec3::Zero(), Vec3::UnitZ(), R};
  ContactWorkspace ws;
  for (int g = 0; g < 40; ++g) {
    const auto grain = test::make_random_grain(rng, 12 + g % 9, r);
    for (int trial = 0; trial < 20; ++trial) {
      // A face turned outwards (+x), slightly tilted; then slid out until the outermost
      // vertex is 0 to 0.01 into the wall.
      const Vec3 &out = grain.faces[static_cast<size_t>(unit(rng) * grain.faces.size()) % grain.faces.size()].normal;
      const Vec3 axis = Vec3(0.0, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
      Pose pose;
      pose.orientation = Quat(Eigen::AngleAxisd(0.03 * unit(rng), axis)) * Quat::FromTwoVectors(out, Vec3::UnitX());
      const double target = -0.01 * unit(rng);
      auto vertex_gap = [&](const Vec3 &v) {
        const Vec3 w = pose.to_world(v);
        return R - std::hypot(w.x(), w.y()) - r;
      };
      double lo = 0.0, hi = R;
      for (int it = 0; it < 100; ++it) {
        pose.position = Vec3(0.5 * (lo + hi), 0, 0);
        double m = 1e300;
        for (const Vec3 &v : grain.vertices) m = std::min(m, vertex_gap(v));
        (m > target ? lo : hi) = 0.5 * (lo + hi);
      }
      pose.position = Vec3(hi, 0, 0);
      const ContactSet set = contact_grain_cylinder(grain, pose, silo, activation, ws);
      int in_band = 0;
      for (const Vec3 &v : grain.vertices) in_band += vertex_gap(v) <= activation;
      EXPECT_EQ(set.count, std::min(in_band, ContactSet::kMaxPoints));
      for (size_t k = 0; k < grain.vertices.size(); ++k) {
        const double gap = vertex_gap(grain.vertices[k]);
        if (gap <= 0.0) {
          EXPECT_TRUE(has_key(set, wall_key(static_cast<int>(k)))) << "gap " << gap;
        }
      }
      expect_unique_keys(set);
    }
  }
}

// Two regular octagonal prisms, the upper one turned by 22.5 degrees: their faces overlap
// in a regular 16-gon, so clipping gives 16 candidates. The upper prism is tilted by
// 5e-5 rad (still face-aligned) so the corners' gaps differ in sign across the patch.
struct OctagonPatch {
  Spheropolyhedron prism;
  double apothem_radius;    // circumradius of the 16-gon of overlap
  static constexpr double kR = 0.05;

  OctagonPatch()
  {
    std::vector<Vec3> pts;
    for (int k = 0; k < 8; ++k)
      for (double z : {-0.5, 0.5}) pts.emplace_back(std::cos(2 * kPi * k / 8), std::sin(2 * kPi * k / 8), z);
    prism = make_spheropolyhedron(pts, kR);
    apothem_radius = std::cos(kPi / 8) / std::cos(kPi / 16);
  }
  Quat upper_rotation(double tilt) const
  {
    return rotation_about(Vec3::UnitX(), tilt) * rotation_about(Vec3::UnitZ(), kPi / 8);
  }
  // The corners of the 16-gon in the contact plane and the gap there: the height of the
  // upper prism's bottom face above the lower's top face, minus both roundings.
  std::vector<std::pair<Vec3, double>> corners(double centre_gap, double tilt) const
  {
    std::vector<std::pair<Vec3, double>> out;
    for (int k = 0; k < 16; ++k) {
      const double a = (k + 0.5) * kPi / 8;
      const Vec3 p(apothem_radius * std::cos(a), apothem_radius * std::sin(a), 0.5);
      out.emplace_back(p, centre_gap + std::tan(tilt) * p.y());
    }
    return out;
  }
  Pose upper_pose(double centre_gap, double tilt) const
  {
    // Bottom-face centre at height 0.5 + 2r + centre_gap.
    const Quat q = upper_rotation(tilt);
    const Vec3 bottom_centre(0, 0, 0.5 + 2 * kR + centre_gap);
    return place(prism, bottom_centre - q * Vec3(0, 0, -0.5), q);
  }
};

TEST(ContactReduction, SixteenPointFacePatchKeepsThePenetratingCorners)
{
  const OctagonPatch oct;
  const double tilt = 5e-5, centre_gap = 1.5e-5;
  ContactWorkspace ws;
  const Pose lower = place(oct.prism, Vec3::Zero());
  const Pose upper = oct.upper_pose(centre_gap, tilt);
  const ContactSet set = contact_grains(oct.prism, upper, oct.prism, lower, 0.01, ws);
  ASSERT_EQ(set.count, ContactSet::kMaxPoints);
  int penetrating = 0;
  for (const auto &[corner, gap] : oct.corners(centre_gap, tilt)) {
    if (gap > -1e-7) continue;    // clearly penetrating (round-off of the tilt model ~1e-9)
    ++penetrating;
    const bool found = std::any_of(set.begin(), set.end(), [&](const ContactPoint &p) {
      return (Vec3(p.point.x(), p.point.y(), 0) - Vec3(corner.x(), corner.y(), 0)).norm() < 2e-5;
    });
    EXPECT_TRUE(found) << "corner " << corner.transpose() << " gap " << gap;
  }
  EXPECT_GE(penetrating, 4);
  for (const auto &p : set) EXPECT_NEAR((p.normal - Vec3::UnitZ()).norm(), 0.0, 1e-4);
  expect_unique_keys(set);
  // Symmetry: swapping i and j gives the same points, swapped keys.
  const ContactSet swapped = contact_grains(oct.prism, lower, oct.prism, upper, 0.01, ws);
  ASSERT_EQ(swapped.count, set.count);
  for (const auto &p : set)
    EXPECT_TRUE(std::any_of(swapped.begin(), swapped.end(), [&](const ContactPoint &q) {
      return q.key == swapped_key(p.key) && (q.point - p.point).norm() < 1e-9 && std::abs(q.gap - p.gap) < 1e-12;
    })) << "point " << p.point.transpose();
}

// All 16 corners penetrating (more than the capacity): the deepest is kept and the other
// 7 spread over the patch (their polygon covers most of the 16-gon).
TEST(ContactReduction, SixteenPenetratingCornersKeepTheDeepestAndSpread)
{
  const OctagonPatch oct;
  const double tilt = 5e-5, centre_gap = -0.002;
  ContactWorkspace ws;
  const ContactSet set = contact_grains(oct.prism, oct.upper_pose(centre_gap, tilt), oct.prism, place(oct.prism, Vec3::Zero()), 0.0, ws);
  ASSERT_EQ(set.count, ContactSet::kMaxPoints);
  double deepest = 1e9;
  for (const auto &c : oct.corners(centre_gap, tilt)) deepest = std::min(deepest, c.second);
  EXPECT_NEAR(test::min_gap(set), deepest, 1e-8);
  std::vector<Vec3> pts;
  for (const auto &p : set) pts.push_back(p.point);
  std::sort(pts.begin(), pts.end(), [](const Vec3 &a, const Vec3 &b) { return std::atan2(a.y(), a.x()) < std::atan2(b.y(), b.x()); });
  double area = 0;
  for (size_t k = 0; k < pts.size(); ++k) area += 0.5 * pts[k].cross(pts[(k + 1) % pts.size()]).z();
  const double full = 0.5 * 16 * oct.apothem_radius * oct.apothem_radius * std::sin(2 * kPi / 16);
  EXPECT_GT(area, 0.85 * full);
  // Deterministic: the same call gives the same keys in the same order.
  const ContactSet again = contact_grains(oct.prism, oct.upper_pose(centre_gap, tilt), oct.prism, place(oct.prism, Vec3::Zero()), 0.0, ws);
  ASSERT_EQ(again.count, set.count);
  for (int k = 0; k < set.count; ++k) EXPECT_EQ(again[k].key, set[k].key);
}

}    // namespace
}    // namespace nscd
