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
        << dt_nscd / requested_substeps << " above the stable " << dt_sp_max
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
  a.mass.resize(3 * n);
  a.fixed.clear();
  a.fixed_position.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 6; ++k)
      for (int d = 0; d < 3; ++d) a.r[k][3 * i + d] = nodes.state[i].r[k][d];
    for (int d = 0; d < 3; ++d) a.mass[3 * i + d] = nodes.mass[i];
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

// The arrays are walked in blocks small enough for all of them to stay in the L1 cache
// between the lines of the predictor (or corrector) that read them.
constexpr std::ptrdiff_t kBlock = 512;

using Span = Eigen::Map<Eigen::ArrayXd>;
using ConstSpan = Eigen::Map<const Eigen::ArrayXd>;

double *flat(std::vector<Vec3> &v) { return v.empty() ? nullptr : v[0].data(); }

}    // namespace

// gear5_predict and the positions and velocities of the nodes, on blocks of the flat
// arrays: the same operations on each number in the same order, so the same result to
// the last bit.
void predict_wire_nodes(WireNodeSet &nodes)
{
  Gear5Arrays &a = nodes.arrays;
  const std::ptrdiff_t size = static_cast<std::ptrdiff_t>(a.r[0].size());
  double *x = flat(nodes.positions), *v = flat(nodes.velocities);
  for (std::ptrdiff_t start = 0; start < size; start += kBlock) {
    const std::ptrdiff_t len = std::min(kBlock, size - start);
    Span r0(a.r[0].data() + start, len), r1(a.r[1].data() + start, len), r2(a.r[2].data() + start, len),
        r3(a.r[3].data() + start, len), r4(a.r[4].data() + start, len);
    const ConstSpan r5(a.r[5].data() + start, len);
    r0 += r1 + r2 + r3 + r4 + r5;
    r1 += 2.0 * r2 + 3.0 * r3 + 4.0 * r4 + 5.0 * r5;
    r2 += 3.0 * r3 + 6.0 * r4 + 10.0 * r5;
    r3 += 4.0 * r4 + 10.0 * r5;
    r4 += 5.0 * r5;
    Span(x + start, len) = r0;
    Span(v + start, len) = r1 / nodes.dt;    // Gear5State::velocity
  }
  for (Vec3 &f : nodes.forces) f.setZero();
}

// gear5_correct with a = force / mass on blocks of the flat arrays (the same operations
// in the same order), then the fixed nodes put back at rest where they were.
void correct_wire_nodes(WireNodeSet &nodes, const std::array<double, 6> &c)
{
  Gear5Arrays &a = nodes.arrays;
  const std::ptrdiff_t size = static_cast<std::ptrdiff_t>(a.r[0].size());
  const double *f = flat(nodes.forces);
  const double scale = 0.5 * nodes.dt * nodes.dt;
  Eigen::Array<double, kBlock, 1> mismatch;
  for (std::ptrdiff_t start = 0; start < size; start += kBlock) {
    const std::ptrdiff_t len = std::min(kBlock, size - start);
    auto m = mismatch.head(len);
    m = scale * (ConstSpan(f + start, len) / ConstSpan(a.mass.data() + start, len)) -
        ConstSpan(a.r[2].data() + start, len);
    for (int k = 0; k < 6; ++k) Span(a.r[k].data() + start, len) += c[k] * m;
  }
  for (std::size_t j = 0; j < a.fixed.size(); ++j) {
    const std::size_t i = static_cast<std::size_t>(a.fixed[j]);
    for (int d = 0; d < 3; ++d) {
      a.r[0][3 * i + d] = a.fixed_position[3 * j + d];
      for (int k = 1; k < 6; ++k) a.r[k][3 * i + d] = 0.0;
    }
  }
}

}    // namespace nscd::wire
