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

// Wire dynamics: axial wave speed of the discrete chain and tightness of the time-step
// bound on the highest axial and bending modes.
#include "wire/stability.h"
#include "wire_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace nscd;
using namespace nscd::wire;
using namespace nscd::wire::test;

TEST(WireDynamics, AxialPulseTravelsAtTheDiscreteWaveSpeed)
{
  // Element stiffness k = k_elo / l and node mass m = rho l give c = l sqrt(k / m) =
  // sqrt(k_elo / rho) for wavelengths >> l. A Gaussian stretch (width 10 elements) started
  // at rest splits into two half pulses; the right one must reach a node 200 elements
  // away after 200 l / c (peak time, within 1 %).
  const int N = 400, start = 100, probe = 300;
  const double l = 0.01, k_elo = 4.0, rho = 1.0, m = rho * l;
  const double c = l * std::sqrt((k_elo / l) / m);
  ChainModel model;
  model.topology = open_chain_topology(N + 1, l);
  model.axial = {k_elo, true};
  std::vector<Vec3> x(N + 1);
  const double amplitude = 1e-4 * l, width = 10 * l;
  for (int i = 0; i <= N; ++i) {
    const double d = (i - start) * l;
    x[i] = Vec3(i * l + amplitude * std::exp(-0.5 * d * d / (width * width)), 0, 0);
  }
  const double dt = 0.05 / (2 * std::sqrt(k_elo / l / m));
  WireNodeSet nodes;
  nodes.reset(x, m, dt);
  const auto coeff = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  GrainForceAccumulator none;
  none.reset(0);
  const SubcyclePlan one_step{1, dt};
  double best = -1, t_best = 0, t = 0;
  double previous[2] = {0, 0};    // displacement at the probe, two steps back
  const double t_end = 1.5 * (probe - start) * l / c;
  while (t < t_end) {
    run_subcycle(one_step, coeff, nodes, none,
                 [&](const SubstepInfo &, const std::vector<Vec3> &xp, const std::vector<Vec3> &vp,
                     std::vector<Vec3> &f, GrainForceAccumulator &) { chain_forces(model, nodes, xp, vp, f); });
    t += dt;
    const double u = nodes.state[probe].position().x() - probe * l;
    // Peak of u(t): parabola through the last three samples when the middle one is highest.
    if (previous[1] > previous[0] && previous[1] >= u && previous[1] > best) {
      best = previous[1];
      const double denom = previous[0] - 2 * previous[1] + u;
      t_best = t - dt + (denom != 0 ? 0.5 * dt * (previous[0] - u) / denom : 0.0);
    }
    previous[0] = previous[1];
    previous[1] = u;
  }
  const double expected = (probe - start) * l / c;
  std::printf("[wave] c = %.4f, arrival %.5f expected %.5f (rel. err %.2e), peak %.3f of half amplitude\n",
              c, t_best, expected, t_best / expected - 1, best / (0.5 * amplitude));
  EXPECT_NEAR(t_best / expected, 1.0, 0.01);
  EXPECT_NEAR(best / (0.5 * amplitude), 1.0, 0.05);    // half the initial bump, little dispersion
}

namespace {

// Runs a free chain of 60 nodes, slightly randomised, at dt = factor * bound for 20000
// steps; returns the fastest node speed of the last 2000 steps over that of steps
// 1000..3000: about 1 or less while stable, large when a mode grows.
double chain_speed_growth(double k_elo, double k_rot, double factor)
{
  const int n = 60;
  const double l = 0.1, m = 0.02;
  ChainModel model;
  model.topology = open_chain_topology(n, l);
  model.axial = {k_elo, true};
  model.k_rot = k_rot;
  std::mt19937 rng(3);
  std::normal_distribution<double> jitter(0.0, 1e-4 * l);
  std::vector<Vec3> x(n);
  for (int i = 0; i < n; ++i) x[i] = Vec3(i * l + jitter(rng), jitter(rng), jitter(rng));
  WireStiffness w;
  w.node_mass = m;
  w.element_length = l;
  w.k_elo = k_elo;
  w.k_rot = k_rot;
  const double dt = factor * max_stable_wire_step(w, GearCorrector::ThreeSixteenths, 1.0);
  WireNodeSet nodes;
  nodes.reset(x, m, dt);
  GrainForceAccumulator none;
  none.reset(0);
  const auto coeff = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  double early = 0, late = 0;
  for (int block = 0; block < 20; ++block) {
    run_subcycle(SubcyclePlan{1000, dt}, coeff, nodes, none,
                 [&](const SubstepInfo &, const std::vector<Vec3> &xp, const std::vector<Vec3> &vp,
                     std::vector<Vec3> &f, GrainForceAccumulator &) { chain_forces(model, nodes, xp, vp, f); });
    double fastest = 0;
    for (const Vec3 &v : nodes.velocities) fastest = std::max(fastest, v.norm());
    if (!std::isfinite(fastest)) return fastest;
    if (block == 1 || block == 2) early = std::max(early, fastest);
    if (block >= 18) late = std::max(late, fastest);
  }
  return late / early;
}

}    // namespace

TEST(WireDynamics, StepBoundIsSafeAndTightForAxialAndBendingModes)
{
  // The Gershgorin bound is the highest frequency of an infinite chain, so a 60-node chain
  // must run at the bound (speeds do not grow by 50 %) and blow up 60 % above it, where
  // the highest mode's amplification 1 + 1.9e-4 per step grows it ~20-fold in 17000 steps.
  struct Case { double k_elo, k_rot; };
  for (const Case &c : {Case{10.0, 0.0}, Case{0.1, 0.05}}) {    // axial, bending dominated
    const double at_bound = chain_speed_growth(c.k_elo, c.k_rot, 1.0);
    const double above = chain_speed_growth(c.k_elo, c.k_rot, 1.6);
    std::printf("[step bound] k_elo=%g k_rot=%g: speed growth %.3f at the bound, %.3g at 1.6x\n",
                c.k_elo, c.k_rot, at_bound, above);
    EXPECT_LT(at_bound, 1.5);
    EXPECT_GT(above, 3.0);
  }
}

TEST(WireDynamics, FreeUndampedChainKeepsItsEnergyAtTheChosenSubstepCount)
{
  // The papers' wire (examples/column: k_elo 5000 on elements of 0.2, nodes of 0.005, k_rot
  // 0.01 and 1; its contacts, k_n 2000 and gamma_n 2, count in the bound though none acts
  // here) as a free chain of 100 nodes, every mode excited by a random start, run for 10^5
  // substeps at the substep count fix wire chooses for dt = 0.005. Undamped, the total
  // energy must never grow by more than 1 %. (It falls: corrector 3/16 damps the highest
  // modes, near w dt = 0.28, which the random start excites; 6-11 % in 10^5 substeps.)
  for (double k_rot : {0.01, 1.0}) {
    const int n = 100;
    const double l = 0.2, m = 0.005;
    ChainModel model;
    model.topology = open_chain_topology(n, l);
    model.axial = {5000.0, true};
    model.k_rot = k_rot;
    std::mt19937 rng(11);
    std::normal_distribution<double> jitter(0.0, 0.01 * l);
    std::vector<Vec3> x(n);
    for (int i = 0; i < n; ++i) x[i] = Vec3(i * l + jitter(rng), jitter(rng), jitter(rng));
    WireStiffness w;
    w.node_mass = m;
    w.element_length = l;
    w.k_elo = 5000.0;
    w.k_rot = k_rot;
    w.k_n = 2000.0;
    w.gamma_contact = 2.0;
    w.contacts_per_node = 2.0;    // fix wire's default
    const SubcyclePlan plan = plan_subcycle(0.005, max_stable_wire_step(w));
    WireNodeSet nodes;
    nodes.reset(x, m, plan.dt_sp);
    GrainForceAccumulator none;
    none.reset(0);
    const auto coeff = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
    auto energy = [&]() {
      std::vector<Vec3> positions(n), f(n, Vec3::Zero());
      double kinetic = 0.0;
      for (int i = 0; i < n; ++i) {
        positions[i] = nodes.state[i].position();
        kinetic += 0.5 * m * nodes.state[i].velocity(plan.dt_sp).squaredNorm();
      }
      const ElasticEnergy e = add_elastic_forces(model.topology, model.axial, model.k_rot, positions, f);
      return kinetic + e.axial + e.bending;
    };
    const double start = energy();
    double highest = start;
    for (int block = 0; block < 100; ++block) {
      run_subcycle(SubcyclePlan{1000, plan.dt_sp}, coeff, nodes, none,
                   [&](const SubstepInfo &, const std::vector<Vec3> &xp, const std::vector<Vec3> &vp,
                       std::vector<Vec3> &f, GrainForceAccumulator &) { chain_forces(model, nodes, xp, vp, f); });
      highest = std::max(highest, energy());
    }
    std::printf("[free chain] k_rot %g: %d substeps per step of 0.005; energy %.6g -> %.6g after 1e5 substeps "
                "(highest %.6g)\n", k_rot, plan.substeps, start, energy(), highest);
    EXPECT_EQ(plan.substeps, 83);
    EXPECT_LT(highest, 1.01 * start);
  }
}
