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

/* compute fabric/atom: the fabric tensor of each grain (the papers' Eq. 3). */

#include "compute_fabric_atom.h"

#include "atom.h"
#include "error.h"
#include "fix_nscd.h"

#include "nscd_contact_pairs.h"

#include <string>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
enum Column { XX, YY, ZZ, XY, XZ, YZ, COUNT, NCOLUMNS };
}

/* compute ID group fabric/atom [contacts active|all] [boundaries no|yes] */
ComputeFabricAtom::ComputeFabricAtom(LAMMPS *lmp, int narg, char **arg) :
    ComputeNSCDGrainSums(lmp, narg, arg, NCOLUMNS, "fabric/atom"), active_only(true)
{
  with_boundaries = false;    // the papers' fabric: grain-grain contacts
  with_wire = false;          // never wire-grain contacts: the keyword 'wire' is refused below
  const char *usage = "see doc/compute_fabric_atom.rst, Syntax";
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, "compute fabric/atom: keyword '{}' needs a value; {}", key, usage);
    const std::string value = arg[iarg + 1];
    if (key == "contacts" && (value == "active" || value == "all")) {
      active_only = value == "active";
    } else if (key == "boundaries" && (value == "yes" || value == "no")) {
      with_boundaries = value == "yes";
    } else if (key == "wire") {
      error->all(FLERR, "compute fabric/atom: 'wire {}': the fabric has no wire-grain "
                 "contacts; drop the keyword (see compute wire/contacts)", value);
    } else {
      error->all(FLERR, "compute fabric/atom: unknown keyword or value '{} {}'; {}", key, value, usage);
    }
  }
}

/* Each contacting pair adds n (x) n and 1 to both its grains (to the grain only, for a
   boundary), on the rank that found it (ComputeNSCDGrainSums takes ghost shares home). */
void ComputeFabricAtom::compute_peratom()
{
  start_sums();
  const auto pairs = group_contact_pairs(fix->contacts(), fix->timestep(),
                                         [this](size_t k) { return fix->boundary_of(k); });
  for (const ContactPair &p : pairs) {
    if (p.boundary != 0 && !with_boundaries) continue;
    if (active_only && !p.carries_force()) continue;
    const nscd::Vec3 &n = p.normal;
    const double nn[NCOLUMNS] = {n.x() * n.x(), n.y() * n.y(), n.z() * n.z(),
                                 n.x() * n.y(), n.x() * n.z(), n.y() * n.z(), 1.0};
    add(p.tag_i, nn);
    if (p.boundary == 0) add(p.tag_j, nn);
  }
  finish_sums();
  normalise_owned();
}

/* Sums to means; grains outside the group and grains without contacts get zeros. */
void ComputeFabricAtom::normalise_owned()
{
  for (int i = 0; i < atom->nlocal; i++) {
    double *row = array_atom[i];
    if (!(atom->mask[i] & groupbit)) {
      for (int k = 0; k < NCOLUMNS; k++) row[k] = 0.0;
    } else if (row[COUNT] > 0.0) {
      for (int k = XX; k <= YZ; k++) row[k] /= row[COUNT];
    }
  }
}
