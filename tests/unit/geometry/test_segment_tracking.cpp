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

// contact_segment_grain_tracked (lib/geometry/segment_tracking.h) against
// contact_segment_grain: the same points, gaps, normals, parameters and keys wherever the
// hint answers, on random grains, boxes, spheres and capsules with segments wandering over
// their surfaces; and the hint must answer most of the time.
#include "geometry/segment_tracking.h"

#include "shapes_for_tests.h"

#include <gtest/gtest.h>

#include <random>

namespace nscd {
namespace {

using test::make_box;
using test::make_capsule;
using test::make_random_grain;
using test::make_sphere;
using test::place;
using test::random_rotation;

struct Agreement {
  int queries = 0, touching = 0, from_hint = 0, touching_from_hint = 0;
  double worst = 0.0;    // largest difference in any compared number, over the length scale
};

// Compares one tracked answer with the direct query; returns the largest difference.
double difference(const TrackedSegmentContact &t, const SegmentGrainContact &d, double scale)
{
  if (t.contact.count != d.count) return INFINITY;
  double worst = 0.0;
  for (int k = 0; k < d.count; ++k) {
    const SegmentContact &p = t.contact[k], &q = d[k];
    if (p.key != q.key) return INFINITY;
    worst = std::max({worst, (p.point - q.point).norm() / scale, (p.normal - q.normal).norm(),
                      std::abs(p.gap - q.gap) / scale, std::abs(p.s_i - q.s_i)});
  }
  return worst;
}

// A segment of the given length wanders in small random steps near the grain's surface
// (its middle held within `reach` of the surface by a pull towards it); every step is
// queried both ways.
void wander(const Spheropolyhedron &shape, const Pose &pose, double length, double r_w, std::mt19937_64 &rng,
            int steps, Agreement &out)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  const ShapeFeatures features(shape);
  const GrainFrame frame(pose);
  ContactWorkspace ws_tracked, ws_direct;
  FeatureHint hint;
  Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
  Vec3 middle = pose.position + (shape.bounding_radius + r_w) * Vec3(normal(rng), normal(rng), normal(rng)).normalized();
  const double activation = r_w, step = 2e-3 * shape.bounding_radius;
  for (int k = 0; k < steps; ++k) {
    const Segment segment{middle - 0.5 * length * direction, middle + 0.5 * length * direction, r_w};
    const TrackedSegmentContact t = contact_segment_grain_tracked(segment, features, frame, activation, hint, ws_tracked);
    const SegmentGrainContact d = contact_segment_grain(segment, shape, pose, activation, ws_direct);
    const double scale = std::max(0.5 * length + r_w, shape.bounding_radius);
    const double diff = difference(t, d, scale);
    out.worst = std::max(out.worst, diff);
    EXPECT_LT(diff, 1e-10) << "step " << k << ": tracked " << t.contact.count << " points (from hint " << t.from_hint
                           << "), direct " << d.count;
    for (const SegmentContact &p : d) EXPECT_GE(p.gap, t.clearance - 1e-12 * scale) << "clearance above a gap";
    out.queries++;
    out.from_hint += t.from_hint;
    if (!d.empty() && d[0].gap <= 0.0) {
      out.touching++;
      out.touching_from_hint += t.from_hint;
    }
    // Drift: random steps, turning slowly, kept near the surface by sliding along the
    // deepest point's normal back to a small overlap.
    middle += step * Vec3(normal(rng), normal(rng), normal(rng));
    direction = (direction + 0.02 * Vec3(normal(rng), normal(rng), normal(rng))).normalized();
    if (!d.empty()) middle += (0.2 * r_w - 0.5 * (d[0].gap + d[d.count - 1].gap)) * d[0].normal * 0.5;
    else middle += (pose.position - middle).normalized() * step * 3.0;
  }
}

TEST(SegmentTracking, AgreesWithTheDirectQueryOnRandomGrains)
{
  std::mt19937_64 rng(2027);
  Agreement a;
  for (int g = 0; g < 40; ++g) {
    const Spheropolyhedron shape = make_random_grain(rng, 12 + g % 13, 0.03);
    const Pose pose = place(shape, Vec3(0.3 * g, -0.1 * g, 0.2), random_rotation(rng));
    for (double length : {0.05, 0.2, 0.6}) wander(shape, pose, length, 0.02, rng, 400, a);
  }
  std::printf("random grains: %d queries, %d touching, %.1f %% of touching answered from the hint, worst "
              "difference %.2e\n", a.queries, a.touching, 100.0 * a.touching_from_hint / a.touching, a.worst);
  EXPECT_GT(a.touching, 5000);
  EXPECT_GT(a.touching_from_hint, 0.9 * a.touching);
}

TEST(SegmentTracking, AgreesWithTheDirectQueryOnBoxesSpheresAndCapsules)
{
  std::mt19937_64 rng(11);
  const std::vector<Spheropolyhedron> shapes = {make_box(0.5, 0.4, 0.3, 0.02), make_sphere(0.4), make_capsule(0.3, 0.1)};
  for (const Spheropolyhedron &shape : shapes) {
    Agreement a;
    for (int g = 0; g < 20; ++g) {
      const Pose pose = place(shape, Vec3(1.0, 2.0, -0.5), random_rotation(rng));
      for (double length : {0.05, 0.3}) wander(shape, pose, length, 0.02, rng, 300, a);
    }
    std::printf("%zu-vertex shape: %d touching, %.1f %% from the hint, worst difference %.2e\n", shape.vertices.size(),
                a.touching, 100.0 * a.touching_from_hint / std::max(1, a.touching), a.worst);
    EXPECT_GT(a.touching, 200);
    EXPECT_GT(a.touching_from_hint, 0.9 * a.touching);
  }
}

// A segment lying on a box face, slid over the face's edge: both ends from the face, then
// the stretch clipped at the edge, then one point at the edge, each in closed form.
TEST(SegmentTracking, SegmentSlidingOffAFaceIsClippedAtItsEdge)
{
  const double r = 0.02, r_w = 0.01, depth = 1e-3;
  const Spheropolyhedron box = make_box(0.5, 0.5, 0.5, r);
  const Pose pose = place(box, Vec3::Zero());
  const ShapeFeatures features(box);
  ContactWorkspace ws;
  FeatureHint hint;
  const double z = 0.5 + r + r_w - depth;
  // 1) whole segment on the top face, its right end a little higher: two ends
  const double tilt = 1e-3;
  auto segment_at = [&](double x0) { return Segment{Vec3(x0, 0, z), Vec3(x0 + 0.2, 0, z + 0.2 * tilt), r_w}; };
  TrackedSegmentContact t = contact_segment_grain_tracked(segment_at(0.1), features, GrainFrame(pose), r_w, hint, ws);
  ASSERT_EQ(t.contact.count, 2);
  t = contact_segment_grain_tracked(segment_at(0.1), features, GrainFrame(pose), r_w, hint, ws);
  EXPECT_TRUE(t.from_hint);
  EXPECT_NEAR(t.contact[0].gap, -depth, 1e-14);
  EXPECT_NEAR(t.contact[1].gap, -depth + 0.2 * tilt, 1e-14);
  EXPECT_NEAR(t.clearance, -depth, 1e-14);
  // 2) right end beyond the edge at x = 0.5: the stretch ends at the edge
  t = contact_segment_grain_tracked(segment_at(0.4), features, GrainFrame(pose), r_w, hint, ws);
  EXPECT_TRUE(t.from_hint);
  ASSERT_EQ(t.contact.count, 2);
  EXPECT_NEAR(t.contact[1].point.x(), 0.5, 1e-12);
  EXPECT_NEAR(t.contact[1].s_i, 0.5, 1e-12);
  EXPECT_NEAR(t.contact[1].gap, -depth + 0.1 * tilt, 1e-14);
}

// An element longer than a face lies across it, tilted a little: within the face-alignment
// tolerance of contact_segment_grain (1.4e-4 rad) it touches with the stretch clipped at
// both sides of the face, beyond it at one point at the lower edge; both from the hint.
TEST(SegmentTracking, ElementAcrossANarrowFaceIsClippedAtBothSidesOrTouchesAnEdge)
{
  const double r = 0.02, r_w = 0.01, depth = 1e-3;
  const Spheropolyhedron box = make_box(0.1, 0.5, 0.5, r);    // top face 0.2 wide in x
  const Pose pose = place(box, Vec3::Zero());
  const ShapeFeatures features(box);
  ContactWorkspace ws_tracked, ws_direct;
  for (double slope : {1e-5, 1e-3}) {
    FeatureHint hint;
    const double z = 0.5 + r + r_w - depth;
    const Segment segment{Vec3(-0.2, 0, z), Vec3(0.2, 0, z + 0.4 * slope), r_w};
    contact_segment_grain_tracked(segment, features, GrainFrame(pose), r_w, hint, ws_tracked);
    const TrackedSegmentContact t = contact_segment_grain_tracked(segment, features, GrainFrame(pose), r_w, hint, ws_tracked);
    const SegmentGrainContact d = contact_segment_grain(segment, box, pose, r_w, ws_direct);
    EXPECT_TRUE(t.from_hint) << "slope " << slope;
    EXPECT_LT(difference(t, d, 0.5), 1e-12) << "slope " << slope;
    ASSERT_EQ(t.contact.count, slope < 1e-4 ? 2 : 1) << "slope " << slope;
    EXPECT_NEAR(t.contact[0].point.x(), -0.1, 1e-4) << "slope " << slope;    // at the lower edge
  }
}

// The same element tilted through the face-alignment tolerance itself (1 - cos = 1e-8, a
// tilt of 1.41421e-4): the tracked answer follows contact_segment_grain's branch on both
// sides, up to a band of 1e-4 of the tolerance where it asks contact_segment_grain.
TEST(SegmentTracking, AtTheFaceAlignmentToleranceTheTrackedAnswerTakesTheSameBranch)
{
  const double r = 0.02, r_w = 0.01, depth = 1e-3;
  const Spheropolyhedron box = make_box(0.1, 0.5, 0.5, r);
  const Pose pose = place(box, Vec3::Zero());
  const ShapeFeatures features(box);
  ContactWorkspace ws_tracked, ws_direct;
  int from_hint = 0, both_points = 0, steps = 0;
  for (double tilt = 1.405e-4; tilt <= 1.424e-4; tilt += 1e-8, ++steps) {
    const double z = 0.5 + r + r_w - depth;
    FeatureHint hint;    // from the top face, as a run finds it
    contact_segment_grain_tracked({Vec3(-0.05, 0, z), Vec3(0.05, 0, z), r_w}, features, GrainFrame(pose), r_w, hint, ws_tracked);
    const Segment segment{Vec3(-0.2, 0, z), Vec3(0.2, 0, z + 0.4 * std::tan(tilt)), r_w};
    const TrackedSegmentContact t = contact_segment_grain_tracked(segment, features, GrainFrame(pose), r_w, hint, ws_tracked);
    const SegmentGrainContact d = contact_segment_grain(segment, box, pose, r_w, ws_direct);
    EXPECT_LT(difference(t, d, 0.5), 1e-12) << "tilt " << tilt;
    from_hint += t.from_hint;
    both_points += d.count == 2;
  }
  EXPECT_GT(both_points, 0);                // face patch below the tolerance
  EXPECT_LT(both_points, steps);            // one point at the edge above it
  EXPECT_GE(from_hint, steps - 3);          // the band is ~3e-12 rad wide here
}

}    // namespace
}    // namespace nscd
