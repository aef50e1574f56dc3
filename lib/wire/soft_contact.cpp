#include "wire/soft_contact.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nscd::wire {

namespace {

void require_non_negative(double value, const char *name)
{
  if (!(value >= 0.0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << "wire contact: " << name << " = " << value << " must be finite and >= 0";
    throw std::invalid_argument(msg.str());
  }
}

Vec3 load(const TangentialHistory &h) { return Vec3(h.xi[0], h.xi[1], h.xi[2]); }

void store(const Vec3 &xi, TangentialHistory &h)
{
  h.xi[0] = xi.x();
  h.xi[1] = xi.y();
  h.xi[2] = xi.z();
}

// The contact frame turns between steps; the stored spring turns with it. Rotating (keep
// the length, drop the normal part) rather than projecting keeps the stored elastic
// energy, so a rolling-over contact does not leak friction force.
Vec3 rotate_into_tangent_plane(const Vec3 &xi, const Vec3 &normal)
{
  const double length = xi.norm();
  if (length == 0.0) return xi;
  const Vec3 in_plane = xi - xi.dot(normal) * normal;
  const double in_plane_length = in_plane.norm();
  if (in_plane_length == 0.0) return Vec3::Zero();    // turned by 90 degrees: no memory left
  return in_plane * (length / in_plane_length);
}

}    // namespace

void validate(const SoftContactLaw &law)
{
  require_non_negative(law.k_n, "k_n");
  require_non_negative(law.gamma_n, "gamma_n");
  require_non_negative(law.k_t, "k_t");
  require_non_negative(law.gamma_t, "gamma_t");
  require_non_negative(law.mu_s, "mu_s");
  require_non_negative(law.mu_d, "mu_d");
  if (law.mu_d > law.mu_s) {
    std::ostringstream msg;
    msg << "wire contact: dynamic friction mu_d = " << law.mu_d
        << " exceeds static friction mu_s = " << law.mu_s << "; use mu_d <= mu_s";
    throw std::invalid_argument(msg.str());
  }
  if (law.k_n == 0.0) throw std::invalid_argument("wire contact: k_n = 0 gives no contact force; use k_n > 0");
}

SoftContactForce soft_contact_force(const SoftContactLaw &law, const Vec3 &normal,
                                    double overlap, const Vec3 &relative_velocity, double dt,
                                    TangentialHistory &history)
{
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
  Vec3 xi = rotate_into_tangent_plane(load(history), normal) + tangential_velocity * dt;
  const Vec3 trial = -(law.k_t * xi + law.gamma_t * tangential_velocity);
  const double trial_magnitude = trial.norm();
  const bool was_sliding = history.sliding != 0.0;
  const double mu = was_sliding && law.slip_reset == SlipReset::ToDynamicLength ? law.mu_d : law.mu_s;

  if (trial_magnitude > mu * out.normal_force) {
    out.slipped = true;
    const Vec3 direction = trial / trial_magnitude;
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
  store(xi, history);
  out.force += out.tangential_force;
  out.elastic_energy += 0.5 * law.k_t * xi.squaredNorm();
  return out;
}

LeverWeights lever_weights(double s)
{
  constexpr double kRoundOff = 1e-12;
  if (!(s >= -kRoundOff && s <= 1.0 + kRoundOff)) {
    std::ostringstream msg;
    msg << "wire: lever-rule parameter s = " << s
        << " is outside [0, 1]; the contact point must lie on the element";
    throw std::invalid_argument(msg.str());
  }
  const double t = std::clamp(s, 0.0, 1.0);
  return {1.0 - t, t};
}

}    // namespace nscd::wire
