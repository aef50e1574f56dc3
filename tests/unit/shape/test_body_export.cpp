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

// body_export: the BODY (rounded/polyhedron) entry of a grain holds the same hull as the
// shape library, checked against closed forms and through the text written for LAMMPS.
#include "shape/body_export.h"
#include "shape/random_grain.h"
#include "shape/shape_library.h"
#include "shape/spheropolyhedron.h"
#include "shape_test_util.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

using namespace nscd;
using namespace nscd::test;

namespace {

// Volume of the closed polyhedron of the entry's faces (divergence theorem over the fan
// triangles of each face): checks vertices, face lists and their outward orientation.
double core_volume(const BodyEntry &e)
{
  double six_v = 0;
  for (const auto &f : e.faces) {
    const int n = f[3] < 0 ? 3 : 4;
    for (int k = 1; k + 1 < n; ++k)
      six_v += e.vertices[f[0]].dot(e.vertices[f[k]].cross(e.vertices[f[k + 1]]));
  }
  return six_v / 6;
}

Vec3 outward_normal(const BodyEntry &e, const std::array<int, 4> &f)
{
  return (e.vertices[f[1]] - e.vertices[f[0]]).cross(e.vertices[f[2]] - e.vertices[f[0]]).normalized();
}

// Steiner's formula V + A r + M r^2 + 4/3 pi r^3 of the dilated grain, from the entry alone:
// A from the faces, M = sum over the entry's edges of length x exterior angle / 2, the
// angle between the normals of the two faces that hold the edge. Faces split from one
// polygon share a plane and add nothing to M; their diagonals are not edges.
double dilated_volume(const BodyEntry &e)
{
  std::map<std::pair<int, int>, std::vector<Vec3>> normals_at_edge;
  double area = 0;
  for (const auto &f : e.faces) {
    const int n = f[3] < 0 ? 3 : 4;
    for (int k = 1; k + 1 < n; ++k)
      area += 0.5 * (e.vertices[f[k]] - e.vertices[f[0]]).cross(e.vertices[f[k + 1]] - e.vertices[f[0]]).norm();
    for (int k = 0; k < n; ++k) {
      const int a = f[k], b = f[(k + 1) % n];
      normals_at_edge[{std::min(a, b), std::max(a, b)}].push_back(outward_normal(e, f));
    }
  }
  double mean_curvature = 0;
  for (const auto &edge : e.edges) {
    const auto &normals = normals_at_edge.at({std::min(edge[0], edge[1]), std::max(edge[0], edge[1])});
    EXPECT_EQ(normals.size(), 2u) << "edge " << edge[0] << "-" << edge[1] << " must lie between two faces";
    const double angle = std::acos(std::clamp(normals[0].dot(normals[1]), -1.0, 1.0));
    mean_curvature += 0.5 * (e.vertices[edge[0]] - e.vertices[edge[1]]).norm() * angle;
  }
  const double r = e.diameter / 2;
  return core_volume(e) + area * r + mean_curvature * r * r + 4.0 / 3.0 * kPi * r * r * r;
}

// Reads back what write_body_entry wrote: "ID 3 M", then 3 integers and M doubles.
BodyEntry parse_entry(const std::string &text, long long &id, int &m)
{
  std::istringstream in(text);
  int ninteger = 0;
  in >> id >> ninteger >> m;
  EXPECT_EQ(ninteger, 3);
  size_t nv = 0, ne = 0, nf = 0;
  in >> nv >> ne >> nf;
  BodyEntry e;
  Mat3 &I = e.inertia;
  in >> I(0, 0) >> I(1, 1) >> I(2, 2) >> I(0, 1) >> I(0, 2) >> I(1, 2);
  I(1, 0) = I(0, 1), I(2, 0) = I(0, 2), I(2, 1) = I(1, 2);
  e.vertices.resize(nv);
  for (auto &v : e.vertices) in >> v.x() >> v.y() >> v.z();
  e.edges.resize(ne);
  for (auto &edge : e.edges) in >> edge[0] >> edge[1];
  e.faces.resize(nf);
  for (auto &f : e.faces) in >> f[0] >> f[1] >> f[2] >> f[3];
  in >> e.diameter;
  EXPECT_FALSE(in.fail()) << text;
  std::string rest;
  EXPECT_FALSE(in >> rest) << "unexpected trailing value '" << rest << "'";
  return e;
}

}    // namespace

TEST(BodyExport, RoundedBoxMatchesClosedForms)
{
  const double a = 1, b = 2, c = 3, r = 0.1, mass = 2.5;
  const Spheropolyhedron box = make_spheropolyhedron(box_corners(a, b, c), r);
  std::mt19937_64 rng(3);
  const Quat q = random_rotation(rng);
  const BodyEntry e = body_entry(box, q, mass);
  EXPECT_EQ(e.vertices.size(), 8u);
  EXPECT_EQ(e.edges.size(), 12u);
  ASSERT_EQ(e.faces.size(), 6u);
  for (const auto &f : e.faces) EXPECT_GE(f[3], 0) << "a box face is a quad";
  EXPECT_NEAR(core_volume(e), a * b * c, 1e-12);
  const double steiner = a * b * c + 2 * (a * b + b * c + c * a) * r + kPi * (a + b + c) * r * r + 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(dilated_volume(e), steiner, 1e-12);
  EXPECT_DOUBLE_EQ(e.diameter, 2 * r);
  // Box frame inertia: its eigenvalues are the grain's principal moments, its trace is
  // invariant, and it turns with the grain (R I_body R^T).
  const Vec3 principal = box.principal_inertia * (mass / box.volume);
  Eigen::SelfAdjointEigenSolver<Mat3> eig(e.inertia);
  EXPECT_NEAR((eig.eigenvalues() - principal).norm(), 0.0, 1e-12 * principal.norm());
  const Mat3 R = q.toRotationMatrix();
  EXPECT_NEAR((R.transpose() * e.inertia * R - Mat3(principal.asDiagonal())).norm(), 0.0, 1e-12 * principal.norm());
}

TEST(BodyExport, FacesOfMoreThanFourVerticesBecomeTriangleFans)
{
  // A pentagonal prism: two pentagons (3 triangles each) and five quads; 15 edges, none a diagonal.
  std::vector<Vec3> points;
  for (int k = 0; k < 5; ++k)
    for (double z : {-0.5, 0.5}) points.emplace_back(std::cos(2 * kPi * k / 5), std::sin(2 * kPi * k / 5), z);
  const Spheropolyhedron prism = make_spheropolyhedron(points, 0.05);
  const BodyEntry e = body_entry(prism, Quat::Identity(), 1.0);
  EXPECT_EQ(e.vertices.size(), 10u);
  EXPECT_EQ(e.edges.size(), 15u);
  EXPECT_EQ(e.faces.size(), 11u);
  const double pentagon = 2.5 * std::sin(2 * kPi / 5);    // area of the unit-circumradius pentagon
  EXPECT_NEAR(core_volume(e), pentagon * 1.0, 1e-12);
  EXPECT_NEAR(dilated_volume(e), prism.volume, 1e-12 * prism.volume);
}

TEST(BodyExport, RandomGrainsRoundTripThroughTheText)
{
  ShapeLibrary library;
  RandomGrainParams params;
  params.min_vertices = 10, params.max_vertices = 20, params.min_diameter = 0.9, params.max_diameter = 1.1;
  params.radius = 0.05;
  add_random_grains(library, params, 16, 7);
  std::mt19937_64 rng(11);
  for (int id = 1; id <= library.size(); ++id) {
    const Spheropolyhedron &shape = library.shape(id);
    const double mass = 0.7 * shape.volume;
    const Quat q = random_rotation(rng);
    std::ostringstream out;
    write_body_entry(out, 100 + id, body_entry(shape, q, mass));
    std::istringstream lines(out.str());
    int line_count = 0;
    for (std::string line; std::getline(lines, line); ++line_count)
      EXPECT_LT(line.size(), 256u) << "read_data truncates lines of 256 characters or more";
    EXPECT_LE(line_count, 32) << "read_data takes at most 32 lines per body (MAXBODY)";
    long long read_id = 0;
    int m = 0;
    const BodyEntry e = parse_entry(out.str(), read_id, m);
    EXPECT_EQ(read_id, 100 + id);
    EXPECT_EQ(m, 6 + 3 * int(e.vertices.size()) + 2 * int(e.edges.size()) + 4 * int(e.faces.size()) + 1);
    EXPECT_EQ(e.vertices.size(), shape.vertices.size()) << "shape " << id;
    EXPECT_EQ(e.edges.size(), shape.edges.size()) << "shape " << id;
    EXPECT_NEAR(dilated_volume(e), shape.volume, 1e-12 * shape.volume) << "shape " << id;
    Eigen::SelfAdjointEigenSolver<Mat3> eig(e.inertia);
    const Vec3 principal = shape.principal_inertia * 0.7;
    EXPECT_NEAR((eig.eigenvalues() - principal).norm(), 0.0, 1e-12 * principal.norm()) << "shape " << id;
    for (size_t k = 0; k < e.vertices.size(); ++k)
      EXPECT_NEAR((e.vertices[k] - q * shape.vertices[k]).norm(), 0.0, 1e-14);
  }
}

TEST(BodyExport, SphereHasNoEdgesOrFaces)
{
  const Spheropolyhedron ball = make_spheropolyhedron({Vec3::Zero()}, 0.5);
  const BodyEntry e = body_entry(ball, Quat::Identity(), 1.0);
  EXPECT_EQ(e.vertices.size(), 1u);
  EXPECT_TRUE(e.edges.empty());
  EXPECT_TRUE(e.faces.empty());
  EXPECT_EQ(e.value_count(), 6 + 3 + 1);
  EXPECT_DOUBLE_EQ(e.diameter, 1.0);
}

TEST(BodyExport, RefusesABadMass)
{
  const Spheropolyhedron box = make_spheropolyhedron(box_corners(1, 1, 1), 0);
  EXPECT_THROW(body_entry(box, Quat::Identity(), 0.0), ShapeError);
  EXPECT_THROW(body_entry(box, Quat::Identity(), std::nan("")), ShapeError);
}
