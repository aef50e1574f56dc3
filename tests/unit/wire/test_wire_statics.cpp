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

// Wire statics by damped dynamic relaxation through the Gear subcycle: a chain pulled at one
// end, a cantilever under a tip load, a chain hanging between two supports.
#include "wire/stability.h"
#include "wire_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace nscd;
using namespace nscd::wire;
using namespace nscd::wire::test;

namespace {

WireNodeSet straight_chain(int num_elements, double l, double node_mass, double dt)
{
  std::vector<Vec3> x(num_elements + 1);
  for (int i = 0; i <= num_elements; ++i) x[i] = Vec3(i * l, 0, 0);
  WireNodeSet nodes;
  nodes.reset(x, node_mass, dt);
  return nodes;
}

struct CantileverResult {
  double deflection;      // measured tip deflection
  double discrete;        // closed form of the discrete linear beam
  double continuum_eff;   // F L^3 / 3EI with L = (N - 1/2) l
  double continuum_full;  // F L^3 / 3EI with L = N l
};

// N elements of length l = 1/N (unit total length), nodes 0 and 1 clamped, EI = 1,
// k_rot = EI / l, unit mass per length, transverse tip load F.
CantileverResult cantilever(int N)
{
  const double L = 1.0, l = L / N, EI = 1.0, F = 1e-3;
  ChainModel model;
  model.topology = open_chain_topology(N + 1, l);
  model.axial = {1e3, true};
  model.k_rot = EI / l;
  model.external.assign(N + 1, Vec3::Zero());
  model.external[N] = Vec3(0, F, 0);
  const double m = l;
  const double omega_1 = 3.516 * std::sqrt(EI / (1.0 * L * L * L * L));    // first bending mode
  model.drag = 2.0 * m * omega_1;                                          // critical for mode 1
  WireStiffness w;
  w.node_mass = m;
  w.element_length = l;
  w.k_elo = model.axial.k_elo;
  w.k_rot = model.k_rot;
  w.node_damping = model.drag;
  const double dt = max_stable_wire_step(w, GearCorrector::ThreeSixteenths, 0.8);
  WireNodeSet nodes = straight_chain(N, l, m, dt);
  nodes.fixed[0] = nodes.fixed[1] = 1;
  const double residual = relax(model, nodes, dt, 1e-7 * F, 2'000'000);
  EXPECT_LT(residual, 1e-7 * F) << "N=" << N << " did not settle";

  // Discrete linear beam: node j carries moment F (N - j) l, angle M / k_rot; the tip
  // deflects by sum_j nu_j (N - j) l = F l^3 / EI * sum_{m=1}^{N-1} m^2.
  const double sum_m2 = (N - 1.0) * N * (2.0 * N - 1.0) / 6.0;
  CantileverResult r;
  r.deflection = nodes.state[N].position().y();
  r.discrete = F * l * l * l / EI * sum_m2;
  r.continuum_eff = F * std::pow((N - 0.5) * l, 3) / (3 * EI);
  r.continuum_full = F * std::pow(L, 3) / (3 * EI);
  return r;
}

}    // namespace

TEST(WireStatics, ChainPulledAtOneEndStretchesAsKeloPredicts)
{
  // 10 elements, node 0 fixed, force P on the last node: every element carries tension P,
  // strain P / k_elo, total elongation N L0 P / k_elo (to 1e-6 relative).
  const int N = 10;
  const double L0 = 0.1, k_elo = 100.0, m = 0.01, P = 2.0;
  ChainModel model;
  model.topology = open_chain_topology(N + 1, L0);
  model.axial = {k_elo, true};
  model.k_rot = 0.5;
  model.external.assign(N + 1, Vec3::Zero());
  model.external[N] = Vec3(P, 0, 0);
  const double omega_1 = M_PI / (2 * N) * 2 * std::sqrt(k_elo / L0 / m);    // ~ lowest axial mode
  model.drag = 2 * m * omega_1;
  WireNodeSet nodes = straight_chain(N, L0, m, 1e-4);
  nodes.fixed[0] = 1;
  ASSERT_LT(relax(model, nodes, 1e-4, 1e-10 * P, 1'000'000), 1e-10 * P);

  for (const WireElement &e : model.topology.elements) {
    const AxialForces f = axial_element_forces(model.axial, L0, nodes.state[e.a].position(),
                                               nodes.state[e.b].position());
    EXPECT_NEAR(f.tension / P, 1.0, 1e-6);
    EXPECT_NEAR(f.strain / (P / k_elo), 1.0, 1e-6);
  }
  const double elongation = nodes.state[N].position().x() - N * L0;
  EXPECT_NEAR(elongation / (N * L0 * P / k_elo), 1.0, 1e-6);
}

TEST(WireStatics, CantileverConvergesToBeamTheory)
{
  // Measured tip deflection vs (a) the discrete beam's closed form (1e-4 relative: the
  // load is small, delta/L ~ 3e-4, so geometric and axial effects are ~1e-7);
  // (b) F L^3 / 3EI with the clamp half-way between the two fixed nodes, L = (N - 1/2) l:
  // error N(N-1)/(N-1/2)^2 - 1 ~ -1/(4N^2), second order; (c) F L^3 / 3EI with L = N l,
  // the full wire length: error ~ -3/(2N), first order.
  std::printf("[cantilever]   N   delta/delta_discrete   err vs L=(N-1/2)l   err vs L=Nl\n");
  double previous_eff = 0, previous_full = 0;
  for (int N : {10, 20, 40}) {
    const CantileverResult r = cantilever(N);
    const double err_eff = r.deflection / r.continuum_eff - 1.0;
    const double err_full = r.deflection / r.continuum_full - 1.0;
    std::printf("[cantilever] %3d   %.8f             %+.3e          %+.3e\n", N,
                r.deflection / r.discrete, err_eff, err_full);
    EXPECT_NEAR(r.deflection / r.discrete, 1.0, 1e-4) << N;
    if (N == 40) {
      EXPECT_LT(std::abs(err_eff), 2e-4);
      EXPECT_LT(std::abs(err_full), 0.04);
    }
    if (previous_eff != 0) {
      EXPECT_NEAR(std::log2(previous_eff / err_eff), 2.0, 0.1) << N;      // second order
      EXPECT_NEAR(std::log2(previous_full / err_full), 1.0, 0.15) << N;   // first order
    }
    previous_eff = err_eff;
    previous_full = err_full;
  }
}

TEST(WireStatics, HangingChainSettlesToCatenary)
{
  // A string of length S = 2 (40 elements, unit mass per length, g = 1, stiff k_elo = 1e5,
  // no bending) hung between supports 2a = 1.6 apart, released from a V shape. The
  // inextensible catenary z = c cosh(x/c) - c cosh(a/c) has S/2 = c sinh(a/c) and horizontal
  // tension H = rho g c. Tolerances: node positions within 0.5 % of the sag, H within 0.5 %
  // (discretisation O(1/N^2) with lumped node masses plus stretch strain ~1e-5).
  const int N = 40;
  const double S = 2.0, a = 0.8, l = S / N, g = 1.0, rho = 1.0;
  ChainModel model;
  model.topology = open_chain_topology(N + 1, l);
  model.axial = {1e5, false};
  model.gravity = Vec3(0, 0, -g);
  model.drag = 2 * rho * l * 2.0;    // ~ critical for the swing mode (omega ~ 2)
  // V shape: each half a straight line of length S/2 from a support down to the middle.
  const double drop = std::sqrt(0.25 * S * S - a * a);
  std::vector<Vec3> x(N + 1);
  for (int i = 0; i <= N; ++i) {
    const double s = i * l, t = std::min(s, S - s) / (0.5 * S);
    x[i] = Vec3(-a + 2 * a * s / S, 0, -drop * t);
  }
  WireStiffness w;
  w.node_mass = rho * l;
  w.element_length = l;
  w.k_elo = model.axial.k_elo;
  w.node_damping = model.drag;
  const double dt = max_stable_wire_step(w, GearCorrector::ThreeSixteenths, 0.8);
  WireNodeSet nodes;
  nodes.reset(x, rho * l, dt);
  nodes.fixed[0] = nodes.fixed[N] = 1;
  const double weight = rho * l * g;
  ASSERT_LT(relax(model, nodes, dt, 1e-7 * weight, 2'000'000), 1e-7 * weight);

  // Catenary parameter: solve c sinh(a/c) = S/2 by bisection.
  double lo = 0.05, hi = 10.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::sinh(a / mid) > 0.5 * S ? lo : hi) = mid;
  }
  const double c = 0.5 * (lo + hi);
  const double sag = c * std::cosh(a / c) - c;
  double worst = 0;
  for (int i = 0; i <= N; ++i) {
    const double sigma = i * l - 0.5 * S;    // arclength from the lowest point
    const double xc = c * std::asinh(sigma / c);
    const Vec3 expected(xc, 0, c * std::cosh(xc / c) - c * std::cosh(a / c));
    worst = std::max(worst, (nodes.state[i].position() - expected).norm());
  }
  const AxialForces end = axial_element_forces(model.axial, l, nodes.state[0].position(),
                                               nodes.state[1].position());
  const double H = end.tension * (nodes.state[1].position() - nodes.state[0].position()).normalized().x();
  std::printf("[catenary] c = %.6f sag = %.6f, max position error / sag = %.3e, H/(rho g c) - 1 = %.3e\n",
              c, sag, worst / sag, H / (rho * g * c) - 1);
  EXPECT_LT(worst / sag, 5e-3);
  EXPECT_NEAR(H / (rho * g * c), 1.0, 5e-3);
}
