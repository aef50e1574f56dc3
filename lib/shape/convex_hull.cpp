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

#include "shape/convex_hull.h"

#include "shape/spheropolyhedron.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace nscd {
namespace {

// Owns one reentrant qhull instance; frees all of its memory on scope exit, also when
// the hull computation failed.
class QhullRun {
 public:
  QhullRun()
  {
    // qhull writes diagnostics to a FILE*: collect them in memory for the error message.
    error_stream_ = open_memstream(&error_text_, &error_size_);
    qh_zero(&qh_, error_stream_);
  }
  ~QhullRun()
  {
    int curlong = 0, totlong = 0;
    qh_freeqhull(&qh_, !qh_ALL);
    qh_memfreeshort(&qh_, &curlong, &totlong);
    if (error_stream_) std::fclose(error_stream_);
    std::free(error_text_);
  }
  QhullRun(const QhullRun &) = delete;
  QhullRun &operator=(const QhullRun &) = delete;

  // Premerge ('C-n'): neighbouring facets whose centrums lie within merge_distance of
  // each other's planes become one facet, so a cube (even a slightly noisy one) has 6 faces.
  int run(std::vector<double> &coordinates, double merge_distance)
  {
    char options[64];
    std::snprintf(options, sizeof options, "qhull C-%.3g", merge_distance);
    const int count = static_cast<int>(coordinates.size() / 3);
    return qh_new_qhull(&qh_, 3, count, coordinates.data(), False, options, nullptr,
                        error_stream_);
  }

  std::string diagnostics()
  {
    if (!error_stream_) return "";
    std::fflush(error_stream_);
    std::string text = error_text_ ? std::string(error_text_, error_size_) : "";
    const auto end = text.find('\n');
    return text.substr(0, end);
  }

  qhT *get() { return &qh_; }

 private:
  qhT qh_;
  FILE *error_stream_ = nullptr;
  char *error_text_ = nullptr;
  size_t error_size_ = 0;
};

// Orders a face's vertices counter-clockwise around `outward` by their angle about
// the face centroid (a convex polygon, so angles are monotonic around it).
void order_counter_clockwise(std::vector<int> &face, const std::vector<Vec3> &points,
                             const Vec3 &outward)
{
  Vec3 centre = Vec3::Zero();
  for (int v : face) centre += points[v];
  centre /= static_cast<double>(face.size());
  const Vec3 u = (points[face[0]] - centre).normalized();
  const Vec3 w = outward.cross(u);
  std::vector<std::pair<double, int>> by_angle;
  by_angle.reserve(face.size());
  for (int v : face) {
    const Vec3 d = points[v] - centre;
    by_angle.emplace_back(std::atan2(d.dot(w), d.dot(u)), v);
  }
  std::sort(by_angle.begin(), by_angle.end());
  for (size_t i = 0; i < face.size(); ++i) face[i] = by_angle[i].second;
}

// Rotates the cyclic list so that it starts at its smallest index (canonical form).
void start_at_smallest(std::vector<int> &face)
{
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
}

// A vertex strictly inside a hull edge (180 degrees in its faces) carries no geometry:
// qhull may keep such points after merging. They are dropped from every face.
void drop_straight_vertices(std::vector<HullPolygon> &faces, const std::vector<Vec3> &points,
                            double merge_distance)
{
  std::map<int, int> corner_count, straight_count;
  for (const auto &face : faces) {
    const size_t n = face.vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec3 &prev = points[face.vertices[(i + n - 1) % n]];
      const Vec3 &here = points[face.vertices[i]];
      const Vec3 &next = points[face.vertices[(i + 1) % n]];
      const Vec3 chord = next - prev;
      const double off_line = (here - prev).cross(chord).norm() / chord.norm();
      const bool between = (here - prev).dot(chord) > 0 && (next - here).dot(chord) > 0;
      const bool straight = between && off_line <= std::max(merge_distance, 1e-12 * chord.norm());
      corner_count[face.vertices[i]]++;
      if (straight) straight_count[face.vertices[i]]++;
    }
  }
  for (auto &face : faces) {
    auto &list = face.vertices;
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](int v) {
                                auto it = straight_count.find(v);
                                return it != straight_count.end() &&
                                       it->second == corner_count[v];
                              }),
               list.end());
  }
}

// The faces must form a closed convex surface: every face a polygon, every edge shared by
// exactly two faces (once in each direction) and Euler's V - E + F = 2. qhull's merged
// output on points close to flat at its precision can break this; mass properties and
// contact code would then index missing faces.
void check_closed_surface(const HullTopology &hull)
{
  auto fail = [](const std::string &why) {
    throw ShapeError("convex hull is degenerate (" + why + "); the points are too close to flat, to a "
                     "line or to each other for a reliable hull: spread them further apart");
  };
  std::vector<std::pair<int, int>> directed;
  for (const auto &face : hull.faces) {
    const size_t n = face.vertices.size();
    if (n < 3) fail("a face with " + std::to_string(n) + " vertices");
    for (size_t i = 0; i < n; ++i) directed.emplace_back(face.vertices[i], face.vertices[(i + 1) % n]);
  }
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) fail("an edge used twice");
  for (const auto &edge : directed) {
    if (!std::binary_search(directed.begin(), directed.end(), std::make_pair(edge.second, edge.first))) {
      fail("an edge with one face");
    }
  }
  const long euler = static_cast<long>(hull.vertices.size()) - static_cast<long>(hull.edges.size()) +
                     static_cast<long>(hull.faces.size());
  if (hull.faces.size() < 4 || euler != 2) fail("V - E + F = " + std::to_string(euler) + ", not 2");
}

HullTopology topology_from_faces(std::vector<HullPolygon> faces)
{
  HullTopology hull;
  for (auto &face : faces) start_at_smallest(face.vertices);
  std::sort(faces.begin(), faces.end(),
            [](const HullPolygon &a, const HullPolygon &b) { return a.vertices < b.vertices; });
  for (const auto &face : faces) {
    const size_t n = face.vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const int a = face.vertices[i], b = face.vertices[(i + 1) % n];
      hull.vertices.push_back(a);
      if (a < b) hull.edges.push_back({a, b});    // every edge is met once in each direction
    }
  }
  std::sort(hull.vertices.begin(), hull.vertices.end());
  hull.vertices.erase(std::unique(hull.vertices.begin(), hull.vertices.end()),
                      hull.vertices.end());
  std::sort(hull.edges.begin(), hull.edges.end());
  hull.faces = std::move(faces);
  return hull;
}

}    // namespace

HullTopology convex_hull_3d(const std::vector<Vec3> &points, double merge_distance)
{
  std::vector<double> coordinates;
  coordinates.reserve(3 * points.size());
  for (const auto &p : points) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});

  QhullRun run;
  if (run.run(coordinates, merge_distance) != 0) {
    throw ShapeError("convex hull failed (qhull: " + run.diagnostics() +
                     "); check that the points are finite and span 3-D space");
  }
  qhT *qh = run.get();
  std::vector<HullPolygon> faces;
  facetT *facet;
  vertexT *vertex, **vertexp;
  FORALLfacets
  {
    HullPolygon face;
    FOREACHvertex_(facet->vertices) face.vertices.push_back(qh_pointid(qh, vertex->point));
    // qhull's facet normals point out of the hull (its vertex order does not matter).
    const Vec3 outward(facet->normal[0], facet->normal[1], facet->normal[2]);
    order_counter_clockwise(face.vertices, points, outward);
    faces.push_back(std::move(face));
  }
  drop_straight_vertices(faces, points, merge_distance);
  HullTopology hull = topology_from_faces(std::move(faces));
  check_closed_surface(hull);
  return hull;
}

}    // namespace nscd
