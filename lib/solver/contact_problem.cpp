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

#include "solver/contact_problem.h"

#include "math/capacity_bytes.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace nscd {
namespace {

// Anderson mixing's small systems, on the stack (no allocation per sweep).
constexpr int kMaxMemory = SolverOptions::kMaxAndersonMemory;
using AndersonMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMemory, kMaxMemory>;
using AndersonVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxMemory, 1>;

// Velocity errors below this fraction of a contact's own velocities are round-off.
constexpr double kRoundOffVelocity = 1e-12;

std::string contact_label(std::size_t index) { return "contact " + std::to_string(index); }

// Orthonormal basis (n, t1, t2) from a unit n without branches on its components' size
// (Duff et al. 2017); rows of the returned matrix.
Mat3 contact_frame(const Vec3 &n)
{
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  Mat3 frame;
  frame.row(0) = n;
  frame.row(1) = Vec3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  frame.row(2) = Vec3(b, sign + n.y() * n.y() * a, -n.y());
  return frame;
}

Mat3 cross_matrix(const Vec3 &r)
{
  Mat3 m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// F diag(d) F^T, the translational part of a Delassus block (d: diagonal of M^-1, world
// frame). For the usual isotropic d it is d 1, without round-off from F F^T.
Mat3 linear_delassus(const Mat3 &frame, const Vec3 &d)
{
  if (d.x() == d.y() && d.y() == d.z()) return d.x() * Mat3::Identity();
  return frame * d.asDiagonal() * frame.transpose();
}

// The local problem when the tangential velocity cannot change (W = W_nn e_n e_n^T, a body
// with locked lateral axes against an immobile one): P_n from u_n = 0, and the friction
// opposes the given tangential velocity (slip) or is zero (stick with u_t = 0). Exact.
LocalSolution solve_normal_only(double W_nn, const Vec3 &u_free, double mu)
{
  LocalSolution solution;
  if (u_free[0] >= 0.0) return solution;
  const double normal = -u_free[0] / W_nn;
  const double speed = std::hypot(u_free[1], u_free[2]);
  solution.impulse = Vec3(normal, 0.0, 0.0);
  if (mu > 0.0 && speed > 0.0) {
    solution.impulse[1] = -mu * normal * u_free[1] / speed;
    solution.impulse[2] = -mu * normal * u_free[2] / speed;
  }
  solution.regime = mu > 0.0 && speed == 0.0 ? ContactRegime::stick : ContactRegime::slip;
  return solution;
}

ContactRegime classify(const Vec3 &P, double mu)
{
  if (!(P[0] > 0.0)) return ContactRegime::open;
  if (mu > 0.0 && std::sqrt(P[1] * P[1] + P[2] * P[2]) < (1.0 - 1e-9) * mu * P[0])
    return ContactRegime::stick;
  return ContactRegime::slip;
}

void validate_body(const SolverBody &body, std::size_t index)
{
  const std::string label = "body " + std::to_string(index);
  if (!(body.inv_mass >= 0.0) || !std::isfinite(body.inv_mass))
    throw SolverError(label + ": inverse mass " + std::to_string(body.inv_mass) +
                      " must be finite and >= 0 (0 for a body of infinite mass)");
  if (!(body.inv_mass_axes.minCoeff() >= 0.0) || !body.inv_mass_axes.allFinite())
    throw SolverError(label + ": inverse-mass axis factors (" +
                      std::to_string(body.inv_mass_axes.x()) + ", " +
                      std::to_string(body.inv_mass_axes.y()) + ", " +
                      std::to_string(body.inv_mass_axes.z()) +
                      ") must be finite and >= 0 (1 = free, 0 = locked axis)");
  if (!(body.share >= 1.0) || !std::isfinite(body.share))
    throw SolverError(label + ": share " + std::to_string(body.share) +
                      " must be finite and >= 1 (the number of copies carrying contacts)");
  if (!body.inv_inertia.allFinite() || !body.velocity.allFinite() ||
      !body.angular_velocity.allFinite() || !body.position.allFinite() ||
      !body.external_impulse.allFinite() || !body.external_angular_impulse.allFinite())
    throw SolverError(label + ": position, velocity, inverse inertia or external impulse is "
                      "not finite; check the state handed to the solver");
}

void validate_contact(const Contact &contact, std::size_t index, std::size_t n_bodies)
{
  const std::string label = contact_label(index);
  const auto n = static_cast<long>(n_bodies);
  if (contact.body_i < 0 || contact.body_i >= n)
    throw SolverError(label + ": body_i = " + std::to_string(contact.body_i) +
                      " is not a body index in [0, " + std::to_string(n) + ")");
  if (contact.body_j != kEnvironment && (contact.body_j < 0 || contact.body_j >= n))
    throw SolverError(label + ": body_j = " + std::to_string(contact.body_j) +
                      " is neither a body index in [0, " + std::to_string(n) +
                      ") nor kEnvironment (-1)");
  if (contact.body_j == contact.body_i)
    throw SolverError(label + ": a body cannot touch itself (body_i = body_j = " +
                      std::to_string(contact.body_i) + ")");
  const double length = contact.normal.norm();
  if (!(std::abs(length - 1.0) <= 1e-6))
    throw SolverError(label + ": normal has length " + std::to_string(length) +
                      "; pass a unit vector pointing from body j to body i");
  if (!std::isfinite(contact.gap) || !contact.point.allFinite() ||
      !contact.wall_velocity.allFinite() || !contact.impulse.allFinite())
    throw SolverError(label + ": gap, point, wall velocity or warm-start impulse is not finite");
  if (!(contact.friction >= 0.0) || !std::isfinite(contact.friction))
    throw SolverError(label + ": friction coefficient " + std::to_string(contact.friction) +
                      " must be finite and >= 0");
  if (!(contact.restitution >= 0.0 && contact.restitution <= 1.0))
    throw SolverError(label + ": restitution " + std::to_string(contact.restitution) +
                      " must lie in [0, 1]");
}

}    // namespace

void SolverOptions::validate() const
{
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw SolverError("solver time step dt = " + std::to_string(dt) + " must be > 0");
  if (!(theta > 0.0 && theta <= 1.0))
    throw SolverError("theta = " + std::to_string(theta) +
                      " must lie in (0, 1] (0.5 for the midpoint rule, 1 for implicit Euler)");
  if (!(relaxation > 0.0 && relaxation <= 1.0))
    throw SolverError("relaxation omega = " + std::to_string(relaxation) +
                      " must lie in (0, 1] (1 = plain Gauss-Seidel)");
  if (!(tolerance > 0.0))
    throw SolverError("solver tolerance " + std::to_string(tolerance) + " must be > 0");
  if (max_sweeps < 1)
    throw SolverError("max_sweeps = " + std::to_string(max_sweeps) + " must be >= 1");
  if (!(coarse_cell >= 0.0) || !std::isfinite(coarse_cell))
    throw SolverError("coarse_cell = " + std::to_string(coarse_cell) +
                      " must be finite and >= 0 (0 = no coarse correction)");
  if (coarse_every < 1)
    throw SolverError("coarse_every = " + std::to_string(coarse_every) +
                      " must be >= 1 (sweeps between coarse corrections)");
  if (coarse_patience < 1)
    throw SolverError("coarse_patience = " + std::to_string(coarse_patience) +
                      " must be >= 1 (sweeps without a new best residual before the coarse "
                      "correction is dropped)");
  if (anderson_memory < 1 || anderson_memory > kMaxAndersonMemory)
    throw SolverError("anderson_memory = " + std::to_string(anderson_memory) + " must lie in [1, " +
                      std::to_string(kMaxAndersonMemory) + "] (sweeps Anderson mixing combines)");
  if (check_every < 1)
    throw SolverError("check_every = " + std::to_string(check_every) +
                      " must be >= 1 (1 = residual after every sweep)");
  if (!(overlap_speed >= 0.0) || !std::isfinite(overlap_speed))
    throw SolverError("overlap_speed = " + std::to_string(overlap_speed) +
                      " must be finite and >= 0 (0 = overlap is not pushed out)");
}

void ResidualTerms::merge(const ResidualTerms &other)
{
  error_squared += other.error_squared;
  scale_squared += other.scale_squared;
  max_interpenetration = std::max(max_interpenetration, other.max_interpenetration);
  contacts += other.contacts;
  active += other.active;
  sticking += other.sticking;
  sliding += other.sliding;
  local_failures += other.local_failures;
}

double ResidualTerms::residual() const
{
  if (error_squared == 0.0) return 0.0;
  if (scale_squared == 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(error_squared / scale_squared);
}

void ContactProblem::prepare(const SolverOptions &options)
{
  options.validate();
  options_ = options;
  for (std::size_t b = 0; b < bodies.size(); ++b) validate_body(bodies[b], b);

  rows_.resize(contacts.size());
  order_.resize(contacts.size());
  std::iota(order_.begin(), order_.end(), 0);
  swept_ = order_;
  random_.seed(options.seed);
  sweeps_done_ = 0;
  local_failures_ = 0;
  sweep_change_ = 0.0;
  previous_change_ = 0.0;
  momentum_steps_ = 0;
  if (options.acceleration == Acceleration::anderson) {
    const std::size_t n = 3 * contacts.size();
    const auto m = static_cast<std::size_t>(options.anderson_memory);
    anderson_dg_.resize(m * n);
    anderson_df_.resize(m * n);
    anderson_g_.resize(n);
    anderson_f_.resize(n);
    anderson_gram_.setZero(options.anderson_memory, options.anderson_memory);
  }
  anderson_has_last_ = false;
  anderson_count_ = 0;
  anderson_last_change_ = 0.0;
  terms_sweep_ = -1;
  acceleration_terms_.clear();

  // Kinematics use the start-of-step velocities (u_n^- enters the active-contact rule),
  // so rows are built before the external impulses are added.
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    validate_contact(contacts[c], c, bodies.size());
    build_row(contacts[c], c, rows_[c]);
  }
  for (SolverBody &body : bodies) {
    body.velocity += (body.inv_mass * body.inv_mass_axes).cwiseProduct(body.external_impulse);
    body.angular_velocity += body.inv_inertia * body.external_angular_impulse;
  }
  build_groups();
  synced_velocity_.resize(bodies.size());
  synced_angular_velocity_.resize(bodies.size());
  movable_.clear();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    synced_velocity_[b] = bodies[b].velocity;
    synced_angular_velocity_[b] = bodies[b].angular_velocity;
    if (bodies[b].inv_mass != 0.0 || !bodies[b].inv_inertia.isZero(0.0)) movable_.push_back((int) b);
  }
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    Row &row = rows_[c];
    if (row.inert) continue;
    row.impulse = project_on_coulomb_cone(row.frame * contacts[c].impulse, row.mu);
    row.regime = classify(row.impulse, row.mu);
    apply_impulse_change(row, row.impulse);
  }
}

void ContactProblem::build_row(const Contact &contact, std::size_t index, Row &row) const
{
  const SolverBody &body_i = bodies[contact.body_i];
  row.i = contact.body_i;
  row.j = contact.body_j;
  row.mu = contact.friction;
  row.frame = contact_frame(contact.normal.normalized());
  // mass splitting: this copy's contacts see the body share times lighter
  row.inv_mass_i = body_i.share * body_i.inv_mass * body_i.inv_mass_axes;
  row.angular_i = -row.frame * cross_matrix(contact.point - body_i.position);
  row.spin_i = body_i.share * body_i.inv_inertia * row.angular_i.transpose();
  row.delassus = linear_delassus(row.frame, row.inv_mass_i) + row.angular_i * row.spin_i;
  Vec3 u_start = row.frame * body_i.velocity + row.angular_i * body_i.angular_velocity;

  if (row.j == kEnvironment) {
    row.inv_mass_j.setZero();
    row.angular_j.setZero();
    row.spin_j.setZero();
    row.offset = -(row.frame * contact.wall_velocity);
  } else {
    const SolverBody &body_j = bodies[row.j];
    row.inv_mass_j = body_j.share * body_j.inv_mass * body_j.inv_mass_axes;
    row.angular_j = -row.frame * cross_matrix(contact.point - body_j.position);
    row.spin_j = body_j.share * body_j.inv_inertia * row.angular_j.transpose();
    row.delassus += linear_delassus(row.frame, row.inv_mass_j) + row.angular_j * row.spin_j;
    row.offset.setZero();
    u_start -= row.frame * body_j.velocity + row.angular_j * body_j.angular_velocity;
  }
  if (row.j == kEnvironment) u_start += row.offset;
  // Symmetrise: A B is symmetric in exact arithmetic only.
  row.delassus = 0.5 * (row.delassus + row.delassus.transpose()).eval();

  // W_nn = 0: no normal impulse can move either body along the normal (both immobile, or
  // locked axes that carry the reaction themselves): the contact is inert.
  row.inert = !(row.delassus(0, 0) > 0.0);
  // Tangential part negligible (both bodies' lateral axes and rotations locked, e.g. a plate
  // moving along z on a wall): u_t cannot change, solved in closed form (solve_normal_only).
  row.normal_only = !row.inert && row.delassus.bottomRows<2>().cwiseAbs().maxCoeff() <=
                                      1e-12 * row.delassus(0, 0);
  row.impulse.setZero();
  row.step.setZero();
  row.direction.setZero();
  row.regime = ContactRegime::open;
  if (row.normal_only) {
    const double W_nn = row.delassus(0, 0);
    row.delassus.setZero();
    row.delassus(0, 0) = W_nn;
    row.delassus_inverse.setZero();    // pseudo-inverse, unused
    row.delassus_inverse(0, 0) = 1.0 / W_nn;
  } else if (!row.inert) {
    const Eigen::LLT<Mat3> cholesky(row.delassus);
    if (cholesky.info() != Eigen::Success)
      throw SolverError(contact_label(index) + " between bodies " + std::to_string(row.i) +
                        " and " + std::to_string(row.j) +
                        ": the Delassus block is singular (a body of zero inverse mass, or "
                        "with locked axes, but free rotation?); lock its rotation too (zero "
                        "inverse inertia)");
    row.delassus_inverse = cholesky.solve(Mat3::Identity());
  }

  row.gap_start = contact.gap + (1.0 - options_.theta) * options_.dt * u_start[0];
  row.normal_shift = lowest_normal_velocity(contact, u_start[0], row.gap_start);
  row.offset[0] -= row.normal_shift;
}

// The Signorini rule (doc/Howto_nscd_solver.rst, "Which contacts act"): u_min, the lowest
// admissible end-of-step normal velocity, from the gap, the start-of-step normal velocity
// u_n^- and g_theta = gap + (1 - theta) dt u_n^- (the end gap if u_n^+ = 0).
double ContactProblem::lowest_normal_velocity(const Contact &contact, double u_n_start,
                                              double gap_theta) const
{
  const double theta_dt = options_.theta * options_.dt;
  const double newton = contact.restitution * std::max(-u_n_start, 0.0);
  if (gap_theta <= 0.0)    // closed: Newton's law, existing overlap kept (or pushed out)
    return std::max(newton, std::min(-gap_theta / theta_dt, options_.overlap_speed));
  // Open, but its start velocity closes it within the step: the impact happens in this
  // step, and Newton's law must see the approach speed u_n^-. Limiting the approach to
  // the gap instead would cut it to gap / dt before the next step's Newton law sees it.
  // With e = 0 the gap is closed exactly (Newton's u_n^+ = 0 then holds from the next
  // step, with no penetration); with e > 0 the bodies leave at e |u_n^-| before the gap
  // is gone.
  const bool closes_within_step = contact.gap + options_.dt * u_n_start <= 0.0;
  if (closes_within_step && contact.restitution > 0.0) return newton;
  return -gap_theta / theta_dt;    // may approach as far as closing the gap
}

void ContactProblem::mark_synchronised()
{
  // Immovable bodies (wire nodes, grains outside the solved group: most of a rank's atoms in
  // the wired column) keep the velocities prepare() marked.
  for (int b : movable_) {
    synced_velocity_[b] = bodies[b].velocity;
    synced_angular_velocity_[b] = bodies[b].angular_velocity;
  }
}

Vec3 ContactProblem::local_velocity(const Row &row) const
{
  const SolverBody &body_i = bodies[row.i];
  Vec3 u = row.frame * body_i.velocity + row.angular_i * body_i.angular_velocity + row.offset;
  if (row.j != kEnvironment) {
    const SolverBody &body_j = bodies[row.j];
    u -= row.frame * body_j.velocity + row.angular_j * body_j.angular_velocity;
  }
  return u;
}

// The round-off of a contact's relative velocity: of the velocities it is the difference
// of (the two bodies' at the point, the environment's), not of the difference itself. Two
// grains falling together at v have a relative velocity of a few ulps of v, not 0, and no
// impulse can make it smaller.
double ContactProblem::round_off_velocity(const Row &row, const Vec3 &u_free) const
{
  const SolverBody &body_i = bodies[row.i];
  double size = u_free.norm() + std::abs(row.normal_shift) + row.offset.norm() +
                body_i.velocity.norm() + (row.angular_i * body_i.angular_velocity).norm();
  if (row.j != kEnvironment) {
    const SolverBody &body_j = bodies[row.j];
    size += body_j.velocity.norm() + (row.angular_j * body_j.angular_velocity).norm();
  }
  return kRoundOffVelocity * size;
}

// A zero change (most open contacts, every sweep) moves no body: adding an exact zero
// changes no velocity but the sign of a zero, so skipping it keeps the answer.
void ContactProblem::apply_impulse_change(const Row &row, const Vec3 &dP)
{
  if (dP.isZero(0.0)) return;
  const Vec3 world = row.frame.transpose() * dP;
  SolverBody &body_i = bodies[row.i];
  body_i.velocity += row.inv_mass_i.cwiseProduct(world);
  body_i.angular_velocity += row.spin_i * dP;
  if (row.j != kEnvironment) {
    SolverBody &body_j = bodies[row.j];
    body_j.velocity -= row.inv_mass_j.cwiseProduct(world);
    body_j.angular_velocity -= row.spin_j * dP;
  }
}

// Most contacts of a step are open (found ahead of impact): no impulse, none after the local
// solve; W P is skipped for them (a zero product, as in apply_impulse_change).
void ContactProblem::relax(Row &row)
{
  if (row.inert) return;
  const bool unloaded = row.impulse.isZero(0.0);
  const Vec3 u_free = unloaded ? local_velocity(row) : Vec3(local_velocity(row) - row.delassus * row.impulse);
  const Vec3 *slip_guess = options_.slip_guess && row.regime == ContactRegime::slip ? &row.impulse : nullptr;
  const LocalSolution local =
      row.normal_only ? solve_normal_only(row.delassus(0, 0), u_free, row.mu)
                      : solve_local_coulomb(row.delassus, row.delassus_inverse, u_free, row.mu, slip_guess);
  if (!local.exact) ++local_failures_;
  const double omega = options_.relaxation;
  const Vec3 impulse = omega == 1.0 ? local.impulse : Vec3(omega * local.impulse + (1.0 - omega) * row.impulse);
  row.step = impulse - row.impulse;
  apply_impulse_change(row, row.step);
  row.impulse = impulse;
  row.regime = local.regime;
  sweep_change_ += row.step.squaredNorm();
}

void ContactProblem::skip_separating_contacts()
{
  swept_.clear();
  for (const int c : order_) {
    Row &row = rows_[c];
    // Contacts relax() would leave as they are now: no impulse, and separating beyond the
    // round-off of their velocities (a pair merely touching, e.g. two grains falling
    // together, is kept: the next sweep may load it). A skipped contact takes no momentum
    // either (its last step is not repeated by accelerate()).
    if (!row.impulse.isZero(0.0)) {
      swept_.push_back(c);
      continue;
    }
    const Vec3 u = local_velocity(row);
    if (u[0] > round_off_velocity(row, u)) {
      row.step.setZero();
      row.direction.setZero();
      continue;
    }
    swept_.push_back(c);
  }
}

void ContactProblem::sweep()
{
  sweep_change_ = 0.0;
  switch (options_.order) {
  case SweepOrder::shuffled:
    std::shuffle(swept_.begin(), swept_.end(), random_);
    [[fallthrough]];
  case SweepOrder::as_given:
    for (const int c : swept_) relax(rows_[c]);
    break;
  case SweepOrder::forward_backward:
    if (sweeps_done_ % 2 == 0)
      for (auto c = swept_.begin(); c != swept_.end(); ++c) relax(rows_[*c]);
    else
      for (auto c = swept_.rbegin(); c != swept_.rend(); ++c) relax(rows_[*c]);
    break;
  }
  ++sweeps_done_;
}

const std::vector<double> &ContactProblem::acceleration_terms()
{
  // Once per sweep: Anderson stores the sweep in its memory (a second call returns the same).
  if (terms_sweep_ == sweeps_done_) return acceleration_terms_;
  terms_sweep_ = sweeps_done_;
  acceleration_terms_.clear();
  if (options_.acceleration == Acceleration::nncg) acceleration_terms_.push_back(sweep_change_);
  if (options_.acceleration == Acceleration::anderson) store_anderson_sweep();
  return acceleration_terms_;
}

void ContactProblem::accelerate(const std::vector<double> &global_terms)
{
  double beta = 0.0;
  switch (options_.acceleration) {
  case Acceleration::none:
    return;
  case Acceleration::anderson:
    mix_anderson(global_terms);
    return;
  case Acceleration::nesterov:
    beta = momentum_steps_ > 0 ? (momentum_steps_ - 1.0) / (momentum_steps_ + 2.0) : 0.0;
    ++momentum_steps_;
    break;
  case Acceleration::nncg: {
    // Fletcher-Reeves; a growing sweep change (beta > 1) restarts.
    const double change = global_terms.empty() ? 0.0 : global_terms[0];
    beta = previous_change_ > 0.0 ? change / previous_change_ : 0.0;
    if (!(beta <= 1.0)) beta = 0.0;
    previous_change_ = change;
    break;
  }
  }
  for (Row &row : rows_) {
    if (row.inert) continue;
    // An open contact that stayed open: no momentum, nothing to move (see relax()).
    if (beta > 0.0 && !(row.impulse.isZero(0.0) && row.direction.isZero(0.0))) {
      const Vec3 target = project_on_coulomb_cone(row.impulse + beta * row.direction, row.mu);
      const Vec3 change = target - row.impulse;
      apply_impulse_change(row, change);
      row.impulse = target;
      row.direction = change + row.step;
    } else {
      row.direction = row.step;
    }
  }
}

// Anderson mixing treats a sweep as a map g = G(x) of all impulses x, with the residual f =
// g - x (the sweep's impulse changes, Row::step). This stores the sweep just done: its g
// and f, and in the next slot of the ring their changes since the previous sweep, dg and
// df; then the terms mix_anderson() needs, summed over ranks: |f|^2, df_new . df_s and
// df_s . f for every filled slot s.
void ContactProblem::store_anderson_sweep()
{
  const std::size_t n = 3 * rows_.size();
  const int memory = options_.anderson_memory;
  acceleration_terms_.push_back(sweep_change_);    // |f|^2, summed by relax()
  const bool difference = anderson_has_last_;
  if (difference) {
    anderson_slot_ = anderson_count_ < memory ? anderson_count_ : (anderson_slot_ + 1) % memory;
    anderson_count_ = std::min(anderson_count_ + 1, memory);
  }
  double *dg = &anderson_dg_[anderson_slot_ * n];
  double *df = &anderson_df_[anderson_slot_ * n];
  for (std::size_t c = 0; c < rows_.size(); ++c)
    for (int k = 0; k < 3; ++k) {
      const std::size_t i = 3 * c + k;
      if (difference) {
        dg[i] = rows_[c].impulse[k] - anderson_g_[i];
        df[i] = rows_[c].step[k] - anderson_f_[i];
      }
      anderson_g_[i] = rows_[c].impulse[k];
      anderson_f_[i] = rows_[c].step[k];
    }
  anderson_has_last_ = true;
  if (!difference) return;
  // Every slot's df against the new df and against f: two products of the slots' matrix
  // (n x count, column s = slot s) with a vector (vectorised, unlike a plain loop).
  const auto rows = static_cast<Eigen::Index>(n);
  const Eigen::Map<const Eigen::MatrixXd> slots(anderson_df_.data(), rows, anderson_count_);
  AndersonMatrix products(anderson_count_, 2);
  products.col(0).noalias() = slots.transpose() * Eigen::Map<const Eigen::VectorXd>(df, rows);
  products.col(1).noalias() = slots.transpose() * Eigen::Map<const Eigen::VectorXd>(anderson_f_.data(), rows);
  for (int s = 0; s < anderson_count_; ++s) {
    acceleration_terms_.push_back(products(s, 0));
    acceleration_terms_.push_back(products(s, 1));
  }
}

// x = g - sum_s gamma_s dg_s, gamma minimising |f - sum_s gamma_s df_s| (Tikhonov-regularised
// normal equations, the Gram matrix of every rank's contacts), each impulse projected onto
// its cone. A sweep whose change grew empties the memory instead: the mixing made things
// worse, so the sweeps go on alone until there is a new history.
void ContactProblem::mix_anderson(const std::vector<double> &global_terms)
{
  if (global_terms.empty()) return;
  const double change = global_terms[0];
  const bool grew = anderson_last_change_ > 0.0 && change > anderson_last_change_;
  anderson_last_change_ = change;
  if (grew) {
    anderson_count_ = 0;
    return;
  }
  const int count = anderson_count_;
  if (count == 0 || static_cast<int>(global_terms.size()) != 1 + 2 * count) return;
  AndersonVector projection(count);
  for (int s = 0; s < count; ++s) {
    anderson_gram_(anderson_slot_, s) = anderson_gram_(s, anderson_slot_) = global_terms[1 + 2 * s];
    projection[s] = global_terms[2 + 2 * s];
  }
  AndersonMatrix gram(count, count);
  double trace = 0.0;
  for (int a = 0; a < count; ++a) {
    for (int b = 0; b < count; ++b) gram(a, b) = anderson_gram_(a, b);
    trace += gram(a, a);
  }
  if (!(trace > 0.0)) return;
  // The sweeps' changes become nearly parallel as they converge: a small multiple of the
  // trace on the diagonal keeps the least-squares problem solvable without changing gamma
  // where it is well posed.
  for (int a = 0; a < count; ++a) gram(a, a) += 1e-10 * trace;
  const AndersonVector gamma = gram.ldlt().solve(projection);
  if (!gamma.allFinite()) return;
  const auto n = static_cast<Eigen::Index>(3 * rows_.size());
  anderson_mix_.noalias() = Eigen::Map<const Eigen::MatrixXd>(anderson_dg_.data(), n, count) * gamma;
  for (std::size_t c = 0; c < rows_.size(); ++c) {
    Row &row = rows_[c];
    if (row.inert) continue;
    const Vec3 mixed = row.impulse - anderson_mix_.segment<3>(static_cast<Eigen::Index>(3 * c));
    if (mixed == row.impulse) continue;    // open and untouched by every remembered sweep
    const Vec3 target = project_on_coulomb_cone(mixed, row.mu);
    apply_impulse_change(row, target - row.impulse);
    row.impulse = target;
  }
}

void ContactProblem::restart_acceleration()
{
  anderson_has_last_ = false;
  anderson_count_ = 0;
  anderson_last_change_ = 0.0;
  momentum_steps_ = 0;
  previous_change_ = 0.0;
  for (Row &row : rows_) row.direction.setZero();
}

void ContactProblem::remember_impulses()
{
  remembered_.resize(rows_.size());
  for (std::size_t c = 0; c < rows_.size(); ++c) remembered_[c] = rows_[c].impulse;
}

void ContactProblem::restore_remembered_impulses()
{
  for (std::size_t c = 0; c < remembered_.size() && c < rows_.size(); ++c) {
    Row &row = rows_[c];
    if (row.inert) continue;
    apply_impulse_change(row, remembered_[c] - row.impulse);
    row.impulse = remembered_[c];
  }
  restart_acceleration();
}

ResidualTerms ContactProblem::residual_terms() const
{
  ResidualTerms terms;
  terms.local_failures = local_failures_;
  const double theta_dt = options_.theta * options_.dt;
  for (const Row &row : rows_) {
    ++terms.contacts;
    if (row.inert) continue;
    const Vec3 u = local_velocity(row);
    const double error = contact_error(row, u);
    terms.error_squared += error * error;
    terms.scale_squared += (row.delassus(0, 0) * row.impulse).squaredNorm();

    const double gap_end = row.gap_start + theta_dt * (u[0] + row.normal_shift);
    terms.max_interpenetration = std::max(terms.max_interpenetration, -gap_end);
    switch (classify(row.impulse, row.mu)) {
    case ContactRegime::open: break;
    case ContactRegime::stick: ++terms.active; ++terms.sticking; break;
    case ContactRegime::slip: ++terms.active; ++terms.sliding; break;
    }
  }
  return terms;
}

// One contact's term of the residual, u its local velocity now.
double ContactProblem::contact_error(const Row &row, const Vec3 &u) const
{
  const Vec3 u_free = u - row.delassus * row.impulse;
  const double error = coulomb_residual(row.delassus, u_free, row.mu, row.impulse, row.delassus(0, 0));
  // An error at the round-off of the contact's velocities is none: when every impulse is
  // itself round-off (a pair that needs no push), error / scale would be a ratio of two
  // round-offs and hold the solve until max_sweeps, or be +inf when they all came out 0.
  // (NaN stays NaN.)
  return error <= round_off_velocity(row, u_free) ? 0.0 : error;
}

void ContactProblem::contact_residuals(std::vector<double> &error, std::vector<double> &scale) const
{
  error.assign(rows_.size(), 0.0);
  scale.assign(rows_.size(), 0.0);
  for (std::size_t c = 0; c < rows_.size(); ++c) {
    const Row &row = rows_[c];
    if (row.inert) continue;
    error[c] = contact_error(row, local_velocity(row));
    scale[c] = (row.delassus(0, 0) * row.impulse).norm();
  }
}

void ContactProblem::finish()
{
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const Row &row = rows_[c];
    contacts[c].impulse = row.frame.transpose() * row.impulse;
    contacts[c].regime = classify(row.impulse, row.mu);
  }
}

SolveControl::Step SolveControl::at_check(double residual, int sweeps)
{
  Step step;
  const bool coarse = options_.coarse_cell > 0.0 && !coarse_dropped_;
  if (coarse) {
    // The residual a window ago (the last check at or before); the window spans at least
    // two coarse corrections.
    const int window = std::max(options_.coarse_patience, 2 * options_.coarse_every);
    double before = -1.0;
    for (const auto &check : checks_)
      if (check.first <= sweeps - window) before = check.second;
    checks_.emplace_back(sweeps, residual);
    const bool new_best = best_ < 0.0 || residual < best_;
    if (before >= 0.0 && !(residual <= 0.5 * before) && residual > options_.tolerance) {
      // Too slow with the coarse correction (stalling, or fighting the sweeps): on without
      // it, from the best impulses if these are worse.
      coarse_dropped_ = true;
      if (!new_best) {
        step.restore = true;
        previous_ = -1.0;
        return step;
      }
    } else if (new_best) {
      best_ = residual;
      step.remember = true;
    }
  }
  if (residual <= options_.tolerance || sweeps >= options_.max_sweeps) {
    step.stop = true;
    return step;
  }
  if (options_.acceleration != Acceleration::none && previous_ >= 0.0 && residual > previous_)
    step.restart = true;
  previous_ = residual;
  if (coarse && !coarse_dropped_ &&
      (last_coarse_ < 0 || sweeps - last_coarse_ >= options_.coarse_every)) {
    step.coarse = true;
    last_coarse_ = sweeps;
    ++coarse_corrections_;
  }
  return step;
}

ResidualTerms reduce(const ResidualTerms &mine, const SolverCommunication &communication)
{
  if (!communication.sum) return mine;
  double sums[ResidualTerms::kSummed] = {mine.error_squared,          mine.scale_squared,
                    static_cast<double>(mine.contacts), static_cast<double>(mine.active),
                    static_cast<double>(mine.sticking), static_cast<double>(mine.sliding),
                    static_cast<double>(mine.local_failures)};
  communication.sum(sums, ResidualTerms::kSummed);
  ResidualTerms all;
  all.error_squared = sums[0];
  all.scale_squared = sums[1];
  all.contacts = static_cast<long>(sums[2]);
  all.active = static_cast<long>(sums[3]);
  all.sticking = static_cast<long>(sums[4]);
  all.sliding = static_cast<long>(sums[5]);
  all.local_failures = static_cast<long>(sums[6]);
  all.max_interpenetration = mine.max_interpenetration;
  if (communication.max) communication.max(&all.max_interpenetration, 1);
  return all;
}

SolveReport iterate(ContactProblem &problem, const SolverOptions &options,
                    const SolverCommunication &communication)
{
  const auto exchange = [&]() {
    if (communication.exchange) communication.exchange(problem);
  };
  std::vector<double> terms;
  const auto global_terms = [&]() -> const std::vector<double> & {
    terms = problem.acceleration_terms();
    if (communication.sum && !terms.empty()) communication.sum(terms.data(), static_cast<int>(terms.size()));
    return terms;
  };
  const int exchange_every = std::max(1, communication.exchange_every);
  exchange();
  SolveControl control(options);
  SolveReport report;
  int sweeps = 0;
  for (;;) {
    report.terms = reduce(problem.residual_terms(), communication);
    report.residual = report.terms.residual();
    const SolveControl::Step step = control.at_check(report.residual, sweeps);
    if (step.remember) problem.remember_impulses();
    if (step.restore) {
      problem.restore_remembered_impulses();
      exchange();
      continue;    // check the restored impulses
    }
    if (step.stop) break;
    if (step.restart) problem.restart_acceleration();
    if (step.coarse) problem.coarse_correction();
    if (options.skip_separating) problem.skip_separating_contacts();
    for (;;) {
      problem.sweep();
      ++sweeps;
      problem.accelerate(global_terms());
      const bool check = sweeps % options.check_every == 0 || sweeps == options.max_sweeps;
      if (check || sweeps % exchange_every == 0) exchange();
      if (check) break;
    }
  }
  report.sweeps = sweeps;
  report.converged = report.residual <= options.tolerance;
  report.coarse_corrections = control.coarse_corrections();
  report.coarse_dropped = control.coarse_dropped();
  problem.finish();
  return report;
}

SolveReport solve(ContactProblem &problem, const SolverOptions &options)
{
  problem.prepare(options);
  return iterate(problem, options);
}

std::size_t ContactProblem::memory_bytes() const
{
  return capacity_bytes(bodies) + capacity_bytes(contacts) + capacity_bytes(rows_) + capacity_bytes(group_) +
      capacity_bytes(remembered_) + capacity_bytes(order_) + capacity_bytes(swept_) + capacity_bytes(synced_velocity_) +
      capacity_bytes(synced_angular_velocity_) + capacity_bytes(movable_) + capacity_bytes(acceleration_terms_) +
      capacity_bytes(anderson_dg_) + capacity_bytes(anderson_df_) + capacity_bytes(anderson_g_) +
      capacity_bytes(anderson_f_) +
      sizeof(double) * static_cast<std::size_t>(anderson_gram_.size() + anderson_mix_.size());
}

}    // namespace nscd
