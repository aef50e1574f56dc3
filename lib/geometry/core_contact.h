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

// The shared machinery of the contact queries (internal to lib/geometry): a convex core in
// a common frame, the separating-axis search and the contact-manifold builder.
#pragma once

#include "geometry/contact.h"

namespace nscd {
namespace geometry_detail {

// Relative tolerances, all multiplied by the length scale of the pair (the larger
// bounding radius) or dimensionless. doc/Howto_nscd_contact_geometry.rst explains each choice.
struct Tolerance {
  // A point within this distance of a clipping plane is on it (round-off of the frame).
  static constexpr double kClip = 1e-9;
  // Two contact points closer than this (times the smaller size) are one support.
  static constexpr double kMerge = 1e-6;
  // Cores closer than this use the separating-axis search: the GJK direction from two
  // nearly coincident closest points is ill-conditioned.
  static constexpr double kNearTouch = 1e-6;
  // A face is the contact plane when 1 - cos(angle to the axis) is below this.
  static constexpr double kFaceAlign = 1e-8;
  // An edge lies in the contact plane when |cos(angle to the axis)| is below this.
  static constexpr double kEdgeAlign = 1e-7;
  // An edge axis must beat the best face axis by this much (times the length scale)
  // to be chosen: faces give stable multi-point patches.
  static constexpr double kEdgeAxisBias = 1e-9;
  // Point reduction: a point with 0 < gap <= max(smallest gap, 0) + this (times the length
  // scale) is "about to touch" and is kept, after the penetrating ones, before any
  // shallower point: it can close within a step, and a point at gap ~ 0 must not drop out
  // of the set because round-off or jitter moved its gap to the positive side.
  static constexpr double kTouchBand = 1e-3;
};

// A convex core placed in the query frame. Polytopes (4+ vertices) carry their topology
// through `shape`; points and segments (1 or 2 vertices) have no faces.
struct Core {
  const Vec3 *vertices = nullptr;    // count vertices, query frame
  int count = 0;
  const Spheropolyhedron *shape = nullptr;    // faces / edges (polytopes only)
  const Vec3 *normals = nullptr;     // face normals, query frame (polytopes only)
  const double *offsets = nullptr;   // face offsets, query frame (polytopes only)
  Vec3 centroid = Vec3::Zero();      // mean of the vertices: inside the core
  double extent = 0.0;               // largest distance from centroid to a vertex
  double radius = 0.0;

  bool is_polytope() const { return shape != nullptr && count >= 4; }
  int face_count() const { return is_polytope() ? static_cast<int>(shape->faces.size()) : 0; }
};

// Places a grain's core in the frame whose origin is `origin` (world), using the buffers.
Core place_core(const Spheropolyhedron &shape, const Pose &pose, const Vec3 &origin,
                std::vector<Vec3> &vertices, std::vector<Vec3> &normals,
                std::vector<double> &offsets);

// The axis of largest separation among face normals and edge-edge cross products.
struct SeparatingAxis {
  double separation;    // < 0: the cores overlap by this much along axis
  Vec3 axis;            // unit, from core a towards core b
};
// Needs at least one polytope core.
SeparatingAxis find_separating_axis(const Core &a, const Core &b, double length_scale,
                                    ContactWorkspace &workspace);

// The contact manifold of cores a and b. The result is in workspace.candidates; the
// return value is the common unit normal, from b to a.
struct ManifoldInput {
  double activation;       // keep points with gap <= activation
  double length_scale;     // larger bounding radius of the pair
  double merge_distance;   // points closer than this are merged
  // Grain pairs: also the points a turning grain brings into contact within a step (every
  // vertex of either core over a face of the other, and the edges at the closest features
  // crossing the border of a face at the other's), with gaps up to this distance (and the
  // activation). 0: none.
  double speculative_distance = 0.0;
};
Vec3 build_manifold(const Core &a, const Core &b, const ManifoldInput &input,
                    ContactWorkspace &workspace);

// Writes workspace.candidates (in the frame shifted back by origin) to out; more than
// ContactSet::kMaxPoints are reduced depth first: every penetrating point (gap <= 0), then
// every point about to touch (see Tolerance::kTouchBand), then the others for coverage of
// the patch (projected along normal); a tier that does not fit is itself chosen deepest
// first, then for coverage. length_scale: the larger bounding radius of the pair.
void write_contact_set(const ContactWorkspace &workspace, const Vec3 &normal,
                       const Vec3 &origin, double length_scale, ContactSet &out);

// Throws ContactError unless the activation distance is finite and >= 0.
void check_activation(double activation);

}    // namespace geometry_detail
}    // namespace nscd
