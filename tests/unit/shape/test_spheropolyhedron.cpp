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

// make_spheropolyhedron: topology, body frame and mass properties against closed forms.
#include "shape/mass_properties.h"
#include "shape/spheropolyhedron.h"
#include "shape_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

using namespace nscd;
using namespace nscd::test;

namespace {

// Closed-form principal moments of a box a x b x c (unit density), sorted ascending.
Vec3 box_inertia(double a, double b, double c)
{
  const double m = a * b * c;
  std::array<double, 3> moments{m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12};
  std::sort(moments.begin(), moments.end());
  return Vec3(moments[0], moments[1], moments[2]);
}

void expect_vec_near(const Vec3 &a, const Vec3 &b, double tolerance)
{
  EXPECT_NEAR((a - b).norm(), 0.0, tolerance) << "got " << a.transpose() << " expected " << b.transpose();
}

std::vector<Vec3> regular_tetrahedron(double edge)
{
  const double s = edge / (2.0 * std::sqrt(2.0));
  return {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s), Vec3(-s, -s, s)};
}

std::vector<Vec3> regular_octahedron(double edge)
{
  const double h = edge / std::sqrt(2.0);
  return {Vec3(h, 0, 0), Vec3(-h, 0, 0), Vec3(0, h, 0), Vec3(0, -h, 0), Vec3(0, 0, h), Vec3(0, 0, -h)};
}

std::vector<Vec3> random_cloud(std::mt19937_64 &rng, int count)
{
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    const Vec3 p = random_in_ball(rng);
    points.push_back(Vec3(1.3 * p.x(), 0.9 * p.y(), 0.6 * p.z()));
  }
  return points;
}

// Moments of the body-frame shape recomputed from its stored geometry.
MassMoments recomputed_moments(const Spheropolyhedron &s)
{
  if (s.is_sphere()) return ball_moments(s.vertices[0], s.radius);
  if (s.is_spherocylinder()) return spherocylinder_moments(s.vertices[0], s.vertices[1], s.radius);
  return dilated_polyhedron_moments(s.vertices, s.faces, s.edges, s.edge_faces, s.radius);
}

}    // namespace

TEST(Spheropolyhedron, UnitCubeTopologyAndMass)
{
  const auto s = make_spheropolyhedron(box_corners(1, 1, 1, Vec3(3, -2, 7)), 0.0);
  EXPECT_EQ(s.vertices.size(), 8u);
  EXPECT_EQ(s.edges.size(), 12u);
  ASSERT_EQ(s.faces.size(), 6u);
  for (const auto &f : s.faces) {
    EXPECT_EQ(f.vertices.size(), 4u);
    EXPECT_NEAR(f.offset, 0.5, 1e-14);
  }
  EXPECT_NEAR(s.volume, 1.0, 1e-14);
  expect_vec_near(s.principal_inertia, Vec3::Constant(1.0 / 6.0), 1e-14);
  EXPECT_NEAR(s.bounding_radius, std::sqrt(3.0) / 2.0, 1e-14);
  expect_vec_near(s.input_centroid, Vec3(3, -2, 7), 1e-14);
}

TEST(Spheropolyhedron, FacesAreCounterClockwiseWithOutwardNormals)
{
  std::mt19937_64 rng(7);
  const auto s = make_spheropolyhedron(random_cloud(rng, 40), 0.1);
  for (const auto &f : s.faces) {
    ASSERT_GE(f.vertices.size(), 3u);
    EXPECT_NEAR(f.normal.norm(), 1.0, 1e-14);
    EXPECT_GT(f.offset, 0.0);    // the centre of mass is inside
    for (int v : f.vertices) EXPECT_NEAR(f.normal.dot(s.vertices[v]), f.offset, 1e-12);
    for (const auto &v : s.vertices) EXPECT_LE(f.normal.dot(v), f.offset + 1e-12);
    const Vec3 &a = s.vertices[f.vertices[0]], &b = s.vertices[f.vertices[1]], &c = s.vertices[f.vertices[2]];
    EXPECT_GT((b - a).cross(c - b).dot(f.normal), 0.0);
  }
  // Euler's formula and each edge bounded by two faces that run it in opposite directions.
  EXPECT_EQ(s.vertices.size() - s.edges.size() + s.faces.size(), 2u);
  ASSERT_EQ(s.edge_faces.size(), s.edges.size());
  for (size_t k = 0; k < s.edges.size(); ++k) {
    EXPECT_LT(s.edges[k][0], s.edges[k][1]);
    EXPECT_NE(s.edge_faces[k][0], s.edge_faces[k][1]);
    for (int side = 0; side < 2; ++side) {
      const auto &poly = s.faces[s.edge_faces[k][side]].vertices;
      const auto it = std::find(poly.begin(), poly.end(), s.edges[k][side]);
      ASSERT_NE(it, poly.end());
      const int next = (it + 1 == poly.end()) ? poly.front() : *(it + 1);
      EXPECT_EQ(next, s.edges[k][1 - side]);
    }
  }
}

TEST(Spheropolyhedron, BoxMassProperties)
{
  const double a = 1.7, b = 0.6, c = 1.1;
  const auto s = make_spheropolyhedron(box_corners(a, b, c, Vec3(-1, 0.5, 2)), 0.0);
  EXPECT_NEAR(s.volume, a * b * c, 1e-14);
  expect_vec_near(s.principal_inertia, box_inertia(a, b, c), 1e-14);
  // Longest side along the body x axis (smallest moment).
  for (const auto &v : s.vertices) EXPECT_NEAR(std::abs(v.x()), a / 2, 1e-14);
}

TEST(Spheropolyhedron, InteriorFaceEdgeAndDuplicatePointsAreDropped)
{
  auto points = box_corners(2, 2, 2);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 30; ++i) points.push_back(0.99 * random_in_ball(rng));
  for (int axis = 0; axis < 3; ++axis) {
    points.push_back(Vec3::Unit(axis));                             // face centre
    points.push_back(Vec3::Unit(axis) + Vec3::Unit((axis + 1) % 3));    // edge midpoint
  }
  points.push_back(points[0] + Vec3(1e-13, -1e-13, 0));              // near-duplicate corner
  const auto s = make_spheropolyhedron(points, 0.0);
  EXPECT_EQ(s.vertices.size(), 8u);
  EXPECT_EQ(s.faces.size(), 6u);
  EXPECT_EQ(s.edges.size(), 12u);
  EXPECT_NEAR(s.volume, 8.0, 1e-13);
}

TEST(Spheropolyhedron, NearlyCoplanarFacetsAreMerged)
{
  // Corners and edge midpoints moved by 1e-12 (below the 1e-10 relative tolerance).
  auto points = box_corners(1, 1, 1);
  for (int axis = 0; axis < 3; ++axis) points.push_back(0.5 * (Vec3::Ones() - Vec3::Unit(axis)));
  std::mt19937_64 rng(13);
  for (auto &p : points) p += 1e-12 * random_in_ball(rng);
  const auto s = make_spheropolyhedron(points, 0.1);
  EXPECT_EQ(s.faces.size(), 6u);
  EXPECT_EQ(s.edges.size(), 12u);
  EXPECT_EQ(s.vertices.size(), 8u);
  // Noise well above the tolerance keeps the true (triangulated) hull.
  auto rough = box_corners(1, 1, 1);
  for (auto &p : rough) p += 1e-4 * random_in_ball(rng);
  EXPECT_GT(make_spheropolyhedron(rough, 0.0).faces.size(), 6u);
}

TEST(Spheropolyhedron, SphereFromOnePoint)
{
  const double r = 0.7;
  const auto s = make_spheropolyhedron({Vec3(1, 2, 3), Vec3(1, 2, 3 + 1e-15)}, r);
  ASSERT_TRUE(s.is_sphere());
  const double volume = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(s.volume, volume, 1e-15);
  expect_vec_near(s.principal_inertia, Vec3::Constant(0.4 * volume * r * r), 1e-15);
  EXPECT_DOUBLE_EQ(s.bounding_radius, r);
  EXPECT_EQ(s.vertices[0], Vec3::Zero());
}

TEST(Spheropolyhedron, SpherocylinderFromCollinearPoints)
{
  const double r = 0.3, length = 2.0;
  const Vec3 dir = Vec3(1, 2, 2) / 3.0;
  std::vector<Vec3> points;
  for (double t : {0.2, -1.0, 0.5, 1.0, -0.3}) points.push_back(Vec3(4, 5, 6) + t * dir);
  const auto s = make_spheropolyhedron(points, r);
  ASSERT_TRUE(s.is_spherocylinder());
  EXPECT_NEAR((s.vertices[1] - s.vertices[0]).norm(), length, 1e-14);
  // Cylinder (mass mc) plus two hemispheres (together a ball of mass ms).
  const double mc = kPi * r * r * length, ms = 4.0 / 3.0 * kPi * r * r * r;
  const double axial = mc * r * r / 2 + 0.4 * ms * r * r;
  const double transverse = mc * (length * length / 12 + r * r / 4) +
                            ms * (0.4 * r * r + length * length / 4 + 3 * length * r / 8);
  EXPECT_NEAR(s.volume, mc + ms, 1e-14);
  expect_vec_near(s.principal_inertia, Vec3(axial, transverse, transverse), 1e-14);
  expect_vec_near(s.vertices[0], Vec3(-1, 0, 0), 1e-14);    // axis = body x (smallest moment)
  EXPECT_NEAR(s.bounding_radius, 1.0 + r, 1e-14);
}

TEST(Spheropolyhedron, RegularTetrahedronAndOctahedron)
{
  const double a = 1.3;
  const auto tet = make_spheropolyhedron(regular_tetrahedron(a), 0.0);
  const double vt = a * a * a / (6 * std::sqrt(2.0));
  EXPECT_NEAR(tet.volume, vt, 1e-14);
  expect_vec_near(tet.principal_inertia, Vec3::Constant(vt * a * a / 20), 1e-14);
  EXPECT_EQ(tet.faces.size(), 4u);

  const auto oct = make_spheropolyhedron(regular_octahedron(a), 0.0);
  const double vo = std::sqrt(2.0) / 3 * a * a * a;
  EXPECT_NEAR(oct.volume, vo, 1e-14);
  expect_vec_near(oct.principal_inertia, Vec3::Constant(vo * a * a / 10), 1e-14);
  EXPECT_EQ(oct.faces.size(), 8u);
}

TEST(Spheropolyhedron, SteinerVolumeOfRoundedPolyhedra)
{
  for (double r : {0.0, 0.05, 0.4, 3.0}) {
    const auto cube = make_spheropolyhedron(box_corners(1, 1, 1), r);
    EXPECT_NEAR(cube.volume, 1 + 6 * r + 3 * kPi * r * r + 4.0 / 3.0 * kPi * r * r * r, 1e-12 * cube.volume);
    // Regular tetrahedron of edge a: M = 6 a (pi - acos(1/3)) / 2.
    const double a = 1.1;
    const auto tet = make_spheropolyhedron(regular_tetrahedron(a), r);
    const double steiner = a * a * a / (6 * std::sqrt(2.0)) + std::sqrt(3.0) * a * a * r +
                           3 * a * (kPi - std::acos(1.0 / 3.0)) * r * r + 4.0 / 3.0 * kPi * r * r * r;
    EXPECT_NEAR(tet.volume, steiner, 1e-12 * steiner);
  }
}

// Independent check of the rounded-box inertia: integrate the cross-sections at height z
// (rectangle a x b dilated by rho(z), 2-D closed forms) with Gauss-Legendre in z.
namespace {

struct Section {
  double area, xx, yy;    // area, integral of x^2, integral of y^2 of the rounded rectangle
};

Section rounded_rectangle(double a, double b, double rho)
{
  auto second_moment = [&](double along, double across) {
    const double h = along / 2;
    const double core = along * along * along * across / 12;
    const double sides = 2 * across * (std::pow(h + rho, 3) - h * h * h) / 3;
    const double caps = 2 * rho * along * along * along / 12;
    const double corners = 4 * (h * h * kPi * rho * rho / 4 + 2 * h * rho * rho * rho / 3 + kPi * std::pow(rho, 4) / 16);
    return core + sides + caps + corners;
  };
  return {a * b + 2 * rho * (a + b) + kPi * rho * rho, second_moment(a, b), second_moment(b, a)};
}

// 20-point Gauss-Legendre nodes/weights on [0, 1] from Newton on the Legendre polynomial.
std::vector<std::pair<double, double>> gauss_legendre_unit(int n)
{
  std::vector<std::pair<double, double>> rule;
  for (int i = 1; i <= n; ++i) {
    double x = std::cos(kPi * (i - 0.25) / (n + 0.5)), dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.emplace_back(0.5 * (x + 1), 1.0 / ((1 - x * x) * dp * dp));
  }
  return rule;
}

Vec3 rounded_box_inertia_by_sections(double a, double b, double c, double r)
{
  double xx = 0, yy = 0, zz = 0;    // integrals of x^2, y^2, z^2 over the solid
  auto add_slice = [&](double z, double rho, double weight) {
    const Section s = rounded_rectangle(a, b, rho);
    xx += weight * s.xx;
    yy += weight * s.yy;
    zz += weight * s.area * z * z;
  };
  const auto rule = gauss_legendre_unit(30);
  for (const auto &[t, w] : rule) add_slice(-c / 2 + c * t, r, w * c);    // prism part, |z| <= c/2
  // Caps: z = c/2 + r sin(phi), rho = r cos(phi), dz = r cos(phi) dphi (smooth integrand).
  for (const auto &[t, w] : rule) {
    const double phi = t * kPi / 2, weight = w * kPi / 2 * r * std::cos(phi);
    add_slice(c / 2 + r * std::sin(phi), r * std::cos(phi), 2 * weight);    // both caps
  }
  return Vec3(yy + zz, xx + zz, xx + yy);
}

}    // namespace

TEST(Spheropolyhedron, RoundedBoxInertiaMatchesSliceIntegration)
{
  const double a = 1.6, b = 1.0, c = 0.7;
  for (double r : {0.1, 0.5}) {
    const auto s = make_spheropolyhedron(box_corners(a, b, c), r);
    Vec3 expected = rounded_box_inertia_by_sections(a, b, c, r);
    std::sort(expected.data(), expected.data() + 3);
    expect_vec_near(s.principal_inertia, expected, 1e-12 * expected.norm());
  }
}

TEST(Spheropolyhedron, ThinRoundedBoxTendsToSpherocylinder)
{
  // A needle of width eps rounded by r differs from the spherocylinder by O(eps).
  const double r = 0.4, length = 1.5, eps = 1e-7;
  const auto needle = make_spheropolyhedron(box_corners(length, eps, eps), r);
  const auto capsule = make_spheropolyhedron({Vec3(-length / 2, 0, 0), Vec3(length / 2, 0, 0)}, r);
  EXPECT_NEAR(needle.volume, capsule.volume, 10 * eps);
  expect_vec_near(needle.principal_inertia, capsule.principal_inertia, 10 * eps);
}

TEST(Spheropolyhedron, RandomRoundedHullMatchesMonteCarlo)
{
  std::mt19937_64 rng(2024);
  const double r = 0.15;
  const auto s = make_spheropolyhedron(random_cloud(rng, 25), r);
  // Sample the bounding cube of the body frame; inside = within r of the core.
  const double half = s.bounding_radius;
  const int samples = 200000;
  double hits = 0;
  Vec3 first = Vec3::Zero(), second = Vec3::Zero();
  for (int i = 0; i < samples; ++i) {
    const Vec3 x = half * Vec3(2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1);
    if (distance_to_core(s, x) > r) continue;
    hits += 1;
    first += x;
    second += Vec3(x.y() * x.y() + x.z() * x.z(), x.x() * x.x() + x.z() * x.z(), x.x() * x.x() + x.y() * x.y());
  }
  const double box = std::pow(2 * half, 3), p = hits / samples;
  const double volume = box * p;
  const double volume_error = box * std::sqrt(p * (1 - p) / samples);
  EXPECT_NEAR(s.volume, volume, 5 * volume_error);
  // Centre of mass at the origin; inertia within 5 standard errors (about 1% here).
  const double com_error = half / std::sqrt(hits);
  expect_vec_near(first / hits, Vec3::Zero(), 5 * com_error);
  const Vec3 inertia = box * second / samples;
  for (int k = 0; k < 3; ++k) {
    const double error = box * 2 * half * half / std::sqrt(static_cast<double>(samples));
    EXPECT_NEAR(s.principal_inertia[k], inertia[k], 5 * error) << "axis " << k;
  }
}

TEST(Spheropolyhedron, SharpRandomHullMatchesMonteCarlo)
{
  std::mt19937_64 rng(99);
  const auto s = make_spheropolyhedron(random_cloud(rng, 30), 0.0);
  const Vec3 lo = Vec3::Constant(-s.bounding_radius), span = Vec3::Constant(2 * s.bounding_radius);
  const int samples = 200000;
  double hits = 0;
  Vec3 second = Vec3::Zero();
  for (int i = 0; i < samples; ++i) {
    const Vec3 x = lo + span.cwiseProduct(Vec3(uniform01(rng), uniform01(rng), uniform01(rng)));
    bool inside = true;
    for (const auto &f : s.faces) inside = inside && f.normal.dot(x) <= f.offset;
    if (!inside) continue;
    hits += 1;
    second += Vec3(x.y() * x.y() + x.z() * x.z(), x.x() * x.x() + x.z() * x.z(), x.x() * x.x() + x.y() * x.y());
  }
  const double box = span.prod(), p = hits / samples;
  EXPECT_NEAR(s.volume, box * p, 5 * box * std::sqrt(p * (1 - p) / samples));
  const double error = box * 2 * std::pow(s.bounding_radius, 2) / std::sqrt(static_cast<double>(samples));
  expect_vec_near(s.principal_inertia, box * second / samples, 5 * error);
}

TEST(Spheropolyhedron, BodyFrameHasCentreAtOriginAndDiagonalInertia)
{
  std::mt19937_64 rng(11);
  for (double r : {0.0, 0.2}) {
    const auto s = make_spheropolyhedron(random_cloud(rng, 24), r);
    const MassMoments m = recomputed_moments(s);
    EXPECT_NEAR(m.volume, s.volume, 1e-13 * s.volume);
    expect_vec_near(m.centre(), Vec3::Zero(), 1e-14);
    const Mat3 inertia = m.inertia_about_centre();
    expect_vec_near(inertia.diagonal(), s.principal_inertia, 1e-14);
    EXPECT_NEAR((inertia - Mat3(inertia.diagonal().asDiagonal())).norm(), 0.0, 1e-14);
    EXPECT_LE(s.principal_inertia[0], s.principal_inertia[1]);
    EXPECT_LE(s.principal_inertia[1], s.principal_inertia[2]);
  }
}

TEST(Spheropolyhedron, NormalConeAnglesAddUpToFourPi)
{
  std::mt19937_64 rng(5);
  const auto s = make_spheropolyhedron(random_cloud(rng, 50), 0.0);
  double total = 0;
  for (double angle : vertex_normal_cone_angles(s.vertices, s.faces)) {
    EXPECT_GT(angle, 0.0);
    total += angle;
  }
  EXPECT_NEAR(total, 4 * kPi, 1e-12);
}

TEST(Spheropolyhedron, InputTransformMapsBodyToInput)
{
  std::mt19937_64 rng(17);
  const auto points = random_cloud(rng, 20);
  const auto s = make_spheropolyhedron(points, 0.1);
  // Every body vertex is one of the input points once moved back.
  for (const auto &v : s.vertices) {
    const Vec3 input = s.input_rotation * v + s.input_centroid;
    double nearest = HUGE_VAL;
    for (const auto &p : points) nearest = std::min(nearest, (p - input).norm());
    EXPECT_LT(nearest, 1e-14);
  }
}

TEST(Spheropolyhedron, InvariantUnderInputTranslationAndRotation)
{
  std::mt19937_64 rng(23);
  const auto points = random_cloud(rng, 24);
  const auto reference = make_spheropolyhedron(points, 0.05);
  for (int trial = 0; trial < 5; ++trial) {
    const Quat q = random_rotation(rng);
    const Vec3 t = 10 * random_in_ball(rng);
    std::vector<Vec3> moved;
    for (const auto &p : points) moved.push_back(q * p + t);
    const auto s = make_spheropolyhedron(moved, 0.05);
    EXPECT_NEAR(s.volume, reference.volume, 1e-13);
    expect_vec_near(s.principal_inertia, reference.principal_inertia, 1e-13);
    expect_vec_near(s.input_centroid, q * reference.input_centroid + t, 1e-12);
    ASSERT_EQ(s.vertices.size(), reference.vertices.size());
    // The body frame is unique up to a half turn about a principal axis (sign choice).
    const Mat3 flip = (s.input_rotation.conjugate() * q * reference.input_rotation).toRotationMatrix();
    EXPECT_NEAR((flip.cwiseAbs() - Mat3::Identity()).norm(), 0.0, 1e-12);
    for (size_t i = 0; i < s.vertices.size(); ++i) expect_vec_near(s.vertices[i], flip * reference.vertices[i], 1e-12);
  }
}

TEST(Spheropolyhedron, RebuildingFromBodyFrameIsTheIdentity)
{
  std::mt19937_64 rng(31);
  std::vector<Spheropolyhedron> shapes = {
      make_spheropolyhedron(random_cloud(rng, 24), 0.1),
      make_spheropolyhedron(box_corners(1, 1, 1, Vec3(1, 1, 1)), 0.0),    // all moments equal
      make_spheropolyhedron(box_corners(2, 1, 1), 0.2),                    // two equal moments
      make_spheropolyhedron(box_corners(1, 1, 2), 0.2),
      make_spheropolyhedron({Vec3(0, 0, 0), Vec3(1, 1, 1)}, 0.3),
      make_spheropolyhedron({Vec3(2, 0, 0)}, 0.3),
  };
  for (const auto &s : shapes) {
    const auto again = make_spheropolyhedron(s.vertices, s.radius);
    ASSERT_EQ(again.vertices.size(), s.vertices.size());
    for (size_t i = 0; i < s.vertices.size(); ++i) expect_vec_near(again.vertices[i], s.vertices[i], 1e-14);
    EXPECT_LT(again.input_rotation.angularDistance(Quat::Identity()), 1e-13);
    expect_vec_near(again.input_centroid, Vec3::Zero(), 1e-14);
    EXPECT_EQ(again.faces.size(), s.faces.size());
    for (size_t f = 0; f < s.faces.size(); ++f) EXPECT_EQ(again.faces[f].vertices, s.faces[f].vertices);
  }
}

TEST(Spheropolyhedron, BadInputIsRejectedWithAClearMessage)
{
  auto message_of = [](const std::vector<Vec3> &points, double r) {
    try {
      make_spheropolyhedron(points, r);
    } catch (const ShapeError &e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto cube = box_corners(1, 1, 1);
  EXPECT_NE(message_of(cube, -0.1).find("radius -0.1 is invalid"), std::string::npos);
  EXPECT_NE(message_of(cube, std::nan("")).find("radius nan is invalid"), std::string::npos);
  EXPECT_NE(message_of({}, 1.0).find("no points"), std::string::npos);
  EXPECT_NE(message_of({Vec3(0, 0, 0), Vec3(1, HUGE_VAL, 0)}, 1.0).find("point 2"), std::string::npos);
  EXPECT_NE(message_of({Vec3(1, 2, 3)}, 0.0).find("give a radius > 0"), std::string::npos);
  EXPECT_NE(message_of({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}, 0.0).find("collinear"), std::string::npos);
  // Flat: a square, with or without rounding.
  const std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 1e-13)};
  for (double r : {0.0, 0.5}) {
    const std::string m = message_of(square, r);
    EXPECT_NE(m.find("flat point set"), std::string::npos) << m;
    EXPECT_NE(m.find("add a point off"), std::string::npos) << m;
  }
}

// extent(): how far the dilated surface reaches along a direction, for turned grains.
TEST(Spheropolyhedron, ExtentAlongADirectionFollowsTheTurnedGrain)
{
  const double r = 0.1;
  const auto cube = make_spheropolyhedron(box_corners(1, 1, 1, Vec3(0, 0, 0)), r);
  const Quat none = Quat::Identity();
  EXPECT_NEAR(extent(cube, none, Vec3::UnitZ()), 0.5 + r, 1e-14);
  EXPECT_NEAR(extent(cube, none, -Vec3::UnitX()), 0.5 + r, 1e-14);
  // turned 45 degrees about x: an edge on top, sqrt(2)/2 above the centre
  const Quat about_x(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));
  EXPECT_NEAR(extent(cube, about_x, Vec3::UnitZ()), std::sqrt(0.5) + r, 1e-14);
  // along the space diagonal of the unturned cube: a corner, sqrt(3)/2 away
  EXPECT_NEAR(extent(cube, none, Vec3(1, 1, 1).normalized()), std::sqrt(0.75) + r, 1e-14);
  // a corner on top: turn the diagonal (1,1,1) onto +z
  const Quat corner_up = Quat::FromTwoVectors(Vec3(1, 1, 1).normalized(), Vec3::UnitZ());
  EXPECT_NEAR(extent(cube, corner_up, Vec3::UnitZ()), std::sqrt(0.75) + r, 1e-13);
  const auto ball = make_spheropolyhedron({Vec3(4, 5, 6)}, 0.3);
  EXPECT_NEAR(extent(ball, corner_up, Vec3(0.6, 0, 0.8)), 0.3, 1e-15);
}
