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

// Soft contact law of wire elements (Cundall-Strack linear spring-dashpot with static and
// dynamic Coulomb friction) and the lever rule that hands a contact force to the nodes.
//
// Conventions (force on body A; body B gets the opposite):
//   normal      unit vector pointing from B to A;
//   overlap     xi >= 0, the interpenetration depth of the two dilated shapes;
//   velocity    v_A - v_B at the contact point.
// Normal:      f_n = k_n xi + gamma_n dxi/dt, dxi/dt = -(v . n), and f_n is clamped at 0:
//              a separating contact is never pulled together by its dashpot.
// Tangential:  spring history xi_t (relative tangential displacement while sticking),
//              trial force f_t = -(k_t xi_t + gamma_t v_t). If |f_t| > mu f_n the contact
//              slips: the spring is dropped and re-attached (see SlipReset) and the force is
//              mu_d f_n along the trial direction. mu = mu_s while sticking, mu_d while
//              sliding. Details and reasons: doc/Howto_nscd_wire_model.rst.
#pragma once

#include "math/types.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace nscd::wire {

// What the history holds right after a slip.
enum class SlipReset : std::uint8_t {
  // Paper's wording taken literally: spring removed, history zero. A steadily sliding
  // contact then saws between 0 and mu_s f_n (mean about mu_s f_n / 2, not mu_d f_n).
  ToZero,
  // Spring re-attached at the length that carries the dynamic force, k_t |xi_t| = mu_d f_n,
  // and the contact remembers it slides (threshold mu_d) until the trial force falls back
  // under mu_d f_n. Steady sliding then carries exactly mu_d f_n. Default.
  ToDynamicLength,
};

struct SoftContactLaw {
  double k_n = 0.0;        // normal stiffness, force / length
  double gamma_n = 0.0;    // normal damping, force * time / length
  double k_t = 0.0;        // tangential stiffness
  double gamma_t = 0.0;    // tangential damping
  double mu_s = 0.0;       // static friction coefficient
  double mu_d = 0.0;       // dynamic friction coefficient, 0 <= mu_d <= mu_s
  SlipReset slip_reset = SlipReset::ToDynamicLength;
};

// Throws std::invalid_argument naming the bad value (negative stiffness, mu_d > mu_s, ...).
// Call once when the law is set up; soft_contact_force does not re-check it per contact.
void validate(const SoftContactLaw &law);

// Per-contact memory, owned by the caller (e.g. LAMMPS' per-contact history, which packs
// it for migration and restart): plain, trivially copyable, 4 doubles.
struct TangentialHistory {
  double xi[3] = {0.0, 0.0, 0.0};    // tangential spring displacement, world frame
  double sliding = 0.0;              // 1 while the contact slides (ToDynamicLength only)
  static constexpr int kNumDoubles = 4;
};

struct SoftContactForce {
  Vec3 force = Vec3::Zero();    // on body A
  double normal_force = 0.0;    // f_n >= 0
  Vec3 tangential_force = Vec3::Zero();
  double elastic_energy = 0.0;  // k_n xi^2/2 + k_t |xi_t|^2/2 after the update
  bool slipped = false;         // the Coulomb limit was reached this step
};

// One time step of the contact: rotates history into the plane normal to `normal`,
// increments it by v_t * dt, evaluates the law and updates history in place.
// A contact with overlap <= 0 is open: zero force and the history is cleared.
// `ahead`: the part of the relative displacement that body B's velocity has carried its
// surface beyond where B is held (the wire's subcycle holds grains still while their
// velocity enters v): the history keeps it, so that it holds the relative displacement
// the velocities give, but it does not stretch the spring, which pulls by the relative
// displacement of the held poses, as the normal overlap does. follow_other_body hands the
// spring B's true motion at the next step. (A spring carried ahead by B's velocity acts
// as if B were half a step further on: a grain ringing on sticking wire contacts then
// grows from h^2 K / m of about 2, held from about 4; doc/Howto_nscd_wire_model.rst.)
// (Inline, below: the wire's substeps call it for every closed contact, and inlined the
// parts of the result a caller does not use cost nothing.)
inline SoftContactForce soft_contact_force(const SoftContactLaw &law, const Vec3 &normal,
                                           double overlap, const Vec3 &relative_velocity, double dt,
                                           TangentialHistory &history, const Vec3 &ahead = Vec3::Zero());

// The other body moved by `displacement` beyond what the relative velocities handed to
// soft_contact_force carried into the spring (the wire's subcycle holds grains still and
// moves them on between grain steps): the spring takes the part in the plane normal to
// `normal`, as that relative tangential motion would have given it, and so holds the
// true relative displacement. A contact without memory is left as it is.
inline void follow_other_body(TangentialHistory &history, const Vec3 &displacement, const Vec3 &normal);

// Lever rule: a force at the point a + s (b - a) of element (a,b) goes (1-s) to a and s to b.
// This is the paper's "weights inversely proportional to the distance" for a point on the
// segment, and it keeps both the total force and the torque about any point.
struct LeverWeights {
  double on_a, on_b;
};
// Throws std::invalid_argument if s is outside [0, 1] (beyond round-off).
inline LeverWeights lever_weights(double s);

/* ---------------------------------------------------------------------- definitions */

[[noreturn]] void throw_lever_outside(double s);

namespace soft_contact_detail {

inline Vec3 load(const TangentialHistory &h) { return Vec3(h.xi[0], h.xi[1], h.xi[2]); }

inline void store(const Vec3 &xi, TangentialHistory &h)
{
  h.xi[0] = xi.x();
  h.xi[1] = xi.y();
  h.xi[2] = xi.z();
}

// The contact frame turns between steps; the stored spring turns with it. Rotating (keep
// the length, drop the normal part) rather than projecting keeps the stored elastic
// energy, so a rolling-over contact does not leak friction force. The length ratio is
// the square root of the squared lengths' ratio (one root instead of two; the same to
// round-off).
inline Vec3 rotate_into_tangent_plane(const Vec3 &xi, const Vec3 &normal)
{
  const double length_squared = xi.squaredNorm();
  if (length_squared == 0.0) return xi;
  const Vec3 in_plane = xi - xi.dot(normal) * normal;
  const double in_plane_squared = in_plane.squaredNorm();
  if (in_plane_squared == 0.0) return Vec3::Zero();    // turned by 90 degrees: no memory left
  return in_plane * std::sqrt(length_squared / in_plane_squared);
}

}    // namespace soft_contact_detail

__attribute__((always_inline)) inline SoftContactForce soft_contact_force(const SoftContactLaw &law,
                                                                          const Vec3 &normal, double overlap,
                                                                          const Vec3 &relative_velocity, double dt,
                                                                          TangentialHistory &history, const Vec3 &ahead)
{
  using namespace soft_contact_detail;
  SoftContactForce out;
  if (overlap <= 0.0) {
    history = TangentialHistory{};
    return out;
  }
  const double normal_speed = relative_velocity.dot(normal);    // < 0 while approaching
  out.normal_force = std::max(0.0, law.k_n * overlap - law.gamma_n * normal_speed);
  out.elastic_energy = 0.5 * law.k_n * overlap * overlap;
  out.force = out.normal_force * normal;
  if (law.mu_s == 0.0) {    // frictionless: no tangential work, no memory
    history = TangentialHistory{};
    return out;
  }

  const Vec3 tangential_velocity = relative_velocity - normal_speed * normal;
  const Vec3 ahead_t = ahead - ahead.dot(normal) * normal;
  Vec3 xi = rotate_into_tangent_plane(load(history), normal) + tangential_velocity * dt - ahead_t;    // the stretch
  const Vec3 trial = -(law.k_t * xi + law.gamma_t * tangential_velocity);
  const bool was_sliding = history.sliding != 0.0;
  const double mu = was_sliding && law.slip_reset == SlipReset::ToDynamicLength ? law.mu_d : law.mu_s;
  const double limit = mu * out.normal_force;

  // |trial| > limit as squares (both >= 0): the root only for a slipping contact
  const double trial_squared = trial.squaredNorm();
  if (trial_squared > limit * limit) {
    out.slipped = true;
    const Vec3 direction = trial / std::sqrt(trial_squared);
    out.tangential_force = law.mu_d * out.normal_force * direction;
    if (law.slip_reset == SlipReset::ToDynamicLength && law.k_t > 0.0) {
      xi = -(law.mu_d * out.normal_force / law.k_t) * direction;
      history.sliding = 1.0;
    } else {
      xi.setZero();
      history.sliding = 0.0;
    }
  } else {
    out.tangential_force = trial;
    history.sliding = 0.0;
  }
  store(xi + ahead_t, history);
  out.force += out.tangential_force;
  out.elastic_energy += 0.5 * law.k_t * xi.squaredNorm();
  return out;
}

inline void follow_other_body(TangentialHistory &history, const Vec3 &displacement, const Vec3 &normal)
{
  using namespace soft_contact_detail;
  const Vec3 xi = load(history);
  if (xi.squaredNorm() == 0.0) return;
  store(xi - (displacement - displacement.dot(normal) * normal), history);    // v_t = v_wire - v_other
}

inline LeverWeights lever_weights(double s)
{
  constexpr double kRoundOff = 1e-12;
  if (!(s >= -kRoundOff && s <= 1.0 + kRoundOff)) throw_lever_outside(s);
  const double t = std::clamp(s, 0.0, 1.0);
  return {1.0 - t, t};
}

}    // namespace nscd::wire
