/* -*- c++ -*- ----------------------------------------------------------
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

// Fifth-order Gear predictor-corrector for m x'' = f(x, x') (Gear 1966, 1971).
//
// The state of one node is six scaled derivatives (Nordsieck form)
//   r_k = dt^k / k! * d^k x / dt^k,   k = 0..5,
// so the predictor is the Pascal-triangle Taylor shift and the corrector adds c_k * D with
// D = dt^2/2 * a(predicted) - r_2(predicted). A step is
//   gear5_predict(state);  a = force(position, velocity) / m;  gear5_correct(state, a, ...).
// Corrector coefficients (3/20 or 3/16, 251/360, 1, 11/18, 1/6, 1/60): see GearCorrector.
#pragma once

#include "math/types.h"

#include <array>

namespace nscd::wire {

// Only c_0 differs between Gear's two tables: 3/20 for forces that depend on positions only,
// 3/16 for velocity-dependent forces (dashpots, friction). Measured on x'' = -w^2 x - g x'
// (tests and doc/Howto_nscd_wire_model.rst): both are 5th order once forces depend on the
// velocity; 3/20 is 6th order for pure springs but amplifies undamped oscillations at every
// step size (spectral radius 1 + 7e-10 at w dt = 0.1), whereas 3/16 damps them slightly and
// is strictly stable up to w dt = 0.313. The wire's contacts are velocity-dependent and its
// springs carry no dashpot, so 3/16 is the default.
enum class GearCorrector {
  ThreeSixteenths,    // c0 = 3/16, default
  ThreeTwentieths,    // c0 = 3/20, Gear's value for position-only forces
};

// The six corrector coefficients c_0..c_5.
std::array<double, 6> gear5_corrector_coefficients(GearCorrector kind);

struct Gear5State {
  std::array<Vec3, 6> r{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
                        Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};

  const Vec3 &position() const { return r[0]; }
  Vec3 velocity(double dt) const { return r[1] / dt; }
  Vec3 acceleration(double dt) const { return r[2] * (2.0 / (dt * dt)); }

  // Flat layout for LAMMPS' per-atom arrays (migration, restart): r_0.x, r_0.y, ..., r_5.z.
  static constexpr int kNumDoubles = 18;
  void pack(double *out) const;
  void unpack(const double *in);
};

// State at rest in the higher derivatives: r_0 = x, r_1 = dt v, r_2 = dt^2/2 a, r_3..5 = 0.
Gear5State gear5_start(const Vec3 &position, const Vec3 &velocity, const Vec3 &acceleration,
                       double dt);

// Taylor shift to t + dt. Throws nothing; O(18) flops.
void gear5_predict(Gear5State &state);

// Correct with the acceleration evaluated at the predicted state.
void gear5_correct(Gear5State &state, const Vec3 &acceleration, double dt,
                   const std::array<double, 6> &coefficients);

// Rescale the scaled derivatives when the step changes from old_dt to new_dt
// (r_k scales with dt^k). Throws std::invalid_argument if a step is not positive.
void gear5_change_step(Gear5State &state, double old_dt, double new_dt);

}    // namespace nscd::wire
