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

// Stability estimate, subcycle planning and the averaged wire->grain force.
#include "wire/soft_contact.h"
#include "wire/stability.h"
#include "wire/subcycle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace nscd;
using namespace nscd::wire;

// examples/column's wire: k_elo 5000 on elements of 0.2, nodes of 0.005, k_rot 0.01, soft
// contacts k_n 2000 with gamma_n 2, 2 per node.
namespace {
WireStiffness papers_wire()
{
  WireStiffness w;
  w.node_mass = 0.005;
  w.element_length = 0.2;
  w.k_elo = 5000.0;
  w.k_rot = 0.01;
  w.k_n = 2000.0;
  w.gamma_contact = 2.0;
  w.contacts_per_node = 2.0;
  return w;
}
}    // namespace

TEST(WireStability, FrequencyBoundAddsAxialBendingAndContactStiffness)
{
  WireStiffness w;
  w.node_mass = 0.5;
  w.element_length = 0.1;
  w.k_elo = 20.0;       // k_elo / l = 200
  w.k_rot = 0.01;       // 4 k_rot / l^2 = 4
  w.k_n = 100.0;        // n_c k_n / 2 = 100 with n_c = 2
  w.contacts_per_node = 2.0;
  EXPECT_NEAR(wire_max_angular_frequency(w), std::sqrt(4.0 * 304.0 / 0.5), 1e-12);
  w.gamma_contact = 0.25;
  w.node_damping = 0.5;
  EXPECT_NEAR(wire_max_damping_rate(w), (2 * 2 * 0.25 + 0.5) / 0.5, 1e-12);
  // The step is safety x the largest dt whose corner (w_max dt, g_max dt) is stable.
  const double dt = max_stable_wire_step(w, GearCorrector::ThreeSixteenths, 0.5);
  const double omega = wire_max_angular_frequency(w), rate = wire_max_damping_rate(w);
  EXPECT_TRUE(gear5_stable(omega * 2.0 * dt, rate * 2.0 * dt, GearCorrector::ThreeSixteenths));
  EXPECT_FALSE(gear5_stable(omega * 2.0 * dt * 1.0001, rate * 2.0 * dt * 1.0001, GearCorrector::ThreeSixteenths));
  // never below the old additive rule at the same safety
  EXPECT_GE(dt, 0.5 / (omega / 0.313 + rate / 0.163));
}

TEST(WireStability, PapersWireNeedsFewerSubstepsThanTheAdditiveRule)
{
  // examples/column's wire: k_elo 5000 on elements of 0.2, nodes of 0.005, k_rot 0.01, soft
  // contacts k_n 2000 with gamma_n 2, 2 per node. w_max = 4648, g_max = 1600: the frequency
  // limit binds (w dt = 0.313 at g dt = 0.108, inside the region).
  WireStiffness w = papers_wire();
  const double omega = wire_max_angular_frequency(w), rate = wire_max_damping_rate(w);
  EXPECT_NEAR(omega, std::sqrt(4.0 * (25000.0 + 1.0 + 2000.0) / 0.005), 1e-9);
  EXPECT_NEAR(rate, 1600.0, 1e-9);
  const double dt = max_stable_wire_step(w, GearCorrector::ThreeSixteenths, 1.0);
  EXPECT_NEAR(dt, 0.313 / omega, 1e-6 * dt);
  const int substeps = plan_subcycle(0.005, max_stable_wire_step(w)).substeps;
  const int before = plan_subcycle(0.005, 0.5 / (omega / 0.313 + rate / 0.163)).substeps;
  std::printf("[stability] papers' wire at dt 0.005: %d substeps at the default safety 0.9 (the additive "
              "rule at 0.5: %d)\n", substeps, before);
  EXPECT_EQ(before, 247);
  EXPECT_EQ(substeps, 83);
}

TEST(WireStability, AutomaticStepResolvesTheFastestModeAndStaysStable)
{
  // The papers' wire again: the accurate step is 0.1 / w_max (233 substeps at dt 0.005),
  // well inside the stable one (83); a wire whose stability limit is the tighter one (heavy
  // damping) gets the stable step.
  WireStiffness w = papers_wire();
  const double omega = wire_max_angular_frequency(w);
  EXPECT_NEAR(accurate_wire_step(w) * omega, kAccurateFrequencyStep, 1e-12);
  EXPECT_EQ(plan_subcycle(0.005, accurate_wire_step(w)).substeps, 233);
  w.gamma_contact = 200.0;    // g_max = 160000: pure drag limits the step to 0.163 / g_max
  EXPECT_EQ(accurate_wire_step(w), max_stable_wire_step(w));
  EXPECT_LT(accurate_wire_step(w) * omega, kAccurateFrequencyStep);
}

TEST(WireStability, TooLargeStepIsRejectedWithTheWayOut)
{
  WireStiffness w;
  w.node_mass = 1e-3;
  w.element_length = 0.01;
  w.k_elo = 1e3;
  const double dt_max = max_stable_wire_step(w);
  EXPECT_NO_THROW(check_wire_step(dt_max, w));
  try {
    check_wire_step(3.5 * dt_max, w);
    FAIL() << "step above the limit accepted";
  } catch (const std::invalid_argument &e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("dt_SP"), std::string::npos) << what;
    EXPECT_NE(what.find("at least 4 times more wire substeps"), std::string::npos) << what;
  }
  EXPECT_THROW(check_wire_step(-1.0, w), std::invalid_argument);
  w.node_mass = 0.0;
  EXPECT_THROW(max_stable_wire_step(w), std::invalid_argument);
}

TEST(Subcycle, PlanDividesTheGrainStep)
{
  EXPECT_EQ(plan_subcycle(1e-3, 1e-4).substeps, 10);    // exact ratio: no extra step
  EXPECT_EQ(plan_subcycle(1e-3, 0.9e-4).substeps, 12);
  const SubcyclePlan p = plan_subcycle(1e-3, 0.9e-4);
  EXPECT_NEAR(p.dt_sp * p.substeps, 1e-3, 1e-18);
  EXPECT_EQ(plan_subcycle(1e-3, 1e-4, 25).substeps, 25);
  EXPECT_EQ(plan_subcycle(1e-3, 1.0).substeps, 1);
  try {
    plan_subcycle(1e-3, 1e-4, 5);
    FAIL() << "too few substeps accepted";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("at least 10 substeps"), std::string::npos) << e.what();
  }
  EXPECT_THROW(plan_subcycle(0.0, 1e-4), std::invalid_argument);
}

TEST(Subcycle, FreeFallIsExactAcrossChangingSubsteps)
{
  // Constant force: the trajectory is a parabola, which Gear-5 reproduces exactly when
  // started with the right acceleration, also when the substep changes between grain
  // steps (the scaled derivatives are rescaled).
  WireNodeSet nodes;
  nodes.reset({Vec3(0, 0, 1)}, 2.0, 1e-4);
  nodes.state[0] = gear5_start(Vec3(0, 0, 1), Vec3(0.5, 0, 0), Vec3(0, 0, -9.81), 1e-4);
  GrainForceAccumulator grains;
  grains.reset(0);
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  const auto gravity = [](const SubstepInfo &, const std::vector<Vec3> &, const std::vector<Vec3> &,
                          std::vector<Vec3> &f, GrainForceAccumulator &) { f[0] = Vec3(0, 0, -2.0 * 9.81); };
  run_subcycle(plan_subcycle(1e-2, 1e-4), c, nodes, grains, gravity);
  run_subcycle(plan_subcycle(1e-2, 3e-4), c, nodes, grains, gravity);    // 34 substeps
  const double t = 2e-2;
  EXPECT_NEAR((nodes.state[0].position() - Vec3(0.5 * t, 0, 1 - 0.5 * 9.81 * t * t)).norm(), 0.0, 1e-13);
  EXPECT_NEAR(nodes.state[0].velocity(nodes.dt).z(), -9.81 * t, 1e-11);
  EXPECT_EQ(grains.substeps(), 134);
}

TEST(Subcycle, AveragedForceOnGrainCarriesTheWireWeight)
{
  // One wire node (mass m) rests, under gravity, on a fixed spherical grain of radius R,
  // off the top so that friction holds it. Once settled, the mean wire->grain force over a
  // subcycle is the node's weight, and the mean torque is (contact arm) x weight.
  const double R = 1.0, r_w = 0.05, m = 0.01, g = 9.81;
  SoftContactLaw law;
  law.k_n = 1e3;
  law.gamma_n = 2 * std::sqrt(law.k_n * m);    // critically damped
  law.k_t = 5e2;
  law.gamma_t = 2 * std::sqrt(law.k_t * m);
  law.mu_s = law.mu_d = 1.0;
  validate(law);
  const Vec3 start = (R + r_w) * Vec3(0.2, 0, 1).normalized();
  WireNodeSet nodes;
  nodes.reset({start}, m, 1e-4);
  TangentialHistory history;
  const Vec3 centre = Vec3::Zero();    // the grain, at rest
  GrainForceAccumulator grains;
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  const auto forces = [&](const SubstepInfo &s, const std::vector<Vec3> &x, const std::vector<Vec3> &v,
                          std::vector<Vec3> &f, GrainForceAccumulator &acc) {
    f[0] = Vec3(0, 0, -m * g);
    const Vec3 d = x[0] - centre;
    const Vec3 n = d.normalized();    // from grain (B) to node (A)
    const double overlap = R + r_w - d.norm();
    const SoftContactForce fc = soft_contact_force(law, n, overlap, v[0], s.dt, history);
    f[0] += fc.force;
    acc.add(0, -fc.force, R * n);
  };
  const double dt_max = 1e-4;
  for (int step = 0; step < 200; ++step) {    // 200 grain steps of 1e-2
    grains.reset(1);
    run_subcycle(plan_subcycle(1e-2, dt_max), c, nodes, grains, forces);
  }
  const Vec3 weight(0, 0, -m * g);
  const Vec3 n = nodes.state[0].position().normalized();
  EXPECT_EQ(grains.substeps(), 100);
  EXPECT_NEAR((grains.mean_force(0) - weight).norm(), 0.0, 1e-9 * m * g);
  EXPECT_NEAR((grains.mean_torque(0) - (R * n).cross(weight)).norm(), 0.0, 1e-9 * m * g * R);
  EXPECT_LT(nodes.state[0].velocity(nodes.dt).norm(), 1e-9);    // stuck, not sliding off
}
