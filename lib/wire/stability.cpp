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

#include "wire/stability.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nscd::wire {

namespace {

void require(bool ok, const char *name, double value, const char *rule)
{
  if (ok && std::isfinite(value)) return;
  std::ostringstream msg;
  msg << "wire stability: " << name << " = " << value << " " << rule;
  throw std::invalid_argument(msg.str());
}

}    // namespace

double gear5_frequency_limit(GearCorrector kind)
{
  // Re-measured by bisection in test Gear5Stability.* (to 1 %).
  return kind == GearCorrector::ThreeTwentieths ? 0.2 : 0.313;
}

double gear5_damping_limit() { return 0.163; }

double gear5_spectral_radius(double w_dt, double g_dt, GearCorrector kind)
{
  // One step maps the scaled derivatives r (dt = 1) to C P r: P is the Taylor shift
  // (Pascal's triangle), C adds c_k D with D = a/2 - p_2 and a = -w_dt^2 p_0 - g_dt p_1.
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  Matrix6 shift = Matrix6::Zero();
  for (int j = 0; j < 6; ++j)
    for (int i = 0, binomial = 1; i <= j; binomial = binomial * (j - i) / (i + 1), ++i) shift(i, j) = binomial;
  Eigen::Matrix<double, 1, 6> mismatch = Eigen::Matrix<double, 1, 6>::Zero();
  mismatch(0) = -0.5 * w_dt * w_dt;
  mismatch(1) = -0.5 * g_dt;
  mismatch(2) = -1.0;
  const std::array<double, 6> c = gear5_corrector_coefficients(kind);
  const Eigen::Matrix<double, 6, 1> coefficients(c[0], c[1], c[2], c[3], c[4], c[5]);
  const Matrix6 step = (Matrix6::Identity() + coefficients * mismatch) * shift;
  return step.eigenvalues().cwiseAbs().maxCoeff();
}

bool gear5_stable(double w_dt, double g_dt, GearCorrector kind)
{
  const double w_limit = gear5_frequency_limit(kind);
  if (!(w_dt >= 0.0 && g_dt >= 0.0) || w_dt > w_limit || g_dt > gear5_damping_limit()) return false;
  // The undamped mode at the frequency limit sets what "not growing" means (1 + 1.5e-9 for
  // 3/16 at 0.313; 3/20 grows slowly at every step, 1 + 1.8e-7 at its limit 0.2).
  const double allowed = std::max(1.0, gear5_spectral_radius(w_limit, 0.0, kind));
  return gear5_spectral_radius(w_dt, g_dt, kind) <= allowed;
}

double wire_max_angular_frequency(const WireStiffness &w)
{
  require(w.node_mass > 0.0, "node mass", w.node_mass, "must be > 0");
  require(w.element_length > 0.0, "element length", w.element_length, "must be > 0");
  require(w.k_elo >= 0.0, "k_elo", w.k_elo, "must be >= 0");
  require(w.k_rot >= 0.0, "k_rot", w.k_rot, "must be >= 0");
  require(w.k_n >= 0.0, "k_n", w.k_n, "must be >= 0");
  require(w.contacts_per_node >= 0.0, "contacts per node", w.contacts_per_node, "must be >= 0");
  const double l = w.element_length;
  const double k_eff = w.k_elo / l + 4.0 * w.k_rot / (l * l) + 0.5 * w.contacts_per_node * w.k_n;
  return std::sqrt(4.0 * k_eff / w.node_mass);
}

double wire_max_damping_rate(const WireStiffness &w)
{
  require(w.node_mass > 0.0, "node mass", w.node_mass, "must be > 0");
  require(w.gamma_contact >= 0.0, "contact damping", w.gamma_contact, "must be >= 0");
  require(w.node_damping >= 0.0, "node damping", w.node_damping, "must be >= 0");
  return (2.0 * w.contacts_per_node * w.gamma_contact + w.node_damping) / w.node_mass;
}

double max_stable_wire_step(const WireStiffness &wire, GearCorrector kind, double safety)
{
  require(safety > 0.0 && safety <= 1.0, "safety factor", safety, "must be in (0, 1]");
  const double omega = wire_max_angular_frequency(wire);
  const double rate = wire_max_damping_rate(wire);
  require(omega > 0.0 || rate > 0.0, "highest wire frequency", omega,
          "and damping rate are both 0: give k_elo, k_rot, k_n or a damping");
  // Each limit alone bounds the step; bisection finds where the rectangle leaves the region
  // (along dt it leaves once: see stability.h).
  double high = std::min(omega > 0.0 ? gear5_frequency_limit(kind) / omega : INFINITY,
                         rate > 0.0 ? gear5_damping_limit() / rate : INFINITY);
  double low = 0.0;
  if (gear5_stable(omega * high, rate * high, kind)) low = high;
  for (int i = 0; i < 60 && high - low > 1e-12 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (gear5_stable(omega * mid, rate * mid, kind) ? low : high) = mid;
  }
  return safety * low;
}

double accurate_wire_step(const WireStiffness &wire, GearCorrector kind, double safety)
{
  const double stable = max_stable_wire_step(wire, kind, safety);
  const double omega = wire_max_angular_frequency(wire);
  return omega > 0.0 ? std::min(stable, kAccurateFrequencyStep / omega) : stable;
}

void check_wire_step(double dt_sp, const WireStiffness &wire, GearCorrector kind, double safety)
{
  const double dt_max = max_stable_wire_step(wire, kind, safety);
  if (dt_sp > 0.0 && dt_sp <= dt_max) return;
  std::ostringstream msg;
  msg << "wire time step dt_SP = " << dt_sp;
  if (!(dt_sp > 0.0)) {
    msg << " must be > 0";
  } else {
    msg << " is above the Gear-5 stability limit " << dt_max << " (omega_max = "
        << wire_max_angular_frequency(wire) << ", damping rate " << wire_max_damping_rate(wire)
        << ", safety " << safety << "); use at least " << std::ceil(dt_sp / dt_max)
        << " times more wire substeps per NSCD step, heavier wire nodes, or softer "
           "k_elo / k_rot / k_n / damping";
  }
  throw std::invalid_argument(msg.str());
}

}    // namespace nscd::wire
