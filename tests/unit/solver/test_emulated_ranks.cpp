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

// The distributed solve loop on 2 and 4 emulated ranks in one process: each rank holds every
// body (those it does not own as ghosts) and the contacts of the bodies it owns; between
// sweeps the velocity corrections of all copies are averaged with mass splitting (share),
// exactly what fix nscd's exchange does; every decision comes from SolveControl with the
// residual summed over the ranks, as a driver with its own loop would do it. The answers
// must be those of one rank.
#include "solver/contact_problem.h"
#include "solver_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace nscd;
using namespace nscd::test;

namespace {

constexpr double kGravity = 9.81;

struct Emulated {
  std::vector<ContactProblem> ranks;
  std::vector<std::vector<std::size_t>> contact_index;    // rank contact -> whole contact
  SolveReport report;
};

// Ghost exchange with mass splitting: every copy's correction since the last
// synchronisation, summed and divided by the body's share, moves all copies.
void exchange(std::vector<ContactProblem> &ranks)
{
  const std::size_t bodies = ranks[0].bodies.size();
  for (std::size_t b = 0; b < bodies; ++b) {
    const int index = static_cast<int>(b);
    Vec3 dv = Vec3::Zero(), dw = Vec3::Zero();
    for (const ContactProblem &rank : ranks) {
      dv += rank.velocity_correction(index);
      dw += rank.angular_velocity_correction(index);
    }
    const SolverBody &any = ranks[0].bodies[b];
    const Vec3 v = any.velocity - ranks[0].velocity_correction(index) + dv / any.share;
    const Vec3 w = any.angular_velocity - ranks[0].angular_velocity_correction(index) + dw / any.share;
    for (ContactProblem &rank : ranks) {
      rank.bodies[b].velocity = v;
      rank.bodies[b].angular_velocity = w;
    }
  }
  for (ContactProblem &rank : ranks) rank.mark_synchronised();
}

// owner[b]: the rank that owns body b; a contact lives on the rank of its body_i.
// exchange_every: sweeps between exchanges, and one before each residual check, as
// iterate() does with SolverCommunication::exchange_every (fix nscd's `exchange`).
Emulated solve_on_ranks(const ContactProblem &whole, const std::vector<int> &owner, int count,
                        const SolverOptions &options, int exchange_every = 1)
{
  Emulated run;
  run.ranks.resize(count);
  run.contact_index.resize(count);
  for (ContactProblem &rank : run.ranks) rank.bodies = whole.bodies;
  for (std::size_t c = 0; c < whole.contacts.size(); ++c) {
    const int r = owner[whole.contacts[c].body_i];
    run.ranks[r].contacts.push_back(whole.contacts[c]);
    run.contact_index[r].push_back(c);
  }
  // share: the number of ranks whose contacts touch the body
  for (std::size_t b = 0; b < whole.bodies.size(); ++b) {
    int copies = 0;
    for (const ContactProblem &rank : run.ranks) {
      bool touches = false;
      for (const Contact &c : rank.contacts)
        touches = touches || c.body_i == static_cast<int>(b) || c.body_j == static_cast<int>(b);
      copies += touches ? 1 : 0;
    }
    for (ContactProblem &rank : run.ranks) rank.bodies[b].share = std::max(1, copies);
  }

  for (ContactProblem &rank : run.ranks) rank.prepare(options);
  exchange(run.ranks);
  SolveControl control(options);
  int sweeps = 0;
  for (;;) {
    ResidualTerms terms;
    for (const ContactProblem &rank : run.ranks) terms.merge(rank.residual_terms());
    run.report.terms = terms;
    run.report.residual = terms.residual();
    const SolveControl::Step step = control.at_check(run.report.residual, sweeps);
    if (step.remember)
      for (ContactProblem &rank : run.ranks) rank.remember_impulses();
    if (step.restore) {
      for (ContactProblem &rank : run.ranks) rank.restore_remembered_impulses();
      exchange(run.ranks);
      continue;
    }
    if (step.stop) break;
    for (ContactProblem &rank : run.ranks) {
      if (step.restart) rank.restart_acceleration();
      if (step.coarse) rank.coarse_correction();
    }
    for (;;) {
      std::vector<double> terms;    // the global sums nncg and anderson need
      for (ContactProblem &rank : run.ranks) {
        rank.sweep();
        const std::vector<double> &mine = rank.acceleration_terms();
        terms.resize(mine.size(), 0.0);
        for (std::size_t t = 0; t < mine.size(); ++t) terms[t] += mine[t];
      }
      for (ContactProblem &rank : run.ranks) rank.accelerate(terms);
      ++sweeps;
      const bool check = sweeps % options.check_every == 0 || sweeps == options.max_sweeps;
      if (check || sweeps % exchange_every == 0) exchange(run.ranks);
      if (check) break;
    }
  }
  run.report.sweeps = sweeps;
  run.report.converged = run.report.residual <= options.tolerance;
  for (ContactProblem &rank : run.ranks) rank.finish();
  return run;
}

// The whole problem's contacts with the impulses the ranks solved.
ContactProblem gathered(const ContactProblem &whole, const Emulated &run)
{
  ContactProblem out = whole;
  out.bodies = run.ranks[0].bodies;
  for (std::size_t r = 0; r < run.ranks.size(); ++r)
    for (std::size_t k = 0; k < run.contact_index[r].size(); ++k)
      out.contacts[run.contact_index[r][k]] = run.ranks[r].contacts[k];
  return out;
}

struct Method {
  std::string name;
  Acceleration acceleration;
  double coarse_cell;
  int coarse_every = 1;
};

SolverOptions options_for(const Method &method, double tolerance)
{
  SolverOptions options;
  options.dt = 1e-3;
  options.tolerance = tolerance;
  options.max_sweeps = 100000;
  options.check_every = 2;    // checks and exchanges need not coincide with every sweep
  options.acceleration = method.acceleration;
  options.coarse_cell = method.coarse_cell;
  options.coarse_every = method.coarse_every;
  return options;
}

// Ranks cut the pyramid into slabs along x.
std::vector<int> slabs_along_x(const ContactProblem &problem, int count)
{
  double low = 1e300, high = -1e300;
  for (const SolverBody &b : problem.bodies) {
    low = std::min(low, b.position.x());
    high = std::max(high, b.position.x());
  }
  std::vector<int> owner;
  for (const SolverBody &b : problem.bodies)
    owner.push_back(std::min(count - 1, static_cast<int>(count * (b.position.x() - low) / (high - low + 1e-9))));
  return owner;
}

// A 7-level brick pyramid and its answer on one rank, plain Gauss-Seidel to the tolerance.
struct Pyramid {
  const int levels = 7;
  const double tolerance = 1e-9, dt = 1e-3;
  const ContactProblem whole = brick_pyramid(levels, 0.5, dt);
  ContactProblem single = whole;
  bool single_converged = solve(single, options_for({"gs", Acceleration::none, 0.0}, tolerance)).converged;

  // A solve on emulated ranks must give one rank's answer: the floor carries the weight,
  // every impulse in its cone, and every brick's velocity is the one-rank solve's within
  // what both tolerances allow.
  void expect_answer_of_one_rank(const Emulated &run, const std::string &label) const;
};

void Pyramid::expect_answer_of_one_rank(const Emulated &run, const std::string &label) const
{
  const double weight = levels * (levels + 1) / 2 * kGravity * dt;
  const ContactProblem result = gathered(whole, run);
  double floor = 0.0;
  for (const Contact &c : result.contacts)
    if (c.body_j == kEnvironment) floor += c.impulse.z();
  EXPECT_NEAR(floor, weight, 1e-8 * weight) << label;
  EXPECT_LT(coulomb_violation(result, weight, kGravity * dt), 1e-6) << label;
  // Both runs stop at contact velocity errors of about tolerance x sqrt(scale_squared);
  // a brick's velocity error adds up those of the contacts below it (levels of them).
  const double velocity_error = 2.0 * levels * tolerance * std::sqrt(run.report.terms.scale_squared);
  for (std::size_t b = 0; b < whole.bodies.size(); ++b)
    EXPECT_LT((result.bodies[b].velocity - single.bodies[b].velocity).norm(), velocity_error)
        << label << ", brick " << b;
}

}    // namespace

TEST(EmulatedRanks, PyramidOnTwoAndFourRanksMatchesOneRank)
{
  const Pyramid pyramid;
  ASSERT_TRUE(pyramid.single_converged);
  for (const Method &method : {Method{"gs", Acceleration::none, 0.0},
                               Method{"nesterov", Acceleration::nesterov, 0.0},
                               Method{"nncg", Acceleration::nncg, 0.0},
                               Method{"anderson", Acceleration::anderson, 0.0},
                               Method{"coarse", Acceleration::none, 2.0},
                               Method{"nesterov+coarse", Acceleration::nesterov, 2.0}}) {
    std::string line = "[ info ] pyramid, " + method.name + ", sweeps to 1e-9 on 1/2/4 ranks:";
    for (const int count : {1, 2, 4}) {
      const Emulated run = solve_on_ranks(pyramid.whole, slabs_along_x(pyramid.whole, count), count,
                                          options_for(method, pyramid.tolerance));
      ASSERT_TRUE(run.report.converged) << method.name << " on " << count << " ranks";
      line += " " + std::to_string(run.report.sweeps);
      pyramid.expect_answer_of_one_rank(run, method.name + " on " + std::to_string(count) + " ranks");
    }
    std::cout << line << "\n";
  }
}

// fix nscd's `exchange N`: between exchanges each rank sweeps its own contacts against its
// ghosts' velocities of the last exchange (block Jacobi between ranks, several Gauss-Seidel
// sweeps within one); with mass splitting the mean of the copies' corrections is still M^-1
// times the sum of all impulses, so the converged answer must be one rank's. Exchanges every
// 2, 3 (not a divisor of the check interval) and 4 sweeps (only at the checks) on 2 and 4
// ranks, checks every 4 sweeps as in fix nscd.
TEST(EmulatedRanks, PyramidWithFewerExchangesMatchesOneRank)
{
  const Pyramid pyramid;
  ASSERT_TRUE(pyramid.single_converged);
  for (const Method &method : {Method{"gs", Acceleration::none, 0.0},
                               Method{"nesterov", Acceleration::nesterov, 0.0},
                               Method{"anderson", Acceleration::anderson, 0.0}}) {
    SolverOptions options = options_for(method, pyramid.tolerance);
    options.check_every = 4;
    std::string line = "[ info ] pyramid, " + method.name + ", sweeps to 1e-9 on 2/4 ranks, exchange 1/2/3/4:";
    for (const int count : {2, 4}) {
      line += " |";
      for (const int every : {1, 2, 3, 4}) {
        const Emulated run =
            solve_on_ranks(pyramid.whole, slabs_along_x(pyramid.whole, count), count, options, every);
        const std::string label = method.name + " on " + std::to_string(count) + " ranks, exchange " +
            std::to_string(every);
        ASSERT_TRUE(run.report.converged) << label;
        line += " " + std::to_string(run.report.sweeps);
        pyramid.expect_answer_of_one_rank(run, label);
      }
    }
    std::cout << line << "\n";
  }
}

TEST(EmulatedRanks, ColumnUnderAHeavyPlateCutIntoFourBands)
{
  // 24 spheres under a plate of 1000 times their mass; ranks own height bands of 6 spheres,
  // the plate belongs to the top rank and its contact too; the spheres at the cuts are
  // shared (share 2). Reactions: the weight above each contact. The coarse correction sees
  // only its rank's contacts: on one rank it solves the column in a few sweeps, cut into
  // bands it stops paying and is dropped (the momentum finishes; without momentum this
  // would be plain Gauss-Seidel, which needs far more than max_sweeps here).
  const int layers = 24;
  const double plate = 1000.0, dt = 1e-3, tolerance = 1e-9;
  const ContactProblem whole = sphere_column_under_plate(layers, plate, 1.0, dt);
  std::vector<int> owner;
  for (int b = 0; b <= layers; ++b) owner.push_back(std::min(3, b / 6));
  for (const Method &method : {Method{"nesterov", Acceleration::nesterov, 0.0},
                               Method{"anderson", Acceleration::anderson, 0.0},
                               Method{"nesterov+coarse/8", Acceleration::nesterov, 1.0, 8}}) {
    const Emulated one = solve_on_ranks(whole, std::vector<int>(layers + 1, 0), 1,
                                        options_for(method, tolerance));
    const Emulated four = solve_on_ranks(whole, owner, 4, options_for(method, tolerance));
    ASSERT_TRUE(four.report.converged) << method.name;
    std::cout << "[ info ] column of 24 under a plate x1000, " << method.name << ", sweeps to 1e-9: 1 rank "
              << one.report.sweeps << ", 4 ranks " << four.report.sweeps << "\n";
    const ContactProblem result = gathered(whole, four);
    if (method.coarse_cell > 0.0) {
      EXPECT_LT(one.report.sweeps, 100);
    }
    // The residual bounds the contacts' velocity errors by tolerance x sqrt(scale_squared);
    // impulse errors are W^-1 times those, and the smallest eigenvalue of W is about
    // 1 / (plate mass x layers) (all contacts pushing harder by dP move only the plate, by
    // dP / M, while the load spreads over the layers): the impulses are known to about
    // M x layers x tolerance x sqrt(scale_squared).
    const double impulse_error =
        plate * layers * tolerance * std::sqrt(four.report.terms.scale_squared);
    for (int k = 0; k <= layers; ++k) {
      const double above = (plate + (layers - k)) * kGravity * dt;
      EXPECT_NEAR(result.contacts[k].impulse.z(), above, impulse_error) << method.name << " contact " << k;
    }
  }
}

// A body of infinite mass and inertia (a wire node or a grain outside fix nscd's group, held
// by its own integrator) keeps its velocity: mark_synchronised() skips it after prepare(), so
// the answer on several ranks, where its copies straddle the cut, must still be one rank's,
// and its copies must not move (a stale mark of its velocity would move the copies of a moving
// body). The middle brick of the pyramid's bottom row is held, sliding along y without
// friction under the two bricks it carries.
TEST(EmulatedRanks, PyramidOnAHeldSlidingBrickMatchesOneRank)
{
  const double tolerance = 1e-9;
  ContactProblem whole = brick_pyramid(7, 0.5, 1e-3);
  SolverBody &held = whole.bodies[3];
  held.inv_mass = 0.0;
  held.inv_inertia = Mat3::Zero();
  held.velocity = Vec3(0.0, 0.05, 0.0);
  for (Contact &c : whole.contacts)
    if (c.body_i == 3 || c.body_j == 3) c.friction = 0.0;
  const SolverOptions options = options_for({"gs", Acceleration::none, 0.0}, tolerance);
  ContactProblem single = whole;
  ASSERT_TRUE(solve(single, options).converged);
  for (const int count : {2, 4}) {
    const Emulated run = solve_on_ranks(whole, slabs_along_x(whole, count), count, options);
    ASSERT_TRUE(run.report.converged) << count << " ranks";
    const double velocity_error = 2.0 * 7 * tolerance * std::sqrt(run.report.terms.scale_squared);
    for (const ContactProblem &rank : run.ranks)
      EXPECT_EQ(rank.bodies[3].velocity, held.velocity) << count << " ranks: the held brick was moved";
    const ContactProblem result = gathered(whole, run);
    for (std::size_t b = 0; b < whole.bodies.size(); ++b)
      EXPECT_LT((result.bodies[b].velocity - single.bodies[b].velocity).norm(), velocity_error)
          << count << " ranks, brick " << b;
    // the held brick carries the bricks on it
    double carried = 0.0;
    for (const Contact &c : result.contacts)
      if (c.body_j == 3) carried += c.impulse.z();
    EXPECT_GT(carried, 1e-3) << count << " ranks";
  }
}
