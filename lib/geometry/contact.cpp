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

// Public contact queries between grains and wire segments (walls: walls.cpp).
#include "geometry/contact.h"

#include "geometry/core_contact.h"
#include "geometry/feature_key.h"
#include "geometry/segment_closest.h"
#include "math/capacity_bytes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

namespace nscd {
namespace geometry_detail {

Core place_core(const Spheropolyhedron &shape, const Pose &pose, const Vec3 &origin,
                std::vector<Vec3> &vertices, std::vector<Vec3> &normals,
                std::vector<double> &offsets)
{
  const Mat3 rotation = pose.orientation.toRotationMatrix();
  const Vec3 shift = pose.position - origin;
  const int n = static_cast<int>(shape.vertices.size());
  vertices.resize(n);
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < n; ++k) {
    vertices[k] = rotation * shape.vertices[k] + shift;
    sum += vertices[k];
  }
  Core core;
  core.vertices = vertices.data();
  core.count = n;
  core.centroid = sum / n;
  for (int k = 0; k < n; ++k) core.extent = std::max(core.extent, (vertices[k] - core.centroid).norm());
  core.radius = shape.radius;
  if (shape.is_polyhedron()) {
    const int nf = static_cast<int>(shape.faces.size());
    normals.resize(nf);
    offsets.resize(nf);
    for (int f = 0; f < nf; ++f) {
      normals[f] = rotation * shape.faces[f].normal;
      offsets[f] = shape.faces[f].offset + normals[f].dot(shift);
    }
    core.shape = &shape;
    core.normals = normals.data();
    core.offsets = offsets.data();
  }
  return core;
}

namespace {

using Candidate = ContactWorkspace::Candidate;
using Vec2 = Eigen::Vector2d;
constexpr int kMax = ContactSet::kMaxPoints;

// Twice the signed area of triangle (o, a, b): > 0 when counter-clockwise.
double cross2(const Vec2 &o, const Vec2 &a, const Vec2 &b)
{
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Insertion sort of a few elements (std::sort on a tiny std::array trips GCC's
// -Warray-bounds through its 16-element insertion threshold).
template <class T, class Less>
void small_sort(T *first, int n, const Less &less)
{
  for (int k = 1; k < n; ++k)
    for (int j = k; j > 0 && less(first[j], first[j - 1]); --j) std::swap(first[j], first[j - 1]);
}

// The points chosen so far, with their coordinates in the contact plane.
struct Selection {
  std::array<int, kMax> index{};
  std::array<Vec2, kMax> planar{};
  int count = 0;

  bool has(int k) const
  {
    return std::find(index.begin(), index.begin() + count, k) != index.begin() + count;
  }
};

// Convex hull of the selection, counter-clockwise, collinear points dropped (Andrew's
// monotone chain; at most kMax points, on the stack). Returns its vertex count.
int selection_hull(const Selection &sel, std::array<Vec2, 2 * kMax> &hull)
{
  std::array<Vec2, kMax> p = sel.planar;
  const int n = sel.count;
  small_sort(p.data(), n, [](const Vec2 &a, const Vec2 &b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (n < 3) {
    std::copy(p.begin(), p.begin() + n, hull.begin());
    return n;
  }
  int m = 0;
  for (int k = 0; k < n; ++k) {    // lower chain
    while (m >= 2 && cross2(hull[m - 2], hull[m - 1], p[k]) <= 0.0) --m;
    hull[m++] = p[k];
  }
  for (int k = n - 2, lower = m + 1; k >= 0; --k) {    // upper chain
    while (m >= lower && cross2(hull[m - 2], hull[m - 1], p[k]) <= 0.0) --m;
    hull[m++] = p[k];
  }
  return m - 1;    // the last point repeats the first
}

// Area the hull gains by adding q: the triangles q makes with the hull edges it sees
// (a 2-point hull is a segment seen from both sides, so the gain is the triangle area).
double area_gain(const std::array<Vec2, 2 * kMax> &hull, int m, const Vec2 &q)
{
  if (m < 2) return 0.0;
  double gain = 0.0;
  for (int k = 0; k < m; ++k) gain += std::max(0.0, -cross2(hull[k], hull[(k + 1) % m], q));
  return 0.5 * gain;
}

// Fills the selection up to kMax with points of `tier`, each adding the most patch area;
// when no point adds a significant area (one point chosen, or all collinear), the point
// farthest from every chosen one. Ties go to the lower index (deterministic).
template <class Tier, class Planar>
void fill_for_coverage(const std::vector<Candidate> &pts, int tier, const Tier &tier_of,
                       const Planar &planar, double min_area, Selection &sel)
{
  const int n = static_cast<int>(pts.size());
  std::array<Vec2, 2 * kMax> hull;
  while (sel.count < kMax) {
    const int m = selection_hull(sel, hull);
    int by_area = -1, by_distance = -1;
    double best_area = 0.0, best_distance = 0.0;
    for (int k = 0; k < n; ++k) {
      if (tier_of(k) != tier || sel.has(k)) continue;
      const Vec2 q = planar(k);
      const double gain = area_gain(hull, m, q);
      double distance = std::numeric_limits<double>::infinity();
      for (int c = 0; c < sel.count; ++c) distance = std::min(distance, (q - sel.planar[c]).squaredNorm());
      if (by_area < 0 || gain > best_area) {
        by_area = k;
        best_area = gain;
      }
      if (by_distance < 0 || distance > best_distance) {
        by_distance = k;
        best_distance = distance;
      }
    }
    if (by_area < 0) return;    // the tier is exhausted
    const int k = best_area > min_area ? by_area : by_distance;
    sel.index[sel.count] = k;
    sel.planar[sel.count++] = planar(k);
  }
}

// Chooses kMax of more than kMax points, depth first. Tiers: 0 penetrating or touching
// (gap <= 0), 1 about to touch (gap <= max(smallest gap, 0) + kTouchBand * L), 2 the
// rest. Whole tiers are kept in that order while they fit; the first that does not fit
// is chosen from for coverage (starting with the deepest point if nothing is chosen yet,
// which is always in the first non-empty tier). So no point is ever dropped in favour of
// a shallower tier, and within a tier the points span the patch.
int choose_points(const std::vector<Candidate> &pts, const Vec3 &normal, double length_scale,
                  std::array<int, kMax> &chosen)
{
  const int n = static_cast<int>(pts.size());
  int deepest = 0;
  for (int k = 1; k < n; ++k)
    if (pts[k].gap < pts[deepest].gap) deepest = k;
  const double touch_limit = std::max(pts[deepest].gap, 0.0) + Tolerance::kTouchBand * length_scale;
  auto tier_of = [&](int k) { return pts[k].gap <= 0.0 ? 0 : (pts[k].gap <= touch_limit ? 1 : 2); };
  const Vec3 u = any_perpendicular(normal).normalized(), w = normal.cross(u);
  auto planar = [&](int k) { return Vec2(u.dot(pts[k].position), w.dot(pts[k].position)); };
  const double min_area = Tolerance::kClip * length_scale * length_scale;

  Selection sel;
  for (int tier = 0; tier < 3 && sel.count < kMax; ++tier) {
    int members = 0;
    for (int k = 0; k < n; ++k) members += tier_of(k) == tier;
    if (sel.count + members <= kMax) {
      for (int k = 0; k < n; ++k)
        if (tier_of(k) == tier) {
          sel.index[sel.count] = k;
          sel.planar[sel.count++] = planar(k);
        }
      continue;
    }
    if (sel.count == 0) {
      sel.index[0] = deepest;
      sel.planar[0] = planar(deepest);
      sel.count = 1;
    }
    fill_for_coverage(pts, tier, tier_of, planar, min_area, sel);
  }
  chosen = sel.index;
  return sel.count;
}

}    // namespace

void write_contact_set(const ContactWorkspace &workspace, const Vec3 &normal,
                       const Vec3 &origin, double length_scale, ContactSet &out)
{
  const auto &pts = workspace.candidates;
  std::array<int, ContactSet::kMaxPoints> chosen{};
  int count = static_cast<int>(pts.size());
  if (count > ContactSet::kMaxPoints) {
    count = choose_points(pts, normal, length_scale, chosen);
    small_sort(chosen.data(), count, std::less<int>());    // keep the clipping order
  } else {
    for (int k = 0; k < count; ++k) chosen[k] = k;
  }
  out.count = count;
  for (int k = 0; k < count; ++k) {
    const Candidate &c = pts[chosen[k]];
    out.points[k] = {c.position + origin, c.normal, c.gap, c.key};
  }
}

void check_activation(double activation)
{
  if (!std::isfinite(activation) || activation < 0.0) {
    std::ostringstream out;
    out << "contact activation distance " << activation
        << " is invalid; give a finite distance >= 0 (0 reports touching contacts only)";
    throw ContactError(out.str());
  }
}

}    // namespace geometry_detail

namespace {

using namespace geometry_detail;

void check_shape(const Spheropolyhedron &shape, const char *which)
{
  const size_t n = shape.vertices.size();
  if (n == 0 || (n == 3) || n >= static_cast<size_t>(kMaxKeyedVertices) ||
      (shape.is_polyhedron() && (shape.faces.empty() || shape.edge_faces.size() != shape.edges.size()))) {
    std::ostringstream out;
    out << "shape of " << which << " with " << n << " vertices, " << shape.faces.size()
        << " faces and " << shape.edges.size() << " edges is not a valid core (1, 2 or 4.."
        << kMaxKeyedVertices - 1 << " vertices with faces and edge-face links); build it "
        << "with make_spheropolyhedron()";
    throw ContactError(out.str());
  }
}

double merge_distance_for(double size_i, double size_j)
{
  return Tolerance::kMerge * std::min(size_i, size_j);
}

// Core of a wire segment (2 vertices, no faces) in the frame at origin.
Core place_segment(const Segment &segment, const Vec3 &origin, std::vector<Vec3> &vertices)
{
  vertices.resize(2);
  vertices[0] = segment.p0 - origin;
  vertices[1] = segment.p1 - origin;
  Core core;
  core.vertices = vertices.data();
  core.count = 2;
  core.centroid = 0.5 * (vertices[0] + vertices[1]);
  core.extent = 0.5 * (vertices[1] - vertices[0]).norm();
  core.radius = segment.radius;
  return core;
}

void check_segment(const Segment &segment, const char *which)
{
  if (!segment.p0.allFinite() || !segment.p1.allFinite() || !std::isfinite(segment.radius) ||
      segment.radius < 0.0) {
    std::ostringstream out;
    out << "wire segment " << which << " (p0 = " << segment.p0.transpose() << ", p1 = "
        << segment.p1.transpose() << ", radius = " << segment.radius
        << ") is invalid; give finite end points and a radius >= 0";
    throw ContactError(out.str());
  }
}

// Two spheres: the line of centres (the most common pair in a sphere packing).
void sphere_pair(const Spheropolyhedron &si, const Pose &pi, const Spheropolyhedron &sj,
                 const Pose &pj, double activation, ContactSet &out)
{
  const Vec3 ci = pi.to_world(si.vertices[0]), cj = pj.to_world(sj.vertices[0]);
  const Vec3 between = ci - cj;
  const double distance = between.norm();
  const double gap = distance - si.radius - sj.radius;
  if (!(gap <= activation)) return;
  // Concentric spheres have no line of centres: any fixed direction will do.
  const Vec3 normal = distance > 0.0 ? Vec3(between / distance) : Vec3::UnitX();
  const Vec3 point = 0.5 * (ci - si.radius * normal + cj + sj.radius * normal);
  out.points[0] = {point, normal, gap, make_key(vertex_feature(0), vertex_feature(0))};
  out.count = 1;
}

}    // namespace

ContactSet contact_grains(const Spheropolyhedron &shape_i, const Pose &pose_i,
                          const Spheropolyhedron &shape_j, const Pose &pose_j,
                          double activation, ContactWorkspace &ws, double speculative_distance)
{
  ContactSet out;
  check_activation(activation);
  if (std::isnan(speculative_distance))
    throw ContactError("speculative distance is NaN; give a distance >= 0 (0: no speculative points)");
  // Bounding spheres first: most pairs handed over by a neighbour list end here.
  const double reach = shape_i.bounding_radius + shape_j.bounding_radius + activation;
  if ((pose_j.position - pose_i.position).squaredNorm() > reach * reach) return out;
  check_shape(shape_i, "grain i");
  check_shape(shape_j, "grain j");
  if (shape_i.is_sphere() && shape_j.is_sphere()) {
    sphere_pair(shape_i, pose_i, shape_j, pose_j, activation, out);
    return out;
  }

  // Frame origin at grain i's centre: coordinates stay small, round-off stays relative.
  const Vec3 &origin = pose_i.position;
  const Core a = place_core(shape_i, pose_i, origin, ws.vertices_i, ws.normals_i, ws.offsets_i);
  const Core b = place_core(shape_j, pose_j, origin, ws.vertices_j, ws.normals_j, ws.offsets_j);
  const double merge = merge_distance_for(shape_i.bounding_radius, shape_j.bounding_radius);
  const ManifoldInput in{activation, std::max(shape_i.bounding_radius, shape_j.bounding_radius), merge, speculative_distance};
  const Vec3 normal = build_manifold(a, b, in, ws);
  write_contact_set(ws, normal, origin, in.length_scale, out);
  return out;
}

SegmentGrainContact contact_segment_grain(const Segment &segment, const Spheropolyhedron &shape,
                                          const Pose &pose, double activation,
                                          ContactWorkspace &ws)
{
  SegmentGrainContact out;
  check_activation(activation);
  check_segment(segment, "i");
  const Vec3 origin = 0.5 * (segment.p0 + segment.p1);
  const double half_length = 0.5 * (segment.p1 - segment.p0).norm();
  const double segment_size = half_length + segment.radius;
  const double reach = segment_size + shape.bounding_radius + activation;
  if ((pose.position - origin).squaredNorm() > reach * reach) return out;
  check_shape(shape, "the grain");

  const Core a = place_segment(segment, origin, ws.vertices_i);
  const Core b = place_core(shape, pose, origin, ws.vertices_j, ws.normals_j, ws.offsets_j);
  const double merge = merge_distance_for(segment_size, shape.bounding_radius);
  const ManifoldInput in{activation, std::max(segment_size, shape.bounding_radius), merge};
  const Vec3 normal = build_manifold(a, b, in, ws);
  if (ws.candidates.empty()) return out;

  // Every point lies on the segment's axis: a clipped face patch or an edge overlap is a
  // stretch of it, whose two ends carry the contact (a third point would lie between them).
  auto s_of = [&](size_t k) {
    return closest_parameter_on_segment(a.vertices[0], a.vertices[1], ws.candidates[k].core_point_i);
  };
  auto add_point = [&](size_t k, double s) {
    SegmentContact &p = out.points[out.count++];
    p.point = ws.candidates[k].position + origin;
    p.normal = normal;
    p.gap = ws.candidates[k].gap;
    p.s_i = s;
    p.key = ws.candidates[k].key;
  };
  size_t first = 0, last = 0;
  double s_first = s_of(0), s_last = s_first;
  for (size_t k = 1; k < ws.candidates.size(); ++k) {
    const double s = s_of(k);
    if (s < s_first) {
      first = k;
      s_first = s;
    }
    if (s > s_last) {
      last = k;
      s_last = s;
    }
  }
  add_point(first, s_first);
  if (last != first) add_point(last, s_last);
  return out;
}

namespace {
SegmentPart segment_part(std::uint32_t feature)
{
  if (feature_type(feature) != FeatureType::Vertex) return SegmentPart::inside;
  return feature_index(feature) == 0 ? SegmentPart::start : SegmentPart::end;
}
}    // namespace

SegmentPart segment_part_i(const SegmentContact &c) { return segment_part(key_feature_i(c.key)); }
SegmentPart segment_part_j(const SegmentContact &c) { return segment_part(key_feature_j(c.key)); }

std::optional<SegmentContact> contact_segments(const Segment &segment_i,
                                               const Segment &segment_j, double activation)
{
  check_activation(activation);
  check_segment(segment_i, "i");
  check_segment(segment_j, "j");
  const Vec3 origin = 0.5 * (segment_i.p0 + segment_i.p1);
  const Vec3 ai = segment_i.p0 - origin, bi = segment_i.p1 - origin;
  const Vec3 aj = segment_j.p0 - origin, bj = segment_j.p1 - origin;
  const double scale = std::max({(bi - ai).norm(), (bj - aj).norm(), segment_i.radius,
                                 segment_j.radius, std::numeric_limits<double>::min()});
  const SegmentClosest c = closest_points_on_segments(ai, bi, aj, bj, Tolerance::kClip * scale);
  const Vec3 between = c.point_a - c.point_b;    // from j to i
  const double distance = between.norm();
  const double gap = distance - segment_i.radius - segment_j.radius;
  if (!(gap <= activation)) return std::nullopt;

  Vec3 normal;
  if (distance > Tolerance::kClip * scale) {
    normal = between / distance;
  } else {
    // Crossing axes: the common perpendicular, oriented from j's middle to i's.
    const Vec3 ei = bi - ai, ej = bj - aj;
    Vec3 n = ei.cross(ej);
    if (!(n.squaredNorm() > 1e-24 * ei.squaredNorm() * ej.squaredNorm()) || n.squaredNorm() == 0.0)
      n = any_perpendicular(ei.squaredNorm() > 0.0 ? ei : (ej.squaredNorm() > 0.0 ? ej : Vec3::UnitX()));
    normal = n.normalized();
    if (normal.dot(0.5 * (ai + bi) - 0.5 * (aj + bj)) < 0.0) normal = -normal;
  }
  SegmentContact out;
  // Midpoint between the dilated surfaces: i's surface is at point_a - r_i n, j's at
  // point_b + r_j n.
  out.point = 0.5 * (c.point_a + c.point_b + (segment_j.radius - segment_i.radius) * normal) + origin;
  out.normal = normal;
  out.gap = gap;
  out.s_i = c.s;
  out.s_j = c.t;
  auto end_feature = [](double s) {
    return s <= 0.0 ? vertex_feature(0) : (s >= 1.0 ? vertex_feature(1) : edge_feature(0, 1));
  };
  out.key = make_key(end_feature(c.s), end_feature(c.t));
  return out;
}

std::size_t ContactWorkspace::memory_bytes() const
{
  return capacity_bytes(vertices_i) + capacity_bytes(vertices_j) + capacity_bytes(normals_i) +
         capacity_bytes(normals_j) + capacity_bytes(offsets_i) + capacity_bytes(offsets_j) + capacity_bytes(polygon) +
         capacity_bytes(clipped) + capacity_bytes(candidates) + capacity_bytes(arcs_i) + capacity_bytes(arcs_j) +
         capacity_bytes(edges_near_i) + capacity_bytes(edges_near_j) + capacity_bytes(marks_ref) +
         capacity_bytes(marks_inc) + capacity_bytes(near_faces) + capacity_bytes(near_sides) +
         capacity_bytes(vertex_rows) + capacity_bytes(marks_measured);
}

}    // namespace nscd
