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

// Shared helpers of the wire tests: a damped chain driven through the subcycle driver.
#pragma once

#include "wire/elastic_forces.h"
#include "wire/subcycle.h"

#include <cmath>
#include <functional>
#include <vector>

namespace nscd::wire::test {

struct ChainModel {
  WireTopology topology;
  AxialLaw axial;
  double k_rot = 0.0;
  double drag = 0.0;                      // viscous -drag * v on every node (relaxation)
  std::vector<Vec3> external;             // constant external force per node
  Vec3 gravity = Vec3::Zero();            // acceleration
};

// Forces of the model on the predicted positions/velocities; the callback of run_subcycle.
inline void chain_forces(const ChainModel &model, const WireNodeSet &nodes,
                         const std::vector<Vec3> &x, const std::vector<Vec3> &v,
                         std::vector<Vec3> &f)
{
  add_elastic_forces(model.topology, model.axial, model.k_rot, x, f);
  for (std::size_t i = 0; i < x.size(); ++i) {
    f[i] += nodes.mass[i] * model.gravity - model.drag * v[i];
    if (!model.external.empty()) f[i] += model.external[i];
  }
}

// Net force on free nodes (elastic + external + gravity, no drag): the equilibrium residual.
inline double max_residual(const ChainModel &model, const WireNodeSet &nodes)
{
  std::vector<Vec3> x(nodes.size()), f(nodes.size(), Vec3::Zero());
  for (int i = 0; i < nodes.size(); ++i) x[i] = nodes.state[i].position();
  ChainModel static_model = model;
  static_model.drag = 0.0;
  chain_forces(static_model, nodes, x, std::vector<Vec3>(x.size(), Vec3::Zero()), f);
  double worst = 0.0;
  for (int i = 0; i < nodes.size(); ++i)
    if (!nodes.fixed[i]) worst = std::max(worst, f[i].norm());
  return worst;
}

// Runs blocks of `block` steps of dt until the residual drops below tolerance or
// max_steps is reached; returns the residual reached.
inline double relax(const ChainModel &model, WireNodeSet &nodes, double dt, double tolerance,
                    long max_steps, int block = 2000)
{
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  GrainForceAccumulator no_grains;
  no_grains.reset(0);
  const SubcyclePlan plan{block, dt};
  double residual = max_residual(model, nodes);
  for (long done = 0; done < max_steps && residual > tolerance; done += block) {
    run_subcycle(plan, c, nodes, no_grains,
                 [&](const SubstepInfo &, const std::vector<Vec3> &x, const std::vector<Vec3> &v,
                     std::vector<Vec3> &f, GrainForceAccumulator &) { chain_forces(model, nodes, x, v, f); });
    residual = max_residual(model, nodes);
  }
  return residual;
}

}    // namespace nscd::wire::test
