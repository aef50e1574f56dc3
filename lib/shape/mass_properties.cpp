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

#include "shape/mass_properties.h"

#include <cmath>

namespace nscd {
namespace {

constexpr double kPi = 3.14159265358979323846;

Mat3 symmetric_product(const Vec3 &a, const Vec3 &b) { return a * b.transpose() + b * a.transpose(); }

double angle_between(const Vec3 &a, const Vec3 &b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// Moments of the triangle (a, b, c) as a surface: area, integral of y, integral of y y^T.
struct TriangleMoments {
  double area;
  Vec3 first;
  Mat3 second;
};

TriangleMoments triangle_moments(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const Vec3 sum = a + b + c;
  const Mat3 outer = a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose();
  return {area, area * sum / 3.0, area / 12.0 * outer};
}

// The part {y + t n : y in face, 0 <= t <= r}.
MassMoments face_prism_moments(const std::vector<Vec3> &vertices, const Face &face, double r)
{
  double area = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  const Vec3 &apex = vertices[face.vertices[0]];
  for (size_t i = 1; i + 1 < face.vertices.size(); ++i) {
    const auto t = triangle_moments(apex, vertices[face.vertices[i]], vertices[face.vertices[i + 1]]);
    area += t.area;
    first += t.first;
    second += t.second;
  }
  const Vec3 &n = face.normal;
  MassMoments m;
  m.volume = area * r;
  m.first = r * first + 0.5 * area * r * r * n;
  m.second = r * second + 0.5 * r * r * symmetric_product(first, n) +
             area * r * r * r / 3.0 * n * n.transpose();
  return m;
}

// The part {a + s e + rho (cos phi n1 + sin phi w) : s in [0, L], rho in [0, r],
// phi in [0, theta]}, w the unit vector orthogonal to e and n1 on the side of n2.
MassMoments edge_wedge_moments(const Vec3 &a, const Vec3 &b, const Vec3 &n1, const Vec3 &n2, double r)
{
  const double length = (b - a).norm();
  const Vec3 e = (b - a) / length;
  Vec3 w = e.cross(n1);
  if (w.dot(n2) < 0.0) w = -w;
  const double theta = angle_between(n1, n2);

  // Integrals over the angle of q(phi) and q q^T(phi).
  const Vec3 q1 = std::sin(theta) * n1 + (1.0 - std::cos(theta)) * w;
  const double s2 = std::sin(2.0 * theta) / 4.0;
  const double half_sin_sq = 0.5 * std::sin(theta) * std::sin(theta);
  const Mat3 q2 = (0.5 * theta + s2) * n1 * n1.transpose() + (0.5 * theta - s2) * w * w.transpose() +
                  half_sin_sq * symmetric_product(n1, w);

  const double section = 0.5 * theta * r * r;    // area of the circular sector
  const double int_s = 0.5 * length * length * section;
  const double int_ss = length * length * length / 3.0 * section;
  const Vec3 int_rho_q = length * r * r * r / 3.0 * q1;
  const Vec3 int_s_rho_q = 0.5 * length * length * r * r * r / 3.0 * q1;
  const Mat3 int_rho2_qq = length * r * r * r * r / 4.0 * q2;

  MassMoments m;
  m.volume = length * section;
  m.first = a * m.volume + e * int_s + int_rho_q;
  m.second = a * a.transpose() * m.volume + symmetric_product(a, e) * int_s +
             symmetric_product(a, int_rho_q) + e * e.transpose() * int_ss +
             symmetric_product(e, int_s_rho_q) + int_rho2_qq;
  return m;
}

// Normal cone of a vertex, as the moments of the directions d over its spherical polygon:
// solid angle, integral of d and integral of d d^T. The last two follow from the
// divergence theorem on the unit cone; each side plane is orthogonal to an edge at the
// vertex (see doc/Howto_nscd_shapes_physics.rst).
struct ConeMoments {
  double solid_angle = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 side_sum = Mat3::Zero();    // sum over sides of tan(theta/2) (n1 + n2) e^T

  Mat3 second() const
  {
    const Mat3 t = (solid_angle * Mat3::Identity() - side_sum) / 3.0;
    return 0.5 * (t + t.transpose());
  }
};

MassMoments vertex_sector_moments(const Vec3 &v, const ConeMoments &cone, double r)
{
  const double r3 = r * r * r;
  const Vec3 d1 = cone.first * (r3 * r / 4.0);
  MassMoments m;
  m.volume = cone.solid_angle * r3 / 3.0;
  m.first = v * m.volume + d1;
  m.second = v * v.transpose() * m.volume + symmetric_product(v, d1) + cone.second() * (r3 * r * r / 5.0);
  return m;
}

std::vector<ConeMoments> vertex_cones(const std::vector<Vec3> &vertices, const std::vector<Face> &faces,
                                      const std::vector<std::array<int, 2>> &edges,
                                      const std::vector<std::array<int, 2>> &edge_faces)
{
  std::vector<ConeMoments> cones(vertices.size());
  const auto angles = vertex_normal_cone_angles(vertices, faces);
  for (size_t i = 0; i < vertices.size(); ++i) cones[i].solid_angle = angles[i];
  for (size_t k = 0; k < edges.size(); ++k) {
    const Vec3 &n1 = faces[edge_faces[k][0]].normal;
    const Vec3 &n2 = faces[edge_faces[k][1]].normal;
    const double theta = angle_between(n1, n2);
    const Vec3 spread = std::tan(0.5 * theta) * (n1 + n2);
    const int a = edges[k][0], b = edges[k][1];
    const Vec3 e = (vertices[b] - vertices[a]).normalized();
    // At vertex a the cone's side is orthogonal to e, outward along e; at b along -e.
    cones[a].first -= 0.5 * theta * e;
    cones[b].first += 0.5 * theta * e;
    cones[a].side_sum += spread * e.transpose();
    cones[b].side_sum -= spread * e.transpose();
  }
  return cones;
}

}    // namespace

Mat3 MassMoments::inertia_about_centre() const
{
  const Vec3 c = centre();
  const Mat3 central = second - volume * c * c.transpose();
  // I = trace(C) 1 - C, with each diagonal entry summed from the other two diagonal
  // entries of C rather than as trace - C_kk: no cancellation for a needle along an axis.
  Mat3 inertia = -central;
  inertia(0, 0) = central(1, 1) + central(2, 2);
  inertia(1, 1) = central(0, 0) + central(2, 2);
  inertia(2, 2) = central(0, 0) + central(1, 1);
  return inertia;
}

MassMoments ball_moments(const Vec3 &centre, double radius)
{
  MassMoments m;
  m.volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  m.first = centre * m.volume;
  m.second = centre * centre.transpose() * m.volume + m.volume * radius * radius / 5.0 * Mat3::Identity();
  return m;
}

MassMoments spherocylinder_moments(const Vec3 &a, const Vec3 &b, double radius)
{
  const double r = radius, length = (b - a).norm();
  const Vec3 e = (b - a) / length, mid = 0.5 * (a + b);
  MassMoments cylinder;
  cylinder.volume = kPi * r * r * length;
  cylinder.first = mid * cylinder.volume;
  cylinder.second = mid * mid.transpose() * cylinder.volume +
                    kPi * r * r * length * length * length / 12.0 * e * e.transpose() +
                    kPi * r * r * r * r * length / 4.0 * (Mat3::Identity() - e * e.transpose());
  // Each hemisphere: half a ball about its centre, plus the offset of its own centroid.
  auto hemisphere = [&](const Vec3 &centre, const Vec3 &outward) {
    MassMoments h;
    const double axial = kPi * r * r * r * r / 4.0;    // integral of (x - centre).outward
    h.volume = 2.0 / 3.0 * kPi * r * r * r;
    h.first = centre * h.volume + axial * outward;
    h.second = centre * centre.transpose() * h.volume + axial * symmetric_product(centre, outward) +
               h.volume * r * r / 5.0 * Mat3::Identity();
    return h;
  };
  MassMoments total = cylinder;
  total += hemisphere(b, e);
  total += hemisphere(a, -e);
  return total;
}

double polygon_area(const std::vector<Vec3> &vertices, const Face &face)
{
  Vec3 twice_area = Vec3::Zero();
  const size_t n = face.vertices.size();
  for (size_t i = 0; i < n; ++i)
    twice_area += vertices[face.vertices[i]].cross(vertices[face.vertices[(i + 1) % n]]);
  return 0.5 * std::abs(twice_area.dot(face.normal));
}

MassMoments polyhedron_moments(const std::vector<Vec3> &vertices, const std::vector<Face> &faces)
{
  MassMoments m;
  for (const auto &face : faces) {
    const Vec3 &a = vertices[face.vertices[0]];
    for (size_t i = 1; i + 1 < face.vertices.size(); ++i) {
      const Vec3 &b = vertices[face.vertices[i]];
      const Vec3 &c = vertices[face.vertices[i + 1]];
      const double det = a.dot(b.cross(c));    // 6 x signed volume of (0, a, b, c)
      const Vec3 sum = a + b + c;
      m.volume += det / 6.0;
      m.first += det / 24.0 * sum;
      m.second += det / 120.0 *
                  (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
    }
  }
  return m;
}

std::vector<double> vertex_normal_cone_angles(const std::vector<Vec3> &vertices,
                                              const std::vector<Face> &faces)
{
  std::vector<double> angle(vertices.size(), 2.0 * kPi);
  for (const auto &face : faces) {
    const size_t n = face.vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec3 &here = vertices[face.vertices[i]];
      const Vec3 to_prev = vertices[face.vertices[(i + n - 1) % n]] - here;
      const Vec3 to_next = vertices[face.vertices[(i + 1) % n]] - here;
      angle[face.vertices[i]] -= angle_between(to_prev, to_next);
    }
  }
  return angle;
}

double mean_curvature_integral(const std::vector<Vec3> &vertices, const std::vector<Face> &faces,
                               const std::vector<std::array<int, 2>> &edges,
                               const std::vector<std::array<int, 2>> &edge_faces)
{
  double sum = 0.0;
  for (size_t k = 0; k < edges.size(); ++k) {
    const double length = (vertices[edges[k][1]] - vertices[edges[k][0]]).norm();
    sum += 0.5 * length * angle_between(faces[edge_faces[k][0]].normal, faces[edge_faces[k][1]].normal);
  }
  return sum;
}

MassMoments dilated_polyhedron_moments(const std::vector<Vec3> &vertices, const std::vector<Face> &faces,
                                       const std::vector<std::array<int, 2>> &edges,
                                       const std::vector<std::array<int, 2>> &edge_faces, double radius)
{
  MassMoments total = polyhedron_moments(vertices, faces);
  if (radius == 0.0) return total;
  for (const auto &face : faces) total += face_prism_moments(vertices, face, radius);
  for (size_t k = 0; k < edges.size(); ++k) {
    total += edge_wedge_moments(vertices[edges[k][0]], vertices[edges[k][1]],
                                faces[edge_faces[k][0]].normal, faces[edge_faces[k][1]].normal, radius);
  }
  const auto cones = vertex_cones(vertices, faces, edges, edge_faces);
  for (size_t i = 0; i < vertices.size(); ++i) total += vertex_sector_moments(vertices[i], cones[i], radius);
  return total;
}

}    // namespace nscd
