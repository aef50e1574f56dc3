/* -*- c++ -*- ----------------------------------------------------------
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

// A convex spheropolyhedron: a convex polyhedral core dilated by a sphere of radius r.
//
// Stored in its body frame: origin at the centre of mass of the dilated shape, axes along
// its principal axes of inertia. One vertex = a sphere, two vertices = a spherocylinder,
// four or more non-coplanar vertices = a rounded polyhedron.
#pragma once

#include "math/types.h"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace nscd {

// Any problem with a shape's definition (degenerate points, negative radius, ...).
class ShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Face {
  std::vector<int> vertices;    // indices into Spheropolyhedron::vertices, counter-clockwise seen from outside
  Vec3 normal;                  // outward unit normal
  double offset;                // normal.dot(x) == offset for every x on the face plane
};

struct Spheropolyhedron {
  std::vector<Vec3> vertices;              // core vertices, body frame
  std::vector<std::array<int, 2>> edges;   // each core edge once, vertex indices
  std::vector<Face> faces;                 // core faces; coplanar hull facets merged
  // The two faces bounding edges[i]: in edge_faces[i][0] the edge runs edges[i][0] ->
  // edges[i][1] in counter-clockwise order, in edge_faces[i][1] it runs the other way.
  std::vector<std::array<int, 2>> edge_faces;
  double radius = 0.0;                     // rounding (dilation) radius r >= 0

  // Mass properties of the dilated shape at unit density, in the body frame.
  double volume = 0.0;
  Vec3 principal_inertia = Vec3::Zero();   // diagonal of the inertia tensor per unit density

  // Largest distance from the centre of mass to the dilated surface.
  double bounding_radius = 0.0;

  // Transform that took the input points into the body frame:
  // body = input_rotation.conjugate() * (input - input_centroid).
  Vec3 input_centroid = Vec3::Zero();
  Quat input_rotation = Quat::Identity();

  bool is_sphere() const { return vertices.size() == 1; }
  bool is_spherocylinder() const { return vertices.size() == 2; }
  bool is_polyhedron() const { return vertices.size() >= 4; }
};

// Builds the shape from a cloud of points (any order, interior points allowed; the
// convex hull is taken). Throws ShapeError for: no points, radius < 0, radius == 0 with
// fewer than 4 non-coplanar points, 3+ points that are collinear or coplanar (flat).
Spheropolyhedron make_spheropolyhedron(const std::vector<Vec3> &points, double radius);

// How far the dilated surface of a grain turned by `orientation` reaches along the unit
// `direction` from its centre of mass: max over core vertices of (R v).d, plus the radius
// (the support function). The grain's top is z + extent(shape, q, +z).
double extent(const Spheropolyhedron &shape, const Quat &orientation, const Vec3 &direction);

// Mass and principal moments of inertia (body frame) of one grain of a shape.
struct GrainInertia {
  double mass = 0.0;
  Vec3 inertia = Vec3::Zero();
};

// The masses a body of the contact problem may have (grains, the loading plate): the solver
// works with squares of impulses of the order of a body's momentum, and beside a body of
// mass 1 one of 1e-160 left it unconverged (every step, 1000 sweeps; 1e-150 was fine).
constexpr double kMinBodyMass = 1e-100, kMaxBodyMass = 1e100;

// From a density (mass = density x volume) or from the grain's mass. Throws ShapeError,
// naming the value, unless it is finite and > 0, the mass lies within kMinBodyMass ..
// kMaxBodyMass and the three moments come out as finite normal numbers (not inf, 0 or
// denormal, which would make garbage motion).
GrainInertia grain_inertia_from_density(const Spheropolyhedron &shape, double density);
GrainInertia grain_inertia_from_mass(const Spheropolyhedron &shape, double mass);

}    // namespace nscd
