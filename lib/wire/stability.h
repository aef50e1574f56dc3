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

// Time-step limit of the explicit wire subcycle.
//
// Gear-5 (corrector 3/16) on the test equation x'' = -w^2 x - g x' is stable where the
// spectral radius of its 6x6 step matrix is at most 1 (gear5_spectral_radius). Undamped,
// that is w dt <= 0.313; pure drag, g dt <= 0.163; a little damping widens the range of w a
// lot (w dt up to 0.74 at g dt = 0.02, 0.30 still at g dt = 0.14), heavy damping narrows it
// (doc/Howto_nscd_wire_model.rst, "Stability limits"). A wire's modes have frequencies up
// to w_max and damping rates up to g_max, in any combination, and its axial modes are
// undamped: a step is taken as stable when every (w, g) of the rectangle [0, w_max] x [0,
// g_max] is, i.e. w_max dt <= 0.313 and the corner (w_max dt, g_max dt) is stable (the
// region's edge w(g) falls monotonically beyond g dt = 0.02 and exceeds 0.313 below g dt =
// 0.139).
// For a wire, Gershgorin's theorem on the stiffness matrix (row sums) bounds the highest
// angular frequency with node mass m and element length l:
//   w_max^2 <= 4 k_eff / m,   k_eff = k_elo / l + 4 k_rot / l^2 + n_c k_n / 2
// (axial springs k_elo / l: row sum 4 k_elo / l; rotational springs, linearised stencil
// k_rot / l^2 * (1, -4, 6, -4, 1): row sum 16 k_rot / l^2; n_c soft contacts per node: row
// sum at most 2 k_n for an element-element contact split by the lever rule), and the
// highest damping rate by g_max <= (2 n_c max(gamma_n, gamma_t) + c_node) / m.
// An earlier version used the sum dt <= 1 / (w_max / 0.313 + g_max / 0.163), which is
// inside the region but gave 2.3x too many substeps for the papers' wire.
#pragma once

#include "wire/gear5.h"

namespace nscd::wire {

// w dt above which Gear-5 amplifies x'' = -w^2 x. For 3/16 the measured limit; 3/20 has
// none (it amplifies at every step, see gear5.h) and gets w dt = 0.2, where its spectral
// radius is 1 + 1.8e-7 per step.
double gear5_frequency_limit(GearCorrector kind);
// g dt above which Gear-5 amplifies x'' = -g x' (measured; same for both correctors).
double gear5_damping_limit();
// Spectral radius of one Gear-5 step on x'' = -w^2 x - g x' at the given w dt and g dt:
// above 1, some solution grows.
double gear5_spectral_radius(double w_dt, double g_dt, GearCorrector kind);
// Whether every test equation with w' dt <= w_dt and g' dt <= g_dt is stable (the rectangle
// rule above); for 3/20, "stable" means growing no faster than its undamped practical limit.
bool gear5_stable(double w_dt, double g_dt, GearCorrector kind);

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

// Largest stable subcycle step: safety x the largest dt with gear5_stable(w_max dt, g_max dt).
// The safety factor in (0, 1] leaves room for more contacts per node than n_c, for stiffening
// under load and for the coupling of modes that the scalar test equation does not have.
double max_stable_wire_step(const WireStiffness &wire,
                            GearCorrector kind = GearCorrector::ThreeSixteenths,
                            double safety = 0.9);

// The automatic subcycle step: the stable step, and no more than kAccurateFrequencyStep /
// w_max, so that the fastest mode gets at least 2 pi / 0.1 = 63 substeps per period. The
// stable step alone (w_max dt ~0.28 at safety 0.9 for the papers' wire) is stable but
// changes the outcome of the papers' column: it kept 4-7 % less of its height through the
// walls than w_max dt = 0.094 on each of 3 seeds (benchmarks/column/README.md, "Accuracy").
constexpr double kAccurateFrequencyStep = 0.1;
double accurate_wire_step(const WireStiffness &wire,
                          GearCorrector kind = GearCorrector::ThreeSixteenths,
                          double safety = 0.9);

// Throws std::invalid_argument with the numbers and the ways out if dt_sp exceeds
// max_stable_wire_step(wire, kind, safety) or is not positive.
void check_wire_step(double dt_sp, const WireStiffness &wire,
                     GearCorrector kind = GearCorrector::ThreeSixteenths, double safety = 0.9);

}    // namespace nscd::wire
