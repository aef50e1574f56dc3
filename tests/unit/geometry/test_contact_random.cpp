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

// Random grains in random poses (fixed seeds): the gap against independent brute-force
// references, symmetry under swapping i and j, determinism, no NaN, and keys that stay
// put under tiny motions.
#include "geometry/contact.h"
#include "geometry/feature_key.h"
#include "shapes_for_tests.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace nscd {
namespace {

using test::place;

struct WorldCore {
  std::vector<Vec3> v;
  std::vector<std::vector<Vec3>> faces;    // polygons, world
  std::vector<Vec3> normals;
  std::vector<std::array<int, 2>> edges;
};

WorldCore to_world(const Spheropolyhedron &s, const Pose &pose)
{
  WorldCore w;
  for (const auto &v : s.vertices) w.v.push_back(pose.to_world(v));
  for (const auto &f : s.faces) {
    std::vector<Vec3> poly;
    for (int k : f.vertices) poly.push_back(w.v[k]);
    w.faces.push_back(poly);
    w.normals.push_back(pose.orientation * f.normal);
  }
  w.edges = s.edges;
  return w;
}

// Reference 1 (separated cores): the minimum over all vertex-face and edge-edge pairs,
// written independently of the library (plain projections and a dense segment search).
double segment_distance_reference(const Vec3 &a0, const Vec3 &a1, const Vec3 &b0, const Vec3 &b1)
{
  // Convex in (s, t): golden-section in s of the exact point-segment distance in t.
  auto point_segment = [&](const Vec3 &p) {
    const Vec3 d = b1 - b0;
    const double t = std::clamp((p - b0).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - (b0 + t * d)).norm();
  };
  double lo = 0, hi = 1;
  const double phi = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 90; ++it) {    // 0.618^90 ~ 1e-19
    const double m1 = hi - phi * (hi - lo), m2 = lo + phi * (hi - lo);
    if (point_segment(a0 + m1 * (a1 - a0)) < point_segment(a0 + m2 * (a1 - a0))) hi = m2;
    else lo = m1;
  }
  return point_segment(a0 + 0.5 * (lo + hi) * (a1 - a0));
}

double vertex_face_reference(const Vec3 &p, const std::vector<Vec3> &poly, const Vec3 &n)
{
  const double h = n.dot(p - poly[0]);
  const Vec3 q = p - h * n;
  for (size_t k = 0; k < poly.size(); ++k) {
    const Vec3 &a = poly[k], &b = poly[(k + 1) % poly.size()];
    if ((b - a).cross(q - a).dot(n) < 0) return std::numeric_limits<double>::infinity();
  }
  return std::abs(h);
}

double brute_force_distance(const WorldCore &a, const WorldCore &b)
{
  double d = std::numeric_limits<double>::infinity();
  for (const auto &ea : a.edges)
    for (const auto &eb : b.edges)
      d = std::min(d, segment_distance_reference(a.v[ea[0]], a.v[ea[1]], b.v[eb[0]], b.v[eb[1]]));
  for (const auto &p : a.v)
    for (size_t f = 0; f < b.faces.size(); ++f) d = std::min(d, vertex_face_reference(p, b.faces[f], b.normals[f]));
  for (const auto &p : b.v)
    for (size_t f = 0; f < a.faces.size(); ++f) d = std::min(d, vertex_face_reference(p, a.faces[f], a.normals[f]));
  return d;
}

// Reference 2 (overlapping cores): the signed separation along u is
// min_b(b.u) - max_a(a.u); the penetration depth is minus its maximum over directions.
// Every direction gives a lower bound of the true separation...
double separation_along(const WorldCore &a, const WorldCore &b, const Vec3 &u)
{
  double amax = -INFINITY, bmin = INFINITY;
  for (const auto &p : a.v) amax = std::max(amax, p.dot(u));
  for (const auto &p : b.v) bmin = std::min(bmin, p.dot(u));
  return bmin - amax;
}

// ...and the maximum over all face normals and all edge-pair cross products (no pruning)
// is the exact one.
double brute_force_separation(const WorldCore &a, const WorldCore &b)
{
  double best = -INFINITY;
  auto consider = [&](const Vec3 &u) {
    if (u.norm() < 1e-9) return;
    const Vec3 n = u.normalized();
    best = std::max({best, separation_along(a, b, n), separation_along(a, b, -n)});
  };
  for (const auto &n : a.normals) consider(n);
  for (const auto &n : b.normals) consider(n);
  for (const auto &ea : a.edges)
    for (const auto &eb : b.edges) consider((a.v[ea[1]] - a.v[ea[0]]).cross(b.v[eb[1]] - b.v[eb[0]]));
  return best;
}

double fibonacci_best_separation(const WorldCore &a, const WorldCore &b, int n)
{
  double best = -INFINITY;
  const double golden = std::acos(-1.0) * (3 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1 - 2 * (k + 0.5) / n, rho = std::sqrt(1 - z * z);
    best = std::max(best, separation_along(a, b, Vec3(rho * std::cos(golden * k), rho * std::sin(golden * k), z)));
  }
  return best;
}

struct RandomPair {
  Spheropolyhedron a, b;
  Pose pa, pb;
};

// Grains of 12-24 vertices; j placed along a random direction at a random core distance
// (bisection on the brute-force separation) between overlap and beyond activation.
class RandomPairs : public ::testing::Test {
 protected:
  static constexpr int kPairs = 150;
  static constexpr double kActivation = 0.05;

  static void SetUpTestSuite()
  {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> npoints(12, 24);
    for (int k = 0; k < kPairs; ++k) {
      RandomPair p;
      p.a = test::make_random_grain(rng, npoints(rng), 0.02 + 0.03 * unit(rng));
      p.b = test::make_random_grain(rng, npoints(rng), 0.02 + 0.03 * unit(rng));
      p.pa = place(p.a, Vec3(unit(rng), unit(rng), unit(rng)), test::random_rotation(rng));
      const Quat qb = test::random_rotation(rng);
      Vec3 dir(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
      dir.normalize();
      // Core separation target: mostly near contact, some overlapping cores.
      const double target = -0.08 + 0.2 * unit(rng) - p.a.radius - p.b.radius;
      const double wanted = target + p.a.radius + p.b.radius;
      double lo = 0, hi = 5;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        const Pose pb = place(p.b, p.pa.position + mid * dir, qb);
        (brute_force_separation(to_world(p.a, p.pa), to_world(p.b, pb)) < wanted ? lo : hi) = mid;
      }
      p.pb = place(p.b, p.pa.position + hi * dir, qb);
      pairs.push_back(p);
    }
  }
  static std::vector<RandomPair> pairs;
};
std::vector<RandomPair> RandomPairs::pairs;

// Exact signed core distance by the references, minus the radii.
double reference_gap(const RandomPair &p)
{
  const WorldCore a = to_world(p.a, p.pa), b = to_world(p.b, p.pb);
  const double separation = brute_force_separation(a, b);
  const double core = separation > 0 ? brute_force_distance(a, b) : separation;
  return core - p.a.radius - p.b.radius;
}

TEST_F(RandomPairs, MinimumGapMatchesBruteForce)
{
  ContactWorkspace ws;
  int overlapping = 0, reported = 0;
  for (const auto &p : pairs) {
    const double ref = reference_gap(p);
    const auto set = contact_grains(p.a, p.pa, p.b, p.pb, kActivation, ws);
    if (ref + p.a.radius + p.b.radius < 0) ++overlapping;
    if (ref < kActivation - 1e-9) {
      ASSERT_GT(set.count, 0) << "reference gap " << ref;
      ++reported;
      // The deepest point is exact (1e-9 of the unit grain size) ...
      EXPECT_NEAR(test::min_gap(set), ref, 1e-9);
    } else if (ref > kActivation + 1e-9) {
      EXPECT_EQ(set.count, 0);
    }
    for (const auto &c : set) {
      // ... and no point claims more overlap than there is.
      EXPECT_GE(c.gap, ref - 1e-9);
      EXPECT_TRUE(c.point.allFinite() && c.normal.allFinite() && std::isfinite(c.gap));
      EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
    }
  }
  EXPECT_GT(reported, kPairs / 2);
  EXPECT_GT(overlapping, 5);    // the separating-axis path is exercised
}

// Overlapping cores: the depth is bounded by any sampled direction (a check of the
// brute-force reference itself, independent of the candidate axes).
TEST_F(RandomPairs, PenetrationDepthIsBelowEverySampledDirection)
{
  for (const auto &p : pairs) {
    const WorldCore a = to_world(p.a, p.pa), b = to_world(p.b, p.pb);
    const double exact = brute_force_separation(a, b);
    if (exact > 0) continue;
    const double sampled = fibonacci_best_separation(a, b, 4000);
    EXPECT_GE(exact, sampled - 1e-12);
    EXPECT_LT(exact - sampled, 0.06);    // 4000 directions: ~0.06 rad apart, grains of size ~1
  }
}

// Cores inside each other (deeper than the two roundings): the whole pair has one normal,
// its penetration axis, even with speculative points on; a point carrying the normal of a
// face it lies over would lock the pair or push it through itself.
TEST_F(RandomPairs, IntersectingCoresGiveOneNormal)
{
  ContactWorkspace ws;
  int checked = 0;
  for (const auto &p : pairs) {
    const auto set = contact_grains(p.a, p.pa, p.b, p.pb, kActivation, ws, kActivation);
    if (set.count == 0 || test::min_gap(set) >= -(p.a.radius + p.b.radius)) continue;
    ++checked;
    for (const auto &c : set) EXPECT_NEAR((c.normal - set[0].normal).norm(), 0.0, 1e-9);
  }
  EXPECT_GE(checked, 10);
}

// contact(j, i) describes the same points with opposite normals and swapped keys.
TEST_F(RandomPairs, SwappingIAndJMirrorsTheContact)
{
  ContactWorkspace ws;
  for (const auto &p : pairs) {
    const auto ij = contact_grains(p.a, p.pa, p.b, p.pb, kActivation, ws);
    const auto ji = contact_grains(p.b, p.pb, p.a, p.pa, kActivation, ws);
    ASSERT_EQ(ij.count, ji.count);
    for (const auto &c : ij) {
      const auto match = std::find_if(ji.begin(), ji.end(), [&](const ContactPoint &d) { return d.key == swapped_key(c.key); });
      ASSERT_NE(match, ji.end()) << "no mirrored key";
      EXPECT_NEAR((match->point - c.point).norm(), 0.0, 1e-9);
      EXPECT_NEAR((match->normal + c.normal).norm(), 0.0, 1e-7);
      EXPECT_NEAR(match->gap, c.gap, 1e-9);
    }
  }
}

TEST_F(RandomPairs, DeterministicAndStableUnderTinyMotions)
{
  ContactWorkspace ws, other;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0, 1);
  int compared = 0;
  for (const auto &p : pairs) {
    const auto first = contact_grains(p.a, p.pa, p.b, p.pb, kActivation, ws);
    const auto again = contact_grains(p.a, p.pa, p.b, p.pb, kActivation, other);
    ASSERT_EQ(first.count, again.count);
    for (int k = 0; k < first.count; ++k) {
      EXPECT_EQ(first[k].key, again[k].key);
      EXPECT_EQ(first[k].gap, again[k].gap);    // bit for bit
      EXPECT_EQ(first[k].point, again[k].point);
    }
    // Move j by 1e-9 of its size and turn it by 1e-9 rad.
    Pose moved = p.pb;
    moved.position += 1e-9 * Vec3(normal(rng), normal(rng), normal(rng));
    moved.orientation = (Quat(Eigen::AngleAxisd(1e-9, Vec3(normal(rng), normal(rng), normal(rng)).normalized())) * moved.orientation).normalized();
    const auto nudged = contact_grains(p.a, p.pa, p.b, moved, kActivation, ws);
    // Points right at the activation threshold may come and go; compare the others.
    bool near_threshold = false;
    for (const auto &c : first) near_threshold |= std::abs(c.gap - kActivation) < 1e-7;
    for (const auto &c : nudged) near_threshold |= std::abs(c.gap - kActivation) < 1e-7;
    if (near_threshold) continue;
    ++compared;
    ASSERT_EQ(first.count, nudged.count);
    for (int k = 0; k < first.count; ++k) EXPECT_EQ(first[k].key, nudged[k].key);
  }
  EXPECT_GT(compared, kPairs / 2);
}

}    // namespace
}    // namespace nscd
