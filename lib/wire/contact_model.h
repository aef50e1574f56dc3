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

// The wire's soft contacts: element-grain, element-element and node-boundary (walls, the
// loading plate). Each substep the caller hands the nodes' positions and velocities; the
// model adds the contact forces to the nodes and the reactions to the grains' and
// boundaries' sums, and updates each contact's friction memory. Used by fix wire (LAMMPS)
// and tested in tests/unit/wire/test_contact_model.cpp. Model:
// doc/Howto_nscd_wire_model.rst section 3b.
//
// The rules it implements:
//  * each element-body pair is its own contact (the paper's model); forces go to an
//    element's two nodes by the lever rule;
//  * an element touching a grain along a stretch (on a face or along an edge) touches with
//    the stretch's two ends, each with its own overlap and friction memory, weighed by
//    stretch_end_weight (contact_weights.h) so the summed force stays continuous;
//  * elements sharing a node, or joined by one element, never touch (that is the wire's
//    own bending);
//  * grains hold still within the grain step (the papers' subcycle: the wire nodes move n
//    times per move of the grains); the grain's velocity still enters the contact's
//    relative velocity (dashpot and friction), so a wire carried along by a moving grain
//    does not slide on it;
//  * a tangential spring thus follows its grain as if the grain kept, over the step, the
//    velocity it had at the step's start; how far the grain moved beyond that (its velocity
//    changed in the grain step) the spring takes at the first substep of the next step, so
//    that it holds the true relative displacement. Without this the spring lags its grain
//    by a step, and a sticking contact gains energy whenever k_t dt > 2 gamma_t (the
//    column's law at its step: 7.5 > 2): grains on the wire ring at the friction limit
//    (doc/Howto_nscd_wire_model.rst, section 5);
//  * friction memory is kept per contact and per end of its stretch ("low" = the end
//    nearer the element's first node): it survives the stretch gaining or losing an end,
//    and when one point opens into a stretch both new ends start from its spring (see
//    ContactMemory).
//
// Speed: candidate pairs are looked for on a grid, within `skin` of touching, and reused
// until some node has moved so far that a pair not in the list could touch
// (node displacement + max(node, grain or boundary displacement) > skin since the build).
// A pair whose last gap was g > 0 is not evaluated again until its nodes have moved by g.
// Element-grain pairs use contact_segment_grain_tracked. No allocation per substep once
// the lists are built.
#pragma once

#include "geometry/contact.h"
#include "geometry/point_grid.h"
#include "geometry/segment_tracking.h"
#include "wire/soft_contact.h"
#include "wire/subcycle.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace nscd::wire {

// A wall or the loading plate as the wire's nodes see it.
class NodeBoundary {
 public:
  // The contact of a sphere (a node dilated by the wire radius) with the boundary as it
  // stands `tau` into the grain step.
  virtual ContactPoint touch_sphere(const Vec3 &centre, double radius, double tau) const = 0;
  virtual Vec3 surface_velocity() const = 0;

 protected:
  ~NodeBoundary() = default;
};

// Identity of a contact that survives re-indexing, restarts and moves between MPI ranks:
// element-element (ids of A's two nodes, then B's), element-grain (A's nodes, grain id, 0),
// node-boundary (node id, 0, boundary id, 0). The first id is the node whose owner
// computes the contact.
using ContactKey = std::array<std::int64_t, 4>;

struct ContactKeyHash {
  std::size_t operator()(const ContactKey &k) const
  {
    std::size_t h = 0;
    for (std::int64_t x : k) h = h * 0x9E3779B97F4A7C15ull + static_cast<std::size_t>(x);
    return h;
  }
};

// The friction memory of one contact: its tangential spring at each end of the touching
// stretch and the weight each end carried at the last evaluation. A contact touching at
// one point holds that point's spring in both ends with weight 1/2 each. Then, from one
// evaluation to the next: two ends keep their own springs (low to low, high to high); one
// point becoming two gives both its spring (a stretch opening from a point keeps its
// friction force: each new end carries half); two ends becoming one give it their weighted
// sum (an end that leaves the query had no overlap, so no spring, and the other weighed
// 1: the spring survives the stretch losing an end). Element-element and node-boundary
// contacts touch at one point: end 0, weight 1.
struct ContactMemory {
  std::array<TangentialHistory, 2> spring{};
  std::array<double, 2> weight{0.0, 0.0};
  bool empty() const;
};

// A contact's memory as it travels (restart files, other ranks).
struct StoredContact {
  ContactKey key;
  ContactMemory memory;
};

// One copy of a wire element on this caller: nodes a and b (indices into the node arrays),
// the global ids of the element's nodes (id_a < id_b) and whether this caller computes the
// contacts of this copy (its node a is owned here; other copies are partners only).
struct ElementCopy {
  int a, b;
  std::int64_t id_a, id_b;
  bool computes;
};

// One copy of a grain: the same grain may appear more than once (periodic images, ghost
// atoms); a contact uses the copy closest to the element's first node.
struct GrainCopy {
  std::int64_t id = 0;
  const Spheropolyhedron *shape = nullptr;
  Pose pose;                        // held over the grain step
  Vec3 velocity = Vec3::Zero();     // of the centre
  Vec3 angular_velocity = Vec3::Zero();    // world frame
  int law = 0;                      // its friction: ContactModel::add_grain_friction's index
};

struct BoundaryLink {
  const NodeBoundary *boundary;
  SoftContactLaw law;               // the wire's law with the boundary's friction
  std::int64_t id;                  // < 0
  double speed;                     // |surface velocity|, for the candidate lists
};

// What the caller hands over at the start of every grain step.
struct ContactScene {
  std::vector<std::int64_t> node_id;              // per node
  std::vector<std::uint32_t> node_boundaries;     // per node: bit k = may touch boundary k
  std::vector<ElementCopy> elements;
  std::vector<GrainCopy> grains;
  std::vector<BoundaryLink> boundaries;
};

// One contact point of the last grain step, for output (compute wire/contacts): the
// contact's key, the end of its stretch (0, or 1 for the second end), where and along
// which normal (from the other body to the wire) it touched at its last evaluation, and
// its forces on the wire averaged over the step's substeps (weighted as applied).
struct ContactRecord {
  enum Kind { wire_grain = 1, wire_wire = 2, wire_boundary = 3 };
  ContactKey key{};
  int kind = wire_grain;
  int end = 0;
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero();
  double normal_force = 0.0, overlap = 0.0;
  Vec3 tangential_force = Vec3::Zero();
  bool sliding = false;
};

// How the friction springs of wire-grain contacts treat a grain's motion within the grain
// step (the subcycle holds grains still at their step-start pose):
//   carried  the spring follows the grain as if it kept its step-start velocity: a wire
//            riding on a moving grain sticks to it at any speed. The spring's force over
//            the step is that of the grain half a step on, which halves the explicit
//            coupling's limit (a grain rings once h^2 K / m passes about 2). Default.
//   held     the spring pulls by the held poses, as the normal overlap does, and takes the
//            grain's whole motion at the next step: the limit is about 4, but a wire riding
//            on a grain at speed v sees a saw-tooth of k_t v h each step and slips once that
//            passes about 2 mu f_n.
// In both the dashpots see the grain's velocity. doc/Howto_nscd_wire_model.rst.
enum class GrainSprings : std::uint8_t { carried, held };

struct ContactTotals {
  double energy = 0.0;          // elastic energy stored in the contacts
  double normal_force = 0.0;    // sum of the (weighted) normal forces
  int wire_wire = 0, wire_grain = 0, wire_boundary = 0;    // closed contacts
};

class ContactModel {
 public:
  // law: the wire's soft contact law (validated); skin > 0: margin of the candidate lists.
  ContactModel(const SoftContactLaw &law, double wire_radius, double skin);
  // Friction between elements (static, dynamic), separate from that with the grains (by
  // default the same); throws std::invalid_argument naming a bad value.
  void set_wire_wire_friction(double mu_s, double mu_d);
  const SoftContactLaw &wire_wire_law() const { return wire_wire_law_; }
  // Friction between the wire and some grains (static, dynamic), the other constants of the
  // law shared: returns the index a GrainCopy gives as its `law` (0: the law given to the
  // constructor). Throws std::invalid_argument naming a bad value.
  int add_grain_friction(double mu_s, double mu_d);
  void set_grain_springs(GrainSprings how) { grain_springs_ = how; }

  // Every element of the wire as (lower id, higher id), for the rule that elements joined
  // by a node or by one element do not touch.
  void set_elements(std::vector<std::array<std::int64_t, 2>> all_elements);
  bool joined(std::int64_t p, std::int64_t q) const;

  // The scene of a new grain step. reindexed: the node, element or grain indices changed
  // since the last step (the candidate lists are rebuilt, memories carried by key).
  void begin_step(ContactScene scene, double dt_step, bool reindexed);
  // Hands the scene back, so that the caller updates it for the next step without a copy.
  ContactScene take_scene() { return std::move(scene_); }

  // One substep: nodes at positions x with velocities v (all nodes of the scene), tau
  // into the grain step, substep dt. Adds the contact forces to f, the reactions to
  // reactions: grain copy g at index g, boundary k at grains.size() + k.
  ContactTotals add_forces(const std::vector<Vec3> &x, const std::vector<Vec3> &v, double tau, double dt,
                           std::vector<Vec3> &f, GrainForceAccumulator &reactions);

  // Memories of all contacts with a non-zero spring (the current ones and those carried
  // to the next rebuild).
  std::vector<StoredContact> memories() const;
  // Removes and returns every memory (to be kept with the atoms while they move between
  // ranks, or in a restart file; add_memories gives them back).
  std::vector<StoredContact> take_memories();
  // Memories to be found by key at the next rebuild (from another rank, a restart file).
  void add_memories(const std::vector<StoredContact> &stored);
  // Forgets the shapes' feature tables (shapes may have moved in memory between runs).
  void forget_shapes() { features_.clear(); }

  // Recording of contact points for output, from the next grain step on (costs a lookup
  // per closed contact and substep while on).
  void record_contacts(bool on) { recording_ = on; }
  // The contact points closed in any substep of the last grain step, forces averaged over
  // its substeps, in the order of their keys.
  std::vector<ContactRecord> contact_records() const;

  int rebuilds() const { return rebuilds_; }
  // Element-grain evaluations so far, and how many of them were answered from the tracked
  // feature (contact_segment_grain_tracked) rather than by the full query.
  long long grain_evaluations() const { return grain_evaluations_; }
  long long grain_evaluations_from_hint() const { return grain_from_hint_; }
  std::size_t candidates() const { return grain_pairs_.size() + wire_pairs_.size() + boundary_pairs_.size(); }
  // Bytes held on the heap: the candidate lists and their watches, the contact records and
  // memories, the scene's copies and the per-node scratch, at capacity. The shapes' feature
  // tables (per shape, not per atom) and the point grid's cells are left out.
  std::size_t memory_bytes() const;

 private:
  // A pair found open at its last evaluation keeps where its nodes were then (`seen`) and
  // its smallest gap then (lowered by its grain's motion since): no point of it can touch
  // while its nodes have moved less than that from there (for two elements: the sum over
  // both). A finer test than the watches below, for the pairs they let through; <= 0:
  // evaluate.
  struct GrainPair {
    int a, b, grain;
    ContactKey key;
    ContactMemory memory;
    FeatureHint hint;
    std::array<Vec3, 2> seen;
    double seen_gap = -1.0;
  };
  struct WirePair {
    int a1, a2, b1, b2;
    ContactKey key;
    ContactMemory memory;
    std::array<Vec3, 4> seen;
    double seen_gap = -1.0;
  };
  // Which pairs need no look this substep, in arrays of their own (read every substep).
  // Coarser than the pairs' own test (it measures displacements from the list build, not
  // from the last evaluation) but a 16-byte read for each candidate pair.
  // A pair whose smallest gap was g at its last evaluation, when its nodes had moved by
  // up to D_then since the lists were built, has a gap > 0 as long as the displacement of
  // its nodes (max over an element's two) stays below threshold = g - D_then (for two
  // elements: their sum). <= 0: evaluate.
  struct GrainWatch {
    int a, b;
    double threshold;
  };
  struct WireWatch {
    int a1, a2, b1, b2;
    double threshold;
  };
  // The watches of one element's pairs, which lie side by side in the lists (an element
  // against grains; the lower element of element pairs): none of them needs a look while
  // the element's nodes have moved less than their smallest threshold (for element pairs:
  // less than it minus the largest displacement of any node). One test per element with
  // candidates instead of one per pair; the same pairs are looked at.
  struct WatchGroup {
    int a, b;            // the element's nodes
    int first, count;    // its pairs
    double threshold;    // the smallest of theirs (NaN if one is)
  };
  struct BoundaryPair {
    int node, boundary;
    ContactKey key;
    ContactMemory memory;
  };

  SoftContactLaw law_;
  SoftContactLaw wire_wire_law_;    // law_ with the wire-wire friction
  std::vector<SoftContactLaw> grain_laws_;    // [0] = law_, then add_grain_friction's
  GrainSprings grain_springs_ = GrainSprings::carried;
  bool recording_ = false;
  int recorded_substeps_ = 0;
  std::vector<ContactRecord> records_;
  std::unordered_map<ContactKey, std::array<int, 2>, ContactKeyHash> record_of_;    // by end
  void record(const ContactKey &key, int kind, int end, const SegmentContact &point, double weight,
              const SoftContactForce &r);
  double radius_, skin_;
  std::vector<std::array<std::int64_t, 2>> all_elements_;
  ContactScene scene_;
  std::vector<GrainFrame> frames_;
  std::vector<const ShapeFeatures *> grain_features_;
  std::unordered_map<const Spheropolyhedron *, std::unique_ptr<ShapeFeatures>> features_;
  std::vector<GrainPair> grain_pairs_;
  std::vector<GrainWatch> grain_watch_;
  std::vector<WatchGroup> grain_groups_;
  std::vector<WirePair> wire_pairs_;
  std::vector<WireWatch> wire_watch_;
  std::vector<WatchGroup> wire_groups_;
  std::vector<BoundaryPair> boundary_pairs_;
  std::unordered_map<ContactKey, ContactMemory, ContactKeyHash> carried_;
  bool lists_valid_ = false;
  int rebuilds_ = 0;
  long long grain_evaluations_ = 0, grain_from_hint_ = 0;

  // displacements since the last build
  std::vector<Vec3> built_at_;              // node positions
  std::vector<double> moved_;               // per node, distance from there (this substep)
  double largest_moved_ = 0.0;              // the largest of them
  std::vector<Pose> grains_built_at_;
  std::vector<GrainCopy> grains_last_step_;    // the last scene's (the caller takes the scene back)
  // Per grain copy of this step's scene: how far it moved over the last step beyond its
  // held pose carried on by the velocities the last subcycle used (turn: a rotation
  // vector); its contacts' springs take it at this step's first substep.
  struct UnseenMotion {
    Vec3 shift = Vec3::Zero(), turn = Vec3::Zero();
  };
  std::vector<UnseenMotion> unseen_;
  bool unseen_pending_ = false;             // the first substep of the step is still to come
  void measure_unseen_motion(const ContactScene &next);
  double boundary_travel_ = 0.0;            // of the fastest boundary, before this step
  double fastest_boundary_ = 0.0;           // speed, this step
  double other_moved_ = 0.0;                // largest grain or boundary displacement at step start
  double step_ = 0.0;

  PointGrid grid_;
  std::vector<Vec3> centres_;
  ContactWorkspace workspace_;

  const ShapeFeatures &features_of(const Spheropolyhedron &shape);
  bool lists_outdated(const std::vector<Vec3> &x, double tau);
  void carry_memories();
  void rebuild(const std::vector<Vec3> &x, double tau);
  void find_grain_pairs(const std::vector<Vec3> &x);
  void find_wire_pairs(const std::vector<Vec3> &x);
  void find_boundary_pairs(const std::vector<Vec3> &x, double tau);
  template <class Pair> void recall(Pair &pair);

  bool grain_contact(GrainPair &p, GrainWatch &watch, const std::vector<Vec3> &x, const std::vector<Vec3> &v,
                     double tau, double dt, std::vector<Vec3> &f, GrainForceAccumulator &reactions, ContactTotals &totals);
  bool wire_contact(WirePair &p, WireWatch &watch, const std::vector<Vec3> &x, const std::vector<Vec3> &v, double dt,
                    std::vector<Vec3> &f, ContactTotals &totals);
  bool boundary_contact(BoundaryPair &p, const std::vector<Vec3> &x, const std::vector<Vec3> &v, double tau,
                        double dt, std::vector<Vec3> &f, GrainForceAccumulator &reactions, ContactTotals &totals);
};

}    // namespace nscd::wire
