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

// Momentum acceleration (nesterov, nncg) and the coarse correction of the contact solver:
// the same answers as plain Gauss-Seidel (closed-form reactions, the contact law checked
// independently of the solver's residual), consistent velocities, the restart and fallback
// logic, and the distributed loop on emulated ranks.
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
constexpr double kPi = 3.14159265358979323846;

struct Method {
  std::string name;
  Acceleration acceleration;
  double coarse_cell;
};

// Every method besides plain Gauss-Seidel.
const std::vector<Method> kAccelerated = {
    {"nesterov", Acceleration::nesterov, 0.0},
    {"nncg", Acceleration::nncg, 0.0},
    {"anderson", Acceleration::anderson, 0.0},
    {"coarse", Acceleration::none, 2.0},
    {"coarse (cell 1)", Acceleration::none, 1.0},
    {"nesterov+coarse", Acceleration::nesterov, 2.0},
};

SolverOptions options_for(const Method &method, double tolerance = 1e-10, double dt = 1e-3)
{
  SolverOptions options;
  options.dt = dt;
  options.tolerance = tolerance;
  options.max_sweeps = 200000;
  options.acceleration = method.acceleration;
  options.coarse_cell = method.coarse_cell;
  return options;
}

double floor_reaction(const ContactProblem &problem)
{
  double sum = 0.0;
  for (const Contact &c : problem.contacts)
    if (c.body_j == kEnvironment) sum += c.impulse.z();
  return sum;
}

}    // namespace

TEST(Acceleration, StackReactionsAreTheWeightAboveForEveryMethod)
{
  for (const Method &method : kAccelerated) {
    BoxColumn column;
    column.floor_friction = column.box_friction = 0.5;
    const std::vector<double> masses = {4.0, 3.0, 2.0, 1.0};
    column.stack(masses, Vec3(0.5, 0.5, 0.5));
    const SolverOptions options = options_for(method);
    ContactProblem problem;
    for (int step = 0; step < 20; ++step) {
      const SolveReport report = column.step(problem, options);
      ASSERT_TRUE(report.converged) << method.name << " step " << step;
      double above = 0.0;
      for (int level = 3; level >= 0; --level) {
        above += masses[level] * kGravity * options.dt;
        EXPECT_NEAR(impulse_on(problem, level).z(), above, 1e-9 * above)
            << method.name << " level " << level << " step " << step;
      }
    }
    for (int level = 0; level < 4; ++level)
      EXPECT_NEAR(column.boxes[level].pose.position.z(), 0.5 + level, 1e-12) << method.name;
  }
}

namespace {
// A block (1.5 kg, on its 0.8 x 0.6 face) on an incline of angle alpha: tilted gravity on a
// level floor. Returns the block's velocity after `steps` steps.
Vec3 block_on_incline(double alpha, double mu, int steps, const SolverOptions &options)
{
  BoxColumn column;
  column.floor_friction = mu;
  column.gravity = kGravity * Vec3(std::sin(alpha), 0.0, -std::cos(alpha));
  column.stack({1.5}, Vec3(0.4, 0.3, 0.25));
  ContactProblem problem;
  for (int step = 0; step < steps; ++step) {
    const SolveReport report = column.step(problem, options);
    EXPECT_TRUE(report.converged) << "step " << step;
  }
  return column.boxes[0].velocity;
}
}    // namespace

TEST(Acceleration, InclineHoldsJustBelowAndSlidesJustAboveTheFrictionAngle)
{
  const double mu = 0.5, dt = 1e-3;
  const int steps = 200;
  const double holding = std::atan(0.98 * mu), sliding = std::atan(1.02 * mu);
  for (const Method &method : kAccelerated) {
    const SolverOptions options = options_for(method, 1e-10, dt);
    // at rest up to the velocity errors the tolerance allows, summed over the steps
    EXPECT_LT(block_on_incline(holding, mu, steps, options).norm(), 1e-9 * kGravity * dt) << method.name;
    const Vec3 v = block_on_incline(sliding, mu, steps, options);
    const double a = kGravity * (std::sin(sliding) - mu * std::cos(sliding));
    EXPECT_NEAR(v.x() / (steps * dt), a, 1e-8 * a) << method.name;
    EXPECT_LT(std::abs(v.y()) + std::abs(v.z()), 1e-12) << method.name;
  }
}

TEST(Acceleration, PyramidCarriesItsWeightAndMeetsTheContactLawExactly)
{
  const int levels = 6;
  const double dt = 1e-3;
  const double weight = levels * (levels + 1) / 2 * kGravity * dt;    // bricks of mass 1
  const Method plain{"gs", Acceleration::none, 0.0};
  ContactProblem reference = brick_pyramid(levels, 0.5, dt);
  ASSERT_TRUE(solve(reference, options_for(plain)).converged);
  for (const Method &method : kAccelerated) {
    ContactProblem problem = brick_pyramid(levels, 0.5, dt);
    const SolveReport report = solve(problem, options_for(method));
    ASSERT_TRUE(report.converged) << method.name;
    EXPECT_NEAR(floor_reaction(problem), weight, 1e-9 * weight) << method.name;
    // Velocity scale g dt; impulses up to the weight.
    EXPECT_LT(coulomb_violation(problem, weight, kGravity * dt), 1e-7) << method.name;
    // The same end-of-step velocities as plain Gauss-Seidel (all at rest), to the velocity
    // errors both solves leave: tolerance x sqrt(scale_squared) per contact, added up over
    // the contacts below a brick (levels of them).
    const double error =
        2.0 * levels * options_for(method).tolerance * std::sqrt(report.terms.scale_squared);
    for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
      EXPECT_LT((problem.bodies[b].velocity - reference.bodies[b].velocity).norm(), error)
          << method.name << " brick " << b;
      EXPECT_LT((problem.bodies[b].angular_velocity - reference.bodies[b].angular_velocity).norm(),
                error) << method.name << " brick " << b;
    }
  }
}

TEST(Acceleration, VelocitiesStayThoseOfTheImpulses)
{
  // After sweeps, momentum steps, coarse corrections and a restore, the velocities the
  // solver carries along must equal v_free + M^-1 J^T P of its impulses.
  for (const Method &method : kAccelerated) {
    const ContactProblem unsolved = brick_pyramid(5, 0.5, 1e-3);
    ContactProblem problem = unsolved;
    SolverOptions options = options_for(method);
    problem.prepare(options);
    for (int sweep = 0; sweep < 30; ++sweep) {
      if (sweep == 10) problem.remember_impulses();
      if (sweep % 7 == 3 && method.coarse_cell > 0.0) problem.coarse_correction();
      problem.sweep();
      problem.accelerate(problem.acceleration_terms());
    }
    problem.restore_remembered_impulses();
    for (int sweep = 0; sweep < 5; ++sweep) {
      problem.sweep();
      problem.accelerate(problem.acceleration_terms());
    }
    problem.finish();
    const std::vector<Vec3> expected = velocities_from_impulses(unsolved, problem);
    for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
      EXPECT_LT((problem.bodies[b].velocity - expected[2 * b]).norm(), 1e-14) << method.name;
      EXPECT_LT((problem.bodies[b].angular_velocity - expected[2 * b + 1]).norm(), 1e-13)
          << method.name;
    }
  }
}

TEST(Acceleration, MomentumStepsStayInsideTheCones)
{
  // Momentum and Anderson mixing both move impulses beyond the sweeps' local solutions.
  for (const Acceleration acceleration : {Acceleration::nesterov, Acceleration::anderson}) {
    ContactProblem problem = brick_pyramid(5, 0.3, 1e-3);
    problem.prepare(options_for({"", acceleration, 0.0}));
    for (int sweep = 0; sweep < 40; ++sweep) {
      problem.sweep();
      problem.accelerate(problem.acceleration_terms());
      problem.finish();
      for (const Contact &c : problem.contacts) {
        const double normal = c.impulse.dot(c.normal);
        ASSERT_GE(normal, 0.0);
        ASSERT_LE((c.impulse - normal * c.normal).norm(), c.friction * normal * (1.0 + 1e-12) + 1e-300);
      }
    }
  }
}

TEST(Acceleration, AndersonEmptiesItsMemoryWhenASweepsChangeGrows)
{
  // The mixing step uses the remembered sweeps only while each sweep changes the impulses
  // less than the one before: given a larger change it leaves the impulses as the sweep
  // left them, given a smaller one it moves them.
  ContactProblem problem = brick_pyramid(4, 0.5, 1e-3);
  problem.prepare(options_for({"anderson", Acceleration::anderson, 0.0}));
  const auto velocities = [&problem]() {
    std::vector<Vec3> v;
    for (const SolverBody &b : problem.bodies) v.push_back(b.velocity);
    return v;
  };
  problem.sweep();
  EXPECT_EQ(problem.acceleration_terms().size(), 1u);    // |f|^2 only: nothing to mix yet
  problem.accelerate(problem.acceleration_terms());       // the same terms: once per sweep
  problem.sweep();
  std::vector<double> terms = problem.acceleration_terms();
  ASSERT_EQ(terms.size(), 3u);    // |f|^2, the new slot's Gram entry, its projection on f
  std::vector<Vec3> before = velocities();
  std::vector<double> grown = terms;
  grown[0] = 1e300;
  ContactProblem copy = problem;
  copy.accelerate(grown);
  for (std::size_t b = 0; b < before.size(); ++b) EXPECT_EQ(copy.bodies[b].velocity, before[b]);
  problem.accelerate(terms);
  double moved = 0.0;
  for (std::size_t b = 0; b < before.size(); ++b)
    moved = std::max(moved, (problem.bodies[b].velocity - before[b]).norm());
  EXPECT_GT(moved, 0.0);
}

TEST(Acceleration, BadAndersonMemoryIsRejected)
{
  for (const int memory : {0, SolverOptions::kMaxAndersonMemory + 1}) {
    SolverOptions options = options_for({"anderson", Acceleration::anderson, 0.0});
    options.anderson_memory = memory;
    EXPECT_THROW(options.validate(), SolverError) << memory;
  }
}

TEST(Acceleration, FewerSweepsThanGaussSeidelWhereItIsSlow)
{
  // A 20-box tower (four corners per face, mu = 0.5) and a column of 20 spheres under a
  // plate of 1000 times a sphere's mass, solved cold to 1e-6.
  auto sweeps = [](const ContactProblem &scene, Acceleration acceleration, double cell) {
    ContactProblem problem = scene;
    SolverOptions options = options_for({"", acceleration, cell}, 1e-6);
    const SolveReport report = solve(problem, options);
    EXPECT_TRUE(report.converged);
    return report.sweeps;
  };
  BoxColumn tower;
  tower.floor_friction = tower.box_friction = 0.5;
  tower.stack(std::vector<double>(20, 1.0), Vec3(0.5, 0.5, 0.5));
  ContactProblem towers;
  tower.build(towers, 1e-3);
  const int gs = sweeps(towers, Acceleration::none, 0.0);
  const int nesterov = sweeps(towers, Acceleration::nesterov, 0.0);
  const int nncg = sweeps(towers, Acceleration::nncg, 0.0);
  const int anderson = sweeps(towers, Acceleration::anderson, 0.0);
  const ContactProblem column = sphere_column_under_plate(20, 1000.0, 1.0, 1e-3);
  const int column_gs = sweeps(column, Acceleration::none, 0.0);
  const int column_coarse = sweeps(column, Acceleration::none, 1.0);
  const int column_nesterov = sweeps(column, Acceleration::nesterov, 0.0);
  const int column_anderson = sweeps(column, Acceleration::anderson, 0.0);
  std::cout << "[ info ] 20-box tower to 1e-6, cold: gs " << gs << ", nesterov " << nesterov
            << ", nncg " << nncg << ", anderson " << anderson
            << " sweeps; column of 20 spheres under a plate x1000: gs " << column_gs << ", coarse "
            << column_coarse << ", nesterov " << column_nesterov << ", anderson " << column_anderson
            << " sweeps\n";
  EXPECT_LT(3 * nesterov, gs);
  EXPECT_LT(2 * nncg, gs);
  EXPECT_LT(100 * column_coarse, column_gs);
  EXPECT_LT(3 * anderson, gs);
  EXPECT_LT(100 * column_anderson, column_gs);
}

TEST(Acceleration, CoarseCorrectionSolvesAStraightColumnInAFewSweeps)
{
  // One contact per group: the coarse problem is the whole (linear) column, so its
  // correction lands on the answer; the reactions are the weight above to 1e-9.
  const int layers = 30;
  const double plate = 1000.0, dt = 1e-3;
  ContactProblem problem = sphere_column_under_plate(layers, plate, 1.0, dt);
  const SolveReport report = solve(problem, options_for({"coarse", Acceleration::none, 1.0}));
  ASSERT_TRUE(report.converged);
  EXPECT_LE(report.sweeps, 3);
  EXPECT_GE(report.coarse_corrections, 1);
  for (int k = 0; k <= layers; ++k) {
    const double above = (plate + (layers - k)) * kGravity * dt;
    EXPECT_NEAR(problem.contacts[k].impulse.z(), above, 1e-9 * above) << "contact " << k;
  }
}

TEST(Acceleration, CoarseGroupsAreCappedOnATallColumn)
{
  // 301 contacts, one cell each at cell size 1: more than kMaxCoarseGroups, so the cells
  // widen (2, 4, ...) until at most that many are left; the dense coarse system stays small
  // and the solve still gives the weight above every contact.
  const int layers = 300;
  const double plate = 1000.0, dt = 1e-3;
  ContactProblem problem = sphere_column_under_plate(layers, plate, 1.0, dt);
  const SolveReport report = solve(problem, options_for({"coarse", Acceleration::none, 1.0}));
  std::cout << "[ info ] " << layers << "-sphere column, coarse cell 1: "
            << problem.coarse_groups() << " groups, " << report.sweeps << " sweeps\n";
  EXPECT_GT(problem.coarse_groups(), ContactProblem::kMaxCoarseGroups / 8);
  EXPECT_LE(problem.coarse_groups(), ContactProblem::kMaxCoarseGroups);
  ASSERT_TRUE(report.converged);
  for (int k = 0; k <= layers; ++k) {
    const double above = (plate + (layers - k)) * kGravity * dt;
    EXPECT_NEAR(problem.contacts[k].impulse.z(), above, 1e-6 * above) << "contact " << k;
  }
}

TEST(Acceleration, SolveControlRestartsWhenTheResidualGrows)
{
  SolverOptions options = options_for({"nesterov", Acceleration::nesterov, 0.0}, 1e-6);
  SolveControl control(options);
  EXPECT_FALSE(control.at_check(1.0, 0).restart);
  EXPECT_FALSE(control.at_check(0.5, 1).restart);
  EXPECT_TRUE(control.at_check(0.7, 2).restart);
  EXPECT_FALSE(control.at_check(0.6, 3).restart);
  EXPECT_TRUE(control.at_check(1e-7, 4).stop);
  // Plain Gauss-Seidel has nothing to restart.
  options.acceleration = Acceleration::none;
  SolveControl plain(options);
  plain.at_check(0.5, 1);
  EXPECT_FALSE(plain.at_check(0.7, 2).restart);
}

TEST(Acceleration, RestartDropsTheMomentum)
{
  // Right after a restart the momentum step moves nothing; with momentum it does.
  auto momentum_moves = [](bool restart) {
    ContactProblem problem = brick_pyramid(4, 0.5, 1e-3);
    problem.prepare(options_for({"nesterov", Acceleration::nesterov, 0.0}));
    for (int sweep = 0; sweep < 6; ++sweep) {
      problem.sweep();
      problem.accelerate();
    }
    problem.sweep();
    if (restart) problem.restart_acceleration();
    std::vector<Vec3> before;
    for (const SolverBody &b : problem.bodies) before.push_back(b.velocity);
    problem.accelerate();
    double moved = 0.0;
    for (std::size_t b = 0; b < before.size(); ++b)
      moved = std::max(moved, (problem.bodies[b].velocity - before[b]).norm());
    return moved;
  };
  EXPECT_GT(momentum_moves(false), 0.0);
  EXPECT_EQ(momentum_moves(true), 0.0);
}

TEST(Acceleration, NncgRestartsWhenTheSweepChangeGrows)
{
  ContactProblem problem = brick_pyramid(4, 0.5, 1e-3);
  problem.prepare(options_for({"nncg", Acceleration::nncg, 0.0}));
  problem.sweep();
  problem.accelerate({1.0});  // first step: no direction yet
  problem.sweep();
  std::vector<Vec3> before;
  for (const SolverBody &b : problem.bodies) before.push_back(b.velocity);
  problem.accelerate({2.0});  // beta = 2 > 1: restart, nothing moves
  for (std::size_t b = 0; b < before.size(); ++b)
    EXPECT_EQ(problem.bodies[b].velocity, before[b]);
  problem.sweep();
  problem.accelerate({1.0});  // beta = 1/2: moves
  double moved = 0.0;
  for (std::size_t b = 0; b < before.size(); ++b)
    moved = std::max(moved, (problem.bodies[b].velocity - before[b]).norm());
  EXPECT_GT(moved, 0.0);
}

TEST(Acceleration, CoarseCorrectionIsDroppedWhenItStopsPaying)
{
  // It must halve the residual every coarse_patience sweeps.
  SolverOptions options = options_for({"coarse", Acceleration::none, 2.0}, 1e-6);
  options.coarse_patience = 4;
  SolveControl control(options);
  SolveControl::Step step = control.at_check(1.0, 0);
  EXPECT_TRUE(step.remember);
  EXPECT_TRUE(step.coarse);
  EXPECT_TRUE(control.at_check(0.5, 2).remember);
  EXPECT_TRUE(control.at_check(0.4, 4).coarse);       // 0.4 <= 1.0 / 2: keeps paying
  EXPECT_TRUE(control.at_check(0.2, 6).coarse);       // 0.2 <= 0.5 / 2
  step = control.at_check(0.3, 8);                    // 0.3 > 0.4 / 2, and worse than 0.2
  EXPECT_TRUE(step.restore);
  EXPECT_FALSE(step.coarse);
  EXPECT_TRUE(control.coarse_dropped());
  step = control.at_check(0.2, 8);                    // the restored impulses
  EXPECT_FALSE(step.coarse);
  EXPECT_FALSE(step.remember);
  EXPECT_FALSE(step.stop);

  // Slow but still the best: dropped without going back.
  SolveControl slow(options);
  slow.at_check(1.0, 0);
  slow.at_check(0.9, 2);
  step = slow.at_check(0.8, 4);
  EXPECT_TRUE(slow.coarse_dropped());
  EXPECT_FALSE(step.restore);
  EXPECT_FALSE(step.coarse);
}

TEST(Acceleration, RestoredImpulsesGiveTheRememberedResidual)
{
  ContactProblem problem = brick_pyramid(5, 0.5, 1e-3);
  problem.prepare(options_for({"coarse", Acceleration::none, 2.0}));
  for (int sweep = 0; sweep < 5; ++sweep) problem.sweep();
  problem.remember_impulses();
  const double remembered = problem.residual_terms().residual();
  problem.coarse_correction();
  for (int sweep = 0; sweep < 5; ++sweep) problem.sweep();
  EXPECT_NE(problem.residual_terms().residual(), remembered);
  problem.restore_remembered_impulses();
  EXPECT_NEAR(problem.residual_terms().residual(), remembered, 1e-12 * remembered);
}

TEST(Acceleration, BadCoarseOptionsAreRejected)
{
  ContactProblem problem = brick_pyramid(2, 0.5, 1e-3);
  SolverOptions options = options_for({"coarse", Acceleration::none, -1.0});
  try {
    problem.prepare(options);
    FAIL() << "coarse_cell -1 accepted";
  } catch (const SolverError &e) {
    EXPECT_NE(std::string(e.what()).find("coarse_cell"), std::string::npos) << e.what();
  }
  options.coarse_cell = 2.0;
  options.coarse_every = 0;
  EXPECT_THROW(problem.prepare(options), SolverError);
  options.coarse_every = 1;
  options.coarse_patience = 0;
  EXPECT_THROW(problem.prepare(options), SolverError);
}
