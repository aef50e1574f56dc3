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

// Repeated contact queries of a wire segment against a grain that holds still (the wire's
// subcycle: tens of substeps per grain step, the segment moving a little each time).
//
// contact_segment_grain finds the closest features of the two cores from scratch (GJK, the
// face search, clipping): about 1.5 us per call. Here the answer is first sought from the
// grain feature (face, edge or vertex) that gave the last one: when the segment's closest
// point lies inside that feature's Voronoi region by a margin, the closest features are
// known and the answer is computed in closed form, the same points, gaps and keys as
// contact_segment_grain up to round-off (tests/unit/geometry/test_segment_tracking.cpp
// compares both on random grains and motions). Otherwise contact_segment_grain answers and
// its deepest point gives the next hint. doc/Howto_nscd_contact_geometry.rst has the details.
#pragma once

#include "geometry/contact.h"

#include <cstdint>
#include <vector>

namespace nscd {

// A shape's faces, edges and vertices arranged for the Voronoi-region checks, in its body
// frame. Build once per shape (it does not depend on the pose).
class ShapeFeatures {
 public:
  explicit ShapeFeatures(const Spheropolyhedron &shape);

  struct Side {          // a side plane of a face: the plane through one of its edges,
    Vec3 outward;        // perpendicular to the face, unit normal pointing away from it
    double offset;       // outward . x on the plane
    int edge;            // the edge it passes through (index into edge())
  };
  struct FaceInfo {
    int first_side, side_count;    // into sides(), in the face's counter-clockwise order
  };
  struct EdgeInfo {
    int v0, v1;          // as in shape.edges
    int faces;           // 2 for a polyhedron's edge, 0 for a capsule's axis
    Vec3 outward[2];     // side-plane normal of each face at this edge (see Side)
  };

  const Spheropolyhedron &shape() const { return *shape_; }
  const Side &side(int k) const { return sides_[k]; }
  const FaceInfo &face(int f) const { return faces_[f]; }
  const EdgeInfo &edge(int e) const { return edges_[e]; }
  int edge_count() const { return static_cast<int>(edges_.size()); }
  // Neighbours of vertex v: neighbour_vertex[first_neighbour[v] .. first_neighbour[v + 1]).
  const std::vector<int> &first_neighbour() const { return first_neighbour_; }
  const std::vector<int> &neighbour_vertex() const { return neighbour_vertex_; }
  // Index of the edge between vertices a and b, -1 if there is none.
  int edge_between(int a, int b) const;

 private:
  const Spheropolyhedron *shape_;
  std::vector<Side> sides_;
  std::vector<FaceInfo> faces_;
  std::vector<EdgeInfo> edges_;
  std::vector<int> first_neighbour_, neighbour_vertex_;
  std::vector<std::pair<std::uint32_t, int>> edge_lookup_;    // (edge feature, index), sorted
};

// The grain feature that gave the last answer of one segment-grain pair, kept by the caller.
struct FeatureHint {
  enum class Kind : std::uint8_t { none, face, edge, vertex };
  Kind kind = Kind::none;
  int index = -1;    // face, edge (into ShapeFeatures) or vertex
};

// Where a grain held still stands: centre and rotation (body to world), computed once per
// grain step.
struct GrainFrame {
  Vec3 centre = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
  explicit GrainFrame(const Pose &pose = Pose())
      : centre(pose.position), rotation(pose.orientation.toRotationMatrix())
  {
  }
};

struct TrackedSegmentContact {
  SegmentGrainContact contact;    // world frame, as contact_segment_grain reports it
  // A lower bound of the smallest gap between segment and grain now: the segment's ends
  // can move by this much before any point of it touches (>= activation when no point
  // was found).
  double clearance = 0.0;
  bool from_hint = false;         // answered in closed form from the hint
};

// contact_segment_grain(segment, features.shape(), pose, activation, workspace), found
// from `hint` where possible; updates `hint`.
TrackedSegmentContact contact_segment_grain_tracked(const Segment &segment,
                                                    const ShapeFeatures &features,
                                                    const GrainFrame &frame, double activation,
                                                    FeatureHint &hint,
                                                    ContactWorkspace &workspace);

}    // namespace nscd
