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

// The Gauss-Seidel contact solver on hand-built scenes with closed-form answers.
#include "solver/contact_problem.h"
#include "solver_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace nscd;
using namespace nscd::test;

namespace {

constexpr double kGravity = 9.81;
constexpr double kPi = 3.14159265358979323846;

SolverOptions tight_options(double dt = 1e-3)
{
  SolverOptions options;
  options.dt = dt;
  options.tolerance = 1e-10;
  options.max_sweeps = 20000;
  return options;
}

struct Sphere {
  double mass = 2.0, radius = 0.5;
  Pose pose;
  Vec3 velocity = Vec3::Zero(), angular_velocity = Vec3::Zero();
  double moment() const { return 0.4 * mass * radius * radius; }
};

SolverBody solver_body(const Sphere &sphere, const Vec3 &gravity, double dt)
{
  SolverBody body;
  body.position = sphere.pose.position;
  body.velocity = sphere.velocity;
  body.angular_velocity = sphere.angular_velocity;
  body.inv_mass = 1.0 / sphere.mass;
  body.inv_inertia = world_inverse_inertia(Vec3::Constant(sphere.moment()), sphere.pose.orientation);
  body.external_impulse = dt * sphere.mass * gravity;
  return body;
}

// One step of a sphere on the floor z = 0 under `gravity`.
SolveReport step_sphere_on_floor(Sphere &sphere, const Vec3 &gravity, double mu,
                                 const SolverOptions &options)
{
  ContactProblem problem;
  problem.bodies.push_back(solver_body(sphere, gravity, options.dt));
  Contact contact;
  contact.body_i = 0;
  contact.point = Vec3(sphere.pose.position.x(), sphere.pose.position.y(), 0.0);
  contact.normal = Vec3::UnitZ();
  contact.gap = sphere.pose.position.z() - sphere.radius;
  contact.friction = mu;
  problem.contacts.push_back(contact);
  SolveReport report = solve(problem, options);
  advance_pose(sphere.pose, sphere.velocity, sphere.angular_velocity, problem.bodies[0].velocity,
               problem.bodies[0].angular_velocity, options.dt, options.theta);
  sphere.velocity = problem.bodies[0].velocity;
  sphere.angular_velocity = problem.bodies[0].angular_velocity;
  return report;
}

}    // namespace

TEST(ContactProblem, SphereRestsOnAPlaneWithoutDriftOrSpin)
{
  Sphere sphere;
  sphere.pose.position = Vec3(0.0, 0.0, sphere.radius);
  const SolverOptions options = tight_options();
  const Vec3 gravity(0.0, 0.0, -kGravity);
  for (int step = 0; step < 2000; ++step) {
    ContactProblem problem;
    problem.bodies.push_back(solver_body(sphere, gravity, options.dt));
    Contact contact;
    contact.point = Vec3(sphere.pose.position.x(), sphere.pose.position.y(), 0.0);
    contact.gap = sphere.pose.position.z() - sphere.radius;
    contact.friction = 0.5;
    problem.contacts.push_back(contact);
    const SolveReport report = solve(problem, options);
    ASSERT_TRUE(report.converged);
    EXPECT_LE(report.sweeps, 1);    // one contact: the local solve is exact
    EXPECT_NEAR(problem.contacts[0].impulse.z(), sphere.mass * kGravity * options.dt,
                1e-13 * sphere.mass * kGravity * options.dt);
    advance_pose(sphere.pose, sphere.velocity, sphere.angular_velocity,
                 problem.bodies[0].velocity, problem.bodies[0].angular_velocity, options.dt,
                 options.theta);
    sphere.velocity = problem.bodies[0].velocity;
    sphere.angular_velocity = problem.bodies[0].angular_velocity;
  }
  EXPECT_NEAR(sphere.pose.position.z(), sphere.radius, 1e-14);
  EXPECT_LT(sphere.velocity.norm(), 1e-15);
  EXPECT_EQ(sphere.angular_velocity.norm(), 0.0);
}

TEST(ContactProblem, BoxOnFourCornersCarriesItsWeight)
{
  BoxColumn column;
  column.floor_friction = 0.6;
  column.stack({2.5}, Vec3(0.5, 0.3, 0.2));
  const SolverOptions options = tight_options();
  ContactProblem problem;
  for (int step = 0; step < 1000; ++step) {
    const SolveReport report = column.step(problem, options);
    ASSERT_TRUE(report.converged) << "step " << step << " residual " << report.residual;
    const Vec3 reaction = impulse_on(problem, 0);
    EXPECT_NEAR(reaction.z(), 2.5 * kGravity * options.dt, 1e-9 * 2.5 * kGravity * options.dt);
    // Tangential impulses cancel up to the solver tolerance (the split between the four
    // corners is not unique, their sum is).
    EXPECT_LT(reaction.head<2>().norm(), 10 * options.tolerance * reaction.z());
  }
  EXPECT_NEAR(column.boxes[0].pose.position.z(), 0.2, 1e-12);
  // Velocity errors are ~ tolerance x g dt (= 1e-12 m/s), over a 0.2 m lever.
  EXPECT_LT(column.boxes[0].angular_velocity.norm(), 1e-10);
  EXPECT_LT(column.boxes[0].pose.orientation.angularDistance(Quat::Identity()), 1e-12);
}

// A block on an incline of angle alpha is a block on a level floor with tilted gravity.
struct InclineRun {
  Vec3 velocity;
  Vec3 displacement;
  double max_spin = 0.0;
};

InclineRun run_block_on_incline(double alpha, double mu, int steps, double dt, bool slip_guess = false)
{
  BoxColumn column;
  column.floor_friction = mu;
  column.gravity = kGravity * Vec3(std::sin(alpha), 0.0, -std::cos(alpha));
  column.stack({1.5}, Vec3(0.4, 0.3, 0.25));
  const Vec3 start = column.boxes[0].pose.position;
  SolverOptions options = tight_options(dt);
  options.slip_guess = slip_guess;
  ContactProblem problem;
  InclineRun run;
  for (int step = 0; step < steps; ++step) {
    const SolveReport report = column.step(problem, options);
    EXPECT_TRUE(report.converged) << "step " << step;
    EXPECT_EQ(report.terms.local_failures, 0);
    run.max_spin = std::max(run.max_spin, column.boxes[0].angular_velocity.norm());
  }
  run.velocity = column.boxes[0].velocity;
  run.displacement = column.boxes[0].pose.position - start;
  return run;
}

TEST(ContactProblem, BlockOnInclineStaysAtRestBelowTheFrictionAngle)
{
  const double mu = 0.5, alpha = 25.0 * kPi / 180.0;    // tan(alpha) = 0.466 < mu
  const InclineRun run = run_block_on_incline(alpha, mu, 500, 1e-3);
  EXPECT_LT(run.velocity.norm(), 1e-12);
  EXPECT_LT(run.displacement.norm(), 1e-12);
  EXPECT_LT(run.max_spin, 1e-11);
}

TEST(ContactProblem, BlockOnInclineSlidesWithCoulombAcceleration)
{
  const double mu = 0.5, alpha = 35.0 * kPi / 180.0, dt = 1e-3;    // tan(alpha) = 0.70
  const int steps = 300;
  // With slip_guess the four sliding corners start Newton from their last slip direction.
  for (const bool slip_guess : {false, true}) {
    const InclineRun run = run_block_on_incline(alpha, mu, steps, dt, slip_guess);
    const double expected = kGravity * (std::sin(alpha) - mu * std::cos(alpha));
    const double measured = run.velocity.x() / (steps * dt);
    EXPECT_NEAR(measured, expected, 1e-9 * expected) << slip_guess;
    EXPECT_LT(std::abs(run.velocity.y()) + std::abs(run.velocity.z()), 1e-12) << slip_guess;
    EXPECT_LT(run.max_spin, 1e-9) << slip_guess;
    // theta = 0.5 integrates the constant acceleration exactly: x = a t^2 / 2.
    EXPECT_NEAR(run.displacement.x(), 0.5 * expected * std::pow(steps * dt, 2), 1e-9) << slip_guess;
  }
}

TEST(ContactProblem, SphereRollsDownAnInclineWithoutSlipping)
{
  // Rolling: a = (5/7) g sin(alpha) when mu >= (2/7) tan(alpha). Exercises the lever arms
  // (the Delassus block couples the tangential and rotational parts).
  const double alpha = 30.0 * kPi / 180.0, mu = 0.3, dt = 1e-3;    // (2/7) tan = 0.165
  const Vec3 gravity = kGravity * Vec3(std::sin(alpha), 0.0, -std::cos(alpha));
  Sphere sphere;
  sphere.pose.position = Vec3(0.0, 0.0, sphere.radius);
  const SolverOptions options = tight_options(dt);
  const int steps = 400;
  for (int step = 0; step < steps; ++step)
    ASSERT_TRUE(step_sphere_on_floor(sphere, gravity, mu, options).converged);
  const double expected = 5.0 / 7.0 * kGravity * std::sin(alpha);
  EXPECT_NEAR(sphere.velocity.x() / (steps * dt), expected, 1e-10 * expected);
  EXPECT_NEAR(sphere.angular_velocity.y() * sphere.radius, sphere.velocity.x(), 1e-12);
  EXPECT_NEAR(sphere.pose.position.z(), sphere.radius, 1e-13);
}

TEST(ContactProblem, SphereOnSteepInclineSlidesAndSpinsUpByFriction)
{
  // mu < (2/7) tan(alpha): slipping. a = g (sin - mu cos), angular acc = (5/2) mu g cos / R.
  const double alpha = 40.0 * kPi / 180.0, mu = 0.1, dt = 1e-3;
  const Vec3 gravity = kGravity * Vec3(std::sin(alpha), 0.0, -std::cos(alpha));
  for (const bool slip_guess : {false, true}) {
    Sphere sphere;
    sphere.pose.position = Vec3(0.0, 0.0, sphere.radius);
    SolverOptions options = tight_options(dt);
    options.slip_guess = slip_guess;
    const int steps = 200;
    for (int step = 0; step < steps; ++step)
      ASSERT_TRUE(step_sphere_on_floor(sphere, gravity, mu, options).converged);
    const double t = steps * dt;
    const double a = kGravity * (std::sin(alpha) - mu * std::cos(alpha));
    const double spin_rate = 2.5 * mu * kGravity * std::cos(alpha) / sphere.radius;
    EXPECT_NEAR(sphere.velocity.x(), a * t, 1e-12 * a * t) << slip_guess;
    EXPECT_NEAR(sphere.angular_velocity.y(), spin_rate * t, 1e-12 * spin_rate * t) << slip_guess;
  }
}

TEST(ContactProblem, StackOfThreeBoxesCarriesTheWeightAbove)
{
  BoxColumn column;
  column.floor_friction = 0.4;
  column.box_friction = 0.4;
  const std::vector<double> masses = {3.0, 2.0, 1.0};    // bottom to top
  column.stack(masses, Vec3(0.5, 0.5, 0.25));
  const SolverOptions options = tight_options();
  ContactProblem problem;
  for (int step = 0; step < 100; ++step) {
    const SolveReport report = column.step(problem, options);
    ASSERT_TRUE(report.converged) << "step " << step;
    double weight_above = 0.0;
    for (int level = 2; level >= 0; --level) {
      weight_above += masses[level] * kGravity * options.dt;
      const Vec3 reaction = impulse_on(problem, level);
      EXPECT_NEAR(reaction.z(), weight_above, 1e-9 * weight_above) << "level " << level;
      // The residual is relative to the whole problem's velocity scale (set by the bottom).
      EXPECT_LT(reaction.head<2>().norm(), 10 * options.tolerance * 6.0 * kGravity * options.dt);
    }
    EXPECT_EQ(report.terms.contacts, 12);
    EXPECT_EQ(report.terms.active, 12);
    EXPECT_LT(report.terms.max_interpenetration, 1e-13);
  }
  for (int level = 0; level < 3; ++level)
    EXPECT_NEAR(column.boxes[level].pose.position.z(), 0.25 + 0.5 * level, 1e-12);
}

TEST(ContactProblem, HeavyBodyOnLightBodyConverges)
{
  BoxColumn column;
  column.floor_friction = 0.5;
  column.box_friction = 0.5;
  column.stack({1.0, 1000.0}, Vec3(0.5, 0.5, 0.5));
  // The residual is a velocity error relative to W_nn P, and W_nn of both contacts is set
  // by the light body: an impulse on the heavy body is then known to about
  // (mass ratio) x tolerance, hence the 1e-5 below for a tolerance of 1e-9.
  SolverOptions options = tight_options();
  options.tolerance = 1e-9;
  options.max_sweeps = 100000;
  ContactProblem problem;
  int first_sweeps = 0;
  for (int step = 0; step < 20; ++step) {
    const SolveReport report = column.step(problem, options);
    ASSERT_TRUE(report.converged) << "step " << step << " residual " << report.residual;
    if (step == 0) first_sweeps = report.sweeps;
    const double top = 1000.0 * kGravity * options.dt;
    EXPECT_NEAR(impulse_on(problem, 1).z(), top, 1e-5 * top);
    EXPECT_NEAR(impulse_on(problem, 0).z(), top + kGravity * options.dt, 1e-5 * top);
  }
  std::cout << "[ info ] mass ratio 1000, tolerance 1e-9: cold start " << first_sweeps
            << " sweeps\n";
  EXPECT_NEAR(column.boxes[0].pose.position.z(), 0.5, 1e-10);
  EXPECT_NEAR(column.boxes[1].pose.position.z(), 1.5, 1e-10);
}

namespace {

// Two spheres on the x axis: 0 at the origin moving +x, 1 to its right moving -x.
ContactProblem two_sphere_collision(double gap, double restitution, double v0, double v1)
{
  ContactProblem problem;
  for (int k = 0; k < 2; ++k) {
    Sphere sphere;
    sphere.mass = k == 0 ? 1.0 : 3.0;
    sphere.pose.position = Vec3(k * (2 * sphere.radius + gap), 0.0, 0.0);
    sphere.velocity = Vec3(k == 0 ? v0 : v1, 0.0, 0.0);
    problem.bodies.push_back(solver_body(sphere, Vec3::Zero(), 1.0));
  }
  Contact contact;
  contact.body_i = 1;
  contact.body_j = 0;
  contact.normal = Vec3::UnitX();
  contact.point = Vec3(0.5 + 0.5 * gap, 0.0, 0.0);
  contact.gap = gap;
  contact.friction = 0.3;
  contact.restitution = restitution;
  problem.contacts.push_back(contact);
  return problem;
}

double momentum_x(const ContactProblem &problem)
{
  return problem.bodies[0].velocity.x() * 1.0 + problem.bodies[1].velocity.x() * 3.0;
}

}    // namespace

TEST(ContactProblem, HeadOnInelasticCollisionConservesMomentum)
{
  ContactProblem problem = two_sphere_collision(0.0, 0.0, 2.0, -1.0);
  const double before = momentum_x(problem);
  const SolveReport report = solve(problem, tight_options());
  ASSERT_TRUE(report.converged);
  EXPECT_NEAR(momentum_x(problem), before, 1e-14);
  EXPECT_NEAR(problem.bodies[1].velocity.x() - problem.bodies[0].velocity.x(), 0.0, 1e-14);
  EXPECT_NEAR(problem.bodies[0].velocity.x(), -0.25, 1e-14);    // (1*2 - 3*1) / 4
  EXPECT_LT(problem.bodies[0].angular_velocity.norm() + problem.bodies[1].angular_velocity.norm(),
            1e-15);
}

TEST(ContactProblem, RestitutionReversesTheRelativeNormalVelocity)
{
  const double e = 0.6;
  ContactProblem problem = two_sphere_collision(0.0, e, 2.0, -1.0);
  const double before = momentum_x(problem);
  ASSERT_TRUE(solve(problem, tight_options()).converged);
  EXPECT_NEAR(momentum_x(problem), before, 1e-14);
  EXPECT_NEAR(problem.bodies[1].velocity.x() - problem.bodies[0].velocity.x(), e * 3.0, 1e-14);
}

// Two spheres at rest overlapping by d: kept as they are by default; with overlap_speed V
// they separate at min(d / (theta dt), V), momentum conserved; and a small overlap is
// removed within the step exactly.
TEST(ContactProblem, OverlapIsPushedOutOnlyWhenAskedAndAtMostAtTheCap)
{
  const double d = 0.02;
  for (const double cap : {0.0, 0.5, 100.0}) {
    ContactProblem problem = two_sphere_collision(-d, 0.0, 0.0, 0.0);
    SolverOptions options = tight_options(0.01);
    options.theta = 1.0;
    options.overlap_speed = cap;
    ASSERT_TRUE(solve(problem, options).converged) << cap;
    const double separation = problem.bodies[1].velocity.x() - problem.bodies[0].velocity.x();
    EXPECT_NEAR(separation, std::min(d / options.dt, cap), 1e-12) << "cap " << cap;
    EXPECT_NEAR(momentum_x(problem), 0.0, 1e-14);
  }
  SolverOptions bad = tight_options();
  bad.overlap_speed = -1.0;
  EXPECT_THROW(bad.validate(), SolverError);
}

// Two grains created overlapping (by less than their rounding, so a plain contact) fall
// together under gravity: no impulse is needed, and their relative velocity is the round-off
// of two equal falling velocities (here one ulp), not zero. Its error is round-off of the
// grains' own velocities, not of the (vanishing) relative one: measured against the latter,
// error / scale was a ratio of round-offs (2.16 after 2000 sweeps in a 27-grain pile), and
// +inf (reported as "no finite solution") on a step where every impulse came out exactly 0.
// Masses, points, normal and gaps of two overlapping grains of that pile.
TEST(ContactProblem, OverlappingPairFallingTogetherNeedsNoImpulseAndConverges)
{
  const double dt = 0.005;
  const Vec3 gravity(0.0, 0.0, -1.0);
  const Vec3 normal = Vec3(0.4888, -0.6492, -0.5828).normalized();
  const Vec3 points[4] = {{-1.195, -0.515, 1.348}, {-1.266, -0.565, 1.316},
                          {-1.223, -0.592, 1.394}, {-1.203, -0.568, 1.393}};
  const double gaps[4] = {-0.06552, -0.03239, -0.04619, -0.05648};
  const double masses[2] = {0.4992517484008223, 0.3899643508917356};
  const Vec3 centres[2] = {{-1.25, -1.25, 1.25}, {-1.25, 0.0, 1.25}};
  const Quat orientations[2] = {Quat(-0.904, -0.161, 0.209, -0.336).normalized(),
                                Quat(-0.228, -0.893, -0.147, -0.359).normalized()};
  const Vec3 moments[2] = {{0.05, 0.07, 0.09}, {0.04, 0.05, 0.06}};
  Vec3 velocity = Vec3::Zero();
  SolverOptions options = tight_options(dt);
  options.tolerance = 1e-6;
  options.max_sweeps = 2000;
  for (int step = 1; step <= 10; ++step) {
    ContactProblem problem;
    for (int b = 0; b < 2; ++b) {
      SolverBody body;
      body.position = centres[b] + (step - 1) * dt * velocity;
      body.velocity = velocity;
      // Grain 2 one ulp faster, as gravity's m g dt / m leaves it for some masses.
      if (b == 1) body.velocity.z() = std::nextafter(velocity.z(), -1.0);
      body.inv_mass = 1.0 / masses[b];
      body.inv_inertia = world_inverse_inertia(moments[b], orientations[b]);
      body.external_impulse = dt * masses[b] * gravity;
      problem.bodies.push_back(body);
    }
    for (int k = 0; k < 4; ++k) {
      Contact contact;
      contact.body_i = 0;
      contact.body_j = 1;
      contact.point = points[k] + (step - 1) * dt * velocity;
      contact.normal = normal;
      contact.gap = gaps[k];
      contact.friction = 0.5;
      problem.contacts.push_back(contact);
    }
    const SolveReport report = solve(problem, options);
    EXPECT_TRUE(report.converged) << "step " << step << ": residual " << report.residual
                                  << " after " << report.sweeps << " sweeps";
    EXPECT_LE(report.sweeps, 10) << "step " << step;
    for (const Contact &contact : problem.contacts)
      EXPECT_LT(contact.impulse.norm(), 1e-12 * masses[1] * dt) << "step " << step;
    velocity = problem.bodies[0].velocity;
    EXPECT_NEAR(velocity.z(), -step * dt, 1e-15) << "step " << step;
  }
}

TEST(ContactProblem, ContactClosingWithinTheStepIsCaughtWithoutPenetration)
{
  // theta = 1: the approach is slowed to exactly close the gap at the end of the step.
  SolverOptions options = tight_options(0.01);
  options.theta = 1.0;
  const double gap = 0.4 * 3.0 * options.dt;    // closes at 40 % of the step
  ContactProblem problem = two_sphere_collision(gap, 0.0, 2.0, -1.0);
  const SolveReport report = solve(problem, options);
  ASSERT_TRUE(report.converged);
  const double u_after = problem.bodies[1].velocity.x() - problem.bodies[0].velocity.x();
  EXPECT_NEAR(u_after, -gap / options.dt, 1e-13);
  EXPECT_LT(report.terms.max_interpenetration, 1e-16);
  EXPECT_GT(report.terms.max_interpenetration, -1e-16);    // touching: end gap exactly 0

  // Far apart: the contact stays open.
  ContactProblem far = two_sphere_collision(2.0 * 3.0 * options.dt, 0.0, 2.0, -1.0);
  const SolveReport far_report = solve(far, options);
  EXPECT_EQ(far_report.terms.active, 0);
  EXPECT_EQ(far.bodies[0].velocity.x(), 2.0);
  EXPECT_EQ(far.contacts[0].impulse, Vec3::Zero());
}

TEST(ContactProblem, WarmStartReducesSweepsOnARestingStack)
{
  BoxColumn column;
  column.floor_friction = 0.5;
  column.box_friction = 0.5;
  column.stack({1, 1, 1, 1, 1, 1, 1, 1}, Vec3(0.5, 0.4, 0.3));
  SolverOptions options = tight_options();
  options.tolerance = 1e-8;
  ContactProblem problem;
  int cold_first = 0, warm_last = 0;
  for (int step = 0; step < 20; ++step) {
    const SolveReport report = column.step(problem, options);
    ASSERT_TRUE(report.converged);
    if (step == 0) cold_first = report.sweeps;
    warm_last = report.sweeps;
  }
  // The same state solved cold.
  column.warm_start = false;
  const SolveReport cold = column.step(problem, options);
  ASSERT_TRUE(cold.converged);
  std::cout << "[ info ] 8-box stack, tolerance 1e-8: cold " << cold.sweeps << " (first step "
            << cold_first << "), warm " << warm_last << " sweeps\n";
  EXPECT_LT(3 * warm_last, cold.sweeps);
}

TEST(ContactProblem, SweepOrdersAgreeOnTheReactions)
{
  for (const SweepOrder order :
       {SweepOrder::as_given, SweepOrder::shuffled, SweepOrder::forward_backward}) {
    BoxColumn column;
    column.floor_friction = 0.3;
    column.box_friction = 0.3;
    column.stack({1.0, 2.0, 4.0}, Vec3(0.5, 0.5, 0.5));
    SolverOptions options = tight_options();
    options.order = order;
    options.relaxation = order == SweepOrder::shuffled ? 0.9 : 1.0;
    ContactProblem problem;
    const SolveReport report = column.step(problem, options);
    ASSERT_TRUE(report.converged) << static_cast<int>(order);
    EXPECT_NEAR(impulse_on(problem, 0).z(), 7.0 * kGravity * options.dt, 1e-9);
    EXPECT_NEAR(impulse_on(problem, 1).z(), 6.0 * kGravity * options.dt, 1e-9);
    EXPECT_NEAR(impulse_on(problem, 2).z(), 4.0 * kGravity * options.dt, 1e-9);
  }
}

TEST(ContactProblem, TwoRankSplitWithGhostExchangeMatchesOneRank)
{
  // Emulates domain decomposition: rank 0 owns boxes 0-1 and the contacts under them,
  // rank 1 owns boxes 2-3 and theirs; each rank holds every box (the others as ghosts).
  BoxColumn column;
  column.floor_friction = 0.5;
  column.box_friction = 0.5;
  column.stack({1.0, 2.0, 3.0, 4.0}, Vec3(0.5, 0.5, 0.5));
  SolverOptions options = tight_options();
  options.tolerance = 1e-10;

  ContactProblem whole;
  column.build(whole, options.dt);
  ContactProblem ranks[2];
  for (ContactProblem &rank : ranks) rank.bodies = whole.bodies;
  for (const Contact &contact : whole.contacts)
    ranks[contact.body_i < 2 ? 0 : 1].contacts.push_back(contact);
  const auto owner = [](int body) { return body < 2 ? 0 : 1; };

  const auto exchange = [&]() {
    for (int b = 0; b < 4; ++b) {
      const int own = owner(b), other = 1 - own;
      const Vec3 v = ranks[own].bodies[b].velocity + ranks[other].velocity_correction(b);
      const Vec3 w =
          ranks[own].bodies[b].angular_velocity + ranks[other].angular_velocity_correction(b);
      for (ContactProblem &rank : ranks) {
        rank.bodies[b].velocity = v;
        rank.bodies[b].angular_velocity = w;
      }
    }
    for (ContactProblem &rank : ranks) rank.mark_synchronised();
  };

  for (ContactProblem &rank : ranks) rank.prepare(options);
  exchange();
  int sweeps = 0;
  double residual = 1.0;
  while (residual > options.tolerance && sweeps < options.max_sweeps) {
    for (ContactProblem &rank : ranks) rank.sweep();
    exchange();
    ResidualTerms terms = ranks[0].residual_terms();
    terms.merge(ranks[1].residual_terms());
    residual = terms.residual();
    ++sweeps;
  }
  ASSERT_LE(residual, options.tolerance) << "after " << sweeps << " sweeps";
  const SolveReport single = solve(whole, options);
  std::cout << "[ info ] 4-box stack, tolerance 1e-10: 1 rank " << single.sweeps
            << " sweeps, 2 ranks " << sweeps << " sweeps\n";
  for (ContactProblem &rank : ranks) rank.finish();
  double weight_above = 0.0;
  for (int level = 3; level >= 0; --level) {
    weight_above += (level + 1.0) * kGravity * options.dt;
    EXPECT_NEAR(impulse_on(ranks[owner(level)], level).z(), weight_above, 1e-9 * weight_above);
    // Both runs stop at a residual of 1e-10 of the velocity scale (~g dt).
    EXPECT_LT((ranks[0].bodies[level].velocity - whole.bodies[level].velocity).norm(),
              10 * options.tolerance * kGravity * options.dt * 4);
  }
}

TEST(ContactProblem, BadInputIsRejectedWithAClearMessage)
{
  BoxColumn column;
  column.stack({1.0}, Vec3(0.5, 0.5, 0.5));
  ContactProblem problem;
  column.build(problem, 1e-3);
  SolverOptions options = tight_options();

  problem.contacts[2].normal = Vec3(0.0, 0.0, 2.0);
  try {
    problem.prepare(options);
    FAIL() << "a normal of length 2 was accepted";
  } catch (const SolverError &error) {
    EXPECT_NE(std::string(error.what()).find("contact 2: normal has length 2"), std::string::npos)
        << error.what();
  }
  column.build(problem, 1e-3);
  problem.contacts[0].body_j = 7;
  EXPECT_THROW(problem.prepare(options), SolverError);
  column.build(problem, 1e-3);
  problem.contacts[0].friction = -0.1;
  EXPECT_THROW(problem.prepare(options), SolverError);
  column.build(problem, 1e-3);
  problem.bodies[0].inv_mass = -1.0;
  EXPECT_THROW(problem.prepare(options), SolverError);
  column.build(problem, 1e-3);
  options.dt = 0.0;
  EXPECT_THROW(problem.prepare(options), SolverError);
  options = tight_options();
  options.theta = 0.0;
  EXPECT_THROW(problem.prepare(options), SolverError);
}

TEST(ContactProblem, ContactBetweenTwoImmobileBodiesIsInert)
{
  ContactProblem problem;
  problem.bodies.resize(1);    // inv_mass = 0: a fixed grain
  Contact contact;
  contact.gap = -0.01;
  problem.contacts.push_back(contact);
  const SolveReport report = solve(problem, tight_options());
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.terms.active, 0);
  EXPECT_EQ(problem.contacts[0].impulse, Vec3::Zero());
}

namespace {

// A loading plate (mass 4, translation locked along x and y, rotation locked) pressed down by
// an external force onto three spheres (mass 2, radius 0.5) that rest on the floor z = 0.
struct PlateOnSpheres {
  static constexpr double plate_mass = 4.0, push = 30.0, half_thickness = 0.1;
  std::vector<Sphere> spheres;
  Vec3 plate_position = Vec3(0.0, 0.0, 1.0 + half_thickness);
  Vec3 plate_velocity = Vec3::Zero();
  Vec3 plate_angular_velocity = Vec3::Zero();
  Vec3 plate_side_force = Vec3(7.0, -3.0, 0.0);    // carried by the locks
  double plate_friction = 0.5, floor_friction = 0.5;
  WarmStartCache cache;

  PlateOnSpheres()
  {
    for (const double x : {-1.2, 0.0, 1.2}) {
      Sphere sphere;
      sphere.pose.position = Vec3(x, 0.3 * x, 0.5);
      spheres.push_back(sphere);
    }
  }
  int plate_index() const { return static_cast<int>(spheres.size()); }

  void build(ContactProblem &problem, double dt) const
  {
    problem.bodies.clear();
    problem.contacts.clear();
    const Vec3 gravity(0.0, 0.0, -kGravity);
    for (const Sphere &sphere : spheres) problem.bodies.push_back(solver_body(sphere, gravity, dt));
    SolverBody plate;
    plate.position = plate_position;
    plate.velocity = plate_velocity;
    plate.angular_velocity = plate_angular_velocity;
    plate.inv_mass = 1.0 / plate_mass;
    plate.inv_mass_axes = Vec3(0.0, 0.0, 1.0);
    plate.external_impulse = dt * (plate_mass * gravity + Vec3(0.0, 0.0, -push) + plate_side_force);
    plate.external_angular_impulse = dt * Vec3(1.0, 2.0, 3.0);    // locked: ignored
    problem.bodies.push_back(plate);
    for (int s = 0; s < plate_index(); ++s) {
      const Vec3 centre = spheres[s].pose.position;
      Contact floor;
      floor.body_i = s;
      floor.point = Vec3(centre.x(), centre.y(), 0.0);
      floor.gap = centre.z() - 0.5;
      floor.friction = floor_friction;
      floor.key = {s, -1, 0};
      problem.contacts.push_back(floor);
      Contact top;
      top.body_i = s;
      top.body_j = plate_index();
      top.point = Vec3(centre.x(), centre.y(), centre.z() + 0.5);
      top.normal = -Vec3::UnitZ();
      top.gap = plate_position.z() - half_thickness - (centre.z() + 0.5);
      top.friction = plate_friction;
      top.key = {s, plate_index(), 0};
      problem.contacts.push_back(top);
    }
  }

  SolveReport step(ContactProblem &problem, const SolverOptions &options)
  {
    build(problem, options.dt);
    cache.apply(problem.contacts);
    const SolveReport report = solve(problem, options);
    cache.store(problem.contacts);
    for (int s = 0; s < plate_index(); ++s) {
      Sphere &sphere = spheres[s];
      const SolverBody &body = problem.bodies[s];
      advance_pose(sphere.pose, sphere.velocity, sphere.angular_velocity, body.velocity,
                   body.angular_velocity, options.dt, options.theta);
      sphere.velocity = body.velocity;
      sphere.angular_velocity = body.angular_velocity;
    }
    const SolverBody &body = problem.bodies[plate_index()];
    plate_position += options.dt * ((1.0 - options.theta) * plate_velocity + options.theta * body.velocity);
    plate_velocity = body.velocity;
    plate_angular_velocity = body.angular_velocity;
    return report;
  }
};

}    // namespace

TEST(ContactProblem, PlateWithLockedLateralAxesIsCarriedByTheGrains)
{
  PlateOnSpheres scene;
  const SolverOptions options = tight_options();
  ContactProblem problem;
  for (int step = 0; step < 200; ++step) {
    const SolveReport report = scene.step(problem, options);
    ASSERT_TRUE(report.converged) << "step " << step;
    EXPECT_EQ(report.terms.local_failures, 0);
    // Locked axes and rotation are never touched, whatever the contacts or external loads do.
    EXPECT_EQ(scene.plate_velocity.x(), 0.0);
    EXPECT_EQ(scene.plate_velocity.y(), 0.0);
    EXPECT_EQ(scene.plate_angular_velocity, Vec3::Zero());
    // The plate is at rest on the grains: the grains carry (F + m g) dt ...
    double on_plate = 0.0, on_floor = 0.0;
    for (const Contact &contact : problem.contacts)
      (contact.body_j == kEnvironment ? on_floor : on_plate) += contact.impulse.z();
    const double load = (PlateOnSpheres::push + PlateOnSpheres::plate_mass * kGravity) * options.dt;
    EXPECT_NEAR(-on_plate, load, 1e-9 * load) << "step " << step;
    // ... and the floor that plus the grains' weight.
    const double total = load + 3 * 2.0 * kGravity * options.dt;
    EXPECT_NEAR(on_floor, total, 1e-9 * total) << "step " << step;
  }
  EXPECT_NEAR(scene.plate_position.z(), 1.1, 1e-12);
  EXPECT_EQ(scene.plate_position.x(), 0.0);
  for (const Sphere &sphere : scene.spheres) EXPECT_LT(sphere.velocity.norm(), 1e-10);
}

TEST(ContactProblem, GrainSlidingUnderALockedPlateDoesNotMoveItSideways)
{
  PlateOnSpheres scene;
  scene.spheres.resize(1);
  scene.spheres[0].velocity = Vec3(0.8, -0.4, 0.0);
  scene.spheres[0].angular_velocity = Vec3(0.0, 0.0, 5.0);
  scene.plate_side_force.setZero();
  scene.floor_friction = 0.0;    // only the plate brakes the grain
  const SolverOptions options = tight_options();
  ContactProblem problem;
  const double speed_before = scene.spheres[0].velocity.norm();
  for (int step = 0; step < 20; ++step) {
    const SolveReport report = scene.step(problem, options);
    ASSERT_TRUE(report.converged) << "step " << step;
    EXPECT_EQ(scene.plate_velocity.x(), 0.0);
    EXPECT_EQ(scene.plate_velocity.y(), 0.0);
    EXPECT_EQ(scene.plate_angular_velocity, Vec3::Zero());
    // Contact 1: sphere below the plate. While the sphere slips the plate brakes it with
    // the full Coulomb force (it rolls without slip after ~10 steps, then P_t = 0).
    const Contact &top = problem.contacts[1];
    if (step == 0) {
      EXPECT_EQ(top.regime, ContactRegime::slip);
    }
    if (top.regime == ContactRegime::slip) {
      EXPECT_NEAR(top.impulse.head<2>().norm(), scene.plate_friction * -top.impulse.z(),
                  1e-9 * -top.impulse.z());
    }
  }
  // Then it rolls on the floor under the laterally fixed plate: its top point is at rest,
  // and the friction impulse P that achieved it gives v = v0 - P/m with
  // v0 = P (1/m + r^2/I) (m = 2, r = 0.5, I = 0.2): v = 5/7 v0.
  EXPECT_EQ(problem.contacts[1].regime, ContactRegime::stick);
  const Vec3 rolling = 5.0 / 7.0 * Vec3(0.8, -0.4, 0.0);
  EXPECT_LT((scene.spheres[0].velocity - rolling).norm(), 1e-9 * speed_before);
  EXPECT_EQ(scene.plate_position.x(), 0.0);
  EXPECT_EQ(scene.plate_position.y(), 0.0);
}

TEST(ContactProblem, LockedPlateOnAMovingFloorSlidesOnlyAlongItsFreeAxis)
{
  // Plate body 0 (locked x, y and rotation) falls onto a floor moving sideways: W has only a
  // normal part (normal_only contact), the plate stops and gets the full sliding friction.
  const double dt = 1e-3, mass = 3.0, mu = 0.4;
  ContactProblem problem;
  SolverBody plate;
  plate.position = Vec3(0.0, 0.0, 0.1);
  plate.velocity = Vec3(0.0, 0.0, -2.0);
  plate.inv_mass = 1.0 / mass;
  plate.inv_mass_axes = Vec3(0.0, 0.0, 1.0);
  plate.external_impulse = dt * mass * Vec3(0.0, 0.0, -kGravity);
  problem.bodies.push_back(plate);
  for (const double x : {-0.5, 0.5}) {
    Contact contact;
    contact.point = Vec3(x, 0.2, 0.0);
    contact.friction = mu;
    contact.wall_velocity = Vec3(1.0, 0.0, 0.0);
    problem.contacts.push_back(contact);
  }
  const SolveReport report = solve(problem, tight_options(dt));
  ASSERT_TRUE(report.converged);
  EXPECT_GE(report.terms.sliding, 1);
  EXPECT_EQ(report.terms.sticking, 0);
  EXPECT_EQ(problem.bodies[0].velocity.x(), 0.0);
  EXPECT_EQ(problem.bodies[0].velocity.y(), 0.0);
  EXPECT_NEAR(problem.bodies[0].velocity.z(), 0.0, 1e-12);
  Vec3 total = Vec3::Zero();
  for (const Contact &contact : problem.contacts) total += contact.impulse;
  const double normal = mass * (2.0 + kGravity * dt);
  EXPECT_NEAR(total.z(), normal, 1e-12 * normal);
  EXPECT_NEAR(total.x(), mu * normal, 1e-12 * normal);    // the floor drags along +x
  EXPECT_NEAR(total.y(), 0.0, 1e-15);
}

TEST(ContactProblem, BodyWithAllAxesLockedActsAsInfiniteMass)
{
  // A sphere hits body 1, once of infinite mass, once with finite mass and all axes locked.
  auto run = [](bool locked) {
    ContactProblem problem;
    Sphere sphere;
    sphere.pose.position = Vec3(0.1, 0.0, 1.5);
    sphere.velocity = Vec3(0.3, 0.0, -1.0);
    problem.bodies.push_back(solver_body(sphere, Vec3(0.0, 0.0, -kGravity), 1e-3));
    SolverBody block;
    block.position = Vec3(0.0, 0.0, 0.5);
    block.velocity = Vec3(0.0, 0.0, 0.2);    // prescribed
    if (locked) {
      block.inv_mass = 0.5;
      block.inv_mass_axes = Vec3::Zero();
      block.external_impulse = Vec3(1.0, 2.0, 3.0);
    }
    problem.bodies.push_back(block);
    Contact contact;
    contact.body_i = 0;
    contact.body_j = 1;
    contact.point = Vec3(0.1, 0.0, 1.0);
    contact.friction = 0.3;
    contact.restitution = 0.5;
    problem.contacts.push_back(contact);
    Contact floor;    // block on the floor: inert
    floor.body_i = 1;
    floor.gap = -1e-3;
    problem.contacts.push_back(floor);
    const SolveReport report = solve(problem, tight_options());
    EXPECT_TRUE(report.converged);
    return problem;
  };
  const ContactProblem infinite = run(false), locked = run(true);
  EXPECT_EQ(locked.bodies[1].velocity, Vec3(0.0, 0.0, 0.2));
  EXPECT_EQ(locked.bodies[1].angular_velocity, Vec3::Zero());
  EXPECT_EQ(locked.contacts[1].impulse, Vec3::Zero());
  EXPECT_EQ(locked.contacts[0].impulse, infinite.contacts[0].impulse);
  EXPECT_EQ(locked.bodies[0].velocity, infinite.bodies[0].velocity);
  EXPECT_EQ(locked.bodies[0].angular_velocity, infinite.bodies[0].angular_velocity);
  EXPECT_GT(locked.contacts[0].impulse.z(), 0.0);
}

TEST(ContactProblem, NegativeAxisFactorIsRejected)
{
  ContactProblem problem;
  problem.bodies.resize(1);
  problem.bodies[0].inv_mass = 1.0;
  problem.bodies[0].inv_mass_axes = Vec3(1.0, -1.0, 1.0);
  SolverOptions options = tight_options();
  EXPECT_THROW(problem.prepare(options), SolverError);
  problem.bodies[0].inv_mass_axes = Vec3::Ones();
  options.check_every = 0;
  EXPECT_THROW(problem.prepare(options), SolverError);
}

TEST(ContactProblem, CheckEverySweepsGivesTheSameAnswerWithFewerResiduals)
{
  BoxColumn column;
  column.floor_friction = column.box_friction = 0.5;
  column.stack({1.0, 1.0, 1.0}, Vec3(0.5, 0.5, 0.5));
  column.warm_start = false;
  SolverOptions options = tight_options();
  options.tolerance = 1e-8;
  ContactProblem every, sparse;
  const SolveReport each = column.step(every, options);
  column.stack({1.0, 1.0, 1.0}, Vec3(0.5, 0.5, 0.5));
  options.check_every = 7;
  const SolveReport seventh = column.step(sparse, options);
  ASSERT_TRUE(each.converged);
  ASSERT_TRUE(seventh.converged);
  EXPECT_EQ(seventh.sweeps % 7, 0);
  EXPECT_GE(seventh.sweeps, each.sweeps);
  EXPECT_LT(seventh.sweeps, each.sweeps + 7);
  for (int level = 0; level < 3; ++level)
    EXPECT_NEAR(impulse_on(sparse, level).z(), impulse_on(every, level).z(),
                1e-6 * impulse_on(every, level).z());
  // max_sweeps is honoured even when it is not a multiple of check_every.
  options.max_sweeps = 10;
  column.stack({1.0, 1.0, 1.0}, Vec3(0.5, 0.5, 0.5));
  EXPECT_EQ(column.step(sparse, options).sweeps, 10);
}

namespace {
// A ball resting on four fixed balls (a pyramid's top) with each of its four contacts on a
// different emulated rank, as when a 2 x 2 decomposition cuts through its centre. Every
// rank holds all bodies; `share` is the ball's SolverBody::share on every rank. Returns the
// residual after `max_sweeps` (or less once converged) and the ranks' summed impulses.
struct SplitResult {
  double residual = 0.0;
  int sweeps = 0;
  Vec3 total_impulse = Vec3::Zero();
};

SplitResult ball_on_four_balls_split_over_four_ranks(double share, int max_sweeps)
{
  SolverOptions options = tight_options();
  Sphere top;
  top.pose.position = Vec3(0, 0, std::sqrt(0.5));
  ContactProblem whole;
  whole.bodies.push_back(solver_body(top, Vec3(0, 0, -kGravity), options.dt));
  for (int k = 0; k < 4; ++k) {
    const Vec3 below(k % 2 ? 0.5 : -0.5, k / 2 ? 0.5 : -0.5, 0.0);
    SolverBody fixed;    // infinite mass
    fixed.position = below;
    whole.bodies.push_back(fixed);
    Contact c;
    c.body_i = 0;
    c.body_j = k + 1;
    c.normal = (top.pose.position - below).normalized();
    c.point = below + 0.5 * c.normal;
    c.friction = 0.5;
    c.key = {0, k + 1, 0};
    whole.contacts.push_back(c);
  }
  whole.bodies[0].share = share;
  std::vector<ContactProblem> ranks(4);
  for (int r = 0; r < 4; ++r) {
    ranks[r].bodies = whole.bodies;
    ranks[r].contacts = {whole.contacts[r]};
  }
  // rank 0 owns the ball: it sums the four copies' corrections and divides by the share
  const auto exchange = [&]() {
    Vec3 dv = Vec3::Zero(), dw = Vec3::Zero();
    for (ContactProblem &rank : ranks) {
      dv += rank.velocity_correction(0);
      dw += rank.angular_velocity_correction(0);
    }
    const Vec3 v = ranks[0].bodies[0].velocity - ranks[0].velocity_correction(0) + dv / share;
    const Vec3 w = ranks[0].bodies[0].angular_velocity - ranks[0].angular_velocity_correction(0) + dw / share;
    for (ContactProblem &rank : ranks) {
      rank.bodies[0].velocity = v;
      rank.bodies[0].angular_velocity = w;
      rank.mark_synchronised();
    }
  };
  for (ContactProblem &rank : ranks) rank.prepare(options);
  exchange();
  SplitResult result;
  result.residual = 1.0;
  while (result.residual > options.tolerance && result.sweeps < max_sweeps) {
    for (ContactProblem &rank : ranks) rank.sweep();
    exchange();
    ResidualTerms terms;
    for (ContactProblem &rank : ranks) terms.merge(rank.residual_terms());
    result.residual = terms.residual();
    ++result.sweeps;
  }
  for (ContactProblem &rank : ranks) {
    rank.finish();
    result.total_impulse += rank.contacts[0].impulse;
  }
  return result;
}
}    // namespace

TEST(ContactProblem, MassSplittingConvergesWhereFourCopiesShareABody)
{
  // Summed corrections: each rank's sticking contact alone stops the ball, four stop it
  // four times over, and the ball's velocity flips and grows: no convergence.
  const SplitResult summed = ball_on_four_balls_split_over_four_ranks(1.0, 500);
  EXPECT_GT(summed.residual, 1e-3);
  // Mass splitting (share 4): the exact answer, the ball's weight over the four contacts.
  const SplitResult split = ball_on_four_balls_split_over_four_ranks(4.0, 500);
  std::cout << "[ info ] ball on 4 balls over 4 ranks: summed corrections residual "
            << summed.residual << " after " << summed.sweeps << " sweeps; mass splitting "
            << split.residual << " after " << split.sweeps << " sweeps\n";
  ASSERT_LE(split.residual, 1e-10);
  const double weight_impulse = 2.0 * kGravity * 1e-3;    // mass 2, dt 1e-3
  EXPECT_NEAR(split.total_impulse.z(), weight_impulse, 1e-9 * weight_impulse);
  EXPECT_NEAR(split.total_impulse.x(), 0.0, 1e-12);
  EXPECT_NEAR(split.total_impulse.y(), 0.0, 1e-12);
}

TEST(ContactProblem, ShareBelowOneIsRejected)
{
  ContactProblem problem;
  problem.bodies.emplace_back();
  problem.bodies[0].inv_mass = 1.0;
  problem.bodies[0].share = 0.5;
  SolverOptions options = tight_options();
  try {
    problem.prepare(options);
    FAIL() << "share 0.5 accepted";
  } catch (const SolverError &e) {
    EXPECT_NE(std::string(e.what()).find("share 0.5"), std::string::npos) << e.what();
  }
}

TEST(ContactProblem, SkippedSeparatingContactIsPutBackWhenANeighbourPushesItShut)
{
  // Three spheres in a row, touching (masses 1, 3, 3); the first moves at 3 towards the
  // second, at rest, and the third moves away at 0.1. At the first check the contact between
  // the second and the third is separating, so the sweeps skip it; the impulse on the
  // second then drives it into the third, and the next check must put that contact back.
  // theta = 1: the end gap is the start gap (0), so the contact must not close at all. The
  // answer is the perfectly inelastic one: all three at (3 + 0.3) / 7.
  for (const bool skip : {false, true}) {
    for (const int check_every : {1, 4, 16}) {
      SolverOptions options = tight_options(0.01);
      options.theta = 1.0;
      options.skip_separating = skip;
      options.check_every = check_every;
      ContactProblem problem = two_sphere_collision(0.0, 0.0, 3.0, 0.0);
      SolverBody third = problem.bodies[1];
      third.position.x() += 1.0;
      third.velocity.x() = 0.1;
      problem.bodies.push_back(third);
      Contact touching = problem.contacts[0];
      touching.body_i = 2;
      touching.body_j = 1;
      touching.point.x() += 1.0;
      touching.key.tag_i = 3;
      touching.key.tag_j = 2;
      problem.contacts.push_back(touching);
      problem.prepare(options);
      if (skip) {
        problem.skip_separating_contacts();
        EXPECT_EQ(problem.swept_contacts(), 1u);    // only the closing contact
      }
      const SolveReport report = iterate(problem, options);
      ASSERT_TRUE(report.converged) << skip << " " << check_every << ": " << report.residual
                                    << " after " << report.sweeps;
      for (int b = 0; b < 3; ++b)
        EXPECT_NEAR(problem.bodies[b].velocity.x(), 3.3 / 7.0, 1e-8) << b << " " << skip << " " << check_every;
      EXPECT_EQ(problem.swept_contacts(), 2u);    // both act at the end
    }
  }
}

TEST(ContactProblem, SkippingSeparatingContactsKeepsTheAnswerAndSweepsFewer)
{
  // A pyramid of bricks with every brick also "in contact" with a far neighbour that moves
  // away (contacts found within a neighbour skin that never close): the reactions and the
  // sweeps are those without the far contacts, and each sweep relaxes only the near ones.
  const ContactProblem base = brick_pyramid(6, 0.5, 1e-3);
  ContactProblem with_far = base;
  const std::size_t near = base.contacts.size();
  for (std::size_t c = 0; c < near; ++c) {
    Contact far = base.contacts[c];
    far.gap = 0.1;    // separated and not approaching: needs no impulse in this step
    far.key.feature += 1000;
    with_far.contacts.push_back(far);
  }
  SolverOptions options = tight_options();
  options.tolerance = 1e-8;
  for (const bool skip : {false, true}) {
    options.skip_separating = skip;
    ContactProblem reference = base, problem = with_far;
    const SolveReport expected = solve(reference, options);
    const SolveReport report = solve(problem, options);
    ASSERT_TRUE(expected.converged);
    ASSERT_TRUE(report.converged) << skip;
    EXPECT_EQ(problem.swept_contacts(), skip ? near : 2 * near);
    for (std::size_t b = 0; b < base.bodies.size(); ++b)
      EXPECT_LT((problem.bodies[b].velocity - reference.bodies[b].velocity).norm(), 1e-6) << b;
    for (std::size_t c = near; c < 2 * near; ++c) EXPECT_EQ(problem.contacts[c].impulse, Vec3::Zero());
  }
}
