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

void throw_lever_outside(double s)
{
  std::ostringstream msg;
  msg << "wire: lever-rule parameter s = " << s << " is outside [0, 1]; the contact point must lie on the element";
  throw std::invalid_argument(msg.str());
}

}    // namespace nscd::wire
