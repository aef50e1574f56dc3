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

#include "shape/spheropolyhedron.h"

#include "shape/convex_hull.h"
#include "shape/mass_properties.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>

namespace nscd {
namespace {

// Points closer than this (relative to the shape's size: the larger of the point cloud's
// extent and the rounding radius) are one point, a cloud thinner than this is flat or
// collinear, and hull facets this close to coplanar are merged into one face.
constexpr double kRelativeTolerance = 1e-10;
// Principal moments closer than this (relative to the largest) are treated as equal: the
// axes in that plane are then taken from the input axes (see choose_principal_axes).
constexpr double kDegenerateMoments = 1e-10;
// Supported lengths (doc/Howto_nscd_shape_library_format.rst, "Size limits"): |coordinate|
// and radius at most kMaxLength, grain size at least kMinLength. Then volume (~ size^3) and
// inertia per unit density (~ size^5) stay far inside the range of doubles, also once
// multiplied by a density and divided into torques later.
constexpr double kMaxLength = 1e30;
constexpr double kMinLength = 1e-30;
// Principal moments are resolved to ~1e-16 of the largest one; a needle whose smallest
// moment is below kMinMomentRatio x the largest (thinner than ~kMinThickness x its
// length) would get an axial moment that is mostly round-off, or zero.
constexpr double kMinMomentRatio = 1e-12;
constexpr double kMinThickness = 1e-6;

std::string describe(const Vec3 &p)
{
  std::ostringstream out;
  out.precision(10);
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

std::string describe(double v)
{
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

void check_input(const std::vector<Vec3> &points, double radius)
{
  if (!std::isfinite(radius) || radius < 0.0) {
    throw ShapeError("rounding radius " + describe(radius) + " is invalid; give a finite radius >= 0");
  }
  if (radius > kMaxLength) {
    throw ShapeError("rounding radius " + describe(radius) + " is above the supported " + describe(kMaxLength) +
                     "; use a larger length unit");
  }
  if (points.empty()) throw ShapeError("no points given; give at least one point (a sphere)");
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw ShapeError("point " + std::to_string(i + 1) + " " + describe(points[i]) +
                       " is not finite; give finite coordinates");
    }
    if (points[i].cwiseAbs().maxCoeff() > kMaxLength) {
      throw ShapeError("point " + std::to_string(i + 1) + " " + describe(points[i]) + " is beyond +-" +
                       describe(kMaxLength) + ": centre the shape or use a larger unit");
    }
  }
}

// Cell of the de-duplication grid: integer coordinates of q / cell size.
struct GridCell {
  std::int64_t i, j, k;
  bool operator==(const GridCell &o) const { return i == o.i && j == o.j && k == o.k; }
};

struct GridCellHash {
  size_t operator()(const GridCell &c) const
  {
    const std::uint64_t h = static_cast<std::uint64_t>(c.i) * 0x9e3779b97f4a7c15ULL ^
                            static_cast<std::uint64_t>(c.j) * 0xc2b2ae3d27d4eb4fULL ^
                            static_cast<std::uint64_t>(c.k) * 0x165667b19e3779f9ULL;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

// The points with near-duplicates removed (first occurrence kept, input order kept),
// shifted by -reference and multiplied by `scale`. A point is a duplicate when it lies
// within `tolerance` (after scaling) of a point kept before it. Kept points are hashed on
// a grid of cells `tolerance` wide, so only the 27 cells around a point can hold one that
// close: O(n) expected instead of comparing every pair.
std::vector<Vec3> distinct_points(const std::vector<Vec3> &points, const Vec3 &reference, double scale,
                                  double tolerance)
{
  const double cell = tolerance > 0.0 ? tolerance : 1.0;
  std::unordered_map<GridCell, std::vector<int>, GridCellHash> grid;
  grid.reserve(points.size());
  std::vector<Vec3> kept;
  kept.reserve(points.size());
  auto cell_of = [&](const Vec3 &q) {
    return GridCell{static_cast<std::int64_t>(std::floor(q.x() / cell)),
                    static_cast<std::int64_t>(std::floor(q.y() / cell)),
                    static_cast<std::int64_t>(std::floor(q.z() / cell))};
  };
  auto near_kept = [&](const Vec3 &q, const GridCell &c) {
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t dk = -1; dk <= 1; ++dk) {
          const auto it = grid.find({c.i + di, c.j + dj, c.k + dk});
          if (it == grid.end()) continue;
          for (int index : it->second)
            if ((kept[index] - q).norm() <= tolerance) return true;
        }
    return false;
  };
  for (const auto &p : points) {
    const Vec3 q = (p - reference) * scale;
    const GridCell c = cell_of(q);
    if (near_kept(q, c)) continue;
    grid[c].push_back(static_cast<int>(kept.size()));
    kept.push_back(q);
  }
  return kept;
}

int farthest_from_line(const std::vector<Vec3> &points, const Vec3 &origin, const Vec3 &direction, double *distance)
{
  int best = 0;
  *distance = -1.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 d = points[i] - origin;
    const double dist = (d - d.dot(direction) * direction).norm();
    if (dist > *distance) {
      *distance = dist;
      best = static_cast<int>(i);
    }
  }
  return best;
}

enum class Dimension { point, line, flat, solid };

// How many dimensions the (distinct) points span, by the farthest-point construction.
Dimension spanned_dimension(const std::vector<Vec3> &points, double tolerance)
{
  if (points.size() == 1) return Dimension::point;
  const Vec3 &a = points[0];
  double distance = 0.0;
  const int b = farthest_from_line(points, a, Vec3::Zero(), &distance);
  if (distance <= tolerance) return Dimension::point;
  const Vec3 axis = (points[b] - a).normalized();
  const int c = farthest_from_line(points, a, axis, &distance);
  if (distance <= tolerance) return Dimension::line;
  const Vec3 normal = axis.cross(points[c] - a).normalized();
  double thickness = 0.0;
  for (const auto &p : points) thickness = std::max(thickness, std::abs((p - a).dot(normal)));
  return thickness <= tolerance ? Dimension::flat : Dimension::solid;
}

// The two extreme points of a collinear set.
std::vector<Vec3> segment_ends(const std::vector<Vec3> &points)
{
  double distance = 0.0;
  const int far = farthest_from_line(points, points[0], Vec3::Zero(), &distance);
  const Vec3 axis = (points[far] - points[0]).normalized();
  auto along = [&](const Vec3 &a, const Vec3 &b) { return a.dot(axis) < b.dot(axis); };
  return {*std::min_element(points.begin(), points.end(), along),
          *std::max_element(points.begin(), points.end(), along)};
}

// Newell's normal of a polygon: robust for slightly non-planar merged faces.
Vec3 polygon_normal(const std::vector<Vec3> &vertices, const std::vector<int> &polygon)
{
  Vec3 n = Vec3::Zero();
  const size_t count = polygon.size();
  for (size_t i = 0; i < count; ++i) n += vertices[polygon[i]].cross(vertices[polygon[(i + 1) % count]]);
  return n.normalized();
}

void set_face_planes(Spheropolyhedron &shape)
{
  for (auto &face : shape.faces) {
    face.normal = polygon_normal(shape.vertices, face.vertices);
    face.offset = -HUGE_VAL;
    for (int v : face.vertices) face.offset = std::max(face.offset, face.normal.dot(shape.vertices[v]));
  }
}

void set_edge_faces(Spheropolyhedron &shape)
{
  shape.edge_faces.assign(shape.edges.size(), {-1, -1});
  for (size_t f = 0; f < shape.faces.size(); ++f) {
    const auto &polygon = shape.faces[f].vertices;
    for (size_t i = 0; i < polygon.size(); ++i) {
      const int a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      const std::array<int, 2> key{std::min(a, b), std::max(a, b)};
      const auto it = std::lower_bound(shape.edges.begin(), shape.edges.end(), key);
      shape.edge_faces[it - shape.edges.begin()][a < b ? 0 : 1] = static_cast<int>(f);
    }
  }
}

// Polyhedron core from the hull of the (distinct, 3-D spanning) points.
void build_polyhedron_core(Spheropolyhedron &shape, const std::vector<Vec3> &points, double tolerance)
{
  const HullTopology hull = convex_hull_3d(points, tolerance);
  std::vector<int> compact(points.size(), -1);
  for (int v : hull.vertices) {
    compact[v] = static_cast<int>(shape.vertices.size());
    shape.vertices.push_back(points[v]);
  }
  for (const auto &polygon : hull.faces) {
    Face face;
    for (int v : polygon.vertices) face.vertices.push_back(compact[v]);
    shape.faces.push_back(std::move(face));
  }
  for (const auto &edge : hull.edges) shape.edges.push_back({compact[edge[0]], compact[edge[1]]});
  set_face_planes(shape);
  set_edge_faces(shape);
}

MassMoments shape_moments(const Spheropolyhedron &shape)
{
  if (shape.is_sphere()) return ball_moments(shape.vertices[0], shape.radius);
  if (shape.is_spherocylinder()) return spherocylinder_moments(shape.vertices[0], shape.vertices[1], shape.radius);
  return dilated_polyhedron_moments(shape.vertices, shape.faces, shape.edges, shape.edge_faces, shape.radius);
}

// Index of the first component whose magnitude is (within round-off) the largest.
int dominant_component(const Vec3 &v)
{
  const double largest = v.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k)
    if (std::abs(v[k]) >= largest - 1e-9) return k;
  return 0;
}

// Eigenvectors have no sign: make the dominant component positive.
Vec3 with_fixed_sign(const Vec3 &v) { return v[dominant_component(v)] < 0.0 ? Vec3(-v) : v; }

// A unit vector orthogonal to `axis`, taken from the input axis most orthogonal to it.
Vec3 orthogonal_from_input_axes(const Vec3 &axis)
{
  const Vec3 magnitude = axis.cwiseAbs();
  const double smallest = magnitude.minCoeff();
  int k = 0;
  while (magnitude[k] > smallest + 1e-9) ++k;
  const Vec3 e = Vec3::Unit(k);
  return (e - e.dot(axis) * axis).normalized();
}

// Principal axes as the columns of a rotation, ascending moments. The choice is
// deterministic and returns the identity for a shape already in its body frame (so that
// rebuilding from body-frame vertices is stable): signs make the dominant component
// positive, and equal moments keep the input axes within their plane.
Mat3 choose_principal_axes(const Mat3 &inertia)
{
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia);
  const Vec3 moments = solver.eigenvalues();
  const Mat3 vectors = solver.eigenvectors();
  const double tolerance = kDegenerateMoments * moments.cwiseAbs().maxCoeff();
  const bool low_pair = moments[1] - moments[0] <= tolerance;
  const bool high_pair = moments[2] - moments[1] <= tolerance;
  Vec3 c0, c1;
  if (low_pair && high_pair) return Mat3::Identity();
  if (low_pair) {
    const Vec3 distinct = with_fixed_sign(vectors.col(2));
    c0 = orthogonal_from_input_axes(distinct);
    c1 = distinct.cross(c0);
  } else if (high_pair) {
    c0 = with_fixed_sign(vectors.col(0));
    c1 = orthogonal_from_input_axes(c0);
  } else {
    c0 = with_fixed_sign(vectors.col(0));
    c1 = with_fixed_sign(vectors.col(1));
  }
  Mat3 axes;
  axes << c0, c1, c0.cross(c1);
  return axes;
}

// Moves the shape into its body frame; input_centroid is set relative to the points'
// reference (their centroid).
void move_to_body_frame(Spheropolyhedron &shape)
{
  const MassMoments moments = shape_moments(shape);
  const Vec3 centre = moments.centre();
  const Mat3 inertia = moments.inertia_about_centre();
  const Mat3 axes = choose_principal_axes(inertia);
  for (auto &v : shape.vertices) v = axes.transpose() * (v - centre);
  if (shape.is_spherocylinder()) {
    const Vec3 d = shape.vertices[1] - shape.vertices[0];
    if (d[dominant_component(d)] < 0.0) std::swap(shape.vertices[0], shape.vertices[1]);
  }
  set_face_planes(shape);
  shape.volume = moments.volume;
  shape.principal_inertia = (axes.transpose() * inertia * axes).diagonal();
  shape.input_centroid = centre;
  shape.input_rotation = Quat(axes).normalized();
  double farthest = 0.0;
  for (const auto &v : shape.vertices) farthest = std::max(farthest, v.norm());
  shape.bounding_radius = farthest + shape.radius;
}

// Takes a shape built in units of `unit` (a power of two, so that this is exact) back to
// the caller's units; `reference` is the input points' centroid.
void scale_to_input_units(Spheropolyhedron &shape, double unit, const Vec3 &reference)
{
  for (auto &v : shape.vertices) v *= unit;
  for (auto &f : shape.faces) f.offset *= unit;
  shape.radius *= unit;
  shape.volume *= unit * unit * unit;
  shape.principal_inertia *= unit * unit * unit * unit * unit;
  shape.bounding_radius *= unit;
  shape.input_centroid = reference + unit * shape.input_centroid;
}

// Within the size limits volume and moments are finite; the check keeps any inf, NaN or
// vanishing moment (which would only show up later as garbage motion) out of the library,
// and refuses needles whose smallest moment is round-off.
void check_mass_properties(const Spheropolyhedron &shape)
{
  auto usable = [](double v) { return std::isfinite(v) && v >= DBL_MIN; };
  const Vec3 &inertia = shape.principal_inertia;
  if (!usable(shape.volume) || !usable(inertia[0]) || !usable(inertia[1]) || !usable(inertia[2]) ||
      !usable(shape.bounding_radius)) {
    throw ShapeError("the shape's volume " + describe(shape.volume) + " or principal inertia " +
                     describe(inertia) + " is not a finite positive number; give points and a radius "
                     "within the size limits of doc/Howto_nscd_shape_library_format.rst");
  }
  if (inertia.minCoeff() < kMinMomentRatio * inertia.maxCoeff()) {
    throw ShapeError("the shape is a needle: its principal moments of inertia " + describe(inertia) +
                     " differ by more than a factor " + describe(1 / kMinMomentRatio) +
                     ", beyond what doubles resolve; make it thicker than " + describe(kMinThickness) +
                     " x its length");
  }
}

// The grain size L (largest distance of a point from the points' centroid, or the
// radius if that is larger) must lie in [kMinLength, ...]; the upper end follows from
// the coordinate and radius limits.
void check_grain_size(double length, size_t point_count)
{
  if (length == 0.0) {
    throw ShapeError((point_count == 1 ? std::string("a single point") : "all " + std::to_string(point_count) +
                      " points coincide; a single point") +
                     " with radius 0 has no volume; give a radius > 0 (a sphere) or at least 4 points that "
                     "are not coplanar");
  }
  if (length < kMinLength) {
    throw ShapeError("the grain size " + describe(length) + " is below the supported " + describe(kMinLength) +
                     "; use a smaller length unit");
  }
}

}    // namespace

Spheropolyhedron make_spheropolyhedron(const std::vector<Vec3> &points, double radius)
{
  check_input(points, radius);
  Vec3 reference = Vec3::Zero();
  for (const auto &p : points) reference += p;
  reference /= static_cast<double>(points.size());
  double size = 0.0;
  for (const auto &p : points) size = std::max(size, (p - reference).stableNorm());    // no underflow at 1e-300
  const double length = std::max(size, radius);
  check_grain_size(length, points.size());
  // Hull and moments are computed in units of a power of two near the grain size: scaling
  // back is exact, and qhull and the moment sums work on numbers near 1 in any length
  // unit (moments ~ L^5 of a 1e-70 grain would underflow otherwise).
  const double unit = std::ldexp(1.0, std::ilogb(length));
  const double tolerance = kRelativeTolerance * length / unit;

  const std::vector<Vec3> distinct = distinct_points(points, reference, 1.0 / unit, tolerance);
  Spheropolyhedron shape;
  shape.radius = radius / unit;
  switch (spanned_dimension(distinct, tolerance)) {
    case Dimension::point:
      if (radius <= 0.0) check_grain_size(0.0, points.size());
      shape.vertices = {distinct[0]};
      break;
    case Dimension::line:
      if (radius <= 0.0) {
        throw ShapeError(std::to_string(distinct.size()) +
                         " collinear points with radius 0 have no volume; give a radius > 0 or a point off the "
                         "line");
      }
      if (radius < kMinThickness * size) {
        throw ShapeError("the radius " + describe(radius) + " of these " + std::to_string(distinct.size()) +
                         " collinear points is below " + describe(kMinThickness) + " x their size " +
                         describe(size) + " (too thin for the axial moment of inertia to be resolved in "
                         "doubles); give a larger radius or add a point off the line");
      }
      shape.vertices = segment_ends(distinct);
      break;
    case Dimension::flat:
      throw ShapeError(std::to_string(distinct.size()) +
                       " coplanar points form a flat point set (no volume); add a point off their plane");
    case Dimension::solid:
      build_polyhedron_core(shape, distinct, tolerance);
      break;
  }
  move_to_body_frame(shape);
  scale_to_input_units(shape, unit, reference);
  check_mass_properties(shape);
  return shape;
}

namespace {

GrainInertia checked_grain_inertia(const Spheropolyhedron &shape, double mass, const std::string &given)
{
  auto usable = [](double v) { return std::isfinite(v) && v >= DBL_MIN && v <= DBL_MAX; };
  GrainInertia grain;
  grain.mass = mass;
  grain.inertia = (mass / shape.volume) * shape.principal_inertia;
  if (!usable(grain.mass) || !usable(grain.inertia[0]) || !usable(grain.inertia[1]) || !usable(grain.inertia[2])) {
    throw ShapeError(given + " gives a grain of mass " + describe(grain.mass) + " and moments of inertia " +
                     describe(grain.inertia) + ", not all finite positive numbers; change the units");
  }
  if (mass < kMinBodyMass || mass > kMaxBodyMass)
    throw ShapeError(given + " gives a grain of mass " + describe(mass) + ", outside the solver's " +
                     describe(kMinBodyMass) + " to " + describe(kMaxBodyMass) + "; change the mass unit");
  return grain;
}

}    // namespace

GrainInertia grain_inertia_from_density(const Spheropolyhedron &shape, double density)
{
  if (!std::isfinite(density) || density <= 0.0) {
    throw ShapeError("density " + describe(density) + " is invalid; give a finite density > 0");
  }
  return checked_grain_inertia(shape, density * shape.volume, "density " + describe(density));
}

GrainInertia grain_inertia_from_mass(const Spheropolyhedron &shape, double mass)
{
  if (!std::isfinite(mass) || mass <= 0.0) throw ShapeError("mass " + describe(mass) + " is invalid; give a finite mass > 0");
  return checked_grain_inertia(shape, mass, "mass " + describe(mass));
}

double extent(const Spheropolyhedron &shape, const Quat &orientation, const Vec3 &direction)
{
  const Vec3 body_direction = orientation.conjugate() * direction;    // one rotation, not one per vertex
  double reach = -INFINITY;
  for (const Vec3 &v : shape.vertices) reach = std::max(reach, v.dot(body_direction));
  return reach + shape.radius;
}

}    // namespace nscd
