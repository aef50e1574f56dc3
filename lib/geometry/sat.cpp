// Separating-axis search over face normals and edge-edge cross products. For polytopes
// the minimum-penetration direction is always one of these axes (a face normal of the
// Minkowski difference), so the answer is exact for overlapping cores.
#include "geometry/core_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nscd {
namespace geometry_detail {
namespace {

struct Interval {
  double lo, hi;
};

Interval project(const Core &core, const Vec3 &axis)
{
  Interval out{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int k = 0; k < core.count; ++k) {
    const double d = core.vertices[k].dot(axis);
    out.lo = std::min(out.lo, d);
    out.hi = std::max(out.hi, d);
  }
  return out;
}

double min_projection(const Core &core, const Vec3 &axis)
{
  double lo = std::numeric_limits<double>::infinity();
  for (int k = 0; k < core.count; ++k) lo = std::min(lo, core.vertices[k].dot(axis));
  return lo;
}

// Face normals of `faces_of`: the other core's deepest point below each face plane.
// direction_sign = +1 when faces_of is core a (axis from a to b), -1 otherwise.
void test_face_axes(const Core &faces_of, const Core &other, double direction_sign,
                    SeparatingAxis &best)
{
  for (int f = 0; f < faces_of.face_count(); ++f) {
    const Vec3 &n = faces_of.normals[f];
    const double separation = min_projection(other, n) - faces_of.offsets[f];
    if (separation > best.separation) {
      best.separation = separation;
      best.axis = direction_sign * n;
    }
  }
}

// Do the arcs (a, b) and (c, d) on the Gauss sphere cross? a, b: normals of the faces of
// an edge of core a; c, d: negated normals of an edge of core b. Only then does the cross
// product of the two edges span a face of the Minkowski difference (Gregorius, GDC 2013).
bool arcs_cross(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
  const Vec3 bxa = b.cross(a), dxc = d.cross(c);
  const double cba = c.dot(bxa), dba = d.dot(bxa), adc = a.dot(dxc), bdc = b.dot(dxc);
  return cba * dba < 0.0 && adc * bdc < 0.0 && cba * bdc > 0.0;
}

// Unit cross product of two edge directions, or false when they are parallel.
bool edge_axis(const Vec3 &ea, const Vec3 &eb, Vec3 &axis)
{
  axis = ea.cross(eb);
  const double n2 = axis.squaredNorm();
  if (n2 <= Tolerance::kEdgeAlign * Tolerance::kEdgeAlign * ea.squaredNorm() * eb.squaredNorm())
    return false;
  axis /= std::sqrt(n2);
  return true;
}

void test_polytope_edge_pairs(const Core &a, const Core &b, double bias, SeparatingAxis &best)
{
  const auto &edges_a = a.shape->edges, &edges_b = b.shape->edges;
  const auto &faces_a = a.shape->edge_faces, &faces_b = b.shape->edge_faces;
  for (size_t i = 0; i < edges_a.size(); ++i) {
    const Vec3 &pa = a.vertices[edges_a[i][0]];
    const Vec3 ea = a.vertices[edges_a[i][1]] - pa;
    const Vec3 &na0 = a.normals[faces_a[i][0]], &na1 = a.normals[faces_a[i][1]];
    for (size_t j = 0; j < edges_b.size(); ++j) {
      const Vec3 &nb0 = b.normals[faces_b[j][0]], &nb1 = b.normals[faces_b[j][1]];
      if (!arcs_cross(na0, na1, -nb0, -nb1)) continue;
      const Vec3 &pb = b.vertices[edges_b[j][0]];
      Vec3 axis;
      if (!edge_axis(ea, b.vertices[edges_b[j][1]] - pb, axis)) continue;
      if (axis.dot(pa - a.centroid) < 0.0) axis = -axis;    // outward from a
      const double separation = axis.dot(pb - pa);
      if (separation > best.separation + bias) {
        best.separation = separation;
        best.axis = axis;
      }
    }
  }
}

// A segment core against the edges of a polytope: full projections (the segment has no
// faces to prune with, and there is only one segment edge).
void test_segment_edge_pairs(const Core &segment, const Core &polytope, double direction_sign,
                             double bias, SeparatingAxis &best)
{
  const Vec3 es = segment.vertices[1] - segment.vertices[0];
  for (const auto &edge : polytope.shape->edges) {
    Vec3 axis;
    if (!edge_axis(es, polytope.vertices[edge[1]] - polytope.vertices[edge[0]], axis)) continue;
    const Interval s = project(segment, axis), p = project(polytope, axis);
    // Separation of the segment from the polytope along +axis or -axis, whichever is larger.
    const double forward = p.lo - s.hi, backward = s.lo - p.hi;
    const double separation = std::max(forward, backward);
    if (separation > best.separation + bias) {
      best.separation = separation;
      best.axis = direction_sign * (forward >= backward ? axis : Vec3(-axis));
    }
  }
}

}    // namespace

SeparatingAxis find_separating_axis(const Core &a, const Core &b, double length_scale)
{
  SeparatingAxis best{-std::numeric_limits<double>::infinity(), Vec3::UnitX()};
  test_face_axes(a, b, +1.0, best);
  test_face_axes(b, a, -1.0, best);
  const double bias = Tolerance::kEdgeAxisBias * length_scale;
  if (a.is_polytope() && b.is_polytope()) {
    test_polytope_edge_pairs(a, b, bias, best);
  } else if (a.is_polytope() && b.count == 2) {
    test_segment_edge_pairs(b, a, -1.0, bias, best);
  } else if (b.is_polytope() && a.count == 2) {
    test_segment_edge_pairs(a, b, +1.0, bias, best);
  }
  return best;
}

}    // namespace geometry_detail
}    // namespace nscd
