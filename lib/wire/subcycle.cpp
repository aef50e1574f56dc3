#include "wire/subcycle.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nscd::wire {

SubcyclePlan plan_subcycle(double dt_nscd, double dt_sp_max, int requested_substeps)
{
  if (!(dt_nscd > 0.0) || !(dt_sp_max > 0.0) || !std::isfinite(dt_nscd)) {
    std::ostringstream msg;
    msg << "wire subcycle: dt_NSCD = " << dt_nscd << " and dt_SP max = " << dt_sp_max
        << " must both be > 0";
    throw std::invalid_argument(msg.str());
  }
  // Small slack so that dt_nscd = 10 * dt_sp_max gives 10, not 11, substeps.
  if (dt_nscd / dt_sp_max > 1e9) {
    std::ostringstream msg;
    msg << "wire subcycle: dt_NSCD = " << dt_nscd << " is " << dt_nscd / dt_sp_max
        << " times the wire step " << dt_sp_max << "; more than 1e9 substeps per step cannot be run";
    throw std::invalid_argument(msg.str());
  }
  const int needed = std::max(1, static_cast<int>(std::ceil(dt_nscd / dt_sp_max * (1.0 - 1e-12))));
  if (requested_substeps < 0) {
    std::ostringstream msg;
    msg << "wire subcycle: requested substeps " << requested_substeps
        << " must be >= 0 (0 = automatic)";
    throw std::invalid_argument(msg.str());
  }
  if (requested_substeps > 0 && requested_substeps < needed) {
    std::ostringstream msg;
    msg << "wire subcycle: " << requested_substeps << " substeps give dt_SP = "
        << dt_nscd / requested_substeps << " above the stability limit " << dt_sp_max
        << "; use at least " << needed << " substeps (or 0 for automatic)";
    throw std::invalid_argument(msg.str());
  }
  SubcyclePlan plan;
  plan.substeps = requested_substeps > 0 ? requested_substeps : needed;
  plan.dt_sp = dt_nscd / plan.substeps;
  return plan;
}

void GrainForceAccumulator::reset(int num_grains)
{
  force_sum_.assign(num_grains, Vec3::Zero());
  torque_sum_.assign(num_grains, Vec3::Zero());
  substeps_ = 0;
}

Vec3 GrainForceAccumulator::mean_force(int grain) const
{
  return substeps_ > 0 ? Vec3(force_sum_[grain] / substeps_) : Vec3::Zero();
}

Vec3 GrainForceAccumulator::mean_torque(int grain) const
{
  return substeps_ > 0 ? Vec3(torque_sum_[grain] / substeps_) : Vec3::Zero();
}

void WireNodeSet::reset(const std::vector<Vec3> &initial_positions, double node_mass, double step)
{
  if (!(node_mass > 0.0) || !(step > 0.0)) {
    std::ostringstream msg;
    msg << "wire nodes: mass " << node_mass << " and step " << step << " must be > 0";
    throw std::invalid_argument(msg.str());
  }
  const std::size_t n = initial_positions.size();
  state.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    state[i] = gear5_start(initial_positions[i], Vec3::Zero(), Vec3::Zero(), step);
  mass.assign(n, node_mass);
  fixed.assign(n, 0);
  dt = step;
  prepare_wire_nodes(*this, step);
}

void prepare_wire_nodes(WireNodeSet &nodes, double dt)
{
  const std::size_t n = nodes.state.size();
  if (nodes.mass.size() != n || nodes.fixed.size() != n) {
    std::ostringstream msg;
    msg << "wire nodes: " << n << " states but " << nodes.mass.size() << " masses and "
        << nodes.fixed.size() << " fixed flags; give one of each per node";
    throw std::invalid_argument(msg.str());
  }
  if (nodes.dt != dt) {
    if (nodes.dt > 0.0)
      for (Gear5State &s : nodes.state) gear5_change_step(s, nodes.dt, dt);
    nodes.dt = dt;
  }
  const std::size_t slots = n + static_cast<std::size_t>(std::max(nodes.copies, 0));
  nodes.positions.resize(slots);
  nodes.velocities.resize(slots);
  nodes.forces.resize(slots);
}

void predict_wire_nodes(WireNodeSet &nodes)
{
  const int n = nodes.size();
  for (int i = 0; i < n; ++i) {
    if (!nodes.fixed[i]) gear5_predict(nodes.state[i]);
    nodes.positions[i] = nodes.state[i].position();
    nodes.velocities[i] = nodes.fixed[i] ? Vec3::Zero() : nodes.state[i].velocity(nodes.dt);
  }
  for (Vec3 &f : nodes.forces) f.setZero();
}

void correct_wire_nodes(WireNodeSet &nodes, const std::array<double, 6> &coefficients)
{
  const int n = nodes.size();
  for (int i = 0; i < n; ++i) {
    if (nodes.fixed[i]) {
      for (int k = 1; k < 6; ++k) nodes.state[i].r[k].setZero();
      continue;
    }
    gear5_correct(nodes.state[i], nodes.forces[i] / nodes.mass[i], nodes.dt, coefficients);
  }
}

}    // namespace nscd::wire
