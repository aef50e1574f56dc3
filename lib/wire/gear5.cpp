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

#include "wire/gear5.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nscd::wire {

std::array<double, 6> gear5_corrector_coefficients(GearCorrector kind)
{
  const double c0 = kind == GearCorrector::ThreeTwentieths ? 3.0 / 20.0 : 3.0 / 16.0;
  return {c0, 251.0 / 360.0, 1.0, 11.0 / 18.0, 1.0 / 6.0, 1.0 / 60.0};
}

void Gear5State::pack(double *out) const
{
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 3; ++i) out[3 * k + i] = r[k][i];
}

void Gear5State::unpack(const double *in)
{
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 3; ++i) r[k][i] = in[3 * k + i];
}

Gear5State gear5_start(const Vec3 &position, const Vec3 &velocity, const Vec3 &acceleration,
                       double dt)
{
  Gear5State s;
  s.r[0] = position;
  s.r[1] = dt * velocity;
  s.r[2] = 0.5 * dt * dt * acceleration;
  return s;
}

void gear5_predict(Gear5State &s)
{
  // Pascal triangle: r_j += sum_{k>j} C(k, j) r_k, with the sums done from the top so
  // each line uses the not-yet-shifted higher derivatives.
  auto &r = s.r;
  r[0] += r[1] + r[2] + r[3] + r[4] + r[5];
  r[1] += 2.0 * r[2] + 3.0 * r[3] + 4.0 * r[4] + 5.0 * r[5];
  r[2] += 3.0 * r[3] + 6.0 * r[4] + 10.0 * r[5];
  r[3] += 4.0 * r[4] + 10.0 * r[5];
  r[4] += 5.0 * r[5];
}

void gear5_correct(Gear5State &s, const Vec3 &acceleration, double dt,
                   const std::array<double, 6> &c)
{
  const Vec3 mismatch = 0.5 * dt * dt * acceleration - s.r[2];
  for (int k = 0; k < 6; ++k) s.r[k] += c[k] * mismatch;
}

void gear5_change_step(Gear5State &s, double old_dt, double new_dt)
{
  if (!(old_dt > 0.0) || !(new_dt > 0.0)) {
    std::ostringstream msg;
    msg << "wire Gear integrator: time steps must be > 0, got old " << old_dt << " new " << new_dt;
    throw std::invalid_argument(msg.str());
  }
  const double ratio = new_dt / old_dt;
  double factor = 1.0;
  for (int k = 1; k < 6; ++k) {
    factor *= ratio;
    s.r[k] *= factor;
  }
}

}    // namespace nscd::wire
