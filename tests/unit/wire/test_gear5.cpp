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

// Gear-5 predictor-corrector on the harmonic and damped oscillators: global order,
// long-run energy behaviour, and the stability limits (measured by bisection on runs).
#include "wire/elastic_forces.h"
#include "wire/gear5.h"
#include "wire/stability.h"
#include "wire/subcycle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

using namespace nscd;
using namespace nscd::wire;

namespace {

// x'' = -w^2 x - g x' with w = 1, started from x = 1, v = 0 with exact scaled derivatives
// (so the measured error is the method's, not the start's).
Gear5State exact_start(double dt, double g)
{
  double d[6] = {1.0, 0.0};
  for (int n = 0; n + 2 < 6; ++n) d[n + 2] = -d[n] - g * d[n + 1];
  Gear5State s;
  double scale = 1.0;
  for (int k = 0; k < 6; ++k) {
    s.r[k] = Vec3(d[k] * scale, 0, 0);
    scale *= dt / (k + 1);
  }
  return s;
}

double exact_position(double t, double g)
{
  const double z = g / 2, wd = std::sqrt(1 - z * z);
  return std::exp(-z * t) * (std::cos(wd * t) + z / wd * std::sin(wd * t));
}

void step(Gear5State &s, double dt, double g, const std::array<double, 6> &c)
{
  gear5_predict(s);
  const double x = s.r[0].x(), v = s.r[1].x() / dt;
  gear5_correct(s, Vec3(-x - g * v, 0, 0), dt, c);
}

// Max |x - x_exact| over t in [0, T].
double max_error(double dt, double T, double g, GearCorrector kind)
{
  const auto c = gear5_corrector_coefficients(kind);
  Gear5State s = exact_start(dt, g);
  const long n = std::lround(T / dt);
  double worst = 0;
  for (long i = 1; i <= n; ++i) {
    step(s, dt, g, c);
    worst = std::max(worst, std::abs(s.r[0].x() - exact_position(i * dt, g)));
  }
  return worst;
}

double observed_order(double dt, double T, double g, GearCorrector kind)
{
  return std::log2(max_error(dt, T, g, kind) / max_error(dt / 2, T, g, kind));
}

// Energy x^2 + v^2 (times 1/2) of the undamped oscillator: max over the last tenth of the
// run divided by max over its second tenth. > 1 means a growing mode. The start has r3..r5
// = 0, which seeds the parasitic modes of the method so that a growing one shows.
double energy_growth(double w_dt, double periods, double g_dt, GearCorrector kind)
{
  const auto c = gear5_corrector_coefficients(kind);
  const double dt = w_dt;    // w = 1
  Gear5State s = gear5_start(Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(-1, 0, 0), dt);
  const long n = std::lround(periods * 2 * M_PI / dt);
  double early = 0, late = 0;
  for (long i = 0; i < n; ++i) {
    step(s, dt, g_dt / dt, c);
    const double x = s.r[0].x(), v = s.r[1].x() / dt, e = x * x + v * v;
    if (!std::isfinite(e) || e > 1e6) return std::numeric_limits<double>::infinity();
    if (i > n / 10 && i < n / 5) early = std::max(early, e);
    if (i > n * 9 / 10) late = std::max(late, e);
  }
  return late / early;
}

// Speed growth of a free particle under pure drag x'' = -g x' (the physical solution
// decays by exp(-g t)): > 1 means the scheme amplifies.
double drag_growth(double g_dt)
{
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  const double dt = 1.0, g = g_dt;
  Gear5State s = gear5_start(Vec3::Zero(), Vec3(1, 0, 0), Vec3(-g, 0, 0), dt);
  double early = 0, late = 0;
  for (int i = 0; i < 4000; ++i) {
    gear5_predict(s);
    gear5_correct(s, -g * s.velocity(dt), dt, c);
    const double v = std::abs(s.velocity(dt).x());
    if (!std::isfinite(v)) return std::numeric_limits<double>::infinity();
    if (i == 100) early = v;
    if (i == 3999) late = v;
  }
  return late / early;
}

// Largest x in [lo, hi] with stable(x), by bisection (stable region assumed an interval).
template <class Stable>
double bisect_limit(double lo, double hi, Stable stable)
{
  for (int it = 0; it < 30; ++it) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

}    // namespace

TEST(Gear5, PredictorIsExactForQuinticPolynomials)
{
  // x(t) = t^5: the Taylor shift of the scaled derivatives is exact.
  const double dt = 0.3;
  Gear5State s;
  s.r[5] = Vec3(std::pow(dt, 5), 0, 0);    // dt^5/5! * 5! = dt^5, all lower derivatives 0 at t=0
  for (int i = 1; i <= 4; ++i) {
    gear5_predict(s);
    EXPECT_NEAR(s.r[0].x(), std::pow(i * dt, 5), 1e-12);
    EXPECT_NEAR(s.velocity(dt).x(), 5 * std::pow(i * dt, 4), 1e-11);
  }
}

TEST(Gear5, GlobalOrderOnOscillators)
{
  // Measured over 20 time units (~3 periods), halving dt from 0.04 to 0.02. Expected:
  // order 5 whenever the force depends on the velocity (both correctors); the undamped
  // oscillator is integrated to order 5 by 3/16 and to order 6 by 3/20.
  struct Case { double g; GearCorrector kind; double order; };
  for (const Case &c : {Case{0.0, GearCorrector::ThreeSixteenths, 5.0},
                        Case{0.0, GearCorrector::ThreeTwentieths, 6.0},
                        Case{0.2, GearCorrector::ThreeSixteenths, 5.0},
                        Case{0.2, GearCorrector::ThreeTwentieths, 5.0},
                        Case{1.0, GearCorrector::ThreeSixteenths, 5.0}}) {
    const double p = observed_order(0.04, 20.0, c.g, c.kind);
    std::printf("[gear5] g=%.1f c0=%s: observed order %.3f (error at dt=0.02: %.2e)\n", c.g,
                c.kind == GearCorrector::ThreeSixteenths ? "3/16" : "3/20", p,
                max_error(0.02, 20.0, c.g, c.kind));
    EXPECT_NEAR(p, c.order, 0.15);
  }
}

TEST(Gear5, LongRunEnergyDriftIsSmallAndOfKnownSign)
{
  // 1000 periods at w dt = 0.05 (126 steps per period). 3/16 loses energy slowly
  // (numerical damping), 3/20 gains slowly; both drift rates stay below 1e-7 per period.
  for (GearCorrector kind : {GearCorrector::ThreeSixteenths, GearCorrector::ThreeTwentieths}) {
    const auto c = gear5_corrector_coefficients(kind);
    const double dt = 0.05;
    Gear5State s = exact_start(dt, 0.0);
    const long n = std::lround(1000 * 2 * M_PI / dt);
    for (long i = 0; i < n; ++i) step(s, dt, 0.0, c);
    const double x = s.r[0].x(), v = s.velocity(dt).x();
    const double drift_per_period = (x * x + v * v - 1.0) / 1000;
    std::printf("[gear5] c0=%s: relative energy drift per period at w dt = 0.05: %.3e\n",
                kind == GearCorrector::ThreeSixteenths ? "3/16" : "3/20", drift_per_period);
    EXPECT_LT(std::abs(drift_per_period), 1e-7);
    if (kind == GearCorrector::ThreeSixteenths) {
      EXPECT_LT(drift_per_period, 0.0);
    } else {
      EXPECT_GT(drift_per_period, 0.0);
    }
  }
}

TEST(Gear5Stability, FrequencyLimitMatchesBisection)
{
  // Undamped: the largest w dt with no growing mode over 1000 periods, by bisection.
  const double limit = bisect_limit(0.05, 1.0, [](double w_dt) {
    return energy_growth(w_dt, 1000, 0.0, GearCorrector::ThreeSixteenths) <= 1.0;
  });
  std::printf("[gear5] measured stability limit (3/16, undamped): w dt = %.4f\n", limit);
  EXPECT_NEAR(limit, gear5_frequency_limit(GearCorrector::ThreeSixteenths), 0.003);
  EXPECT_GT(energy_growth(1.02 * limit, 1000, 0.0, GearCorrector::ThreeSixteenths), 1.0);

  // 3/20 amplifies an undamped oscillation even at w dt = 0.05, only just.
  const double growth = energy_growth(0.05, 1000, 0.0, GearCorrector::ThreeTwentieths);
  EXPECT_GT(growth, 1.0);
  EXPECT_LT(growth, 1.0 + 1e-5);
  // ...and stays usable at its documented practical limit: < 1 % growth in 1000 periods.
  EXPECT_LT(energy_growth(gear5_frequency_limit(GearCorrector::ThreeTwentieths), 1000, 0.0,
                          GearCorrector::ThreeTwentieths), 1.01);
}

TEST(Gear5Stability, DampingLimitMatchesBisection)
{
  const double limit = bisect_limit(0.01, 1.0, [](double g_dt) { return drag_growth(g_dt) <= 1.0; });
  std::printf("[gear5] measured stability limit for pure drag: g dt = %.4f\n", limit);
  EXPECT_NEAR(limit, gear5_damping_limit(), 0.002);
}

namespace {

// Largest |x| + |v| over the last half of n steps of x'' = -w^2 x - g x' (w = 1) at step dt,
// started at x = 1 at rest with r_3..r_5 = 0 (which seeds every parasitic mode).
double late_peak(double dt, double g, int n)
{
  Gear5State s = gear5_start(Vec3(1, 0, 0), Vec3::Zero(), Vec3(-1, 0, 0), dt);
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  double peak = 0;
  for (int i = 0; i < n; ++i) {
    step(s, dt, g, c);
    const double size = s.r[0].norm() + s.velocity(dt).norm();
    if (!std::isfinite(size)) return std::numeric_limits<double>::infinity();    // overflowed
    if (i > n / 2) peak = std::max(peak, size);
  }
  return peak;
}

}    // namespace

TEST(Gear5Stability, SpectralRadiusGivesTheMeasuredLimits)
{
  const auto kind = GearCorrector::ThreeSixteenths;
  // The eigenvalues of the step matrix put the edges where the runs above measured them.
  EXPECT_LT(gear5_spectral_radius(0.30, 0.0, kind), 1.0);
  EXPECT_GT(gear5_spectral_radius(0.32, 0.0, kind), 1.0);
  EXPECT_LT(gear5_spectral_radius(0.0, 0.160, kind), 1.0);
  EXPECT_GT(gear5_spectral_radius(0.0, 0.166, kind), 1.0);
  // A little damping stabilises frequencies far above the undamped limit; heavy damping
  // narrows the range (the table in doc/Howto_nscd_wire_model.rst).
  EXPECT_LT(gear5_spectral_radius(0.70, 0.02, kind), 1.0);
  EXPECT_GT(gear5_spectral_radius(0.35, 0.15, kind), 1.0);
  // And runs agree where the radius says stable or not, on both sides of the edge.
  struct Point { double w_dt, g_dt; };
  for (const Point p : {Point{0.7, 0.02}, Point{0.45, 0.11}, Point{0.30, 0.14}, Point{0.10, 0.16}}) {
    const double radius = gear5_spectral_radius(p.w_dt, p.g_dt, kind);
    const double peak = late_peak(p.w_dt, p.g_dt / p.w_dt, 40000);
    std::printf("[gear5] w dt %.3f g dt %.3f: spectral radius %.9f, late peak %.3g\n", p.w_dt, p.g_dt, radius, peak);
    EXPECT_EQ(radius < 1.0, peak < 2.0) << "w dt " << p.w_dt << " g dt " << p.g_dt;
  }
  for (const Point p : {Point{0.80, 0.02}, Point{0.50, 0.11}, Point{0.33, 0.14}, Point{0.16, 0.16}}) {
    EXPECT_GT(gear5_spectral_radius(p.w_dt, p.g_dt, kind), 1.0);
    EXPECT_GT(late_peak(p.w_dt, p.g_dt / p.w_dt, 40000), 2.0) << "w dt " << p.w_dt << " g dt " << p.g_dt;
  }
}

TEST(Gear5Stability, RectangleRuleHoldsForEveryModeUnderTheCorner)
{
  // gear5_stable(w, g) must mean: every w' <= w, g' <= g is stable. Check on a grid under
  // corners on the rule's edge (found by bisection), and that just beyond them is not.
  const auto kind = GearCorrector::ThreeSixteenths;
  for (double g_dt : {0.0, 0.02, 0.08, 0.12, 0.14, 0.15, 0.16}) {
    double low = 0.0, high = 1.0;
    for (int i = 0; i < 50; ++i) (gear5_stable(0.5 * (low + high), g_dt, kind) ? low : high) = 0.5 * (low + high);
    std::printf("[gear5] g dt %.3f: the rule allows w dt up to %.4f\n", g_dt, low);
    EXPECT_LE(low, gear5_frequency_limit(kind) + 1e-12);
    EXPECT_FALSE(gear5_stable(low * 1.01 + 1e-6, g_dt, kind));
    for (int a = 0; a <= 20; ++a)
      for (int b = 0; b <= 20; ++b)
        EXPECT_LE(gear5_spectral_radius(low * a / 20.0, g_dt * b / 20.0, kind), 1.0 + 2e-9)
            << "w dt " << low * a / 20 << " g dt " << g_dt * b / 20;
  }
}

TEST(Gear5Stability, OldAdditiveRuleIsInsideTheNewOne)
{
  // dt = 1 / (w / w_limit + g / g_limit), the rule before 2026-11, is stable everywhere the
  // new rule says so, and the new rule never allows a smaller step.
  for (double g : {0.0, 0.01, 0.1, 0.3, 0.6, 1.0, 2.0, 5.0}) {
    const double old_dt = 1.0 / (1.0 / gear5_frequency_limit(GearCorrector::ThreeSixteenths) + g / gear5_damping_limit());
    EXPECT_TRUE(gear5_stable(old_dt, g * old_dt, GearCorrector::ThreeSixteenths)) << "g=" << g;
    EXPECT_LT(late_peak(old_dt, g, 20000), 2.0) << "g=" << g << " dt=" << old_dt;    // decays, never grows
  }
}

TEST(Gear5, StepChangeKeepsTheTrajectory)
{
  // Halve dt mid-run: rescaling r_k by 2^-k continues the same solution (to the method's error).
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  Gear5State s = exact_start(0.02, 0.0);
  for (int i = 0; i < 250; ++i) step(s, 0.02, 0.0, c);
  gear5_change_step(s, 0.02, 0.01);
  for (int i = 0; i < 500; ++i) step(s, 0.01, 0.0, c);
  EXPECT_NEAR(s.r[0].x(), std::cos(10.0), 1e-8);
  EXPECT_NEAR(s.velocity(0.01).x(), -std::sin(10.0), 1e-8);
  EXPECT_THROW(gear5_change_step(s, 0.01, 0.0), std::invalid_argument);
}

TEST(Gear5, PackUnpackRoundTrips)
{
  Gear5State s;
  for (int k = 0; k < 6; ++k) s.r[k] = Vec3(k, 10 + k, 100 + k);
  double buffer[Gear5State::kNumDoubles];
  s.pack(buffer);
  Gear5State t;
  t.unpack(buffer);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(s.r[k], t.r[k]);
}

namespace {

// The subcycle's integration as it was before the states went to flat arrays: each node's
// Gear5State predicted and corrected by gear5_predict / gear5_correct (fixed nodes held).
void reference_subcycle(std::vector<Gear5State> &state, const std::vector<double> &mass,
                        const std::vector<std::uint8_t> &fixed, double dt, int substeps,
                        const std::array<double, 6> &c,
                        const std::function<void(const std::vector<Vec3> &, const std::vector<Vec3> &, std::vector<Vec3> &)> &forces)
{
  const std::size_t n = state.size();
  std::vector<Vec3> x(n), v(n), f(n);
  for (int k = 0; k < substeps; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!fixed[i]) gear5_predict(state[i]);
      x[i] = state[i].position();
      v[i] = fixed[i] ? Vec3::Zero() : state[i].velocity(dt);
      f[i].setZero();
    }
    forces(x, v, f);
    for (std::size_t i = 0; i < n; ++i) {
      if (fixed[i]) {
        for (int m = 1; m < 6; ++m) state[i].r[m].setZero();
        continue;
      }
      gear5_correct(state[i], f[i] / mass[i], dt, c);
    }
  }
}

}    // namespace

TEST(Gear5, SubcycleOnFlatArraysStepsLikeGear5StatesToRoundOff)
{
  // run_subcycle keeps the states in flat arrays and fuses the corrector of one substep
  // with the predictor of the next, multiplying by dt^2 / (2 m) and 1 / dt where
  // gear5_correct and Gear5State::velocity divide; every number must come out as
  // gear5_predict and gear5_correct give it node by node, to round-off (1e-12 of the
  // largest |r_k| over the nodes, of |r_2| for r_3 .. r_5, after 39 substeps; a wrong
  // factor, e.g. dt^2 / m, is off by O(1)): with and without fixed nodes (the fused pass runs only without), across a
  // change of substep, for an odd number of coordinates. Positions of fixed nodes exact.
  const int n = 37;
  const double l = 0.01, m0 = 1e-4;
  const WireTopology chain = open_chain_topology(n, l);
  const auto c = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  const auto forces = [&](const std::vector<Vec3> &x, const std::vector<Vec3> &v, std::vector<Vec3> &f) {
    add_elastic_forces(chain, AxialLaw{10.0, true}, 1e-4, x, f);
    for (std::size_t i = 0; i < x.size(); ++i) f[i] += Vec3(0, 0, -9.81e-4) - 0.3 * v[i];
  };
  for (int with_fixed = 0; with_fixed < 2; ++with_fixed) {
    std::vector<Vec3> x0(n);
    for (int i = 0; i < n; ++i) x0[i] = Vec3(i * l, 0.002 * std::sin(0.7 * i), 0.001 * std::cos(1.3 * i));
    WireNodeSet nodes;
    nodes.reset(x0, m0, 1e-5);
    for (int i = 0; i < n; ++i) {
      nodes.mass[i] = m0 * (1.0 + 0.01 * i);
      nodes.state[i] = gear5_start(x0[i], Vec3(0.01 * i, -0.02, 0.03), Vec3(0, 0, -9.81), 1e-5);
    }
    if (with_fixed) nodes.fixed[0] = nodes.fixed[17] = 1;
    std::vector<Gear5State> expected = nodes.state;
    GrainForceAccumulator none;
    none.reset(0);
    for (const double dt : {1e-5, 1e-5, 7e-6}) {
      run_subcycle(SubcyclePlan{13, dt}, c, nodes, none,
                   [&](const SubstepInfo &, const std::vector<Vec3> &x, const std::vector<Vec3> &v, std::vector<Vec3> &f,
                       GrainForceAccumulator &) { forces(x, v, f); });
      const double from = dt == 7e-6 ? 1e-5 : dt;
      if (from != dt)
        for (Gear5State &s : expected) gear5_change_step(s, from, dt);
      reference_subcycle(expected, nodes.mass, nodes.fixed, dt, 13, c, forces);
    }
    // (r_3 .. r_5 are the corrector's multiples of the mismatch a dt^2 / 2 - r_2, a
    // difference of near equals: their round-off is that of r_2)
    std::array<double, 6> largest{};
    for (int k = 0; k < 6; ++k)
      for (int i = 0; i < n; ++i) largest[k] = std::max(largest[k], expected[i].r[k].cwiseAbs().maxCoeff());
    for (int k = 0; k < 6; ++k) {
      const double scale = k < 3 ? largest[k] : std::max(largest[k], largest[2]);
      ASSERT_GT(scale, 0.0) << "r_" << k;
      for (int i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d)
          ASSERT_NEAR(nodes.state[i].r[k][d], expected[i].r[k][d], 1e-12 * scale)
              << "fixed nodes " << with_fixed << ", node " << i << " r_" << k;
    }
    if (with_fixed) {
      EXPECT_EQ(nodes.state[17].position(), x0[17]);    // held where it was
    }
  }
}
