#include "wire/stability.h"

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
  const double inverse = omega / gear5_frequency_limit(kind) + rate / gear5_damping_limit();
  require(inverse > 0.0, "highest wire frequency", omega,
          "and damping rate are both 0: give k_elo, k_rot, k_n or a damping");
  return safety / inverse;
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
