// Time-step limit of the explicit wire subcycle.
//
// Gear-5 (corrector 3/16) on x'' = -w^2 x - g x' is stable while (measured by bisection on
// runs in tests/unit/wire, see doc/wire_model.md)
//   w dt < 0.313 (undamped)   and   g dt < 0.163 (pure damping),
// and the combination  dt <= 1 / (w / 0.313 + g / 0.163)  was stable on every mixed case
// tested. For a wire, Gershgorin's theorem on the stiffness matrix (row sums) bounds the
// highest angular frequency with node mass m and element length l:
//   w_max^2 <= 4 k_eff / m,   k_eff = k_elo / l + 4 k_rot / l^2 + n_c k_n / 2
// (axial springs k_elo / l: row sum 4 k_elo / l; rotational springs, linearised stencil
// k_rot / l^2 * (1, -4, 6, -4, 1): row sum 16 k_rot / l^2; n_c soft contacts per node: row
// sum at most 2 k_n for an element-element contact split by the lever rule), and the
// highest damping rate by g_max <= (2 n_c max(gamma_n, gamma_t) + c_node) / m.
#pragma once

#include "wire/gear5.h"

namespace nscd::wire {

// w dt above which Gear-5 amplifies x'' = -w^2 x. For 3/16 the measured limit; 3/20 has
// none (it amplifies at every step, see gear5.h) and gets w dt = 0.2, where its spectral
// radius is 1 + 1.8e-7 per step.
double gear5_frequency_limit(GearCorrector kind);
// g dt above which Gear-5 amplifies x'' = -g x' (measured; same for both correctors).
double gear5_damping_limit();

struct WireStiffness {
  double node_mass = 0.0;
  double element_length = 0.0;     // l = L0
  double k_elo = 0.0;              // axial, force per unit strain
  double k_rot = 0.0;              // bending, moment per radian
  double k_n = 0.0;                // soft-contact normal stiffness (0: no contacts)
  double gamma_contact = 0.0;      // max(gamma_n, gamma_t) of the soft contacts
  double contacts_per_node = 1.0;  // n_c, how many contacts a node may feel at once
  double node_damping = 0.0;       // c_node of a viscous drag -c_node v on each node
};

// Gershgorin bound on the highest angular frequency of the wire, sqrt(4 k_eff / m).
// Throws std::invalid_argument on non-positive mass or length, or negative stiffness.
double wire_max_angular_frequency(const WireStiffness &wire);
// Bound on the highest damping rate g_max (1 / time).
double wire_max_damping_rate(const WireStiffness &wire);

// Largest stable subcycle step: safety / (w_max / w_limit + g_max / g_limit). The safety
// factor in (0, 1] leaves room for stiffening under load and for nonlinear contacts.
double max_stable_wire_step(const WireStiffness &wire,
                            GearCorrector kind = GearCorrector::ThreeSixteenths,
                            double safety = 0.5);

// Throws std::invalid_argument with the numbers and the ways out if dt_sp exceeds
// max_stable_wire_step(wire, kind, safety) or is not positive.
void check_wire_step(double dt_sp, const WireStiffness &wire,
                     GearCorrector kind = GearCorrector::ThreeSixteenths, double safety = 0.5);

}    // namespace nscd::wire
