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

/* compute wire/contacts: the rows fix wire recorded over its last step, those whose
   element's first node (or the node, at a boundary) is in the group. */

#include "compute_wire_contacts.h"

#include "atom.h"
#include "error.h"
#include "fix_wire.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;

ComputeWireContacts::ComputeWireContacts(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), fix(nullptr), nmax(0)
{
  if (narg > 3)
    error->all(FLERR, "Illegal compute wire/contacts command: unexpected '{}' (it takes no keyword: "
               "'compute ID group wire/contacts')", arg[3]);
  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = FixWire::CONTACT_COLUMNS;
}

ComputeWireContacts::~ComputeWireContacts()
{
  memory->destroy(array_local);
}

/* After fix wire's init (fixes come first), which may have made a new contact model. */
void ComputeWireContacts::init()
{
  fix = nullptr;
  for (Fix *f : modify->get_fix_list())
    if (auto *w = dynamic_cast<FixWire *>(f)) fix = w;
  if (!fix) error->all(FLERR, "compute wire/contacts needs fix wire (it reports that fix's contacts)");
  int dim = 0;
  const auto *k_n = static_cast<const double *>(fix->extract("k_n", dim));
  if (!k_n || !(*k_n > 0.0))
    error->all(FLERR, "compute wire/contacts {}: fix wire {} has no contacts (k_n {}); give "
               "it 'k_n K' and 'radius R', or drop the compute", id, fix->id, k_n ? *k_n : 0.0);
  fix->record_contacts();
}

void ComputeWireContacts::compute_local()
{
  invoked_local = update->ntimestep;
  const std::vector<double> rows = fix ? fix->contact_rows() : std::vector<double>();
  const int cols = FixWire::CONTACT_COLUMNS, all = (int) (rows.size() / cols);
  if (all > nmax) {
    nmax = all;
    memory->destroy(array_local);
    memory->create(array_local, std::max(1, nmax), cols, "wire/contacts:array_local");
  }
  int n = 0;
  for (int r = 0; r < all; r++) {
    const int i = atom->map((tagint) rows[(size_t) r * cols]);
    if (i < 0 || !(atom->mask[i] & groupbit)) continue;
    std::copy(&rows[(size_t) r * cols], &rows[(size_t) r * cols] + cols, array_local[n++]);
  }
  size_local_rows = n;
}

double ComputeWireContacts::memory_usage()
{
  return (double) nmax * size_local_cols * sizeof(double);
}
