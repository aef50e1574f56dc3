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

// The arcs of the edges of a core on the Gauss sphere; sign -1 negates the normals
// (for core b, whose normals enter the Minkowski difference negated).
void load_arcs(const Core &core, double sign, std::vector<ContactWorkspace::EdgeArc> &arcs)
{
  const auto &edge_faces = core.shape->edge_faces;
  arcs.resize(edge_faces.size());
  for (size_t e = 0; e < edge_faces.size(); ++e) {
    const Vec3 n0 = sign * core.normals[edge_faces[e][0]], n1 = sign * core.normals[edge_faces[e][1]];
    arcs[e] = {n0, n1, n1.cross(n0)};
  }
}

// Do the arcs of an edge of a and an edge of b cross? Only then does the cross product of
// the two edges span a face of the Minkowski difference (Gregorius, GDC 2013). The cheap
// half of the test comes first: most pairs fail it.
bool arcs_cross(const ContactWorkspace::EdgeArc &a, const ContactWorkspace::EdgeArc &b)
{
  const double cba = b.n0.dot(a.n1_x_n0), dba = b.n1.dot(a.n1_x_n0);
  if (!(cba * dba < 0.0)) return false;
  const double adc = a.n0.dot(b.n1_x_n0), bdc = a.n1.dot(b.n1_x_n0);
  return adc * bdc < 0.0 && cba * bdc > 0.0;
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

// Edges of `core` passing within `margin` of the other core's bounding sphere. The edges
// of the best edge-edge axis pass within the penetration depth of the other core (they
// touch once the cores are pushed apart along it), and that depth is at most the one of
// the best face axis, so the other edges cannot win and are skipped.
void edges_near(const Core &core, const Core &other, double margin, std::vector<int> &out)
{
  out.clear();
  const auto &edges = core.shape->edges;
  const double reach = other.extent + margin;
  for (size_t e = 0; e < edges.size(); ++e) {
    const Vec3 &p0 = core.vertices[edges[e][0]], &p1 = core.vertices[edges[e][1]];
    const Vec3 d = p1 - p0;
    const double t = std::min(1.0, std::max(0.0, (other.centroid - p0).dot(d) / d.squaredNorm()));
    if ((p0 + t * d - other.centroid).squaredNorm() <= reach * reach) out.push_back(static_cast<int>(e));
  }
}

void test_polytope_edge_pairs(const Core &a, const Core &b, double bias, ContactWorkspace &ws,
                              SeparatingAxis &best)
{
  const double margin = std::abs(best.separation) + bias;
  edges_near(a, b, margin, ws.edges_near_i);
  edges_near(b, a, margin, ws.edges_near_j);
  load_arcs(a, +1.0, ws.arcs_i);
  load_arcs(b, -1.0, ws.arcs_j);
  const auto &edges_a = a.shape->edges, &edges_b = b.shape->edges;
  for (int i : ws.edges_near_i) {
    const Vec3 &pa = a.vertices[edges_a[i][0]];
    const Vec3 ea = a.vertices[edges_a[i][1]] - pa;
    for (int j : ws.edges_near_j) {
      if (!arcs_cross(ws.arcs_i[i], ws.arcs_j[j])) continue;
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

SeparatingAxis find_separating_axis(const Core &a, const Core &b, double length_scale,
                                    ContactWorkspace &ws)
{
  SeparatingAxis best{-std::numeric_limits<double>::infinity(), Vec3::UnitX()};
  test_face_axes(a, b, +1.0, best);
  test_face_axes(b, a, -1.0, best);
  const double bias = Tolerance::kEdgeAxisBias * length_scale;
  if (a.is_polytope() && b.is_polytope()) {
    test_polytope_edge_pairs(a, b, bias, ws, best);
  } else if (a.is_polytope() && b.count == 2) {
    test_segment_edge_pairs(b, a, -1.0, bias, best);
  } else if (b.is_polytope() && a.count == 2) {
    test_segment_edge_pairs(a, b, +1.0, bias, best);
  }
  return best;
}

}    // namespace geometry_detail
}    // namespace nscd
