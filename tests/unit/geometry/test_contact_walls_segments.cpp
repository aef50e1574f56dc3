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

// Walls (plane, inside of a cylinder) and wire segments, against closed-form answers.
#include "geometry/contact.h"
#include "geometry/feature_key.h"
#include "shapes_for_tests.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace nscd {
namespace {

using test::make_box;
using test::place;
using test::rotation_about;

constexpr double kTol = 1e-12;
const double kPi = std::acos(-1.0);

bool has_point_at(const ContactSet &set, const Vec3 &where)
{
  return std::any_of(set.begin(), set.end(), [&](const ContactPoint &p) { return (p.point - where).norm() < 1e-9; });
}

TEST(ContactPlane, BoxFaceOnPlaneGivesFourCorners)
{
  const double r = 0.1, g = 0.02;
  const auto box = make_box(1, 0.5, 0.25, r);
  ContactWorkspace ws;
  const PlaneWall floor{Vec3(0, 0, -1), Vec3(0, 0, 2)};    // normal need not be unit
  const auto set = contact_grain_plane(box, place(box, Vec3(3, 4, -1 + 0.25 + r + g)), floor, 0.05, ws);
  ASSERT_EQ(set.count, 4);
  for (const auto &p : set) {
    EXPECT_NEAR(p.gap, g, kTol);
    EXPECT_NEAR((p.normal - Vec3::UnitZ()).norm(), 0.0, kTol);
    EXPECT_EQ(key_feature_j(p.key), wall_feature());
  }
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) EXPECT_TRUE(has_point_at(set, Vec3(3 + sx, 4 + 0.5 * sy, -1 + 0.5 * g)));
}

// Box tilted by a small angle: the low edge touches; the high edge's corners are reported
// only when their gap is below the activation distance.
TEST(ContactPlane, TiltedBoxAndActivation)
{
  const double r = 0.1, tilt = 0.01;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const PlaneWall floor{Vec3::Zero(), Vec3::UnitZ()};
  const Quat q = rotation_about(Vec3::UnitY(), tilt);
  // Lowest corners (x = -1 side after rotation) at height: centre - (cos + sin).
  const double centre = std::cos(tilt) + std::sin(tilt) + r;
  const double high_gap = 2 * std::sin(tilt);
  const auto touching = contact_grain_plane(box, place(box, Vec3(0, 0, centre), q), floor, 1e-12, ws);
  ASSERT_EQ(touching.count, 2);
  for (const auto &p : touching) EXPECT_NEAR(p.gap, 0.0, kTol);
  const auto rocking = contact_grain_plane(box, place(box, Vec3(0, 0, centre), q), floor, 1.01 * high_gap, ws);
  ASSERT_EQ(rocking.count, 4);
  std::vector<double> gaps;
  for (const auto &p : rocking) gaps.push_back(p.gap);
  std::sort(gaps.begin(), gaps.end());
  EXPECT_NEAR(gaps[0], 0.0, kTol);
  EXPECT_NEAR(gaps[3], high_gap, kTol);
}

TEST(ContactPlane, SphereAndErrors)
{
  const auto ball = test::make_sphere(0.5);
  ContactWorkspace ws;
  const PlaneWall wall{Vec3(1, 0, 0), Vec3(-1, 0, 0)};    // domain at x < 1
  const auto set = contact_grain_plane(ball, place(ball, Vec3(0.7, 2, 3)), wall, 0.0, ws);
  ASSERT_EQ(set.count, 1);
  EXPECT_NEAR(set[0].gap, -0.2, kTol);
  EXPECT_NEAR((set[0].normal + Vec3::UnitX()).norm(), 0.0, kTol);
  EXPECT_NEAR((set[0].point - Vec3(1.1, 2, 3)).norm(), 0.0, kTol);    // midway: 1.2 and 1.0
  EXPECT_THROW(contact_grain_plane(ball, Pose{}, PlaneWall{Vec3::Zero(), Vec3::Zero()}, 0.0, ws), ContactError);
  EXPECT_THROW(contact_grain_plane(ball, Pose{}, wall, -0.1, ws), ContactError);
}

TEST(ContactCylinder, SphereInsideCylinder)
{
  const auto ball = test::make_sphere(0.5);
  ContactWorkspace ws;
  const CylinderWall silo{Vec3(1, 1, 0), Vec3(0, 0, 3), 4.0};
  const Vec3 radial = Vec3(3, 4, 0) / 5.0;
  const auto set = contact_grain_cylinder(ball, place(ball, Vec3(1, 1, 7) + 3.45 * radial), silo, 0.1, ws);
  ASSERT_EQ(set.count, 1);
  EXPECT_NEAR(set[0].gap, 0.05, kTol);
  EXPECT_NEAR((set[0].normal + radial).norm(), 0.0, kTol);
  EXPECT_NEAR((set[0].point - (Vec3(1, 1, 7) + 3.975 * radial)).norm(), 0.0, kTol);
  EXPECT_TRUE(contact_grain_cylinder(ball, place(ball, Vec3(1, 1, 7) + 3.3 * radial), silo, 0.1, ws).empty());
  EXPECT_THROW(contact_grain_cylinder(ball, Pose{}, CylinderWall{Vec3::Zero(), Vec3::UnitZ(), 0.0}, 0.0, ws), ContactError);
}

// A wire node (a sphere) against walls: closed forms, and the same point, normal and gap as
// the grain queries give a one-vertex grain of that radius.
TEST(ContactSphereWall, PlaneAndCylinderMatchClosedFormsAndTheGrainQueries)
{
  ContactWorkspace ws;
  const PlaneWall floor{Vec3(0, 0, 1), Vec3(0, 0, 2)};    // normal not unit: normalised
  const ContactPoint p = contact_sphere_plane(Vec3(3, -2, 1.04), 0.05, floor);
  EXPECT_NEAR(p.gap, -0.01, kTol);
  EXPECT_NEAR((p.normal - Vec3::UnitZ()).norm(), 0.0, kTol);
  EXPECT_NEAR((p.point - Vec3(3, -2, 0.995)).norm(), 0.0, kTol);    // midway: 0.99 and 1.0
  EXPECT_NEAR(contact_sphere_plane(Vec3(0, 0, 3), 0.05, floor).gap, 1.95, kTol);    // far: still reported

  const CylinderWall silo{Vec3(1, 1, 0), Vec3(0, 0, 3), 4.0};
  const Vec3 radial = Vec3(3, 4, 0) / 5.0;
  const ContactPoint c = contact_sphere_cylinder(Vec3(1, 1, 7) + 3.97 * radial, 0.05, silo);
  EXPECT_NEAR(c.gap, -0.02, kTol);
  EXPECT_NEAR((c.normal + radial).norm(), 0.0, kTol);
  EXPECT_NEAR((c.point - (Vec3(1, 1, 7) + 4.01 * radial)).norm(), 0.0, kTol);
  const ContactPoint axis = contact_sphere_cylinder(Vec3(1, 1, -2), 0.05, silo);    // on the axis
  EXPECT_NEAR(axis.gap, 3.95, kTol);
  EXPECT_NEAR(axis.normal.dot(Vec3::UnitZ()), 0.0, kTol);

  for (const Vec3 &centre : {Vec3(0.3, 0.2, 1.01), Vec3(-1, 2, 1.3), Vec3(2.5, 3.2, -4)}) {
    const auto ball = test::make_sphere(0.05);
    const ContactPoint s = contact_sphere_plane(centre, 0.05, floor);
    const ContactSet g = contact_grain_plane(ball, place(ball, centre), floor, 10.0, ws);
    ASSERT_EQ(g.count, 1);
    EXPECT_NEAR(s.gap, g[0].gap, kTol);
    EXPECT_NEAR((s.point - g[0].point).norm(), 0.0, kTol);
    EXPECT_NEAR((s.normal - g[0].normal).norm(), 0.0, kTol);
    const ContactPoint sc = contact_sphere_cylinder(centre, 0.05, silo);
    const ContactSet gc = contact_grain_cylinder(ball, place(ball, centre), silo, 10.0, ws);
    ASSERT_EQ(gc.count, 1);
    EXPECT_NEAR(sc.gap, gc[0].gap, kTol);
    EXPECT_NEAR((sc.point - gc[0].point).norm(), 0.0, kTol);
    EXPECT_NEAR((sc.normal - gc[0].normal).norm(), 0.0, kTol);
  }
  EXPECT_THROW(contact_sphere_plane(Vec3::Zero(), 0.1, PlaneWall{Vec3::Zero(), Vec3::Zero()}), ContactError);
  EXPECT_THROW(contact_sphere_cylinder(Vec3::Zero(), 0.1, CylinderWall{Vec3::Zero(), Vec3::UnitZ(), -1.0}), ContactError);
}

// A box with edges parallel to the axis touches the wall with its two outer vertical
// edges: 4 corners, all at distance sqrt((x+1)^2 + 1) from the axis.
TEST(ContactCylinder, BoxAgainstWall)
{
  const double r = 0.05, R = 5.0;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const CylinderWall silo{Vec3::Zero(), Vec3::UnitZ(), R};
  const double x = std::sqrt((R - r) * (R - r) - 1.0) - 1.0 - 0.01;    // 0.01 off the wall
  const double rho = std::hypot(x + 1, 1.0);
  const auto set = contact_grain_cylinder(box, place(box, Vec3(x, 0, 0)), silo, 0.02, ws);
  ASSERT_EQ(set.count, 4);
  for (const auto &p : set) {
    EXPECT_NEAR(p.gap, R - rho - r, kTol);
    const Vec3 corner_dir = Vec3(x + 1, p.point.y() > 0 ? 1 : -1, 0) / rho;
    EXPECT_NEAR((p.normal + corner_dir).norm(), 0.0, 1e-12);
  }
}

TEST(ContactSegments, CrossedParallelAndZeroLength)
{
  // Perpendicular, 0.5 apart: closest points at the parameters of the crossing.
  const Segment a{Vec3(0, 0, 0), Vec3(2, 0, 0), 0.1}, b{Vec3(0.5, -1, 0.5), Vec3(0.5, 3, 0.5), 0.15};
  EXPECT_FALSE(contact_segments(b, a, 0.2).has_value());
  auto c = contact_segments(b, a, 0.3);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->gap, 0.25, kTol);
  EXPECT_NEAR(c->s_i, 0.25, kTol);
  EXPECT_NEAR(c->s_j, 0.25, kTol);
  EXPECT_NEAR((c->normal - Vec3::UnitZ()).norm(), 0.0, kTol);
  EXPECT_NEAR((c->point - Vec3(0.5, 0, 0.1 + 0.125)).norm(), 0.0, kTol);
  // Parallel overlapping by [1, 2] on a: middle of the overlap.
  const Segment p{Vec3(1, 0.3, 0), Vec3(4, 0.3, 0), 0.1};
  c = contact_segments(p, a, 0.2);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->gap, 0.1, kTol);
  EXPECT_NEAR(c->s_i, 1.0 / 6.0, kTol);
  EXPECT_NEAR(c->s_j, 0.75, kTol);
  EXPECT_NEAR((c->normal - Vec3::UnitY()).norm(), 0.0, kTol);
  // Zero-length segment = sphere: point-segment distance.
  const Segment dot{Vec3(2.3, 0.4, 0), Vec3(2.3, 0.4, 0), 0.2};
  c = contact_segments(dot, a, 0.5);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->gap, 0.5 - 0.3, kTol);
  EXPECT_NEAR(c->s_j, 1.0, kTol);
  EXPECT_NEAR((c->normal - Vec3(0.3, 0.4, 0) / 0.5).norm(), 0.0, kTol);
  // Intersecting axes: gap = -(r_i + r_j), normal along the common perpendicular.
  const Segment cross{Vec3(1, -1, 0), Vec3(1, 1, 0), 0.1};
  c = contact_segments(cross, a, 0.0);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->gap, -0.2, kTol);
  EXPECT_NEAR(std::abs(c->normal.z()), 1.0, kTol);
  EXPECT_THROW(contact_segments(Segment{Vec3(NAN, 0, 0), Vec3::Zero(), 0.1}, a, 0.0), ContactError);
}

TEST(ContactSegmentGrain, FlatOnAFaceGivesBothEndsOfTheTouchingStretch)
{
  const double r = 0.1, rw = 0.05, g = 0.01;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  // Segment from x = 0 to x = 3 along the top face; the face covers x in [0, 1] of it.
  const Segment wire{Vec3(0, 0.2, 1 + r + rw + g), Vec3(3, 0.2, 1 + r + rw + g), rw};
  const SegmentGrainContact c = contact_segment_grain(wire, box, place(box, Vec3::Zero()), 0.05, ws);
  ASSERT_EQ(c.count, 2);
  for (const SegmentContact &p : c) {
    EXPECT_NEAR(p.gap, g, kTol);
    EXPECT_NEAR((p.normal - Vec3::UnitZ()).norm(), 0.0, kTol);
  }
  EXPECT_NEAR(c[0].s_i, 0.0, 1e-12);    // the segment's own end (the node's sphere)
  EXPECT_EQ(segment_part_i(c[0]), SegmentPart::start);
  EXPECT_NEAR((c[0].point - Vec3(0, 0.2, 1 + r + 0.5 * g)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(c[1].s_i, 1.0 / 3.0, 1e-12);    // where it leaves the face
  EXPECT_EQ(segment_part_i(c[1]), SegmentPart::inside);
  EXPECT_NEAR((c[1].point - Vec3(1, 0.2, 1 + r + 0.5 * g)).norm(), 0.0, 1e-12);
}

// A segment of length 1 resting with overlap d on the top face, lifted at its far end by
// the angle a: each end keeps its own gap (closed form: its height above the face), so the
// force of a soft contact moves smoothly onto the lower end as the segment tilts, from flat
// to 0.3 rad (the separating axis stays the face normal while the low end is over the face).
TEST(ContactSegmentGrain, TiltingSegmentKeepsEachEndsOwnGap)
{
  const double r = 0.1, rw = 0.05, d = 1e-3;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  for (double a : {0.0, 1e-9, 1e-6, 1e-4, 5e-4, 9.9e-4, 1.01e-3, 1e-2, 0.3}) {
    const Vec3 p0(-0.5, 0.1, 1 + r + rw - d);
    const Vec3 p1 = p0 + Vec3(std::cos(a), 0, std::sin(a));
    const SegmentGrainContact c = contact_segment_grain({p0, p1, rw}, box, place(box, Vec3::Zero()), 0.0, ws);
    const double far_gap = std::sin(a) - d;
    ASSERT_EQ(c.count, far_gap <= 0.0 ? 2 : 1) << "tilt " << a;
    EXPECT_NEAR(c[0].gap, -d, kTol) << "tilt " << a;
    EXPECT_EQ(segment_part_i(c[0]), SegmentPart::start);
    EXPECT_NEAR(c[0].normal.z(), 1.0, kTol);
    if (c.count == 2) {
      EXPECT_NEAR(c[1].gap, far_gap, kTol) << "tilt " << a;
      EXPECT_EQ(segment_part_i(c[1]), SegmentPart::end);
    }
  }
}

TEST(ContactSegmentGrain, TiltedSegmentTouchesWithItsLowEnd)
{
  const double r = 0.1, rw = 0.05;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const Segment wire{Vec3(0.5, 0, 1 + r + rw - 0.02), Vec3(0.5, 1, 2), rw};
  const SegmentGrainContact c = contact_segment_grain(wire, box, place(box, Vec3::Zero()), 0.0, ws);
  ASSERT_EQ(c.count, 1);
  EXPECT_NEAR(c[0].gap, -0.02, kTol);
  EXPECT_NEAR(c[0].s_i, 0.0, kTol);
  // Segment over the box edge (x = 1, z = 1), along it, at 45 degrees.
  const Vec3 d = Vec3(1, 0, 1).normalized();
  const Vec3 mid = Vec3(1, 0, 1) + (r + rw + 0.03) * d;
  const Segment over_edge{mid - Vec3(0, 0.4, 0), mid + Vec3(0, 0.6, 0), rw};
  const SegmentGrainContact e = contact_segment_grain(over_edge, box, place(box, Vec3::Zero()), 0.1, ws);
  // The whole segment is equally far from the edge (which spans y in [-1, 1]): both ends.
  ASSERT_EQ(e.count, 2);
  for (const SegmentContact &p : e) {
    EXPECT_NEAR(p.gap, 0.03, kTol);
    EXPECT_NEAR((p.normal - d).norm(), 0.0, 1e-9);
  }
  EXPECT_NEAR(e[0].s_i, 0.0, 1e-9);
  EXPECT_NEAR(e[1].s_i, 1.0, 1e-9);
  // Crossing the edge at a right angle: one point, inside the segment.
  const Segment across{mid - Vec3(0.3, 0, -0.3), mid + Vec3(0.5, 0, -0.5), rw};
  const SegmentGrainContact x = contact_segment_grain(across, box, place(box, Vec3::Zero()), 0.1, ws);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR(x[0].gap, 0.03, kTol);
  EXPECT_NEAR(x[0].s_i, 0.3 / 0.8, 1e-9);
  EXPECT_EQ(segment_part_i(x[0]), SegmentPart::inside);
  EXPECT_TRUE(contact_segment_grain(over_edge, box, place(box, Vec3::Zero()), 0.02, ws).empty());
}

TEST(ContactSegments, PartsNameTheEndSpheres)
{
  const Segment a{Vec3(0, 0, 0), Vec3(1, 0, 0), 0.1};
  // b crosses a's middle, then touches a's far end with its own start
  const auto inside = contact_segments(a, Segment{Vec3(0.5, -1, 0.15), Vec3(0.5, 1, 0.15), 0.1}, 0.0);
  ASSERT_TRUE(inside);
  EXPECT_EQ(segment_part_i(*inside), SegmentPart::inside);
  EXPECT_EQ(segment_part_j(*inside), SegmentPart::inside);
  const auto ends = contact_segments(a, Segment{Vec3(1.15, 0, 0), Vec3(2, 0.5, 0), 0.1}, 0.0);
  ASSERT_TRUE(ends);
  EXPECT_EQ(segment_part_i(*ends), SegmentPart::end);
  EXPECT_EQ(segment_part_j(*ends), SegmentPart::start);
}

}    // namespace
}    // namespace nscd
