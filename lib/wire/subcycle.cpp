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

void load_states(WireNodeSet &nodes)
{
  Gear5Arrays &a = nodes.arrays;
  const std::size_t n = nodes.state.size();
  for (std::vector<double> &r : a.r) r.resize(3 * n);
  a.acceleration_scale.resize(3 * n);
  const double half_dt_squared = 0.5 * nodes.dt * nodes.dt;
  a.fixed.clear();
  a.fixed_position.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 6; ++k)
      for (int d = 0; d < 3; ++d) a.r[k][3 * i + d] = nodes.state[i].r[k][d];
    for (int d = 0; d < 3; ++d) a.acceleration_scale[3 * i + d] = half_dt_squared / nodes.mass[i];
    if (!nodes.fixed[i]) continue;
    // A fixed node is not integrated: with its derivatives zero the predictor leaves it
    // where it is, and the corrector's move is undone (correct_wire_nodes).
    a.fixed.push_back(static_cast<int>(i));
    for (int d = 0; d < 3; ++d) a.fixed_position.push_back(nodes.state[i].r[0][d]);
    for (int k = 1; k < 6; ++k)
      for (int d = 0; d < 3; ++d) a.r[k][3 * i + d] = 0.0;
  }
}

void store_states(WireNodeSet &nodes)
{
  const Gear5Arrays &a = nodes.arrays;
  for (std::size_t i = 0; i < nodes.state.size(); ++i)
    for (int k = 0; k < 6; ++k)
      for (int d = 0; d < 3; ++d) nodes.state[i].r[k][d] = a.r[k][3 * i + d];
}

namespace {

// Two numbers at a time (one SSE2 register; Eigen picks the instructions of the machine).
using Pair = Eigen::Array2d;
template <class T> __attribute__((always_inline)) inline T load(const double *p) { return Eigen::Map<const T>(p); }
template <class T> __attribute__((always_inline)) inline void store(const T &v, double *p)
{
  Eigen::Map<T> to(p);
  to = v;
}

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a vector of Vec3 is read as 3 N numbers in a row");
double *flat(std::vector<Vec3> &v) { return v.empty() ? nullptr : v[0].data(); }

// The flat arrays as plain pointers that the compiler may keep in registers (they do not
// alias each other nor anything the loops write).
struct Derivatives {
  double *__restrict r[6];
  explicit Derivatives(std::array<std::vector<double>, 6> &a)
  {
    for (int k = 0; k < 6; ++k) r[k] = a[k].data();
  }
};

// gear5_predict's Taylor shift of one number's six scaled derivatives (the same
// operations in the same order: each line reads only higher, not yet shifted ones).
template <class T> __attribute__((always_inline)) inline void shift(T &r0, T &r1, T &r2, T &r3, T &r4, const T &r5)
{
  r0 = r0 + (r1 + r2 + r3 + r4 + r5);
  r1 = r1 + (2.0 * r2 + 3.0 * r3 + 4.0 * r4 + 5.0 * r5);
  r2 = r2 + (3.0 * r3 + 6.0 * r4 + 10.0 * r5);
  r3 = r3 + (4.0 * r4 + 10.0 * r5);
  r4 = r4 + 5.0 * r5;
}

// Numbers j .. j + T::size() - 1 of the flat arrays (T: Pair, or one number as a 1 x 1
// array for the last): gear5_correct with a = force / mass if `correct`, then
// gear5_predict with the predicted position and velocity and the force zeroed for the next
// substep if `predict`. Multiplications by dt^2 / (2 m) and 1 / dt where those divide (two
// divisions per number fewer).
template <class T, bool correct, bool predict>
__attribute__((always_inline)) inline void step_numbers(const Derivatives &d, double *__restrict f,
                                                        const double *__restrict acceleration_scale, const double *c,
                                                        double *__restrict x, double *__restrict v, double inverse_dt,
                                                        std::size_t j)
{
  T r0 = load<T>(d.r[0] + j), r1 = load<T>(d.r[1] + j), r2 = load<T>(d.r[2] + j), r3 = load<T>(d.r[3] + j),
    r4 = load<T>(d.r[4] + j), r5 = load<T>(d.r[5] + j);
  if (correct) {
    const T mismatch = load<T>(f + j) * load<T>(acceleration_scale + j) - r2;
    r0 = r0 + c[0] * mismatch;
    r1 = r1 + c[1] * mismatch;
    r2 = r2 + c[2] * mismatch;
    r3 = r3 + c[3] * mismatch;
    r4 = r4 + c[4] * mismatch;
    r5 = r5 + c[5] * mismatch;
    store<T>(r5, d.r[5] + j);
  }
  if (predict) {
    shift<T>(r0, r1, r2, r3, r4, r5);
    store<T>(r0, x + j);
    store<T>(r1 * inverse_dt, v + j);    // Gear5State::velocity
    store<T>(T::Zero(), f + j);
  }
  store<T>(r0, d.r[0] + j);
  store<T>(r1, d.r[1] + j);
  store<T>(r2, d.r[2] + j);
  store<T>(r3, d.r[3] + j);
  store<T>(r4, d.r[4] + j);
}

// step_numbers along all the flat arrays.
template <bool correct, bool predict> void step_all(WireNodeSet &nodes, const std::array<double, 6> &coefficients)
{
  Gear5Arrays &a = nodes.arrays;
  const Derivatives d(a.r);
  const std::size_t size = a.r[0].size();
  double *f = flat(nodes.forces);
  double *x = flat(nodes.positions), *v = flat(nodes.velocities);
  const double inverse_dt = 1.0 / nodes.dt;
  const double c[6] = {coefficients[0], coefficients[1], coefficients[2], coefficients[3], coefficients[4], coefficients[5]};
  std::size_t j = 0;
  for (; j + 2 <= size; j += 2) step_numbers<Pair, correct, predict>(d, f, a.acceleration_scale.data(), c, x, v, inverse_dt, j);
  for (; j < size; ++j)
    step_numbers<Eigen::Array<double, 1, 1>, correct, predict>(d, f, a.acceleration_scale.data(), c, x, v, inverse_dt, j);
}

// The forces of the copies after the integrated nodes zeroed (step_all zeroes the nodes').
void zero_copy_forces(WireNodeSet &nodes)
{
  for (std::size_t k = nodes.state.size(); k < nodes.forces.size(); ++k) nodes.forces[k].setZero();
}

// The fixed nodes back at rest where they were (after a correction; r_1 .. r_5 zero).
void hold_fixed_nodes(Gear5Arrays &a)
{
  for (std::size_t n = 0; n < a.fixed.size(); ++n) {
    const std::size_t i = static_cast<std::size_t>(a.fixed[n]);
    for (int k = 0; k < 3; ++k) {
      a.r[0][3 * i + k] = a.fixed_position[3 * n + k];
      for (int m = 1; m < 6; ++m) a.r[m][3 * i + k] = 0.0;
    }
  }
}

}    // namespace

// gear5_predict and the positions and velocities of the nodes, number by number along the
// flat arrays: the same Taylor shift on each number in the same order (the positions equal
// to the last bit; the velocities r_1 times 1 / dt, equal to round-off). All forces zeroed.
void predict_wire_nodes(WireNodeSet &nodes)
{
  step_all<false, true>(nodes, {});
  zero_copy_forces(nodes);
}

// gear5_correct along the flat arrays with the scaled acceleration force times dt^2 / (2 m)
// (gear5_correct's force / mass times dt^2 / 2, to round-off), then the fixed nodes put back
// at rest where they were.
void correct_wire_nodes(WireNodeSet &nodes, const std::array<double, 6> &coefficients)
{
  step_all<true, false>(nodes, coefficients);
  hold_fixed_nodes(nodes.arrays);
}

void correct_and_predict_wire_nodes(WireNodeSet &nodes, const std::array<double, 6> &coefficients)
{
  if (!nodes.arrays.fixed.empty()) {    // (they are put back between the two)
    correct_wire_nodes(nodes, coefficients);
    predict_wire_nodes(nodes);
    return;
  }
  step_all<true, true>(nodes, coefficients);
  zero_copy_forces(nodes);
}

}    // namespace nscd::wire
