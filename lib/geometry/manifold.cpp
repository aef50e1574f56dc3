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

// Contact manifold of two convex cores: the exact closest features (GJK when the cores are
// apart, the separating-axis search when they touch or overlap), then the points of the
// touching features: face against face or edge is clipped (reference face + incident
// feature), edge against edge or vertex gives the closest points.
#include "geometry/core_contact.h"

#include "geometry/feature_key.h"
#include "geometry/gjk.h"
#include "geometry/segment_closest.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace nscd {
namespace geometry_detail {
namespace {

using ClipVertex = ContactWorkspace::ClipVertex;
using Candidate = ContactWorkspace::Candidate;

int support_vertex(const Core &core, const Vec3 &direction)
{
  int best = 0;
  double best_dot = core.vertices[0].dot(direction);
  for (int k = 1; k < core.count; ++k) {
    const double d = core.vertices[k].dot(direction);
    if (d > best_dot) {
      best_dot = d;
      best = k;
    }
  }
  return best;
}

bool face_has_vertex(const Face &face, int vertex)
{
  return std::find(face.vertices.begin(), face.vertices.end(), vertex) != face.vertices.end();
}

// The face through `vertex` whose normal is closest to `direction`; its cosine in
// alignment (-inf when the core has no faces). Only faces through the support vertex
// can carry the deepest point, so no other face is considered.
int face_towards(const Core &core, int vertex, const Vec3 &direction, double &alignment)
{
  alignment = -std::numeric_limits<double>::infinity();
  int best = -1;
  for (int f = 0; f < core.face_count(); ++f) {
    const double c = core.normals[f].dot(direction);
    if (c > alignment && face_has_vertex(core.shape->faces[f], vertex)) {
      alignment = c;
      best = f;
    }
  }
  return best;
}

// The vertex `vertex`, or the edge through it lying in the contact plane (perpendicular
// to axis), whichever the core presents to the other body.
struct FeatureSegment {
  Vec3 p0, p1;
  int v0, v1;
  bool is_edge;
};

FeatureSegment feature_facing(const Core &core, int vertex, const Vec3 &axis)
{
  FeatureSegment out{core.vertices[vertex], core.vertices[vertex], vertex, vertex, false};
  double best = Tolerance::kEdgeAlign;
  auto consider = [&](int v0, int v1) {
    const Vec3 e = core.vertices[v1] - core.vertices[v0];
    const double len = e.norm();
    if (len == 0.0) return;
    const double c = std::abs(e.dot(axis)) / len;
    if (c <= best) {
      best = c;
      out = {core.vertices[v0], core.vertices[v1], v0, v1, true};
    }
  };
  if (core.is_polytope()) {
    for (const auto &e : core.shape->edges)
      if (e[0] == vertex || e[1] == vertex) consider(e[0], e[1]);
  } else if (core.count == 2) {
    consider(0, 1);
  }
  return out;
}

std::uint32_t feature_at(const FeatureSegment &f, double s)
{
  if (!f.is_edge || s <= 0.0) return vertex_feature(f.v0);
  if (s >= 1.0) return vertex_feature(f.v1);
  return edge_feature(f.v0, f.v1);
}

// Adds the point pair (pa on a, pb on b), gap measured along the unit axis a -> b.
void add_point_pair(const Core &a, const Core &b, const Vec3 &pa, const Vec3 &pb,
                    const Vec3 &axis, std::uint64_t key, double activation,
                    ContactWorkspace &ws)
{
  const double gap = (pb - pa).dot(axis) - a.radius - b.radius;
  if (!(gap <= activation)) return;
  const Vec3 position = 0.5 * (pa + pb + (a.radius - b.radius) * axis);
  ws.candidates.push_back({position, pa, gap, key});
}

// Edge / vertex against edge / vertex: the closest points of the two features; parallel
// edges give the two ends of their overlap.
void add_feature_pair(const Core &a, const FeatureSegment &fa, const Core &b,
                      const FeatureSegment &fb, const Vec3 &axis, const ManifoldInput &in,
                      ContactWorkspace &ws)
{
  const double length_tol = Tolerance::kClip * in.length_scale;
  const SegmentClosest c = closest_points_on_segments(fa.p0, fa.p1, fb.p0, fb.p1, length_tol);
  const Vec3 ea = fa.p1 - fa.p0, eb = fb.p1 - fb.p0;
  auto add_at = [&](double s) {
    const Vec3 pa = fa.p0 + s * ea;
    const double t = fb.is_edge ? closest_parameter_on_segment(fb.p0, fb.p1, pa) : 0.0;
    add_point_pair(a, b, pa, fb.p0 + t * eb, axis, make_key(feature_at(fa, s), feature_at(fb, t)),
                   in.activation, ws);
  };
  const bool line_contact = fa.is_edge && fb.is_edge && c.parallel &&
                            (c.s_hi - c.s_lo) * ea.norm() > in.merge_distance;
  if (line_contact) {
    add_at(c.s_lo);
    add_at(c.s_hi);
  } else {
    add_point_pair(a, b, c.point_a, c.point_b, axis,
                   make_key(feature_at(fa, c.s), feature_at(fb, c.t)), in.activation, ws);
  }
}

// ---- face clipping ------------------------------------------------------------------

struct ReferenceFace {
  const Core *core;
  int face;
  Vec3 normal;    // outward from the reference core, towards the incident one
  double offset;
};

// The incident core's feature facing the reference face, as a polygon in ws.polygon:
// the face through its support vertex most opposed to the reference normal, its segment,
// or its single vertex. Returns the feature id of the polygon's interior.
std::uint32_t load_incident_polygon(const Core &inc, int support, const Vec3 &ref_normal,
                                    std::uint32_t ref_feature, ContactWorkspace &ws)
{
  ws.polygon.clear();
  if (inc.is_polytope()) {
    double alignment;
    const int g = face_towards(inc, support, -ref_normal, alignment);
    const auto &loop = inc.shape->faces[g].vertices;
    const int m = static_cast<int>(loop.size());
    for (int k = 0; k < m; ++k) {
      const int v = loop[k], next = loop[(k + 1) % m];
      ws.polygon.push_back({inc.vertices[v], vertex_feature(v), ref_feature, edge_feature(v, next), -1});
    }
    return face_feature(g);
  }
  for (int k = 0; k < inc.count; ++k)
    ws.polygon.push_back({inc.vertices[k], vertex_feature(k), ref_feature, edge_feature(0, inc.count - 1), -1});
  return edge_feature(0, inc.count - 1);
}

// Feature of the reference body where side planes `earlier` and `side` meet: their
// common vertex when the two reference edges are adjacent.
std::uint32_t side_corner(const std::vector<int> &loop, int earlier, int side)
{
  const int m = static_cast<int>(loop.size());
  if (earlier == (side + m - 1) % m) return vertex_feature(loop[side]);
  if (earlier == (side + 1) % m) return vertex_feature(loop[(side + 1) % m]);
  return edge_feature(loop[side], loop[(side + 1) % m]);
}

// Where polygon edge P->Q crosses side plane `side` (signed distances dp, dq).
ClipVertex crossing(const ClipVertex &p, const ClipVertex &q, double dp, double dq,
                    const std::vector<int> &loop, int side, std::uint32_t incident_interior)
{
  const int m = static_cast<int>(loop.size());
  const double t = std::min(1.0, std::max(0.0, dp / (dp - dq)));
  ClipVertex out;
  out.position = p.position + t * (q.position - p.position);
  if (p.reference_side < 0) {    // P->Q is an incident edge: edge against edge
    out.incident_feature = p.incident_edge;
    out.reference_feature = edge_feature(loop[side], loop[(side + 1) % m]);
  } else {                       // P->Q runs along an earlier side plane: a reference corner
    out.incident_feature = incident_interior;
    out.reference_feature = side_corner(loop, p.reference_side, side);
  }
  return out;
}

// One Sutherland-Hodgman step: keeps the part of ws.polygon inside side plane `side`.
void clip_by_side(const ReferenceFace &ref, int side, double tol,
                  std::uint32_t incident_interior, ContactWorkspace &ws)
{
  const auto &loop = ref.core->shape->faces[ref.face].vertices;
  const int m = static_cast<int>(loop.size());
  const Vec3 &r0 = ref.core->vertices[loop[side]];
  const Vec3 &r1 = ref.core->vertices[loop[(side + 1) % m]];
  const Vec3 outward = (r1 - r0).cross(ref.normal).normalized();    // CCW loop
  ws.clipped.clear();
  const int n = static_cast<int>(ws.polygon.size());
  for (int k = 0; k < n; ++k) {
    const ClipVertex &p = ws.polygon[k], &q = ws.polygon[(k + 1) % n];
    const double dp = outward.dot(p.position - r0), dq = outward.dot(q.position - r0);
    const bool p_in = dp <= tol, q_in = dq <= tol;
    if (p_in && !q_in) {
      ClipVertex exit = crossing(p, q, dp, dq, loop, side, incident_interior);
      exit.reference_side = side;    // the polygon now runs along this side plane
      exit.incident_edge = p.incident_edge;
      ws.clipped.push_back(exit);
    } else if (!p_in && q_in) {
      ClipVertex entry = crossing(p, q, dp, dq, loop, side, incident_interior);
      entry.reference_side = p.reference_side;
      entry.incident_edge = p.incident_edge;
      ws.clipped.push_back(entry);
    }
    if (q_in) ws.clipped.push_back(q);
  }
  ws.polygon.swap(ws.clipped);
}

// Face of `ref` against the incident core. Returns false when nothing of the incident
// feature lies over the face (then the caller falls back to the closest features).
bool add_face_contact(const ReferenceFace &ref, const Core &inc, int inc_support,
                      bool ref_is_a, const ManifoldInput &in, ContactWorkspace &ws)
{
  const std::uint32_t ref_face = face_feature(ref.face);
  const std::uint32_t interior = load_incident_polygon(inc, inc_support, ref.normal, ref_face, ws);
  const int sides = static_cast<int>(ref.core->shape->faces[ref.face].vertices.size());
  const double tol = Tolerance::kClip * in.length_scale;
  for (int side = 0; side < sides && !ws.polygon.empty(); ++side)
    clip_by_side(ref, side, tol, interior, ws);
  if (ws.polygon.empty()) return false;

  const double r_ref = ref.core->radius, r_inc = inc.radius;
  for (const ClipVertex &v : ws.polygon) {
    const double height = ref.normal.dot(v.position) - ref.offset;    // core-to-core distance
    const double gap = height - r_ref - r_inc;
    if (!(gap <= in.activation)) continue;
    const Vec3 position = v.position + 0.5 * (r_ref - r_inc - height) * ref.normal;
    const Vec3 on_ref = v.position - height * ref.normal;
    if (ref_is_a) {
      ws.candidates.push_back({position, on_ref, gap, make_key(v.reference_feature, v.incident_feature)});
    } else {
      ws.candidates.push_back({position, v.position, gap, make_key(v.incident_feature, v.reference_feature)});
    }
  }
  return true;
}

// ---- speculative points: vertices over faces ---------------------------------------------

// Largest gap of a speculative point: what can close within the step, never beyond the
// activation distance; at least the touching band of the point reduction (a point at gap ~ 0
// must not come and go with round-off or the jitter of a grain at rest).
double speculative_limit(const ManifoldInput &in)
{
  return std::min(in.activation, std::max(in.speculative_distance, Tolerance::kTouchBand * in.length_scale));
}

// The face of `ref` that point p lies highest above (largest signed distance from its
// plane), and that height.
int highest_face(const Core &ref, const Vec3 &p, double &height)
{
  int best = 0;
  height = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < ref.face_count(); ++f) {
    const double h = ref.normals[f].dot(p) - ref.offsets[f];
    if (h > height) {
      height = h;
      best = f;
    }
  }
  return best;
}

// Whether p projects onto face f of `ref` inside the face (its side planes, within tol).
bool over_face(const Core &ref, int f, const Vec3 &p, double tol)
{
  const auto &loop = ref.shape->faces[f].vertices;
  const int m = static_cast<int>(loop.size());
  for (int k = 0; k < m; ++k) {
    const Vec3 &r0 = ref.vertices[loop[k]], &r1 = ref.vertices[loop[(k + 1) % m]];
    const Vec3 outward = (r1 - r0).cross(ref.normals[f]);    // counter-clockwise loop
    if (outward.dot(p - r0) > tol * outward.norm()) return false;
  }
  return true;
}

// Every vertex of `inc` over a face of `ref` and within the activation distance of it, as a
// point with that face's normal. The closest features give one point where two grains meet
// edge-first or corner-first; a grain turning about it brings its other vertices down onto
// the neighbour within the step, and the solver must already hold those points then (else
// they sink in unseen, by |w| R dt per step). A vertex beside a face (over an edge's or a
// vertex's region) is not taken: its plane distance would understate its true one.
void add_vertices_over_faces(const Core &ref, const Core &inc, bool ref_is_a, const ManifoldInput &in,
                             ContactWorkspace &ws)
{
  if (!ref.is_polytope()) return;
  const double tol = Tolerance::kClip * in.length_scale;
  const double limit = speculative_limit(in);
  const double reach = limit + ref.radius + inc.radius;
  for (int k = 0; k < inc.count; ++k) {
    const Vec3 &v = inc.vertices[k];
    if ((v - ref.centroid).squaredNorm() > (ref.extent + reach) * (ref.extent + reach)) continue;
    double height;
    const int f = highest_face(ref, v, height);
    const double gap = height - ref.radius - inc.radius;
    if (!(gap <= limit) || !over_face(ref, f, v, tol)) continue;
    const std::uint64_t key = ref_is_a ? make_key(face_feature(f), vertex_feature(k))
                                       : make_key(vertex_feature(k), face_feature(f));
    // the closest features may already be this vertex on this face: one point per key
    if (std::any_of(ws.candidates.begin(), ws.candidates.end(), [&](const Candidate &c) { return c.key == key; }))
      continue;
    const Vec3 &n = ref.normals[f];    // outward from ref
    const Vec3 position = v + 0.5 * (ref.radius - inc.radius - height) * n;
    const Vec3 on_ref = v - height * n;
    ws.candidates.push_back({position, ref_is_a ? on_ref : v, gap, key, ref_is_a ? Vec3(-n) : n});
  }
}

// The part of an edge over a face of `ref` (inside its m side planes), from its ends'
// distances d0[k], d1[k] beside side k (> 0: outside): parameters [lo, hi] along the edge
// and the side crossed at each end (-1: the edge's own end). Returns false when no part of
// it is over the face.
struct OverFace {
  double lo = 0.0, hi = 1.0;
  int side_lo = -1, side_hi = -1;
};

bool clip_to_face(int m, const double *d0, const double *d1, OverFace &out)
{
  out = OverFace{};
  for (int k = 0; k < m; ++k) {
    if (d0[k] > 0.0 && d1[k] > 0.0) return false;
    if (d0[k] <= 0.0 && d1[k] <= 0.0) continue;
    const double t = d0[k] / (d0[k] - d1[k]);
    if (d0[k] > 0.0 && t > out.lo) {
      out.lo = t;
      out.side_lo = k;
    } else if (d0[k] <= 0.0 && t < out.hi) {
      out.hi = t;
      out.side_hi = k;
    }
  }
  return out.lo < out.hi;
}

// Where vertex p of `inc` lies against the faces of `ref` in `faces`: its height over each
// face's plane, then its distance beside each side of each face in turn (`sides`: their
// outward normals, loop by loop). Written to row.
void measure_vertex(const Core &ref, const std::vector<int> &faces, const std::vector<Vec3> &sides,
                    const Vec3 &p, double *row)
{
  double *beside = row + faces.size();
  const Vec3 *outward = sides.data();
  for (const int f : faces) {
    *row++ = ref.normals[f].dot(p) - ref.offsets[f];
    for (const int corner : ref.shape->faces[f].vertices) *beside++ = (*outward++).dot(p - ref.vertices[corner]);
  }
}

// One point per key: the same pair of edges is found from a face of either core; the nearer
// of the two points stays, whichever core came first (so contact(j, i) mirrors contact(i, j)).
void add_or_keep_nearer(const Candidate &point, std::vector<Candidate> &candidates)
{
  const auto same = std::find_if(candidates.begin(), candidates.end(), [&](const Candidate &c) { return c.key == point.key; });
  if (same == candidates.end())
    candidates.push_back(point);
  else if (point.gap < same->gap)
    *same = point;
}

// Keeps the first `closest` candidates and, of the others, the ones of smallest gap up to
// ContactSet::kMaxPoints in all, in their order (which is stable under small motions).
// Ties go to the smaller key of the pair either way round (the same for contact(j, i)).
void keep_nearest_speculative(std::size_t closest, std::vector<Candidate> &candidates)
{
  const std::size_t room = static_cast<std::size_t>(ContactSet::kMaxPoints);
  if (candidates.size() <= room) return;
  std::vector<std::size_t> rest;
  for (std::size_t k = closest; k < candidates.size(); ++k) rest.push_back(k);
  auto rank = [&](std::size_t k) {
    const std::uint64_t key = candidates[k].key;
    return std::pair(candidates[k].gap, std::min(key, swapped_key(key)));
  };
  std::sort(rest.begin(), rest.end(), [&](std::size_t p, std::size_t q) { return rank(p) < rank(q); });
  rest.resize(room - closest);
  std::sort(rest.begin(), rest.end());
  std::size_t kept = closest;
  for (const std::size_t k : rest) candidates[kept++] = candidates[k];
  candidates.resize(kept);
}

// Marks the vertices of `feature` of `core` (a vertex, an edge's two ends, a face's loop).
void mark_feature_vertices(const Core &core, std::uint32_t feature, std::vector<char> &marks)
{
  const std::uint32_t index = feature_index(feature);
  switch (feature_type(feature)) {
  case FeatureType::Vertex: marks[index] = 1; break;
  case FeatureType::Edge:
    marks[index & 0x7fffu] = 1;
    marks[index >> 15] = 1;
    break;
  case FeatureType::Face:
    for (const int v : core.shape->faces[index].vertices) marks[v] = 1;
    break;
  case FeatureType::Wall: break;
  }
}

// The faces of `ref` through a marked vertex, and the outward normals of their sides (not
// unit), loop by loop.
void collect_near_faces(const Core &ref, const std::vector<char> &marked, std::vector<int> &faces,
                        std::vector<Vec3> &sides)
{
  faces.clear();
  sides.clear();
  for (int f = 0; f < ref.face_count(); ++f) {
    const auto &loop = ref.shape->faces[f].vertices;
    if (std::none_of(loop.begin(), loop.end(), [&](int v) { return marked[v] != 0; })) continue;
    faces.push_back(f);
    const int m = static_cast<int>(loop.size());
    for (int k = 0; k < m; ++k)    // counter-clockwise loop
      sides.push_back((ref.vertices[loop[(k + 1) % m]] - ref.vertices[loop[k]]).cross(ref.normals[f]));
  }
}

// Every edge of `inc` at the closest features crossing the border of a face of `ref` at the
// closest features, within the speculative limit: a point where it crosses (the edge
// counterpart of the vertices over faces). A grain lying almost edge-on across a
// neighbour's face gets one closest point (the face is not aligned closely enough to be
// clipped); turning about it brings the edge down onto the face's far border within the
// step, and the ends of the edge lie beside the face, so no vertex over a face stands for
// that point. Measured in benchmarks/hard/in.fast_pour (doc/BENCHMARKS.md): every overlap
// that grew by more than 0.2 r in a step grew at an edge-edge crossing next to the closest
// features (an edge through a vertex of one closest feature, an edge of a face through a
// vertex of the other); these are the ones searched, as all edges over all faces cost 5x
// the whole contact detection. The point is the nearer of: the height over the face plane
// (the distance to the core where positive, a lower bound otherwise), with the face's
// normal; the distance to the border edge, with the two edges' closest points and their
// direction, where those lie inside both edges (beyond the border the neighbour face falls
// away, so the edges may be nearer). Taken where the face is the one the crossing is
// highest above. Key: the border edge and the edge of `inc`, as face clipping gives it.
// `closest`: the number of closest-feature points at the front of the candidates.
void add_edges_over_faces(const Core &ref, const Core &inc, bool ref_is_a, std::size_t closest,
                          double nearest, const ManifoldInput &in, ContactWorkspace &ws)
{
  if (!ref.is_polytope() || !inc.is_polytope()) return;
  std::vector<char> &at_ref = ws.marks_ref, &at_inc = ws.marks_inc;
  at_ref.assign(ref.count, 0);
  at_inc.assign(inc.count, 0);
  for (std::size_t k = 0; k < closest; ++k) {
    const std::uint64_t key = ws.candidates[k].key;
    mark_feature_vertices(ref, ref_is_a ? key_feature_i(key) : key_feature_j(key), at_ref);
    mark_feature_vertices(inc, ref_is_a ? key_feature_j(key) : key_feature_i(key), at_inc);
  }
  collect_near_faces(ref, at_ref, ws.near_faces, ws.near_sides);
  const std::vector<int> &faces = ws.near_faces;
  const std::vector<Vec3> &sides = ws.near_sides;
  // Each vertex of inc measured against them once, when an edge first needs it: every edge
  // through it meets every near face (measured per edge and face, the clipping alone was
  // half of this function's time, perf).
  const std::size_t face_n = faces.size(), row = face_n + sides.size();
  ws.vertex_rows.resize(static_cast<std::size_t>(inc.count) * row);
  ws.marks_measured.assign(inc.count, 0);
  auto measured = [&](int v) {
    double *r = ws.vertex_rows.data() + static_cast<std::size_t>(v) * row;
    if (!ws.marks_measured[v]) measure_vertex(ref, faces, sides, inc.vertices[v], r);
    ws.marks_measured[v] = 1;
    return static_cast<const double *>(r);
  };
  const double tol = Tolerance::kClip * in.length_scale;
  const double radii = ref.radius + inc.radius, limit = speculative_limit(in);
  // Cores apart: no point of inc is nearer to ref than `nearest`, so an edge wholly lower
  // than that under a face plane (a face turned away) has no crossing over it to offer.
  const double lowest = nearest > 0.0 ? nearest - tol : -std::numeric_limits<double>::infinity();
  for (const auto &edge : inc.shape->edges) {
    if (!at_inc[edge[0]] && !at_inc[edge[1]]) continue;
    const Vec3 &p0 = inc.vertices[edge[0]], &p1 = inc.vertices[edge[1]];
    const double *row0 = measured(edge[0]), *row1 = measured(edge[1]);
    std::size_t side0 = face_n;    // the face's first side in a row
    for (std::size_t fi = 0; fi < face_n; ++fi) {
      const int f = faces[fi];
      const auto &loop = ref.shape->faces[f].vertices;
      const int m = static_cast<int>(loop.size());
      const double *beside0 = row0 + side0, *beside1 = row1 + side0;
      side0 += m;
      const double h0 = row0[fi], h1 = row1[fi];
      OverFace over;
      if (std::min(h0, h1) - radii > limit || std::max(h0, h1) - radii < lowest ||
          !clip_to_face(m, beside0, beside1, over))
        continue;
      const Vec3 &n = ref.normals[f];
      for (const auto &[s, side] : {std::pair(over.lo, over.side_lo), std::pair(over.hi, over.side_hi)}) {
        if (side < 0) continue;    // the edge's own end: a vertex over the face
        const Vec3 p = p0 + s * (p1 - p0);
        const double height = h0 + s * (h1 - h0);
        if (!(height - radii <= limit) || height - radii < lowest) continue;
        double highest;
        highest_face(ref, p, highest);
        if (highest > height + tol) continue;
        const int r0 = loop[side], r1 = loop[(side + 1) % m];
        const std::uint64_t key = ref_is_a ? make_key(edge_feature(r0, r1), edge_feature(edge[0], edge[1]))
                                           : make_key(edge_feature(edge[0], edge[1]), edge_feature(r0, r1));
        Vec3 normal = n, on_ref = p - height * n, on_inc = p;
        double gap = height - radii;
        if (height > tol) {
          const SegmentClosest c = closest_points_on_segments(p0, p1, ref.vertices[r0], ref.vertices[r1], tol);
          const Vec3 between = c.point_a - c.point_b;    // from ref to inc
          const double distance = between.norm();
          const bool inside_both = c.s > 0.0 && c.s < 1.0 && c.t > 0.0 && c.t < 1.0;    // else a vertex's
          if (inside_both && distance > tol && distance < height) {
            normal = between / distance;
            on_ref = c.point_b;
            on_inc = c.point_a;
            gap = distance - radii;
          }
        }
        const Vec3 position = 0.5 * (on_ref + on_inc + (ref.radius - inc.radius) * normal);
        add_or_keep_nearer({position, ref_is_a ? on_ref : on_inc, gap, key, ref_is_a ? Vec3(-normal) : normal}, ws.candidates);
      }
    }
  }
}

// ---- choice of the axis and of the features -------------------------------------------

// Unit axis from core a to core b at the closest approach, or false when the cores are
// farther apart than the activation distance allows.
bool contact_axis(const Core &a, const Core &b, const ManifoldInput &in, ContactWorkspace &ws,
                  Vec3 &axis)
{
  const GjkResult g = gjk_distance(a.vertices, a.count, b.vertices, b.count, in.length_scale);
  if (!g.overlap && g.distance - a.radius - b.radius > in.activation) return false;
  if (g.overlap || g.distance < Tolerance::kNearTouch * in.length_scale) {
    // Touching or overlapping cores: the exact axis is a face normal or an edge-edge
    // cross product, which the separating-axis search finds without cancellation.
    const SeparatingAxis s = find_separating_axis(a, b, in.length_scale, ws);
    if (s.separation - a.radius - b.radius > in.activation) return false;
    axis = s.axis;
  } else {
    axis = (g.point_b - g.point_a) / g.distance;
  }
  return true;
}

// Merges points closer than merge_distance: keeps the one touching more vertices (its
// key is the stabler one), then the deeper one.
int vertex_count(std::uint64_t key)
{
  return (feature_type(key_feature_i(key)) == FeatureType::Vertex) +
         (feature_type(key_feature_j(key)) == FeatureType::Vertex);
}

void merge_close_points(double merge_distance, std::vector<Candidate> &points)
{
  const double d2 = merge_distance * merge_distance;
  size_t kept = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    bool merged = false;
    for (size_t j = 0; j < kept && !merged; ++j) {
      if ((points[j].position - points[k].position).squaredNorm() > d2) continue;
      merged = true;
      const int vj = vertex_count(points[j].key), vk = vertex_count(points[k].key);
      if (vk > vj || (vk == vj && points[k].gap < points[j].gap)) points[j] = points[k];
    }
    if (!merged) points[kept++] = points[k];
  }
  points.resize(kept);
}

// Both cores are points or segments: closed form, two points for parallel segments.
Vec3 segment_pair_manifold(const Core &a, const Core &b, const ManifoldInput &in,
                           ContactWorkspace &ws)
{
  const FeatureSegment fa{a.vertices[0], a.vertices[a.count - 1], 0, a.count - 1, a.count == 2};
  const FeatureSegment fb{b.vertices[0], b.vertices[b.count - 1], 0, b.count - 1, b.count == 2};
  const SegmentClosest c = closest_points_on_segments(fa.p0, fa.p1, fb.p0, fb.p1,
                                                      Tolerance::kClip * in.length_scale);
  const Vec3 between = c.point_b - c.point_a;
  const double distance = between.norm();
  Vec3 axis;
  if (distance > Tolerance::kClip * in.length_scale) {
    axis = between / distance;
  } else {
    // Crossing segments: their common normal, pointing from a's centre towards b's.
    const Vec3 ea = fa.p1 - fa.p0, eb = fb.p1 - fb.p0;
    Vec3 n = ea.cross(eb);
    if (n.squaredNorm() <= 1e-24 * ea.squaredNorm() * eb.squaredNorm() || n.squaredNorm() == 0.0)
      n = any_perpendicular(ea.squaredNorm() > 0.0 ? ea : (eb.squaredNorm() > 0.0 ? eb : Vec3::UnitX()));
    axis = n.normalized();
    if (axis.dot(b.centroid - a.centroid) < 0.0) axis = -axis;
  }
  add_feature_pair(a, fa, b, fb, axis, in, ws);
  return -axis;
}

}    // namespace

Vec3 build_manifold(const Core &a, const Core &b, const ManifoldInput &in, ContactWorkspace &ws)
{
  ws.candidates.clear();
  if (a.count <= 2 && b.count <= 2) {
    const Vec3 normal = segment_pair_manifold(a, b, in, ws);
    for (Candidate &c : ws.candidates) c.normal = normal;
    merge_close_points(in.merge_distance, ws.candidates);
    return normal;
  }
  Vec3 axis;
  if (!contact_axis(a, b, in, ws, axis)) return Vec3::UnitX();

  const int va = support_vertex(a, axis), vb = support_vertex(b, -axis);
  double align_a, align_b;
  const int fa = face_towards(a, va, axis, align_a);
  const int fb = face_towards(b, vb, -axis, align_b);
  const double face_cos = 1.0 - Tolerance::kFaceAlign;
  Vec3 normal = -axis;
  bool done = false;
  if (std::max(align_a, align_b) >= face_cos) {
    const bool ref_is_a = align_a >= align_b;
    const Core &ref_core = ref_is_a ? a : b;
    const int face = ref_is_a ? fa : fb;
    const ReferenceFace ref{&ref_core, face, ref_core.normals[face], ref_core.offsets[face]};
    done = add_face_contact(ref, ref_is_a ? b : a, ref_is_a ? vb : va, ref_is_a, in, ws);
    if (done) normal = ref_is_a ? Vec3(-ref.normal) : ref.normal;
  }
  if (!done) {
    add_feature_pair(a, feature_facing(a, va, axis), b, feature_facing(b, vb, -axis), axis, in, ws);
  }
  for (Candidate &c : ws.candidates) c.normal = normal;
  // A patch (three or more points) already holds the grain against turning onto the
  // neighbour; the speculative points are for pairs meeting edge- or corner-first.
  // A speculative point's gap is at least the cores' distance (its height over a face it
  // lies over), so a pair farther apart than the limit has none.
  double nearest = std::numeric_limits<double>::infinity();
  for (const Candidate &c : ws.candidates) nearest = std::min(nearest, c.gap);
  // Cores inside each other (grains placed deeper into each other than their rounding): the
  // face a vertex lies highest above says nothing about where they separate, and points with
  // such normals lock the pair or push it through itself. Only the closest features then.
  const bool cores_intersect = nearest < -(a.radius + b.radius);
  if (in.speculative_distance > 0.0 && ws.candidates.size() < 3 && nearest <= speculative_limit(in) &&
      !cores_intersect) {
    const std::size_t closest = ws.candidates.size();
    add_edges_over_faces(a, b, true, closest, nearest, in, ws);
    add_edges_over_faces(b, a, false, closest, nearest, in, ws);
    add_vertices_over_faces(a, b, true, in, ws);
    add_vertices_over_faces(b, a, false, in, ws);
    // More than a contact holds: the closest features, then the speculative points that
    // close first (smallest gap). The reduction for patch coverage is for touching patches;
    // it would drop a point about to close for one far away.
    merge_close_points(in.merge_distance, ws.candidates);
    keep_nearest_speculative(std::min(closest, ws.candidates.size()), ws.candidates);
    return normal;
  }
  merge_close_points(in.merge_distance, ws.candidates);
  return normal;
}

}    // namespace geometry_detail
}    // namespace nscd
