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

// The wire subcycle of one NSCD grain step, independent of LAMMPS.
//
// One NSCD step of length dt_NSCD runs n wire substeps of dt_SP = dt_NSCD / n with the
// Gear-5 integrator. Grains are not integrated during the subcycle: they hold still (the
// papers' subcycle: the wire nodes move n times per move of the grains), and their
// velocities enter only the contacts' relative velocity (contact_model.h). The
// wire->grain forces and torques are summed over the n substeps and their mean handed to
// the NSCD solver as an external force (mean force = impulse / dt_NSCD).
//
// Usage (the caller owns the force computation: elastic forces, contacts, gravity, ...):
//   const SubcyclePlan plan = plan_subcycle(dt_nscd, dt_sp_max);
//   grains.reset(num_grains);
//   run_subcycle(plan, coefficients, nodes, grains,
//       [&](const SubstepInfo &s, const std::vector<Vec3> &x, const std::vector<Vec3> &v,
//           std::vector<Vec3> &f, GrainForceAccumulator &g) { ... f[i] += ...; g.add(...); });
//   grains.mean_force(j), grains.mean_torque(j)  ->  NSCD external force on grain j.
#pragma once

#include "math/types.h"
#include "wire/gear5.h"

#include <array>
#include <cstdint>
#include <vector>

namespace nscd::wire {

struct SubcyclePlan {
  int substeps = 1;
  double dt_sp = 0.0;
};

// n = requested_substeps if > 0, else ceil(dt_nscd / dt_sp_max); dt_sp = dt_nscd / n.
// Throws std::invalid_argument if the steps are not positive or if the requested n gives a
// dt_SP above dt_sp_max (the message names the n that would do).
SubcyclePlan plan_subcycle(double dt_nscd, double dt_sp_max, int requested_substeps = 0);

// Sums of wire->grain forces and torques (about each grain's centre) over the substeps.
// No allocation after reset() unless the grain count grows.
class GrainForceAccumulator {
 public:
  void reset(int num_grains);
  // Force on grain `grain` applied at lever_arm = contact point - grain centre.
  void add(int grain, const Vec3 &force, const Vec3 &lever_arm)
  {
    force_sum_[grain] += force;
    torque_sum_[grain] += lever_arm.cross(force);
  }
  void count_substep() { ++substeps_; }

  int num_grains() const { return static_cast<int>(force_sum_.size()); }
  int substeps() const { return substeps_; }
  // Means over the substeps counted so far (zero if none).
  Vec3 mean_force(int grain) const;
  Vec3 mean_torque(int grain) const;

 private:
  std::vector<Vec3> force_sum_;
  std::vector<Vec3> torque_sum_;
  int substeps_ = 0;
};

// The Gear states of the integrated nodes while a subcycle runs, as six flat arrays (r_k of
// node i at 3 i .. 3 i + 2): the predictor and the corrector are then the same few
// operations on 3 N numbers in a row, two at a time (Eigen Array2d), instead of 6 x 3
// numbers per node in a Gear5State (the integration took 13 % of fix wire's time that way).
// Filled from WireNodeSet::state before the substeps and written back after.
struct Gear5Arrays {
  std::array<std::vector<double>, 6> r;
  // dt^2 / (2 m) of each node, three times (one per coordinate): the corrector's scaled
  // acceleration is force times this (one multiplication instead of gear5_correct's
  // division by the mass and multiplication by dt^2 / 2; equal to round-off)
  std::vector<double> acceleration_scale;
  std::vector<int> fixed;                // the fixed nodes
  std::vector<double> fixed_position;    // and their positions, 3 numbers each
};

// The wire nodes: Gear state, mass, fixed flag, plus scratch arrays reused every substep.
struct WireNodeSet {
  std::vector<Gear5State> state;
  std::vector<double> mass;
  std::vector<std::uint8_t> fixed;    // 1: position kept, velocity zero (clamps, anchors)
  double dt = 0.0;                    // step the scaled derivatives refer to

  // Scratch, sized by prepare_wire_nodes(): predicted positions/velocities and the forces,
  // with `copies` more slots after the nodes for copies the caller fills in each substep
  // (e.g. ghost atoms of other MPI ranks; they are not integrated).
  std::vector<Vec3> positions, velocities, forces;
  int copies = 0;
  Gear5Arrays arrays;    // the states during a subcycle (load_states .. store_states)

  int size() const { return static_cast<int>(state.size()); }
  // Nodes at rest at the given positions with the given mass each, none fixed.
  void reset(const std::vector<Vec3> &initial_positions, double node_mass, double step);
};

struct SubstepInfo {
  int index;        // 0 .. n-1
  double time;      // time since the start of the NSCD step of the predicted state
  double dt;        // dt_SP
};

// Brings nodes.dt to dt (rescales the scaled derivatives) and sizes the scratch arrays.
void prepare_wire_nodes(WireNodeSet &nodes, double dt);
// Copies nodes.state into nodes.arrays, where the substeps' predictor and corrector work,
// and back into nodes.state after them (run_subcycle does both).
void load_states(WireNodeSet &nodes);
void store_states(WireNodeSet &nodes);
// Between load_states and store_states: predicts every free node and fills
// nodes.positions / nodes.velocities; zeroes all forces (copies included).
void predict_wire_nodes(WireNodeSet &nodes);
// Corrects every free node with a = force / mass (as force times dt^2 / (2 m), and the
// velocity as r_1 times 1 / dt: gear5_correct and Gear5State::velocity to round-off);
// fixed nodes stay put at rest.
void correct_wire_nodes(WireNodeSet &nodes, const std::array<double, 6> &coefficients);
// correct_wire_nodes then predict_wire_nodes, in one pass over the arrays (the same result).
void correct_and_predict_wire_nodes(WireNodeSet &nodes, const std::array<double, 6> &coefficients);

template <class ForceFn>
void run_subcycle(const SubcyclePlan &plan, const std::array<double, 6> &coefficients,
                  WireNodeSet &nodes, GrainForceAccumulator &grains, ForceFn &&compute_forces)
{
  prepare_wire_nodes(nodes, plan.dt_sp);
  load_states(nodes);
  predict_wire_nodes(nodes);
  for (int k = 0; k < plan.substeps; ++k) {
    const SubstepInfo info{k, (k + 1) * plan.dt_sp, plan.dt_sp};
    compute_forces(info, nodes.positions, nodes.velocities, nodes.forces, grains);
    grains.count_substep();
    if (k + 1 < plan.substeps) correct_and_predict_wire_nodes(nodes, coefficients);
    else correct_wire_nodes(nodes, coefficients);
  }
  store_states(nodes);
}

}    // namespace nscd::wire
