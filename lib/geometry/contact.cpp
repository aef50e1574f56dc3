// Public contact queries between grains and wire segments (walls: walls.cpp).
#include "geometry/contact.h"

#include "geometry/core_contact.h"
#include "geometry/feature_key.h"
#include "geometry/segment_closest.h"

#include <algorithm>
#include <cmath>
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

// Signed area of triangle (p, q, r) seen along `normal`.
double signed_area(const Vec3 &p, const Vec3 &q, const Vec3 &r, const Vec3 &normal)
{
  return (q - p).cross(r - p).dot(normal);
}

// Picks at most kMaxPoints points spanning the patch: the deepest point (it must be
// resolved), the point farthest from it, the one making the largest triangle with
// those, and the one adding the most area outside that triangle.
int choose_spanning_points(const std::vector<Candidate> &pts, const Vec3 &normal,
                           std::array<int, ContactSet::kMaxPoints> &chosen)
{
  const int n = static_cast<int>(pts.size());
  auto argmax = [n](auto score) {
    int best = -1;
    double best_score = 0.0;
    for (int k = 0; k < n; ++k) {
      const double s = score(k);
      if (best < 0 || s > best_score) {
        best = k;
        best_score = s;
      }
    }
    return std::make_pair(best, best_score);
  };
  const int p1 = argmax([&](int k) { return -pts[k].gap; }).first;
  const int p2 = argmax([&](int k) { return (pts[k].position - pts[p1].position).squaredNorm(); }).first;
  const auto [p3, area3] = argmax([&](int k) {
    return std::abs(signed_area(pts[p1].position, pts[p2].position, pts[k].position, normal));
  });
  chosen = {p1, p2, p3, -1};
  if (area3 <= 0.0) return p2 == p1 ? 1 : 2;
  const double orientation =
      signed_area(pts[p1].position, pts[p2].position, pts[p3].position, normal) > 0.0 ? 1.0 : -1.0;
  const auto [p4, gain] = argmax([&](int k) {
    const Vec3 &q = pts[k].position;
    const double e12 = -orientation * signed_area(pts[p1].position, pts[p2].position, q, normal);
    const double e23 = -orientation * signed_area(pts[p2].position, pts[p3].position, q, normal);
    const double e31 = -orientation * signed_area(pts[p3].position, pts[p1].position, q, normal);
    return std::max({e12, e23, e31});
  });
  if (gain <= 0.0) return 3;
  chosen[3] = p4;
  return 4;
}

}    // namespace

void write_contact_set(const ContactWorkspace &workspace, const Vec3 &normal,
                       const Vec3 &origin, ContactSet &out)
{
  const auto &pts = workspace.candidates;
  std::array<int, ContactSet::kMaxPoints> chosen{};
  int count = static_cast<int>(pts.size());
  if (count > ContactSet::kMaxPoints) {
    count = choose_spanning_points(pts, normal, chosen);
    std::sort(chosen.begin(), chosen.begin() + count);    // keep the clipping order
  } else {
    for (int k = 0; k < count; ++k) chosen[k] = k;
  }
  out.count = count;
  for (int k = 0; k < count; ++k) {
    const Candidate &c = pts[chosen[k]];
    out.points[k] = {c.position + origin, normal, c.gap, c.key};
  }
}

}    // namespace geometry_detail

namespace {

using namespace geometry_detail;

void check_activation(double activation)
{
  if (!std::isfinite(activation) || activation < 0.0) {
    std::ostringstream out;
    out << "contact activation distance " << activation
        << " is invalid; give a finite distance >= 0 (0 reports touching contacts only)";
    throw ContactError(out.str());
  }
}

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
                          double activation, ContactWorkspace &ws)
{
  ContactSet out;
  check_activation(activation);
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
  const ManifoldInput in{activation, std::max(shape_i.bounding_radius, shape_j.bounding_radius), merge};
  const Vec3 normal = build_manifold(a, b, in, ws);
  write_contact_set(ws, normal, origin, out);
  return out;
}

std::optional<SegmentContact> contact_segment_grain(const Segment &segment,
                                                    const Spheropolyhedron &shape,
                                                    const Pose &pose, double activation,
                                                    ContactWorkspace &ws)
{
  check_activation(activation);
  check_segment(segment, "i");
  const Vec3 origin = 0.5 * (segment.p0 + segment.p1);
  const double half_length = 0.5 * (segment.p1 - segment.p0).norm();
  const double segment_size = half_length + segment.radius;
  const double reach = segment_size + shape.bounding_radius + activation;
  if ((pose.position - origin).squaredNorm() > reach * reach) return std::nullopt;
  check_shape(shape, "the grain");

  const Core a = place_segment(segment, origin, ws.vertices_i);
  const Core b = place_core(shape, pose, origin, ws.vertices_j, ws.normals_j, ws.offsets_j);
  const double merge = merge_distance_for(segment_size, shape.bounding_radius);
  const ManifoldInput in{activation, std::max(segment_size, shape.bounding_radius), merge};
  const Vec3 normal = build_manifold(a, b, in, ws);
  const auto &pts = ws.candidates;
  if (pts.empty()) return std::nullopt;

  // One point for a soft contact: the deepest; a segment lying flat on a face (equal
  // depths within round-off) gets the middle of the touching stretch instead, so the
  // force does not jump from one end to the other.
  size_t deepest = 0;
  for (size_t k = 1; k < pts.size(); ++k)
    if (pts[k].gap < pts[deepest].gap) deepest = k;
  ContactWorkspace::Candidate c = pts[deepest];
  if (pts.size() == 2 && std::abs(pts[0].gap - pts[1].gap) <= Tolerance::kClip * in.length_scale) {
    c.position = 0.5 * (pts[0].position + pts[1].position);
    c.core_point_i = 0.5 * (pts[0].core_point_i + pts[1].core_point_i);
    // The grain's feature is the face under the segment when one point names it.
    const std::uint32_t fj0 = key_feature_j(pts[0].key), fj1 = key_feature_j(pts[1].key);
    const std::uint32_t grain_feature = feature_type(fj1) == FeatureType::Face ? fj1 : fj0;
    c.key = make_key(edge_feature(0, 1), grain_feature);
  }
  SegmentContact result;
  result.point = c.position + origin;
  result.normal = normal;
  result.gap = c.gap;
  result.s_i = closest_parameter_on_segment(a.vertices[0], a.vertices[1], c.core_point_i);
  result.s_j = 0.0;
  result.key = c.key;
  return result;
}

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

}    // namespace nscd
