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

// Soft contact law: normal spring-dashpot with clamping, tangential spring with static and
// dynamic friction, history rotation, and the lever rule.
#include "wire/soft_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>
#include <vector>

using namespace nscd;
using namespace nscd::wire;

namespace {

SoftContactLaw frictional_law(SlipReset reset = SlipReset::ToDynamicLength)
{
  SoftContactLaw law;
  law.k_n = 1000.0;
  law.gamma_n = 2.0;
  law.k_t = 400.0;
  law.gamma_t = 0.0;
  law.mu_s = 0.6;
  law.mu_d = 0.4;
  law.slip_reset = reset;
  return law;
}

}    // namespace

TEST(SoftContact, HistoryIsPlainData)
{
  static_assert(std::is_trivially_copyable_v<TangentialHistory>);
  static_assert(sizeof(TangentialHistory) == TangentialHistory::kNumDoubles * sizeof(double));
}

TEST(SoftContact, StaticOverlapGivesSpringForceAndEnergy)
{
  const SoftContactLaw law = frictional_law();
  TangentialHistory h;
  const Vec3 n = Vec3(1, 2, 2) / 3.0;
  const SoftContactForce f = soft_contact_force(law, n, 0.01, Vec3::Zero(), 1e-3, h);
  EXPECT_NEAR(f.normal_force, 10.0, 1e-12);
  EXPECT_NEAR((f.force - 10.0 * n).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.elastic_energy, 0.5 * 1000.0 * 1e-4, 1e-15);
  EXPECT_FALSE(f.slipped);
  // -dE/dxi = f_n: energy at overlap 0.01 +- h.
  TangentialHistory h2;
  const double ep = soft_contact_force(law, n, 0.01 + 1e-6, Vec3::Zero(), 1e-3, h2).elastic_energy;
  const double em = soft_contact_force(law, n, 0.01 - 1e-6, Vec3::Zero(), 1e-3, h2).elastic_energy;
  EXPECT_NEAR((ep - em) / 2e-6, f.normal_force, 1e-6);
}

TEST(SoftContact, DashpotAddsOnApproachAndIsClampedOnSeparation)
{
  const SoftContactLaw law = frictional_law();
  const Vec3 n = Vec3::UnitZ();
  TangentialHistory h;
  // Approaching at 1 (v_A - v_B = -n): f_n = k xi + gamma * 1.
  EXPECT_NEAR(soft_contact_force(law, n, 0.01, -n, 1e-3, h).normal_force, 12.0, 1e-12);
  // Separating at 2: k xi - gamma * 2 = 6.
  EXPECT_NEAR(soft_contact_force(law, n, 0.01, 2 * n, 1e-3, h).normal_force, 6.0, 1e-12);
  // Separating fast at 10: k xi - 20 < 0 would pull the bodies together; clamped to 0.
  const SoftContactForce fast = soft_contact_force(law, n, 0.01, 10 * n, 1e-3, h);
  EXPECT_EQ(fast.normal_force, 0.0);
  EXPECT_EQ(fast.force.norm(), 0.0);
}

TEST(SoftContact, OpenContactClearsHistory)
{
  const SoftContactLaw law = frictional_law();
  TangentialHistory h;
  soft_contact_force(law, Vec3::UnitZ(), 0.01, Vec3(1, 0, 0), 1e-4, h);
  EXPECT_NE(h.xi[0], 0.0);
  const SoftContactForce open = soft_contact_force(law, Vec3::UnitZ(), -0.001, Vec3(1, 0, 0), 1e-4, h);
  EXPECT_EQ(open.force.norm(), 0.0);
  EXPECT_EQ(h.xi[0], 0.0);
  EXPECT_EQ(h.sliding, 0.0);
}

TEST(SoftContact, BlockDrivenSidewaysSticksThenSlidesAtDynamicFriction)
{
  // Block pressed with f_n = 10 and dragged at constant speed V along x. Force on the block
  // (A) is -x: |f_t| = k_t V t while sticking, up to mu_s f_n = 6 at t* = 6/(k_t V); then it
  // drops to mu_d f_n = 4 and stays there while sliding. On reversal it sticks again.
  SoftContactLaw law = frictional_law();
  law.gamma_n = 0.0;
  const Vec3 n = Vec3::UnitZ();
  const double V = 0.45, dt = 1e-4;
  TangentialHistory h;
  int first_slip = -1;
  for (int i = 1; i <= 600; ++i) {
    const SoftContactForce f = soft_contact_force(law, n, 0.01, Vec3(V, 0, 0), dt, h);
    if (first_slip < 0 && !f.slipped) {
      EXPECT_NEAR(f.tangential_force.x(), -law.k_t * V * i * dt, 1e-9) << i;    // linear growth
      EXPECT_LE(f.tangential_force.norm(), 6.0 + 1e-12);
    }
    if (f.slipped && first_slip < 0) {
      first_slip = i;
      EXPECT_NEAR(f.tangential_force.x(), -4.0, 1e-12);
      // History reset: spring re-attached at the length carrying mu_d f_n.
      EXPECT_NEAR(std::hypot(h.xi[0], h.xi[1]), 4.0 / law.k_t, 1e-15);
      EXPECT_EQ(h.sliding, 1.0);
    }
    if (first_slip > 0 && i > first_slip) {
      EXPECT_TRUE(f.slipped) << i;
      EXPECT_NEAR(f.tangential_force.x(), -4.0, 1e-12) << i;
    }
  }
  // The force k_t V dt i first exceeds 6 at i = ceil(6 / (k_t V dt)) = ceil(333.3) = 334.
  EXPECT_EQ(first_slip, 334);
  // Reverse: the spring unloads, the contact sticks again with the force decreasing linearly.
  const SoftContactForce back = soft_contact_force(law, n, 0.01, Vec3(-V, 0, 0), dt, h);
  EXPECT_FALSE(back.slipped);
  EXPECT_NEAR(back.tangential_force.x(), -4.0 + law.k_t * V * dt, 1e-12);
  EXPECT_EQ(h.sliding, 0.0);
}

TEST(SoftContact, PaperResetToZeroSawsBetweenZeroAndStaticLimit)
{
  // SlipReset::ToZero: spring removed on slip, so a steady slide loads and drops it again:
  // the force peaks just above mu_s f_n, is mu_d f_n at each slip and restarts from 0.
  SoftContactLaw law = frictional_law(SlipReset::ToZero);
  law.gamma_n = 0.0;
  TangentialHistory h;
  const double V = 0.45, dt = 1e-4;
  std::vector<int> slips;
  for (int i = 1; i <= 1100; ++i) {
    const SoftContactForce f = soft_contact_force(law, Vec3::UnitZ(), 0.01, Vec3(V, 0, 0), dt, h);
    if (f.slipped) {
      slips.push_back(i);
      EXPECT_NEAR(f.tangential_force.norm(), 4.0, 1e-12);
      EXPECT_EQ(h.xi[0], 0.0);    // history reset on slip
    } else {
      EXPECT_LE(f.tangential_force.norm(), 6.0 + 1e-12);
    }
  }
  ASSERT_GE(slips.size(), 3u);
  EXPECT_EQ(slips[0], 334);
  EXPECT_EQ(slips[1] - slips[0], 334);
  EXPECT_EQ(slips[2] - slips[1], 334);    // reload from 0 takes as long as the first time
}

TEST(SoftContact, HistoryRotatesWithTheContactFrame)
{
  // A stuck contact whose normal turns by 30 degrees keeps the spring length, in the new
  // tangent plane: same force magnitude, perpendicular to the new normal.
  SoftContactLaw law = frictional_law();
  law.mu_s = law.mu_d = 10.0;    // never slips here
  TangentialHistory h;
  soft_contact_force(law, Vec3::UnitZ(), 0.01, Vec3(1, 0, 0), 1e-3, h);    // xi = (1e-3, 0, 0)
  const Vec3 turned(std::sin(M_PI / 6), 0, std::cos(M_PI / 6));
  const SoftContactForce f = soft_contact_force(law, turned, 0.01, Vec3::Zero(), 1e-3, h);
  EXPECT_NEAR(f.tangential_force.norm(), law.k_t * 1e-3, 1e-12);
  EXPECT_NEAR(f.tangential_force.dot(turned), 0.0, 1e-15);
  EXPECT_NEAR(Vec3(h.xi[0], h.xi[1], h.xi[2]).dot(turned), 0.0, 1e-18);
}

// The other body moved by d beyond what the relative velocity carried: the spring takes
// -d's part in the tangent plane (it measures wire minus other body); a contact without
// memory has nothing to shift.
TEST(SoftContact, SpringFollowsTheOtherBodysUnseenMotionInTheTangentPlane)
{
  TangentialHistory h;
  soft_contact_force(frictional_law(), Vec3::UnitZ(), 0.01, Vec3(1, 0, 0), 1e-3, h);    // xi = (1e-3, 0, 0)
  follow_other_body(h, Vec3(2e-4, -1e-4, 5e-4), Vec3::UnitZ());
  EXPECT_NEAR(h.xi[0], 8e-4, 1e-18);
  EXPECT_NEAR(h.xi[1], 1e-4, 1e-18);
  EXPECT_EQ(h.xi[2], 0.0);
  TangentialHistory none;
  follow_other_body(none, Vec3(2e-4, -1e-4, 5e-4), Vec3::UnitZ());
  EXPECT_EQ(Vec3(none.xi[0], none.xi[1], none.xi[2]), Vec3::Zero());
}

// The part of the history that body B's velocity carried ahead of its held pose (held
// springs) is kept in the history but does not stretch the spring: the force is k_t times
// the history less that part's tangential component, the energy that of the stretch; a
// slipping contact keeps it on top of the dynamic length. (f_n 10, mu_s f_n 6, mu_d f_n 4.)
TEST(SoftContact, HistoryCarriedAheadIsKeptButDoesNotStretchTheSpring)
{
  const SoftContactLaw law = frictional_law();
  const Vec3 n = Vec3::UnitZ(), ahead(-2e-3, 1e-3, 7.0);    // (its normal part is dropped)
  TangentialHistory h;
  // the history moves by v dt = (1e-3, 0, 0); the stretch is that less the carried part
  const SoftContactForce f = soft_contact_force(law, n, 0.01, Vec3(1, 0, 0), 1e-3, h, ahead);
  const Vec3 stretch(3e-3, -1e-3, 0.0);
  EXPECT_NEAR((f.tangential_force + law.k_t * stretch).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.elastic_energy, 0.5 * law.k_n * 1e-4 + 0.5 * law.k_t * stretch.squaredNorm(), 1e-15);
  EXPECT_NEAR((Vec3(h.xi[0], h.xi[1], h.xi[2]) - Vec3(1e-3, 0, 0)).norm(), 0.0, 1e-18);
  EXPECT_FALSE(f.slipped);
  // carried far enough to slip: the spring goes to the dynamic length along the stretch,
  // and the history keeps the carried part on top of it
  TangentialHistory s;
  const Vec3 far(-0.02, 0.0, 0.0);    // a stretch of 0.02 + 1e-3: k_t times it 8.4 > 6
  const SoftContactForce slip = soft_contact_force(law, n, 0.01, Vec3(1, 0, 0), 1e-3, s, far);
  EXPECT_TRUE(slip.slipped);
  EXPECT_NEAR((slip.tangential_force - Vec3(-4.0, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((Vec3(s.xi[0], s.xi[1], s.xi[2]) - (Vec3(0.01, 0, 0) + far)).norm(), 0.0, 1e-15);
}

TEST(SoftContact, TangentialDampingAndFrictionlessFastPath)
{
  SoftContactLaw law = frictional_law();
  law.gamma_t = 3.0;
  law.mu_s = law.mu_d = 100.0;
  TangentialHistory h;
  const SoftContactForce f = soft_contact_force(law, Vec3::UnitZ(), 0.01, Vec3(0, 0.2, 0), 1e-3, h);
  EXPECT_NEAR(f.tangential_force.y(), -(law.k_t * 0.2e-3 + 3.0 * 0.2), 1e-12);

  law.mu_s = law.mu_d = 0.0;
  TangentialHistory h2;
  const SoftContactForce frictionless = soft_contact_force(law, Vec3::UnitZ(), 0.01, Vec3(0, 0.2, 0), 1e-3, h2);
  EXPECT_EQ(frictionless.tangential_force.norm(), 0.0);
  EXPECT_EQ(h2.xi[1], 0.0);
}

namespace {

// The tangential part of the law as written before its roots were cut (soft_contact.h
// takes one root for the spring's turn and compares |trial| with the Coulomb limit as
// squares): the reference that soft_contact_force must equal to round-off.
struct ReferenceTangential {
  Vec3 force, xi;
  bool slipped;
  double trial, limit;    // |trial force| and the Coulomb limit it was held against
};
ReferenceTangential reference_tangential(const SoftContactLaw &law, const Vec3 &n, double overlap, const Vec3 &v,
                                         double dt, const TangentialHistory &h)
{
  const double normal_speed = v.dot(n);
  const double fn = std::max(0.0, law.k_n * overlap - law.gamma_n * normal_speed);
  const Vec3 vt = v - normal_speed * n;
  Vec3 xi(h.xi[0], h.xi[1], h.xi[2]);
  const double length = xi.norm();
  if (length > 0.0) {
    const Vec3 in_plane = xi - xi.dot(n) * n;
    xi = in_plane.norm() > 0.0 ? Vec3(in_plane * (length / in_plane.norm())) : Vec3::Zero();
  }
  xi += vt * dt;
  const Vec3 trial = -(law.k_t * xi + law.gamma_t * vt);
  const double mu = h.sliding != 0.0 ? law.mu_d : law.mu_s;
  if (trial.norm() > mu * fn) {
    const Vec3 direction = trial / trial.norm();
    return {law.mu_d * fn * direction, -(law.mu_d * fn / law.k_t) * direction, true, trial.norm(), mu * fn};
  }
  return {trial, xi, false, trial.norm(), mu * fn};
}

}    // namespace

TEST(SoftContact, EqualsTheLawWithTwoRootsToRoundOff)
{
  // Random turned springs, velocities and overlaps, sticking and slipping: the force, the
  // spring and the slip decision as the law with a root per length (reference_tangential),
  // to 1e-13 of the force's and the spring's size; a decision may differ only where
  // |trial| is within 1e-12 of the limit. (Fails if the turn keeps the squared ratio, or if
  // the slip test compares a square with a length.)
  SoftContactLaw law = frictional_law();
  law.gamma_t = 0.3;
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int slipped = 0, stuck = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 n = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Vec3 v = 0.05 * Vec3(u(rng), u(rng), u(rng));
    const double overlap = 1e-3 * (1.0 + u(rng));
    TangentialHistory h;
    const double spring = 1e-3 * std::pow(10.0, 1.5 * u(rng));
    for (int d = 0; d < 3; ++d) h.xi[d] = spring * u(rng);
    h.sliding = trial % 3 == 0 ? 1.0 : 0.0;
    const ReferenceTangential expected = reference_tangential(law, n, overlap, v, 1e-4, h);
    TangentialHistory got_h = h;
    const SoftContactForce got = soft_contact_force(law, n, overlap, v, 1e-4, got_h);
    const Vec3 xi(got_h.xi[0], got_h.xi[1], got_h.xi[2]);
    if (got.slipped != expected.slipped) {    // only at the threshold itself
      EXPECT_NEAR(expected.trial, expected.limit, 1e-12 * expected.limit) << "trial " << trial;
      continue;
    }
    (got.slipped ? slipped : stuck)++;
    const double force_scale = std::max(expected.force.norm(), 1e-300), xi_scale = std::max(expected.xi.norm(), 1e-300);
    EXPECT_LE((got.tangential_force - expected.force).norm(), 1e-13 * force_scale) << "trial " << trial;
    EXPECT_LE((xi - expected.xi).norm(), 1e-13 * xi_scale) << "trial " << trial;
  }
  EXPECT_GT(slipped, 100);
  EXPECT_GT(stuck, 100);
}

TEST(SoftContact, ValidationNamesTheBadValue)
{
  SoftContactLaw law = frictional_law();
  EXPECT_NO_THROW(validate(law));
  law.mu_d = 0.7;
  try {
    validate(law);
    FAIL() << "mu_d > mu_s accepted";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("mu_d = 0.7"), std::string::npos) << e.what();
  }
  law = frictional_law();
  law.k_t = -1.0;
  EXPECT_THROW(validate(law), std::invalid_argument);
}

TEST(LeverRule, SplitsForceLinearlyAndKeepsTorque)
{
  const Vec3 a(1, 0, 0), b(0, 2, 1), F(0.3, -1.0, 2.0), origin(5, -1, 2);
  for (double s : {0.0, 0.25, 0.5, 0.9, 1.0}) {
    const LeverWeights w = lever_weights(s);
    EXPECT_DOUBLE_EQ(w.on_a + w.on_b, 1.0);
    const Vec3 p = a + s * (b - a);
    // Weights inversely proportional to the distance to the contact point: w_a/w_b = |pb|/|pa|.
    if (s > 0 && s < 1) {
      EXPECT_NEAR(w.on_a / w.on_b, (b - p).norm() / (p - a).norm(), 1e-12);
    }
    const Vec3 torque = (a - origin).cross(w.on_a * F) + (b - origin).cross(w.on_b * F);
    EXPECT_NEAR((torque - (p - origin).cross(F)).norm(), 0.0, 1e-12);
  }
  EXPECT_THROW(lever_weights(1.1), std::invalid_argument);
  EXPECT_THROW(lever_weights(-0.01), std::invalid_argument);
  EXPECT_THROW(lever_weights(std::nan("")), std::invalid_argument);
}
