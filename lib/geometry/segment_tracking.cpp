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

// Segment-grain contact from the last closest feature (segment_tracking.h).
//
// Why a Voronoi check is enough: the distance from the segment's point at parameter s to
// the grain's core, f(s), is convex. If the point p of the segment closest to a feature F
// lies strictly inside F's Voronoi region (the points whose closest core point is on F),
// then f equals the distance to F near p, which is smallest at p, so p is a local and
// therefore the global minimum of f: F and p are the closest features of segment and core,
// which is what contact_segment_grain finds with GJK. Margins keep every case away from
// the tolerances at which contact_segment_grain switches branch (face alignment, the
// near-touch separating-axis path, clipping, merging); there it answers itself.
#include "geometry/segment_tracking.h"

#include "geometry/core_contact.h"
#include "geometry/feature_key.h"
#include "geometry/gjk.h"
#include "geometry/segment_closest.h"

#include <algorithm>
#include <cmath>

namespace nscd {

using namespace geometry_detail;

namespace {

// The closest-point direction must keep this sine of an angle from the boundary of the
// feature's Voronoi region: well above contact_segment_grain's face alignment (1.4e-4
// rad) and edge perpendicularity (1e-7) tolerances.
constexpr double kAngleMargin = 1e-3;
// Cores closer than this (times the length scale) go to contact_segment_grain, which
// switches to its separating-axis search below Tolerance::kNearTouch.
constexpr double kNearTouchMargin = 10.0 * Tolerance::kNearTouch;
// A clipping distance or a parameter this close (times the length scale) to a decision
// threshold goes to contact_segment_grain: round-off could decide either way.
constexpr double kDecisionMargin = 1e-12;

// Lengths of contact_segment_grain for this pair.
struct Scales {
  double length;    // length scale of the manifold (larger size)
  double merge;     // merge distance of close points
  double clip;      // clipping tolerance
};

Scales scales_of(const Vec3 &a, const Vec3 &b, double wire_radius, const Spheropolyhedron &shape)
{
  const double segment_size = 0.5 * (b - a).norm() + wire_radius;
  const double length = std::max(segment_size, shape.bounding_radius);
  return {length, Tolerance::kMerge * std::min(segment_size, shape.bounding_radius), Tolerance::kClip * length};
}

// The segment's feature at parameter s (end sphere or inside), as in the manifold's keys.
std::uint32_t segment_feature_at(double s)
{
  if (s <= 0.0) return vertex_feature(0);
  if (s >= 1.0) return vertex_feature(1);
  return edge_feature(0, 1);
}

// Answer in the grain's body frame, written where the caller's world-frame answer goes
// (to_world turns it in place). An answer function that gives up writes nothing.
struct BodyAnswer {
  SegmentGrainContact &contact;
  double smallest_gap = 0.0;
  void start()    // before the first point (the caller's answer starts zeroed; add_point
  {                // writes every field of a point but s_j, which stays 0 for a grain)
    contact.count = 0;
    smallest_gap = INFINITY;
  }
};

// Adds the point `core_point` of the segment (body frame, at parameter s along a -> b, known
// to the caller from how it found the point) at core_distance from the core along the unit
// normal from grain to segment: position midway between the dilated surfaces, gap. Points
// with gap > activation are not reported.
void add_point(const Vec3 &core_point, double s, const Vec3 &normal, double core_distance, double grain_radius,
               double wire_radius, double activation, std::uint64_t key, BodyAnswer &out)
{
  const double gap = core_distance - grain_radius - wire_radius;
  out.smallest_gap = std::min(out.smallest_gap, gap);
  if (!(gap <= activation)) return;
  SegmentContact &p = out.contact.points[out.contact.count++];
  p.point = core_point + 0.5 * (grain_radius - wire_radius - core_distance) * normal;
  p.normal = normal;
  p.gap = gap;
  p.s_i = s;
  p.key = key;
}

// Where the segment leaves face f's prism (the region over the face, inside its side
// planes) at each end: -1 if that end lies over the face, else the side plane it crosses
// last on the way out (the innermost crossing), at parameter `at` along a -> b. False
// where round-off could decide otherwise (an end or a crossing next to a side plane), or
// where the segment misses the prism.
struct FaceSides {
  int exit[2] = {-1, -1};
  double at[2] = {0.0, 1.0};
};

bool sides_of(const ShapeFeatures &features, int f, const Vec3 &a, const Vec3 &b, const Scales &scale, FaceSides &out)
{
  const ShapeFeatures::FaceInfo &info = features.face(f);
  const double guard = kDecisionMargin * scale.length;
  for (int k = 0; k < info.side_count; ++k) {
    const ShapeFeatures::Side &side = features.side(info.first_side + k);
    const double d[2] = {side.outward.dot(a) - side.offset, side.outward.dot(b) - side.offset};
    if (std::abs(d[0] - scale.clip) <= guard || std::abs(d[1] - scale.clip) <= guard) return false;
    const bool out0 = d[0] > scale.clip, out1 = d[1] > scale.clip;
    if (out0 && out1) return false;    // the whole segment beyond this side
    if (!out0 && !out1) continue;
    const int e = out0 ? 0 : 1;
    const double t = std::min(1.0, std::max(0.0, d[0] / (d[0] - d[1])));    // Sutherland-Hodgman's crossing
    if (out.exit[e] >= 0 && std::abs(t - out.at[e]) <= 1e3 * kDecisionMargin) return false;    // at a corner
    if (out.exit[e] < 0 || (e == 0 ? t > out.at[0] : t < out.at[1])) {
      out.exit[e] = k;
      out.at[e] = t;
    }
  }
  return out.at[0] < out.at[1];
}

// The face case of contact_segment_grain for face f (the contact axis is f's normal): the
// segment clipped by f's side planes, each end over the face or where the segment leaves
// the face's prism. False where round-off could decide otherwise.
bool clip_to_face(const ShapeFeatures &features, int f, const FaceSides &sides, const Vec3 &a, const Vec3 &b,
                  const Scales &scale, double wire_radius, double activation, BodyAnswer &out)
{
  const Spheropolyhedron &shape = features.shape();
  const Face &face = shape.faces[f];
  const ShapeFeatures::FaceInfo &info = features.face(f);
  const double guard = kDecisionMargin * scale.length;
  const Vec3 end[2] = {a, b};
  Vec3 core_point[2];
  double s[2] = {0.0, 1.0};
  std::uint64_t key[2];
  for (int e = 0; e < 2; ++e) {
    const int k = sides.exit[e];
    if (k < 0) {
      core_point[e] = end[e];
      key[e] = make_key(vertex_feature(e), face_feature(f));
      continue;
    }
    core_point[e] = a + sides.at[e] * (b - a);
    s[e] = sides.at[e];
    for (int j = 0; j < info.side_count; ++j) {    // inside the face's other side planes
      if (j == k) continue;
      const ShapeFeatures::Side &other = features.side(info.first_side + j);
      if (other.outward.dot(core_point[e]) - other.offset > scale.clip - guard) return false;
    }
    const int m = info.side_count;
    key[e] = make_key(edge_feature(0, 1), edge_feature(face.vertices[k], face.vertices[(k + 1) % m]));
  }
  if ((core_point[1] - core_point[0]).norm() <= 4.0 * scale.merge) return false;    // would merge

  out.start();
  for (int e = 0; e < 2; ++e) {
    const double height = face.normal.dot(core_point[e]) - face.offset;
    add_point(core_point[e], s[e], face.normal, height, shape.radius, wire_radius, activation, key[e], out);
  }
  return true;
}

// The segment's closest point to edge e lies over the edge's inside and outside both its
// faces: then it is the closest point to the core. The contact is that point, unless the
// direction is one of the faces' normals within contact_segment_grain's face alignment:
// then it is that face's clipped stretch.
bool answer_from_edge(const ShapeFeatures &features, int e, const Vec3 &a, const Vec3 &b, const Scales &scale,
                      double wire_radius, double activation, BodyAnswer &out)
{
  const Spheropolyhedron &shape = features.shape();
  const ShapeFeatures::EdgeInfo &edge = features.edge(e);
  const Vec3 &v0 = shape.vertices[edge.v0], &v1 = shape.vertices[edge.v1];
  const SegmentClosest c = closest_points_on_segments(a, b, v0, v1, scale.clip);
  if (c.parallel) return false;    // a line contact: two points
  if (!(c.t > 1e-9 && c.t < 1.0 - 1e-9)) return false;
  const Vec3 d = c.point_a - c.point_b;    // from the edge to the segment
  const double distance = d.norm();
  if (distance <= kNearTouchMargin * scale.length) return false;
  for (int k = 0; k < edge.faces; ++k)
    if (edge.outward[k].dot(d) < -1e-9 * distance) return false;    // over a face, not the edge
  const Vec3 normal = d * (1.0 / distance);
  for (int k = 0; k < edge.faces; ++k) {
    const int f = shape.edge_faces[e][k];
    const double misalignment = 1.0 - shape.faces[f].normal.dot(normal);
    // (the band leaves room for the round-off of the direction contact_segment_grain gets)
    if (misalignment <= (1.0 - 1e-4) * Tolerance::kFaceAlign) {
      FaceSides sides;
      return sides_of(features, f, a, b, scale, sides) &&
             clip_to_face(features, f, sides, a, b, scale, wire_radius, activation, out);
    }
    if (misalignment < (1.0 + 1e-4) * Tolerance::kFaceAlign) return false;
  }
  out.start();
  add_point(c.point_a, c.s, normal, distance, shape.radius, wire_radius, activation,
            make_key(segment_feature_at(c.s), edge_feature(edge.v0, edge.v1)), out);
  return true;
}

// The segment a-b over face f. If its lower end lies over the face, that end is the
// segment's closest point to the core, the contact axis is f's normal and the contact is
// f's clipped stretch. If the lower end lies beyond the face, the closest point lies beyond
// the edge through which the segment leaves the face: that edge decides.
bool answer_from_face(const ShapeFeatures &features, int f, const Vec3 &a, const Vec3 &b, const Scales &scale,
                      double wire_radius, double activation, BodyAnswer &out)
{
  const Face &face = features.shape().faces[f];
  const double height[2] = {face.normal.dot(a) - face.offset, face.normal.dot(b) - face.offset};
  if (std::min(height[0], height[1]) <= kNearTouchMargin * scale.length) return false;
  FaceSides sides;
  if (!sides_of(features, f, a, b, scale, sides)) return false;
  const int low = height[0] <= height[1] ? 0 : 1;
  if (sides.exit[low] < 0) return clip_to_face(features, f, sides, a, b, scale, wire_radius, activation, out);
  const ShapeFeatures::Side &side = features.side(features.face(f).first_side + sides.exit[low]);
  return answer_from_edge(features, side.edge, a, b, scale, wire_radius, activation, out);
}

// The segment's closest point to vertex v lies inside the vertex's cone: every edge from
// v leads away from it.
bool answer_from_vertex(const ShapeFeatures &features, int v, const Vec3 &a, const Vec3 &b, const Scales &scale,
                        double wire_radius, double activation, BodyAnswer &out)
{
  const Spheropolyhedron &shape = features.shape();
  const Vec3 &p = shape.vertices[v];
  const double s = closest_parameter_on_segment(a, b, p);
  const Vec3 on_segment = a + s * (b - a);
  const Vec3 d = on_segment - p;
  const double distance = d.norm();
  if (distance <= kNearTouchMargin * scale.length) return false;
  const std::vector<int> &first = features.first_neighbour(), &neighbour = features.neighbour_vertex();
  for (int k = first[v]; k < first[v + 1]; ++k) {
    const Vec3 along = shape.vertices[neighbour[k]] - p;
    if (along.dot(d) >= -kAngleMargin * distance * along.norm()) return false;
  }
  out.start();
  add_point(on_segment, s, d * (1.0 / distance), distance, shape.radius, wire_radius, activation,
            make_key(segment_feature_at(s), vertex_feature(v)), out);
  return true;
}

bool answer_from_hint(const ShapeFeatures &features, const FeatureHint &hint, const Vec3 &a, const Vec3 &b,
                      double wire_radius, double activation, BodyAnswer &out)
{
  const Scales scale = scales_of(a, b, wire_radius, features.shape());
  switch (hint.kind) {
    case FeatureHint::Kind::face: return answer_from_face(features, hint.index, a, b, scale, wire_radius, activation, out);
    case FeatureHint::Kind::edge: return answer_from_edge(features, hint.index, a, b, scale, wire_radius, activation, out);
    case FeatureHint::Kind::vertex: return answer_from_vertex(features, hint.index, a, b, scale, wire_radius, activation, out);
    case FeatureHint::Kind::none: return false;
  }
  return false;
}

// The face among `faces` whose normal is the contact normal (a face patch), else -1.
template <class Faces>
int aligned_face(const Spheropolyhedron &shape, const Faces &faces, const Vec3 &normal)
{
  for (int f : faces)
    if (f >= 0 && shape.faces[f].normal.dot(normal) >= 1.0 - Tolerance::kFaceAlign) return f;
  return -1;
}

// The grain feature of the deepest point of a body-frame answer: a face when the normal
// is a face's (the clipped ends of a face patch carry edge or vertex keys), else the
// edge or vertex the point lies on.
FeatureHint hint_from(const ShapeFeatures &features, const SegmentGrainContact &c)
{
  FeatureHint hint;
  if (c.empty()) return hint;
  const SegmentContact *deepest = &c[0];
  for (const SegmentContact &p : c)
    if (p.gap < deepest->gap) deepest = &p;
  const Spheropolyhedron &shape = features.shape();
  const std::uint32_t feature = key_feature_j(deepest->key);
  const int index = static_cast<int>(feature_index(feature));
  switch (feature_type(feature)) {
    case FeatureType::Face: return {FeatureHint::Kind::face, index};
    case FeatureType::Edge: {
      const int e = features.edge_between(index & 0x7fff, index >> 15);
      if (e < 0) return hint;
      const ShapeFeatures::EdgeInfo &edge = features.edge(e);
      const int faces[2] = {edge.faces > 0 ? shape.edge_faces[e][0] : -1, edge.faces > 0 ? shape.edge_faces[e][1] : -1};
      const int f = aligned_face(shape, faces, deepest->normal);
      return f >= 0 ? FeatureHint{FeatureHint::Kind::face, f} : FeatureHint{FeatureHint::Kind::edge, e};
    }
    case FeatureType::Vertex: {
      std::vector<int> faces;
      for (int f = 0; f < static_cast<int>(shape.faces.size()); ++f)
        if (std::find(shape.faces[f].vertices.begin(), shape.faces[f].vertices.end(), index) != shape.faces[f].vertices.end())
          faces.push_back(f);
      const int f = aligned_face(shape, faces, deepest->normal);
      return f >= 0 ? FeatureHint{FeatureHint::Kind::face, f} : FeatureHint{FeatureHint::Kind::vertex, index};
    }
    case FeatureType::Wall: return hint;
  }
  return hint;
}

}    // namespace

ShapeFeatures::ShapeFeatures(const Spheropolyhedron &shape) : shape_(&shape)
{
  for (const Face &face : shape.faces) {
    const int m = static_cast<int>(face.vertices.size());
    faces_.push_back({static_cast<int>(sides_.size()), m});
    for (int k = 0; k < m; ++k) {
      const Vec3 &r0 = shape.vertices[face.vertices[k]], &r1 = shape.vertices[face.vertices[(k + 1) % m]];
      const Vec3 outward = (r1 - r0).cross(face.normal).normalized();    // as clip_by_side
      sides_.push_back({outward, outward.dot(r0), -1});
    }
  }
  auto add_edge = [&](int v0, int v1, int faces, const Vec3 &out0, const Vec3 &out1) {
    edge_lookup_.push_back({edge_feature(v0, v1), static_cast<int>(edges_.size())});
    edges_.push_back({v0, v1, faces, {out0, out1}});
  };
  if (shape.vertices.size() == 2) add_edge(0, 1, 0, Vec3::Zero(), Vec3::Zero());
  for (size_t i = 0; i < shape.edges.size() && i < shape.edge_faces.size(); ++i) {
    const int v0 = shape.edges[i][0], v1 = shape.edges[i][1];
    const Vec3 along = shape.vertices[v1] - shape.vertices[v0];
    // In edge_faces[i][0] the edge runs v0 -> v1 counter-clockwise, in [1] the other way.
    const Vec3 out0 = along.cross(shape.faces[shape.edge_faces[i][0]].normal).normalized();
    const Vec3 out1 = (-along).cross(shape.faces[shape.edge_faces[i][1]].normal).normalized();
    add_edge(v0, v1, 2, out0, out1);
  }
  std::sort(edge_lookup_.begin(), edge_lookup_.end());
  for (size_t f = 0; f < shape.faces.size(); ++f) {
    const std::vector<int> &loop = shape.faces[f].vertices;
    for (size_t k = 0; k < loop.size(); ++k)
      sides_[faces_[f].first_side + k].edge = edge_between(loop[k], loop[(k + 1) % loop.size()]);
  }

  const int n = static_cast<int>(shape.vertices.size());
  std::vector<std::vector<int>> around(n);
  for (const EdgeInfo &e : edges_) {
    around[e.v0].push_back(e.v1);
    around[e.v1].push_back(e.v0);
  }
  first_neighbour_.assign(1, 0);
  for (const std::vector<int> &list : around) {
    neighbour_vertex_.insert(neighbour_vertex_.end(), list.begin(), list.end());
    first_neighbour_.push_back(static_cast<int>(neighbour_vertex_.size()));
  }
}

int ShapeFeatures::edge_between(int a, int b) const
{
  const std::uint32_t key = edge_feature(a, b);
  const auto it = std::lower_bound(edge_lookup_.begin(), edge_lookup_.end(), std::make_pair(key, -1));
  return it != edge_lookup_.end() && it->first == key ? it->second : -1;
}

namespace {

// The body-frame answer turned to the world frame.
void to_world(const GrainFrame &frame, SegmentGrainContact &contact)
{
  for (int k = 0; k < contact.count; ++k) {
    SegmentContact &p = contact.points[k];
    p.point = frame.rotation * p.point + frame.centre;
    p.normal = frame.rotation * p.normal;
  }
}

}    // namespace

TrackedSegmentContact contact_segment_grain_tracked(const Segment &segment, const ShapeFeatures &features,
                                                    const GrainFrame &frame, double activation,
                                                    FeatureHint &hint, ContactWorkspace &workspace)
{
  const Mat3 to_body = frame.rotation.transpose();
  const Vec3 a = to_body * (segment.p0 - frame.centre), b = to_body * (segment.p1 - frame.centre);
  TrackedSegmentContact out;
  BodyAnswer body{out.contact};
  const Spheropolyhedron &shape = features.shape();
  const bool valid = segment.p0.allFinite() && segment.p1.allFinite() && segment.radius >= 0.0 &&
                     std::isfinite(activation) && activation >= 0.0;
  out.from_hint = valid && answer_from_hint(features, hint, a, b, segment.radius, activation, body);
  if (out.from_hint) {
    out.clearance = body.smallest_gap;
    to_world(frame, out.contact);
    return out;
  }
  // Nothing within the activation distance (most candidate pairs): the core distance says so.
  if (valid && !shape.vertices.empty()) {
    const Vec3 ends[2] = {a, b};
    const GjkResult g = gjk_distance(ends, 2, shape.vertices.data(), static_cast<int>(shape.vertices.size()),
                                     scales_of(a, b, segment.radius, shape).length);
    const double gap = g.distance - shape.radius - segment.radius;
    if (!g.overlap && gap > activation) {
      out.clearance = gap;
      return out;
    }
  }
  out.contact = contact_segment_grain({a, b, segment.radius}, shape, Pose(), activation, workspace);
  if (!out.contact.empty()) hint = hint_from(features, out.contact);    // else keep the last one
  // Nothing within the activation distance: every gap is larger, and larger than the gap of
  // the bounding spheres.
  const double bounding_gap = (0.5 * (a + b)).norm() - 0.5 * (b - a).norm() - segment.radius - shape.bounding_radius;
  out.clearance = std::max(activation, bounding_gap);
  for (const SegmentContact &p : out.contact) out.clearance = std::min(out.clearance, p.gap);
  to_world(frame, out.contact);
  return out;
}

}    // namespace nscd
