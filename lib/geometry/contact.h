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

// Narrow-phase contact geometry: where two bodies touch, or nearly touch.
//
// Bodies are spheropolyhedra (a convex core dilated by a sphere of radius r), plane walls,
// the inside of a cylinder wall and wire segments (spherocylinders). All functions are
// exact on the cores (no sampling, no iteration tolerance beyond round-off) and allocate
// no heap memory once their ContactWorkspace has grown to the largest shape seen.
//
// Conventions (doc/Howto_nscd_contact_geometry.rst has the details and the reasons):
//  * contact(i, j): the normal points from j to i (it pushes i away from j);
//  * gap = distance between the dilated surfaces, negative when they overlap;
//  * point = midpoint between the two dilated surfaces along the normal;
//  * a contact is reported when gap <= activation (activation >= 0), so a solver sees
//    contacts that may close during the coming step;
//  * key = 64-bit id of the pair of features (vertex / edge / face on each side) that made
//    the point; the high 32 bits describe i's feature, the low 32 bits j's feature. The
//    key depends only on which features touch, so it persists from step to step.
#pragma once

#include "math/types.h"
#include "shape/spheropolyhedron.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace nscd {

// Any invalid argument of a contact query (bad wall, negative activation distance, ...).
class ContactError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct ContactPoint {
  Vec3 point;             // world position, midway between the two dilated surfaces
  Vec3 normal;            // unit, from body j to body i
  double gap;             // signed distance between dilated surfaces (< 0: overlap)
  std::uint64_t key;      // persistent feature-pair id, see feature_key.h
};

// All points of one contact between two bodies; fixed capacity, no heap.
struct ContactSet {
  // At most this many points per contact. Every touching or penetrating point must be
  // given to the solver (it only stops the overlap of the points it sees from growing), and
  // a grain resting on a wall has ~8 vertices within a typical activation distance, so 8;
  // a box on a box gives its 4 corners, two turned squares the 8 corners of their octagon.
  // Larger patches are reduced depth first, then for coverage
  // (doc/Howto_nscd_contact_geometry.rst).
  static constexpr int kMaxPoints = 8;
  std::array<ContactPoint, kMaxPoints> points{};
  int count = 0;

  bool empty() const { return count == 0; }
  const ContactPoint *begin() const { return points.data(); }
  const ContactPoint *end() const { return points.data() + count; }
  const ContactPoint &operator[](int k) const { return points[k]; }
  // The deepest overlap of its points (minus the smallest gap); -infinity when empty.
  double deepest_overlap() const
  {
    double deepest = -std::numeric_limits<double>::infinity();
    for (const ContactPoint &p : *this) deepest = std::max(deepest, -p.gap);
    return deepest;
  }
};

// One point of the contact of a wire segment i with a body j (or another segment j).
struct SegmentContact {
  Vec3 point;             // world, midway between the two dilated surfaces
  Vec3 normal;            // unit, from j to i
  double gap;             // signed distance between dilated surfaces (< 0: overlap)
  double s_i = 0.0;       // position of the contact along segment i: 0 at p0, 1 at p1
  double s_j = 0.0;       // same along segment j (0 when j is a grain)
  std::uint64_t key = 0;  // feature pair, as in ContactPoint
};

// Contact of a wire segment with a grain: the ends of the touching stretch, in the order
// of s_i. Two points when the segment lies on a face or along an edge (each with its own
// gap, so a tilting segment's force moves smoothly to its lower end), else one.
struct SegmentGrainContact {
  static constexpr int kMaxPoints = 2;
  std::array<SegmentContact, kMaxPoints> points{};
  int count = 0;

  bool empty() const { return count == 0; }
  const SegmentContact *begin() const { return points.data(); }
  const SegmentContact *end() const { return points.data() + count; }
  const SegmentContact &operator[](int k) const { return points[k]; }
};

// Where along a segment a contact point lies: at one of its end spheres (the sphere of a
// wire node, part of every element meeting at the node) or inside.
enum class SegmentPart { start, end, inside };
SegmentPart segment_part_i(const SegmentContact &c);
SegmentPart segment_part_j(const SegmentContact &c);

// A spherocylinder: segment p0-p1 dilated by radius (p0 == p1 is a sphere).
struct Segment {
  Vec3 p0;
  Vec3 p1;
  double radius = 0.0;
};

// Half-space wall: the domain is on the side `normal` points to.
struct PlaneWall {
  Vec3 point;             // any point of the wall plane
  Vec3 normal;            // unit normal pointing into the domain
};

// Cylindrical wall; the grains are inside it.
struct CylinderWall {
  Vec3 axis_point;        // any point on the axis
  Vec3 axis_direction;    // unit vector along the axis
  double radius = 0.0;    // inner radius of the wall
};

// Scratch memory of the contact queries. Keep one per thread and pass it to every call:
// its buffers grow to the largest shape seen and are then reused without allocation.
class ContactWorkspace {
 public:
  struct ClipVertex {
    Vec3 position;
    std::uint32_t incident_feature;   // feature of the incident body this point lies on
    std::uint32_t reference_feature;  // feature of the reference body it projects onto
    // What the polygon edge leaving this vertex lies on: an edge of the incident face
    // (incident_edge) when reference_side < 0, else the side plane of reference edge
    // number reference_side.
    std::uint32_t incident_edge;
    int reference_side;
  };
  struct Candidate {
    Vec3 position;                    // midway between the dilated surfaces
    Vec3 core_point_i;                // the point's foot on core i
    double gap;
    std::uint64_t key;
    Vec3 normal = Vec3::Zero();       // unit, from body j to body i
  };

  // An edge on the Gauss sphere: the arc between the normals of its two faces (negated
  // for body j), with their cross product, for the separating-axis pruning.
  struct EdgeArc {
    Vec3 n0, n1, n1_x_n0;
  };

  std::vector<Vec3> vertices_i, vertices_j;     // core vertices in the query frame
  std::vector<Vec3> normals_i, normals_j;       // face normals in the query frame
  std::vector<double> offsets_i, offsets_j;     // face plane offsets in the query frame
  std::vector<ClipVertex> polygon, clipped;     // ping-pong buffers of face clipping
  std::vector<Candidate> candidates;            // manifold points before reduction
  std::vector<EdgeArc> arcs_i, arcs_j;          // edge arcs of the two cores
  std::vector<int> edges_near_i, edges_near_j;  // edges close enough to the other core
  std::vector<char> marks_ref, marks_inc;       // vertices of the closest features
  std::vector<int> near_faces;                  // faces through them
  std::vector<Vec3> near_sides;                 // their sides' outward normals, loop by loop
  std::vector<double> vertex_rows;              // each vertex's heights and distances beside them
  std::vector<char> marks_measured;             // the vertices measured so far

  // Bytes its buffers hold (their capacities), for the LAMMPS styles' memory_usage().
  std::size_t memory_bytes() const;
};

// Two grains i and j. Returns the contact points with gap <= activation (maybe none).
// Where they meet edge- or corner-first, also the speculative points that a grain turning
// about its first contact brings down within a step (vertices over faces, edges across the
// borders of faces; doc/Howto_nscd_contact_geometry.rst) with gaps up to
// speculative_distance (the distance the pair can close within the step; at most the
// activation, at least 1e-3 of the larger grain's bounding radius; 0: none). Throws
// ContactError for a NaN distance.
ContactSet contact_grains(const Spheropolyhedron &shape_i, const Pose &pose_i,
                          const Spheropolyhedron &shape_j, const Pose &pose_j,
                          double activation, ContactWorkspace &workspace,
                          double speculative_distance = std::numeric_limits<double>::infinity());

// Grain i against a plane wall j.
ContactSet contact_grain_plane(const Spheropolyhedron &shape, const Pose &pose,
                               const PlaneWall &wall, double activation,
                               ContactWorkspace &workspace);

// Grain i inside a cylindrical wall j.
ContactSet contact_grain_cylinder(const Spheropolyhedron &shape, const Pose &pose,
                                  const CylinderWall &wall, double activation,
                                  ContactWorkspace &workspace);

// A sphere i (a wire node dilated by the wire's radius) against a wall j: the one point,
// whatever its gap. A chain of spherocylinders touches a plane or the inside of a cylinder
// only with the spheres at its nodes (height is linear and the distance from an axis convex
// along a segment, so both are extreme at an end), so these are the wire's wall contacts.
ContactPoint contact_sphere_plane(const Vec3 &centre, double radius, const PlaneWall &wall);
ContactPoint contact_sphere_cylinder(const Vec3 &centre, double radius, const CylinderWall &wall);

// Wire segment i against grain j: the points with gap <= activation (see
// SegmentGrainContact).
SegmentGrainContact contact_segment_grain(const Segment &segment, const Spheropolyhedron &shape,
                                          const Pose &pose, double activation,
                                          ContactWorkspace &workspace);

// Wire segment i against wire segment j (parallel overlapping segments: middle of the
// overlap; zero-length segments are spheres).
std::optional<SegmentContact> contact_segments(const Segment &segment_i,
                                               const Segment &segment_j, double activation);

}    // namespace nscd
