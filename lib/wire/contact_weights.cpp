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

#include "wire/contact_weights.h"

#include <algorithm>

namespace nscd::wire {

double stretch_end_weight(double stretch, double ramp)
{
  if (!(ramp > 0.0)) return 1.0;
  return 0.5 + 0.5 * std::clamp(stretch / ramp, 0.0, 1.0);
}

}    // namespace nscd::wire
