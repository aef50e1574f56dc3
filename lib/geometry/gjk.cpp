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

#include "geometry/gjk.h"

#include <array>
#include <limits>

namespace nscd {
namespace geometry_detail {
namespace {

// Stop when a new support point improves |v|^2 by less than this fraction: the
// remaining error of the distance is then below 1e-12 relative.
constexpr double kRelativeProgress = 1e-12;
// Below this fraction of the length scale the hulls touch within round-off.
constexpr double kTouchingFraction = 1e-12;
// GJK terminates in a few tens of steps on polytopes; this only guards round-off cycles.
constexpr int kMaxIterations = 128;

struct SimplexVertex {
  Vec3 w;        // a[ia] - b[ib], a point of the Minkowski difference
  int ia, ib;
};

// Sub-simplex holding the point closest to the origin, with its barycentric weights.
struct Simplex {
  std::array<SimplexVertex, 4> v;
  std::array<double, 4> weight;
  int size = 0;

  void keep(std::initializer_list<int> which, std::initializer_list<double> weights)
  {
    std::array<SimplexVertex, 4> kept = v;    // the entries past `which` are unused
    int n = 0;
    for (int k : which) kept[n++] = v[k];
    n = 0;
    for (double wgt : weights) weight[n++] = wgt;
    v = kept;
    size = n;
  }
  Vec3 point() const
  {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < size; ++k) p += weight[k] * v[k].w;
    return p;
  }
};

void reduce_segment(Simplex &s)
{
  const Vec3 &a = s.v[0].w, &b = s.v[1].w;
  const Vec3 ab = b - a;
  const double t = -a.dot(ab);
  if (t <= 0.0) return s.keep({0}, {1.0});
  const double len2 = ab.squaredNorm();
  if (t >= len2) return s.keep({1}, {1.0});
  s.keep({0, 1}, {1.0 - t / len2, t / len2});
}

// Closest point of triangle (v0, v1, v2) to the origin by Voronoi regions (Ericson,
// Real-Time Collision Detection, 5.1.5).
void reduce_triangle(Simplex &s)
{
  const Vec3 a = s.v[0].w, b = s.v[1].w, c = s.v[2].w;
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0.0 && d2 <= 0.0) return s.keep({0}, {1.0});
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0.0 && d4 <= d3) return s.keep({1}, {1.0});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return s.keep({0, 1}, {1.0 - t, t});
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0.0 && d5 <= d6) return s.keep({2}, {1.0});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return s.keep({0, 2}, {1.0 - t, t});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return s.keep({1, 2}, {1.0 - t, t});
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // Degenerate (collinear) triangle: its closest point is on its longest edge.
    const double lab = ab.squaredNorm(), lac = ac.squaredNorm(), lbc = (c - b).squaredNorm();
    if (lab >= lac && lab >= lbc) s.keep({0, 1}, {0.5, 0.5});
    else if (lac >= lbc) s.keep({0, 2}, {0.5, 0.5});
    else s.keep({1, 2}, {0.5, 0.5});
    return reduce_segment(s);
  }
  s.weight = {va / sum, vb / sum, vc / sum, 0.0};
}

// True when the origin and vertex d lie on opposite sides of plane (a, b, c). A
// degenerate (flat) tetrahedron counts as "outside" so its faces get examined.
bool origin_outside_face(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
  const Vec3 n = (b - a).cross(c - a);
  const double side_origin = -n.dot(a);
  const double side_d = n.dot(d - a);
  return side_origin * side_d <= 0.0;
}

// Returns false when the origin is inside the tetrahedron (the hulls overlap).
bool reduce_tetrahedron(Simplex &s)
{
  static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
  double best = std::numeric_limits<double>::infinity();
  Simplex best_simplex;
  bool any_outside = false;
  for (const auto &f : kFaces) {
    if (!origin_outside_face(s.v[f[0]].w, s.v[f[1]].w, s.v[f[2]].w, s.v[f[3]].w)) continue;
    any_outside = true;
    Simplex face;
    face.v = {s.v[f[0]], s.v[f[1]], s.v[f[2]], s.v[f[3]]};
    face.size = 3;
    reduce_triangle(face);
    const double d2 = face.point().squaredNorm();
    if (d2 < best) {
      best = d2;
      best_simplex = face;
    }
  }
  if (!any_outside) return false;
  s = best_simplex;
  return true;
}

// Reduces the simplex to the part nearest the origin; false when it encloses the origin.
bool reduce(Simplex &s)
{
  switch (s.size) {
    case 1: s.weight[0] = 1.0; return true;
    case 2: reduce_segment(s); return true;
    case 3: reduce_triangle(s); return true;
    default: return reduce_tetrahedron(s);
  }
}

int support_index(const Vec3 *p, int n, const Vec3 &direction)
{
  int best = 0;
  double best_dot = p[0].dot(direction);
  for (int k = 1; k < n; ++k) {
    const double d = p[k].dot(direction);
    if (d > best_dot) {
      best_dot = d;
      best = k;
    }
  }
  return best;
}

bool contains(const Simplex &s, int ia, int ib)
{
  for (int k = 0; k < s.size; ++k)
    if (s.v[k].ia == ia && s.v[k].ib == ib) return true;
  return false;
}

void set_closest_points(const Simplex &s, const Vec3 *a, const Vec3 *b, GjkResult &out)
{
  out.point_a.setZero();
  out.point_b.setZero();
  for (int k = 0; k < s.size; ++k) {
    out.point_a += s.weight[k] * a[s.v[k].ia];
    out.point_b += s.weight[k] * b[s.v[k].ib];
  }
  out.distance = (out.point_a - out.point_b).norm();
}

}    // namespace

GjkResult gjk_distance(const Vec3 *a, int na, const Vec3 *b, int nb, double length_scale)
{
  GjkResult out;
  const double touching2 = (kTouchingFraction * length_scale) * (kTouchingFraction * length_scale);
  Simplex s;
  s.v[0] = {a[0] - b[0], 0, 0};
  s.weight[0] = 1.0;
  s.size = 1;
  Vec3 v = s.v[0].w;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double vv = v.squaredNorm();
    if (vv <= touching2) {
      out.overlap = true;
      return out;
    }
    const int ia = support_index(a, na, -v);
    const int ib = support_index(b, nb, v);
    const Vec3 w = a[ia] - b[ib];
    // No support point beyond the current closest point: v is the exact answer.
    if (vv - v.dot(w) <= kRelativeProgress * vv || contains(s, ia, ib)) break;
    const Simplex previous = s;
    s.v[s.size++] = {w, ia, ib};
    if (!reduce(s)) {
      out.overlap = true;
      return out;
    }
    const Vec3 next = s.point();
    if (next.squaredNorm() >= vv) {
      s = previous;    // round-off stalled the descent: keep the better simplex
      break;
    }
    v = next;
  }
  set_closest_points(s, a, b, out);
  return out;
}

}    // namespace geometry_detail
}    // namespace nscd
