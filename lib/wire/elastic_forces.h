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

// Elastic forces of a wire: tensile springs along elements, rotational springs at nodes.
//
// The wire is a chain of point masses (nodes). Element (a,b) carries the tensile force
// f = k_elo * strain, strain = (L - L0) / L0, so k_elo is a force (it plays the role of EA).
// Node b between elements (a,b) and (b,c) carries the bending moment M = k_rot * (nu - nu0),
// where nu is the angle between the element directions b-a and c-b (0 for a straight wire)
// and nu0 the joint's turn at rest (0 unless the wire was given a rest curvature), so k_rot
// is a moment (it plays the role of EI / l). Both laws derive from energies:
//   E_axial   = k_elo * L0 * strain^2 / 2
//   E_bending = k_rot * (nu - nu0)^2 / 2
// and the kernels below return exactly -dE/dx on every node, so the forces sum to zero and
// carry no net torque. They are pure functions of positions: the LAMMPS bond/angle styles
// and the wire subcycle both call them. Derivations: doc/Howto_nscd_wire_model.rst.
#pragma once

#include "math/types.h"

#include <array>
#include <vector>

namespace nscd::wire {

struct AxialLaw {
  double k_elo = 0.0;                 // force per unit strain (EA of the continuum wire)
  bool resists_compression = true;    // false: a string, zero force while L < L0
};

struct AxialForces {
  Vec3 on_a = Vec3::Zero();
  Vec3 on_b = Vec3::Zero();
  double energy = 0.0;
  double tension = 0.0;    // k_elo * strain, > 0 when stretched (0 for a slack string)
  double strain = 0.0;     // (L - L0) / L0, reported even when the string is slack
};

// Tensile spring of the element from node a to node b with rest length rest_length.
// Throws std::invalid_argument if the nodes coincide or rest_length <= 0.
AxialForces axial_element_forces(const AxialLaw &law, double rest_length, const Vec3 &a,
                                 const Vec3 &b);

struct BendingForces {
  Vec3 on_a = Vec3::Zero();
  Vec3 on_b = Vec3::Zero();
  Vec3 on_c = Vec3::Zero();
  double energy = 0.0;
  double angle = 0.0;    // nu in [0, pi]: angle between b-a and c-b
};

// Rotational spring at node b between elements (a,b) and (b,c), moment k_rot * (nu - rest_turn)
// (rest_turn = nu0 in [0, pi): the turn the joint has at rest; 0: straight). Smooth through
// nu -> 0 when rest_turn is 0; with rest_turn > 0 the energy is a cone at nu = 0 (every plane
// of bending is as good) and the force there is zero, the symmetric choice. At nu == pi
// exactly (wire folded back on itself) the direction of the force is undefined and the
// forces are zero. Throws std::invalid_argument if an element has zero length.
BendingForces bending_node_forces(double k_rot, const Vec3 &a, const Vec3 &b, const Vec3 &c,
                                  double rest_turn = 0.0);

// atan2(sine, cosine) for sine >= 0, within 2 units in the last place of std::atan2 and
// a third of its time or less (glibc's atan2 saves and restores the rounding mode; it
// took 2/3 of the bending kernel's time in the wire benchmark). NaN in, NaN out.
double angle_from_sine_cosine(double sine, double cosine);

// Angle between two vectors in [0, pi], accurate near 0 and near pi (atan2 form).
double angle_between(const Vec3 &u, const Vec3 &w);

// Topology of wires as index lists, so one call adds the elastic forces of many chains.
struct WireElement {
  int a, b;
  double rest_length;
  AxialLaw law{};    // used by the add_elastic_forces overload without a law
};
struct WireJoint {
  int a, b, c;         // b is the node carrying the rotational spring
  double k_rot = 0.0;  // used by the add_elastic_forces overload without k_rot
  double rest_turn = 0.0;    // nu0, the turn at rest (ignored by the overload with one k_rot)
};
struct WireTopology {
  std::vector<WireElement> elements;
  std::vector<WireJoint> joints;
};

// Topology of one open chain of num_nodes nodes 0..num_nodes-1 with the given rest length
// per element: elements (i,i+1), joints (i-1,i,i+1).
WireTopology open_chain_topology(int num_nodes, double rest_length);

struct ElasticEnergy {
  double axial = 0.0;
  double bending = 0.0;
  double total() const { return axial + bending; }
};

// Adds the axial and bending forces of all elements and joints to forces (indexed like
// positions; not cleared) and returns the elastic energy: with one law and k_rot for all
// (straight at rest), or with each element's law and each joint's k_rot and rest turn.
ElasticEnergy add_elastic_forces(const WireTopology &topology, const AxialLaw &axial,
                                 double k_rot, const std::vector<Vec3> &positions,
                                 std::vector<Vec3> &forces);
ElasticEnergy add_elastic_forces(const WireTopology &topology, const std::vector<Vec3> &positions,
                                 std::vector<Vec3> &forces);

// add_elastic_forces (each element's law and each joint's k_rot) for one topology, prepared
// once and then evaluated every substep: every force and energy equal to add_elastic_forces'
// to the last bit (each law's operations in the same order, each node's forces summed in the
// same order), in under half its time on the wire's chains. A run of elements (i, i+1),
// (i+1, i+2), ... listed one after the other, and of joints (i, i+1, i+2), ... likewise, is
// evaluated two at a time on contiguous arrays (Eigen Array2d), each element's direction
// and length once for its law and both its joints; the rest one by one with
// add_elastic_forces' laws. All results go to arrays first and are then summed per node in
// add_elastic_forces' order. Details: doc/Howto_nscd_wire_model.rst section 2b.
class ElasticKernel {
 public:
  // Throws std::invalid_argument for a rest length <= 0 or a negative node index.
  void prepare(const WireTopology &topology);
  bool prepared_for(const WireTopology &topology) const;
  // Adds the forces at `positions` to `forces` (not cleared; both indexed like the
  // topology's nodes) and returns the energy if with_energy, else zero.
  ElasticEnergy add_forces(const std::vector<Vec3> &positions, std::vector<Vec3> &forces, bool with_energy);

 private:
  struct Run {
    int first, count;    // elements or joints first .. first + count - 1
    int first_node;      // node a of the first one
    int first_element;   // joints: the element (a, b) of the first one
  };
  // Nodes whose forces all come from the same five places as their neighbours' one further:
  // elements (v - 1, v) and (v, v + 1), joints at v - 1, v and v + 1.
  struct NodeRun {
    int first_node, count, element, joint;    // element (v - 1, v) and joint at v - 1 of the first
  };
  enum Part : int { on_a_of_element, on_b_of_element, on_a_of_joint, on_b_of_joint, on_c_of_joint };
  struct Share {    // one term of a node's force
    Part part;
    int index;      // element or joint
  };

  WireTopology topology_;
  std::vector<Run> element_runs_, joint_runs_;
  std::vector<int> single_elements_, single_joints_;    // the others, in the topology's order
  std::vector<NodeRun> node_runs_;
  std::vector<int> single_nodes_;                       // the others
  std::vector<int> first_share_;                        // of each single node, into shares_
  std::vector<Share> shares_;
  int nodes_ = 0;
  // per element: rest length, k_elo, 1 if it resists compression (contiguous for the runs)
  std::vector<double> rest_, k_elo_, resists_, k_rot_, rest_turn_;
  // scratch: node positions by coordinate; per element its unit direction, 1 / length and
  // force on b; per joint the forces on a and c; energies
  std::array<std::vector<double>, 3> position_, direction_, on_b_, on_a_, on_c_;
  std::vector<double> inverse_length_, element_energy_, joint_energy_;

  struct Columns;    // the arrays' pointers for the loops (elastic_forces.cpp)
  Columns columns(bool with_energy);
  void elements_in_runs(bool with_energy);
  void joints_in_runs(bool with_energy);
  void single_element(int e, const std::vector<Vec3> &positions, bool with_energy);
  void single_joint(int j, const std::vector<Vec3> &positions, bool with_energy);
  void sum_per_node(std::vector<Vec3> &forces) const;
  Vec3 share(const Share &s) const;
};

}    // namespace nscd::wire
