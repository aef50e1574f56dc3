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

// Grain-grain contacts with closed-form answers: boxes, rotated boxes, spheres, capsules.
#include "geometry/contact.h"
#include "geometry/feature_key.h"
#include "bar_across_block.h"
#include "shapes_for_tests.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace nscd {
namespace {

using test::make_box;
using test::place;
using test::rotation_about;

constexpr double kTol = 1e-12;     // closed-form geometry, unit-size shapes
const double kPi = std::acos(-1.0);

// True when some point of the set is at `where` (within 1e-9).
bool has_point_at(const ContactSet &set, const Vec3 &where)
{
  return std::any_of(set.begin(), set.end(), [&](const ContactPoint &p) { return (p.point - where).norm() < 1e-9; });
}

void expect_all(const ContactSet &set, const Vec3 &normal, double gap, double tol = kTol)
{
  for (const auto &p : set) {
    EXPECT_NEAR((p.normal - normal).norm(), 0.0, tol) << "normal " << p.normal.transpose();
    EXPECT_NEAR(p.gap, gap, tol);
  }
}

class BoxOnBox : public ::testing::TestWithParam<double> {};

// Unit boxes (half size 1, rounding 0.1), i stacked on j with gap g: the 4 corners.
TEST_P(BoxOnBox, FaceOnFaceGivesTheFourCorners)
{
  const double g = GetParam(), r = 0.1;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const auto set = contact_grains(box, place(box, Vec3(0, 0, 2 + 2 * r + g)), box, place(box, Vec3::Zero()), 0.1, ws);
  ASSERT_EQ(set.count, 4);
  expect_all(set, Vec3::UnitZ(), g);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) EXPECT_TRUE(has_point_at(set, Vec3(sx, sy, 1 + r + 0.5 * g)));
  // Four different keys: a vertex of one box against the face of the other.
  std::vector<std::uint64_t> keys;
  for (const auto &p : set) {
    keys.push_back(p.key);
    const FeatureType ti = feature_type(key_feature_i(p.key)), tj = feature_type(key_feature_j(p.key));
    EXPECT_TRUE((ti == FeatureType::Vertex && tj == FeatureType::Face) || (ti == FeatureType::Face && tj == FeatureType::Vertex));
  }
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::unique(keys.begin(), keys.end()), keys.end());
}
INSTANTIATE_TEST_SUITE_P(SeparatedTouchingOverlapping, BoxOnBox, ::testing::Values(0.05, 0.0, -0.01, -0.15));

TEST(ContactGrains, BeyondActivationNothing)
{
  const auto box = make_box(1, 1, 1, 0.1);
  ContactWorkspace ws;
  EXPECT_TRUE(contact_grains(box, place(box, Vec3(0, 0, 2.2 + 0.1001)), box, place(box, Vec3::Zero()), 0.1, ws).empty());
  EXPECT_EQ(contact_grains(box, place(box, Vec3(0, 0, 2.2 + 0.0999)), box, place(box, Vec3::Zero()), 0.1, ws).count, 4);
  // Far apart: rejected by the bounding spheres.
  EXPECT_TRUE(contact_grains(box, place(box, Vec3(10, 0, 0)), box, place(box, Vec3::Zero()), 0.1, ws).empty());
}

// The workspace's buffers grow to the shapes seen and are then reused: what memory_usage()
// reports is 0 before any query, at least the two boxes' core vertices after one, and the
// same after the same query again (no growth, no allocation).
TEST(ContactGrains, WorkspaceReportsItsBuffersAndStopsGrowing)
{
  const auto box = make_box(1, 1, 1, 0.1);
  ContactWorkspace ws;
  EXPECT_EQ(ws.memory_bytes(), 0u);
  contact_grains(box, place(box, Vec3(0, 0, 2.2)), box, place(box, Vec3::Zero()), 0.1, ws);
  const std::size_t after_one = ws.memory_bytes();
  EXPECT_GE(after_one, 2 * 8 * sizeof(Vec3));
  EXPECT_GE(after_one, ws.vertices_i.capacity() * sizeof(Vec3) + ws.candidates.capacity() * sizeof(ws.candidates[0]));
  contact_grains(box, place(box, Vec3(0, 0, 2.2)), box, place(box, Vec3::Zero()), 0.1, ws);
  EXPECT_EQ(ws.memory_bytes(), after_one);
}

// Sharp boxes whose cores overlap: the separating-axis search gives the exact depth.
TEST(ContactGrains, OverlappingSharpCoresUseTheMinimumPenetrationAxis)
{
  const auto box = make_box(1, 1, 1, 0.0);
  ContactWorkspace ws;
  // Overlap 0.01 along x; the boxes are shifted in y and z so x is the shallowest axis.
  const auto set = contact_grains(box, place(box, Vec3(1.99, 0.5, 0.3)), box, place(box, Vec3::Zero()), 0.0, ws);
  ASSERT_EQ(set.count, 4);
  expect_all(set, Vec3::UnitX(), -0.01, 1e-12);
  EXPECT_TRUE(has_point_at(set, Vec3(0.995, -0.5, -0.7)));
  EXPECT_TRUE(has_point_at(set, Vec3(0.995, 1.0, 1.0)));
}

TEST(ContactGrains, OffsetBoxesGiveTheCornersOfTheOverlapRectangle)
{
  const double r = 0.05;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const auto set = contact_grains(box, place(box, Vec3(0.5, 0.3, 2 + 2 * r)), box, place(box, Vec3::Zero()), 1e-12, ws);
  ASSERT_EQ(set.count, 4);
  expect_all(set, Vec3::UnitZ(), 0.0);
  for (double x : {-0.5, 1.0})
    for (double y : {-0.7, 1.0}) EXPECT_TRUE(has_point_at(set, Vec3(x, y, 1 + r)));
}

TEST(ContactGrains, SmallRotatedBoxOnBigBoxGivesItsOwnCorners)
{
  const double r = 0.05, g = 0.01;
  const auto big = make_box(1, 1, 1, r), small = make_box(0.5, 0.5, 0.5, r);
  ContactWorkspace ws;
  const Quat q = rotation_about(Vec3::UnitZ(), kPi / 4);
  const auto set = contact_grains(small, place(small, Vec3(0, 0, 1.5 + 2 * r + g), q), big, place(big, Vec3::Zero()), 0.02, ws);
  ASSERT_EQ(set.count, 4);
  expect_all(set, Vec3::UnitZ(), g);
  const double c = 0.5 * std::sqrt(2.0);
  for (const Vec3 &xy : {Vec3(c, 0, 0), Vec3(-c, 0, 0), Vec3(0, c, 0), Vec3(0, -c, 0)})
    EXPECT_TRUE(has_point_at(set, xy + Vec3(0, 0, 1 + r + 0.5 * g)));
}

// Equal squares rotated 45 degrees overlap in a regular octagon. This test used to expect
// the octagon reduced to 4 spanning points (ContactSet::kMaxPoints was 4); the capacity is
// now 8 so that no touching point is ever dropped (a dropped point is unconstrained and
// sinks), hence all 8 corners, each once. Reduction of larger patches:
// test_contact_reduction.cpp.
TEST(ContactGrains, OctagonPatchGivesItsEightCorners)
{
  const double r = 0.05;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const Quat q = rotation_about(Vec3::UnitZ(), kPi / 4);
  const auto set = contact_grains(box, place(box, Vec3(0, 0, 2 + 2 * r), q), box, place(box, Vec3::Zero()), 1e-12, ws);
  ASSERT_EQ(set.count, 8);
  expect_all(set, Vec3::UnitZ(), 0.0);
  // Octagon vertices are at distance 1/cos(22.5 deg) from the centre, at angles
  // 22.5 + 45 k degrees.
  const double rim = 1.0 / std::cos(kPi / 8);
  for (int k = 0; k < 8; ++k) {
    const double a = kPi / 8 + k * kPi / 4;
    EXPECT_TRUE(has_point_at(set, Vec3(rim * std::cos(a), rim * std::sin(a), 1 + r))) << "corner " << k;
  }
}

// Box i tilted 45 degrees about x rests on its lowest edge: 2 points, the ends of the edge.
TEST(ContactGrains, EdgeOnFaceGivesTwoPoints)
{
  const double r = 0.1, g = 0.02;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const Quat q = rotation_about(Vec3::UnitX(), kPi / 4);
  const auto set = contact_grains(box, place(box, Vec3(0, 0, 1 + 2 * r + g + std::sqrt(2.0)), q), box, place(box, Vec3::Zero()), 0.05, ws);
  ASSERT_EQ(set.count, 2);
  expect_all(set, Vec3::UnitZ(), g);
  EXPECT_TRUE(has_point_at(set, Vec3(1, 0, 1 + r + 0.5 * g)));
  EXPECT_TRUE(has_point_at(set, Vec3(-1, 0, 1 + r + 0.5 * g)));
}

// Box i tilted by a about x rests on its lowest edge over a wide box j. Its other bottom
// edge is 2 sin(a) higher: within the activation distance its two vertices are points too
// (a grain turning about the edge brings them down within a step), with the face's normal
// and their own gap; below it, only the edge's two points.
TEST(ContactGrains, VerticesOverAFaceWithinTheActivationArePointsToo)
{
  const double r = 0.1, g = 0.02, a = 10.0 * kPi / 180.0;
  const auto small = make_box(1, 1, 1, r), wide = make_box(3, 3, 1, r);
  ContactWorkspace ws;
  const Pose tilted = place(small, Vec3(0, 0, 1 + 2 * r + g + std::sin(a) + std::cos(a)), rotation_about(Vec3::UnitX(), a));
  const Pose below = place(wide, Vec3::Zero());
  ASSERT_EQ(contact_grains(small, tilted, wide, below, 0.05, ws).count, 2);
  const double raised = g + 2 * std::sin(a);
  const auto set = contact_grains(small, tilted, wide, below, raised + 0.01, ws);
  ASSERT_EQ(set.count, 4);
  for (const auto &p : set) EXPECT_NEAR((p.normal - Vec3::UnitZ()).norm(), 0.0, kTol);
  // rotating (y, z) = (-1, -1) and (1, -1) about x: the lowest and the raised edge
  for (double x : {-1.0, 1.0}) {
    EXPECT_TRUE(has_point_at(set, Vec3(x, std::sin(a) - std::cos(a), 1 + r + 0.5 * g)));
    EXPECT_TRUE(has_point_at(set, Vec3(x, std::sin(a) + std::cos(a), 1 + r + 0.5 * raised)));
  }
  for (const auto &p : set)
    EXPECT_TRUE(std::abs(p.gap - g) < kTol || std::abs(p.gap - raised) < kTol) << p.gap;
  // Only pairs meeting on an edge or a corner get them: a face-on-face patch is enough.
  const Pose flat = place(small, Vec3(0, 0, 1 + 2 * r + g + 1));
  EXPECT_EQ(contact_grains(small, flat, wide, below, 0.5, ws).count, 4);
}

// A bar's lowest edge lies across a narrow block's top face, tilted by 2 degrees: the
// closest features are the edge and the block's lower border edge (1 point); a bar turning
// about it brings the edge down onto the other border edge within the step, so within the
// speculative distance that crossing is a point too, with the edges' common normal and
// their distance (2 half_width sin(tilt) more), found from either grain. Both ends of the
// edge lie beside the face: no vertex over a face stands for it.
TEST(ContactGrains, EdgeCrossingTheFarBorderOfAFaceIsAPointToo)
{
  test::BarAcrossBlock scene;
  scene.tilt = 2.0 * kPi / 180.0;
  scene.gap = 0.01;
  ContactWorkspace ws;
  const double upper = scene.upper_gap();    // 0.0309
  const auto without = contact_grains(scene.bar, scene.bar_pose(), scene.block, scene.block_pose(), 0.05, ws, 0.0);
  ASSERT_EQ(without.count, 1);
  EXPECT_NEAR(without[0].gap, scene.gap, kTol);
  for (const bool swapped : {false, true}) {
    const auto set = swapped ? contact_grains(scene.block, scene.block_pose(), scene.bar, scene.bar_pose(), 0.05, ws)
                             : contact_grains(scene.bar, scene.bar_pose(), scene.block, scene.block_pose(), 0.05, ws);
    ASSERT_EQ(set.count, 2) << "swapped " << swapped;
    const Vec3 normal = swapped ? Vec3(-scene.normal()) : scene.normal();
    for (const auto &p : set) {
      EXPECT_NEAR((p.normal - normal).norm(), 0.0, 1e-9);
      EXPECT_EQ(feature_type(key_feature_i(p.key)), FeatureType::Edge);
      EXPECT_EQ(feature_type(key_feature_j(p.key)), FeatureType::Edge);
    }
    EXPECT_NEAR(std::min(set[0].gap, set[1].gap), scene.gap, kTol);
    EXPECT_NEAR(std::max(set[0].gap, set[1].gap), upper, kTol);
  }
  // Beyond the speculative distance (what the pair can close in the step), only the closest.
  EXPECT_EQ(contact_grains(scene.bar, scene.bar_pose(), scene.block, scene.block_pose(), 0.05, ws, 0.5 * upper).count, 1);
  EXPECT_THROW(contact_grains(scene.bar, scene.bar_pose(), scene.block, scene.block_pose(), 0.05, ws, std::nan("")),
               ContactError);
}

// Box i standing on a corner: 1 point under the corner.
TEST(ContactGrains, VertexOnFaceGivesOnePoint)
{
  const double r = 0.1, g = -0.03;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  // Rotation taking the diagonal (-1,-1,-1)/sqrt3 to -z: that corner points down.
  const Quat q = Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), -Vec3::UnitZ());
  const auto set = contact_grains(box, place(box, Vec3(0.2, -0.1, 1 + 2 * r + g + std::sqrt(3.0)), q), box, place(box, Vec3::Zero()), 0.05, ws);
  ASSERT_EQ(set.count, 1);
  expect_all(set, Vec3::UnitZ(), g);
  EXPECT_TRUE(has_point_at(set, Vec3(0.2, -0.1, 1 + r + 0.5 * g)));
  EXPECT_EQ(feature_type(key_feature_i(set[0].key)), FeatureType::Vertex);
  EXPECT_EQ(feature_type(key_feature_j(set[0].key)), FeatureType::Face);
}

// Crossed edges: i's lowest edge along x, j's highest edge along y: 1 point between them.
TEST(ContactGrains, CrossedEdgesGiveOnePoint)
{
  const double r = 0.1;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const Quat qi = rotation_about(Vec3::UnitX(), kPi / 4), qj = rotation_about(Vec3::UnitY(), kPi / 4);
  for (double g : {0.04, 0.0, -0.05, -0.3}) {
    const auto set = contact_grains(box, place(box, Vec3(0, 0, 2 * std::sqrt(2.0) + 2 * r + g), qi), box,
                                    place(box, Vec3::Zero(), qj), 0.05, ws);
    ASSERT_EQ(set.count, 1) << "gap " << g;
    expect_all(set, Vec3::UnitZ(), g, 1e-12);
    EXPECT_TRUE(has_point_at(set, Vec3(0, 0, std::sqrt(2.0) + r + 0.5 * g)));
    EXPECT_EQ(feature_type(key_feature_i(set[0].key)), FeatureType::Edge);
    EXPECT_EQ(feature_type(key_feature_j(set[0].key)), FeatureType::Edge);
  }
}

// Parallel edges (both boxes tilted about x, i shifted along x): the overlap's two ends.
TEST(ContactGrains, ParallelEdgesGiveTheEndsOfTheOverlap)
{
  const double r = 0.1, g = 0.01;
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const Quat q = rotation_about(Vec3::UnitX(), kPi / 4);
  const auto set = contact_grains(box, place(box, Vec3(0.6, 0, 2 * std::sqrt(2.0) + 2 * r + g), q), box,
                                  place(box, Vec3::Zero(), q), 0.05, ws);
  ASSERT_EQ(set.count, 2);
  expect_all(set, Vec3::UnitZ(), g, 1e-12);
  EXPECT_TRUE(has_point_at(set, Vec3(-0.4, 0, std::sqrt(2.0) + r + 0.5 * g)));
  EXPECT_TRUE(has_point_at(set, Vec3(1.0, 0, std::sqrt(2.0) + r + 0.5 * g)));
}

TEST(ContactGrains, SpheresTouchAlongTheLineOfCentres)
{
  const auto a = test::make_sphere(0.5), b = test::make_sphere(0.3);
  ContactWorkspace ws;
  const Vec3 d = Vec3(1, 2, 2) / 3.0;
  for (double g : {0.1, 0.0, -0.2}) {
    const auto set = contact_grains(b, place(b, (0.8 + g) * d), a, place(a, Vec3::Zero()), 0.2, ws);
    ASSERT_EQ(set.count, 1);
    EXPECT_NEAR(set[0].gap, g, kTol);
    EXPECT_NEAR((set[0].normal - d).norm(), 0.0, kTol);
    EXPECT_NEAR((set[0].point - (0.5 + 0.5 * g) * d).norm(), 0.0, kTol);
  }
}

// Sphere against the face, the edge and the corner of a box.
TEST(ContactGrains, SphereAgainstFaceEdgeAndCornerOfABox)
{
  const double r = 0.1, R = 0.4, g = 0.03;
  const auto box = make_box(1, 1, 1, r);
  const auto ball = test::make_sphere(R);
  ContactWorkspace ws;
  const Pose box_pose = place(box, Vec3::Zero());
  const Vec3 directions[3] = {Vec3(0, 0, 1), Vec3(1, 0, 1).normalized(), Vec3(1, 1, 1).normalized()};
  const Vec3 anchors[3] = {Vec3(0.3, -0.2, 1), Vec3(1, 0.4, 1), Vec3(1, 1, 1)};
  for (int k = 0; k < 3; ++k) {
    const Vec3 centre = anchors[k] + (r + R + g) * directions[k];
    const auto set = contact_grains(ball, place(ball, centre), box, box_pose, 0.05, ws);
    ASSERT_EQ(set.count, 1) << "case " << k;
    EXPECT_NEAR(set[0].gap, g, kTol);
    EXPECT_NEAR((set[0].normal - directions[k]).norm(), 0.0, 1e-9);
    EXPECT_NEAR((set[0].point - (anchors[k] + (r + 0.5 * g) * directions[k])).norm(), 0.0, 1e-9);
    // Swapped roles: same point and gap, opposite normal.
    const auto swapped = contact_grains(box, box_pose, ball, place(ball, centre), 0.05, ws);
    ASSERT_EQ(swapped.count, 1);
    EXPECT_NEAR(swapped[0].gap, g, kTol);
    EXPECT_NEAR((swapped[0].normal + directions[k]).norm(), 0.0, 1e-9);
    EXPECT_EQ(swapped[0].key, swapped_key(set[0].key));
  }
}

// Sphere centre inside the core of a sharp box: pushed out through the nearest face.
TEST(ContactGrains, SphereCentreInsideSharpBox)
{
  const auto box = make_box(1, 1, 1, 0.0);
  const auto ball = test::make_sphere(0.2);
  ContactWorkspace ws;
  const auto set = contact_grains(ball, place(ball, Vec3(0.3, 0.9, -0.2)), box, place(box, Vec3::Zero()), 0.0, ws);
  ASSERT_EQ(set.count, 1);
  EXPECT_NEAR(set[0].gap, -0.1 - 0.2, kTol);
  EXPECT_NEAR((set[0].normal - Vec3::UnitY()).norm(), 0.0, kTol);
}

// Capsule lying on a box face: the two ends; crossing a box edge: one point.
TEST(ContactGrains, CapsuleOnBox)
{
  const double r = 0.1, rc = 0.2, g = 0.01;
  const auto box = make_box(1, 1, 1, r);
  const auto capsule = test::make_capsule(0.5, rc);
  ContactWorkspace ws;
  const auto flat = contact_grains(capsule, place(capsule, Vec3(0.1, 0.2, 1 + r + rc + g)), box, place(box, Vec3::Zero()), 0.05, ws);
  ASSERT_EQ(flat.count, 2);
  expect_all(flat, Vec3::UnitZ(), g);
  EXPECT_TRUE(has_point_at(flat, Vec3(-0.4, 0.2, 1 + r + 0.5 * g)));
  EXPECT_TRUE(has_point_at(flat, Vec3(0.6, 0.2, 1 + r + 0.5 * g)));
  // Capsule across the box edge x = 1, z = 1 (along y), at 45 degrees from both faces.
  const Vec3 d = Vec3(1, 0, 1).normalized();
  const auto across = contact_grains(capsule, place(capsule, Vec3(1, 0, 1) + (r + rc + g) * d, rotation_about(Vec3::UnitY(), kPi / 4)),
                                     box, place(box, Vec3::Zero()), 0.05, ws);
  ASSERT_EQ(across.count, 1);
  EXPECT_NEAR(across[0].gap, g, kTol);
  EXPECT_NEAR((across[0].normal - d).norm(), 0.0, 1e-9);
}

// Two capsules: parallel (2 points, the ends of the overlap) and crossed (1 point).
TEST(ContactGrains, CapsulePairs)
{
  const auto capsule = test::make_capsule(1.0, 0.25);
  ContactWorkspace ws;
  const auto parallel = contact_grains(capsule, place(capsule, Vec3(0.5, 0, 0.45)), capsule, place(capsule, Vec3::Zero()), 0.0, ws);
  ASSERT_EQ(parallel.count, 2);
  expect_all(parallel, Vec3::UnitZ(), -0.05);
  EXPECT_TRUE(has_point_at(parallel, Vec3(-0.5, 0, 0.225)));
  EXPECT_TRUE(has_point_at(parallel, Vec3(1.0, 0, 0.225)));
  const auto crossed = contact_grains(capsule, place(capsule, Vec3(0.3, 0.2, 0.6), rotation_about(Vec3::UnitZ(), 1.0)),
                                      capsule, place(capsule, Vec3::Zero()), 0.2, ws);
  ASSERT_EQ(crossed.count, 1);
  EXPECT_NEAR(crossed[0].gap, 0.1, kTol);
  EXPECT_NEAR((crossed[0].normal - Vec3::UnitZ()).norm(), 0.0, kTol);
}

// Tetrahedron standing on a face / on a vertex on a box: 3 points / 1 point.
TEST(ContactGrains, TetrahedronFaceAndVertex)
{
  const double r = 0.05, g = 0.0;
  const std::vector<Vec3> tet = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const auto tetra = make_spheropolyhedron(tet, r);
  const auto box = make_box(1, 1, 1, r);
  ContactWorkspace ws;
  const Vec3 base(-0.2, -0.3, 1 + 2 * r + g);
  const auto on_face = contact_grains(tetra, place(tetra, base), box, place(box, Vec3::Zero()), 0.01, ws);
  ASSERT_EQ(on_face.count, 3);
  expect_all(on_face, Vec3::UnitZ(), g);
  for (const Vec3 &v : {tet[0], tet[1], tet[2]}) EXPECT_TRUE(has_point_at(on_face, base + v - Vec3(0, 0, r)));
  // Upside down (apex (0,0,1) pointing down).
  const Quat flip = rotation_about(Vec3::UnitX(), kPi);
  const auto on_vertex = contact_grains(tetra, place(tetra, Vec3(0.1, 0.1, 2 + 2 * r + g), flip), box, place(box, Vec3::Zero()), 0.01, ws);
  ASSERT_EQ(on_vertex.count, 1);
  EXPECT_NEAR(on_vertex[0].gap, g, kTol);
}

TEST(ContactGrains, BadActivationIsAnError)
{
  const auto box = make_box(1, 1, 1, 0.1);
  ContactWorkspace ws;
  EXPECT_THROW(contact_grains(box, place(box, Vec3::Zero()), box, place(box, Vec3(1, 0, 0)), -1.0, ws), ContactError);
  EXPECT_THROW(contact_grains(box, place(box, Vec3::Zero()), box, place(box, Vec3(1, 0, 0)), NAN, ws), ContactError);
}

}    // namespace
}    // namespace nscd
