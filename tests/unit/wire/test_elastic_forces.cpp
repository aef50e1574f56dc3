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

// Axial and bending kernels: forces are -dE/dx (central finite differences), sum to zero
// and carry no torque, including the near-straight and near-folded limits.
#include "wire/elastic_forces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

using namespace nscd;
using namespace nscd::wire;

namespace {

template <std::size_t N>
using Nodes = std::array<Vec3, N>;

// Central-difference gradient of energy(nodes) with respect to node i, step h.
template <std::size_t N>
Vec3 numerical_gradient(const std::function<double(const Nodes<N> &)> &energy, Nodes<N> nodes,
                        std::size_t i, double h)
{
  Vec3 g;
  for (int d = 0; d < 3; ++d) {
    const double x0 = nodes[i][d];
    nodes[i][d] = x0 + h;
    const double ep = energy(nodes);
    nodes[i][d] = x0 - h;
    const double em = energy(nodes);
    nodes[i][d] = x0;
    g[d] = (ep - em) / (2 * h);
  }
  return g;
}

Vec3 random_vector(std::mt19937 &rng, double scale = 1.0)
{
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

Nodes<3> bent_nodes(double angle, double l1, double l2)
{
  // a->b along x, b->c turned by `angle` in a tilted plane (not axis-aligned on purpose).
  const Quat tilt(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  const Vec3 a = tilt * Vec3(-l1, 0, 0);
  const Vec3 b = tilt * Vec3(0, 0, 0) + Vec3(0.1, -0.2, 0.3);
  const Vec3 c = b + tilt * Vec3(l2 * std::cos(angle), l2 * std::sin(angle), 0);
  return {a + Vec3(0.1, -0.2, 0.3), b, c};
}

}    // namespace

TEST(AxialElement, EnergyAndForceMatchClosedForm)
{
  const AxialLaw law{250.0, true};
  const double l0 = 0.4;
  const Vec3 a(0, 0, 0), b(0.5, 0, 0);    // strain 0.25
  const AxialForces f = axial_element_forces(law, l0, a, b);
  EXPECT_NEAR(f.strain, 0.25, 1e-15);
  EXPECT_NEAR(f.tension, 250.0 * 0.25, 1e-12);
  EXPECT_NEAR(f.energy, 0.5 * 250.0 * 0.4 * 0.25 * 0.25, 1e-12);
  EXPECT_NEAR((f.on_b - Vec3(-62.5, 0, 0)).norm(), 0.0, 1e-12);    // pulled back towards a
  EXPECT_NEAR((f.on_a + f.on_b).norm(), 0.0, 1e-15);
}

TEST(AxialElement, ForceIsMinusEnergyGradient)
{
  std::mt19937 rng(7);
  for (bool resists : {true, false}) {
    const AxialLaw law{3.0, resists};
    for (int trial = 0; trial < 50; ++trial) {
      Nodes<2> x{random_vector(rng), random_vector(rng)};
      const double l0 = (x[1] - x[0]).norm() * (trial % 2 ? 0.8 : 1.25);    // stretched or compressed
      const auto energy = [&](const Nodes<2> &y) { return axial_element_forces(law, l0, y[0], y[1]).energy; };
      const AxialForces f = axial_element_forces(law, l0, x[0], x[1]);
      const double scale = std::max(1.0, f.on_a.norm());
      EXPECT_LT((f.on_a + numerical_gradient<2>(energy, x, 0, 1e-6)).norm(), 1e-7 * scale);
      EXPECT_LT((f.on_b + numerical_gradient<2>(energy, x, 1, 1e-6)).norm(), 1e-7 * scale);
    }
  }
}

TEST(AxialElement, StringCarriesNoCompression)
{
  const AxialLaw string{100.0, false};
  const AxialForces slack = axial_element_forces(string, 1.0, Vec3::Zero(), Vec3(0.9, 0, 0));
  EXPECT_DOUBLE_EQ(slack.tension, 0.0);
  EXPECT_DOUBLE_EQ(slack.energy, 0.0);
  EXPECT_DOUBLE_EQ(slack.on_a.norm(), 0.0);
  EXPECT_NEAR(slack.strain, -0.1, 1e-15);
  const AxialForces rod = axial_element_forces({100.0, true}, 1.0, Vec3::Zero(), Vec3(0.9, 0, 0));
  EXPECT_NEAR(rod.tension, -10.0, 1e-12);
  EXPECT_NEAR(rod.on_b.x(), 10.0, 1e-12);    // a compressed rod pushes b away from a
}

TEST(AxialElement, BadInputNamesTheProblem)
{
  const AxialLaw law{1.0, true};
  EXPECT_THROW(axial_element_forces(law, 0.0, Vec3::Zero(), Vec3::UnitX()), std::invalid_argument);
  try {
    axial_element_forces(law, 1.0, Vec3::UnitX(), Vec3::UnitX());
    FAIL() << "coincident nodes accepted";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("coincide"), std::string::npos) << e.what();
  }
}

TEST(NodeAngle, AgreesWithAtan2ToRoundOffOverTheWholeRange)
{
  // The polynomial arctangent against glibc's atan2 (correctly rounded in practice): over
  // random angles in [0, pi] at scales 1e-3..1e3, dense around the branch points pi/8,
  // pi/4, 3 pi/4, and at the ends. Measured: at most 2 units in the last place (one from
  // the polynomial, the rest from the division and the reduction to |y| <= tan(pi/8)).
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> angle(0.0, M_PI), log_scale(-3.0, 3.0);
  std::vector<double> angles;
  for (int k = 0; k < 200000; ++k) angles.push_back(angle(rng));
  for (double centre : {M_PI / 8, M_PI / 4, 3 * M_PI / 4, M_PI / 2})
    for (int k = -1000; k <= 1000; ++k) angles.push_back(centre + k * 1e-15);
  for (double a : {0.0, 1e-300, 1e-20, 1e-8, M_PI - 1e-8, M_PI}) angles.push_back(a);
  double worst = 0.0;
  for (double a : angles) {
    const double r = std::pow(10.0, log_scale(rng));
    const double s = std::abs(r * std::sin(a)), c = r * std::cos(a);
    const double exact = std::atan2(s, c), ours = angle_from_sine_cosine(s, c);
    if (exact == 0.0) {
      EXPECT_EQ(ours, 0.0) << s << " " << c;
      continue;
    }
    worst = std::max(worst, std::abs(ours - exact) / (std::nextafter(exact, 4.0) - exact));
  }
  EXPECT_LE(worst, 2.0) << "units in the last place";
  std::printf("node angle vs atan2: largest difference %.0f units in the last place\n", worst);
  EXPECT_EQ(angle_from_sine_cosine(0.0, 0.0), 0.0);
  EXPECT_EQ(angle_from_sine_cosine(0.0, -1.0), std::atan2(0.0, -1.0));
  EXPECT_EQ(angle_from_sine_cosine(1.0, 0.0), std::atan2(1.0, 0.0));
  EXPECT_TRUE(std::isnan(angle_from_sine_cosine(std::nan(""), 1.0)));
  EXPECT_TRUE(std::isnan(angle_from_sine_cosine(1.0, std::nan(""))));
}

TEST(BendingNode, AngleAndEnergyMatchClosedForm)
{
  const double k_rot = 2.5;
  for (double angle : {0.0, 1e-9, 1e-3, 0.5, 1.5, 3.0, M_PI - 1e-6}) {
    const Nodes<3> x = bent_nodes(angle, 0.7, 1.3);
    const BendingForces f = bending_node_forces(k_rot, x[0], x[1], x[2]);
    EXPECT_NEAR(f.angle, angle, 1e-9 + 1e-12 * angle) << angle;
    EXPECT_NEAR(f.energy, 0.5 * k_rot * angle * angle, 1e-9) << angle;
    // Moment balance: the force on c times its arm is the moment k_rot * nu.
    EXPECT_NEAR(f.on_c.norm() * 1.3, k_rot * angle, 1e-8 * (1 + angle)) << angle;
  }
}

TEST(BendingNode, ForceIsMinusEnergyGradientFromStraightToFolded)
{
  const double k_rot = 1.7;
  // FD with step h has error ~h^2 E'''; near nu = pi the energy has a cusp, so keep the
  // configuration at least 1e-3 from it for the FD check (the no-NaN check goes closer).
  for (double angle : {1e-7, 1e-4, 0.01, 0.3, 1.0, 2.0, 2.9, M_PI - 1e-3}) {
    const Nodes<3> x = bent_nodes(angle, 0.9, 1.1);
    const auto energy = [&](const Nodes<3> &y) { return bending_node_forces(k_rot, y[0], y[1], y[2]).energy; };
    const BendingForces f = bending_node_forces(k_rot, x[0], x[1], x[2]);
    const double h = 1e-7;
    const double tol = 2e-6 * k_rot;
    EXPECT_LT((f.on_a + numerical_gradient<3>(energy, x, 0, h)).norm(), tol) << "nu=" << angle;
    EXPECT_LT((f.on_b + numerical_gradient<3>(energy, x, 1, h)).norm(), tol) << "nu=" << angle;
    EXPECT_LT((f.on_c + numerical_gradient<3>(energy, x, 2, h)).norm(), tol) << "nu=" << angle;
  }
}

TEST(BendingNode, FiniteForcesAtStraightAndFoldedLimits)
{
  for (double angle : {0.0, 1e-300, M_PI - 1e-12, M_PI - 1e-15}) {
    const Nodes<3> x = bent_nodes(angle, 1.0, 1.0);
    const BendingForces f = bending_node_forces(1.0, x[0], x[1], x[2]);
    for (const Vec3 &v : {f.on_a, f.on_b, f.on_c}) EXPECT_TRUE(v.allFinite()) << angle;
    EXPECT_LE(f.on_a.norm(), angle + 1e-6);    // |F_a| = k nu / l
  }
  // Exactly folded back onto itself: symmetric, zero force, finite energy.
  const BendingForces folded = bending_node_forces(1.0, Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(2, 0, 0));
  EXPECT_NEAR(folded.angle, M_PI, 1e-15);
  EXPECT_TRUE(folded.on_a.allFinite() && folded.on_c.allFinite());
  EXPECT_NEAR(folded.energy, 0.5 * M_PI * M_PI, 1e-12);
}

TEST(BendingNode, RestTurnShiftsTheLawAndStaysMinusTheGradient)
{
  // With a turn nu0 at rest the moment is k_rot (nu - nu0) and the energy k_rot (nu - nu0)^2 / 2:
  // zero force at nu = nu0 (a loop laid at its rest curvature holds its shape), a force
  // bending the joint further below nu0 and straightening it above, always -grad E.
  const double k_rot = 1.3;
  for (double rest : {0.05, 0.3, 1.1}) {
    const Nodes<3> at_rest = bent_nodes(rest, 0.8, 1.2);
    const BendingForces held = bending_node_forces(k_rot, at_rest[0], at_rest[1], at_rest[2], rest);
    EXPECT_NEAR(held.angle, rest, 1e-12);
    EXPECT_LT(held.on_a.norm() + held.on_c.norm(), 1e-12 * k_rot) << "nu0=" << rest;
    EXPECT_LT(held.energy, 1e-24);
    for (double angle : {1e-4, 0.5 * rest, 2.0 * rest, 2.5, M_PI - 1e-3}) {
      const Nodes<3> x = bent_nodes(angle, 0.8, 1.2);
      const BendingForces f = bending_node_forces(k_rot, x[0], x[1], x[2], rest);
      EXPECT_NEAR(f.energy, 0.5 * k_rot * (angle - rest) * (angle - rest), 1e-9) << angle;
      EXPECT_NEAR(f.on_c.norm() * 1.2, k_rot * std::abs(angle - rest), 1e-8) << angle;    // moment balance
      const auto energy = [&](const Nodes<3> &y) { return bending_node_forces(k_rot, y[0], y[1], y[2], rest).energy; };
      const double h = 1e-7, tol = 2e-6 * k_rot;
      EXPECT_LT((f.on_a + numerical_gradient<3>(energy, x, 0, h)).norm(), tol) << "nu=" << angle << " nu0=" << rest;
      EXPECT_LT((f.on_b + numerical_gradient<3>(energy, x, 1, h)).norm(), tol) << "nu=" << angle << " nu0=" << rest;
      EXPECT_LT((f.on_c + numerical_gradient<3>(energy, x, 2, h)).norm(), tol) << "nu=" << angle << " nu0=" << rest;
      EXPECT_LT((f.on_a + f.on_b + f.on_c).norm(), 1e-12);
    }
  }
  // Straight exactly: the cone's tip, every plane as good: zero force, the energy k nu0^2 / 2.
  const BendingForces straight = bending_node_forces(1.0, Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), 0.4);
  EXPECT_EQ(straight.on_a.norm() + straight.on_c.norm(), 0.0);
  EXPECT_NEAR(straight.energy, 0.08, 1e-15);
}

TEST(ElasticForces, MomentumAndAngularMomentumConservedOnRandomWires)
{
  // A random crooked 12-node wire: the sum of forces and of torques about an arbitrary
  // point vanish to round-off, for every element and every joint together.
  std::mt19937 rng(2024);
  const WireTopology topology = open_chain_topology(12, 0.5);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3> x(12);
    x[0] = random_vector(rng);
    for (int i = 1; i < 12; ++i) x[i] = x[i - 1] + random_vector(rng, 0.4) + Vec3(0.2, 0, 0);
    std::vector<Vec3> f(12, Vec3::Zero());
    const ElasticEnergy e = add_elastic_forces(topology, {40.0, true}, 3.0, x, f);
    Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
    double scale = 0;
    const Vec3 origin = random_vector(rng, 5.0);
    for (int i = 0; i < 12; ++i) {
      total += f[i];
      torque += (x[i] - origin).cross(f[i]);
      scale = std::max(scale, f[i].norm() * (x[i] - origin).norm());
    }
    EXPECT_GT(e.axial, 0.0);
    EXPECT_GT(e.bending, 0.0);
    EXPECT_LT(total.norm(), 1e-12 * scale);
    EXPECT_LT(torque.norm(), 1e-12 * scale);
  }
}

namespace {

// A random wire of several chains in a shuffled, partly reversed and partly regular layout,
// with every kind of element and joint add_elastic_forces handles: springs and strings
// (slack and taut), k_rot 0, bends above pi/8 and below 1e-6, an element closing a ring,
// elements to copies of nodes, a doubled element.
WireTopology mixed_topology(std::mt19937 &rng, int chains, std::vector<Vec3> &x)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  WireTopology t;
  x.clear();
  for (int k = 0; k < chains; ++k) {
    const int first = static_cast<int>(x.size());
    const int n = 2 + static_cast<int>(u(rng) * 14);    // 2 .. 15 nodes: every tail of four
    Vec3 p = random_vector(rng, 3.0), dir = random_vector(rng).normalized();
    for (int i = 0; i < n; ++i) {
      x.push_back(p);
      const double r = u(rng);
      if (r < 0.15) dir = (dir + random_vector(rng, 1.5)).normalized();                 // sharp bend
      else if (r < 0.3) dir = dir;                                                      // straight on
      else dir = (dir + random_vector(rng, 0.05)).normalized();
      p += (0.05 + 0.02 * u(rng)) * dir;
      if (r >= 0.15 && r < 0.3 && u(rng) < 0.5) p += 1e-9 * random_vector(rng);       // bend below 1e-6
    }
    for (int i = 0; i + 1 < n; ++i) {
      const double r = u(rng);
      AxialLaw law{20.0 + 10.0 * u(rng), r > 0.2};    // a string now and then
      const double rest = (r < 0.1 ? 1.2 : 0.9) * (x[first + i + 1] - x[first + i]).norm();    // slack or taut
      if (u(rng) < 0.1) t.elements.push_back({first + i + 1, first + i, rest, law});        // reversed
      else t.elements.push_back({first + i, first + i + 1, rest, law});
    }
    for (int i = 1; i + 1 < n; ++i) {
      const double k_rot = u(rng) < 0.1 ? 0.0 : 0.01 + 0.01 * u(rng);
      const double rest_turn = u(rng) < 0.3 ? 0.4 * u(rng) : 0.0;    // some bent at rest
      if (u(rng) < 0.1) t.joints.push_back({first + i + 1, first + i, first + i - 1, k_rot, rest_turn});    // reversed
      else t.joints.push_back({first + i - 1, first + i, first + i + 1, k_rot, rest_turn});
    }
    if (n > 3 && u(rng) < 0.3) {    // a ring
      t.elements.push_back({first + n - 1, first, 0.06, AxialLaw{30.0, true}});
      t.joints.push_back({first + n - 2, first + n - 1, first, 0.01});
    }
  }
  const int owned = static_cast<int>(x.size());
  for (int copy = 0; copy < 3; ++copy) {    // copies of nodes (ghost atoms): an element to each
    const int of = static_cast<int>(u(rng) * owned);
    x.push_back(x[of] + Vec3(0.05, 0.0, 0.0));
    t.elements.push_back({of, owned + copy, 0.05, AxialLaw{25.0, true}});
  }
  t.elements.push_back(t.elements[static_cast<std::size_t>(u(rng) * t.elements.size())]);    // doubled
  // Mostly in order (as fix wire lists them), with a few swaps.
  std::stable_sort(t.elements.begin(), t.elements.end(), [](const auto &p, const auto &q) { return p.a < q.a; });
  std::stable_sort(t.joints.begin(), t.joints.end(), [](const auto &p, const auto &q) { return p.b < q.b; });
  for (int s = 0; s < 2; ++s) {
    std::swap(t.elements[static_cast<std::size_t>(u(rng) * t.elements.size())], t.elements.back());
    if (!t.joints.empty()) std::swap(t.joints[static_cast<std::size_t>(u(rng) * t.joints.size())], t.joints.front());
  }
  return t;
}

}    // namespace

TEST(ElasticKernel, EqualsAddElasticForcesToTheLastBit)
{
  // The prepared kernel must give add_elastic_forces' forces and energies exactly (same
  // operations, same order of summation per node), on plain chains and on every irregular
  // case, added to forces already there; its energy only when asked.
  std::mt19937 rng(77);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> x;
    const WireTopology t = trial % 4 == 0 ? open_chain_topology(3 + trial % 37, 0.05) : mixed_topology(rng, 1 + trial % 5, x);
    if (trial % 4 == 0) {
      x.resize(3 + trial % 37);
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = Vec3(0.049 * i, 0.01 * std::sin(0.7 * i), 0.003 * i * i);
    }
    std::vector<Vec3> expected(x.size()), got(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) expected[i] = got[i] = random_vector(rng, 1e-3);
    std::vector<Vec3> got_without_energy = got;
    const ElasticEnergy e = add_elastic_forces(t, x, expected);
    ElasticKernel kernel;
    kernel.prepare(t);
    ASSERT_TRUE(kernel.prepared_for(t));
    const ElasticEnergy k = kernel.add_forces(x, got, true);
    const ElasticEnergy none = kernel.add_forces(x, got_without_energy, false);
    EXPECT_EQ(k.axial, e.axial) << "trial " << trial;
    EXPECT_EQ(k.bending, e.bending) << "trial " << trial;
    EXPECT_EQ(none.total(), 0.0);
    for (std::size_t i = 0; i < x.size(); ++i)
      for (int d = 0; d < 3; ++d) {
        ASSERT_EQ(got[i][d], expected[i][d]) << "trial " << trial << " node " << i << " coordinate " << d;
        ASSERT_EQ(got_without_energy[i][d], expected[i][d]) << "trial " << trial << " node " << i;
      }
  }
}

TEST(ElasticKernel, PreparedForItsTopologyOnlyAndRefusesWhatAddElasticForcesRefuses)
{
  WireTopology t = open_chain_topology(6, 0.1);
  ElasticKernel kernel;
  kernel.prepare(t);
  EXPECT_TRUE(kernel.prepared_for(t));
  WireTopology other = t;
  other.joints[2].k_rot = 1.0;
  EXPECT_FALSE(kernel.prepared_for(other));
  other = t;
  other.joints[2].rest_turn = 0.1;
  EXPECT_FALSE(kernel.prepared_for(other));
  other = t;
  other.elements[1].law.resists_compression = false;
  EXPECT_FALSE(kernel.prepared_for(other));
  other = t;
  other.elements.pop_back();
  EXPECT_FALSE(kernel.prepared_for(other));

  std::vector<Vec3> x(6), f(6, Vec3::Zero());
  for (int i = 0; i < 6; ++i) x[i] = Vec3(0.1 * i, 0, 0);
  x[3] = x[2];    // a zero-length element
  EXPECT_THROW(kernel.add_forces(x, f, true), std::invalid_argument);
  EXPECT_THROW(add_elastic_forces(t, x, f), std::invalid_argument);
  x[3] = Vec3(0.3, 0, 0);
  std::vector<Vec3> too_few(5, Vec3::Zero());
  EXPECT_THROW(kernel.add_forces(x, too_few, true), std::invalid_argument);
  other = t;
  other.elements[0].rest_length = 0.0;
  EXPECT_THROW(kernel.prepare(other), std::invalid_argument);
}
