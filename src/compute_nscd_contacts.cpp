/* compute nscd/contacts: contact points, normals and forces (impulse / dt) per row. */

#include "compute_nscd_contacts.h"

#include "atom.h"
#include "error.h"
#include "fix_nscd.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "solver/contact_problem.h"

#include <cstdint>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
enum Column { ID_I, ID_J, PX, PY, PZ, NX, NY, NZ, FN, FT, FX, FY, FZ, GAP, STATUS, NCOLUMNS };
}

/* compute ID group nscd/contacts [active] : with `active`, only contacts that carry a force. */
ComputeNSCDContacts::ComputeNSCDContacts(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  if (narg > 4 || (narg == 4 && strcmp(arg[3], "active") != 0))
    error->all(FLERR, "Illegal compute nscd/contacts command: expected 'compute ID group "
               "nscd/contacts [active]'");
  active_only = narg == 4;
  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = NCOLUMNS;
}

ComputeNSCDContacts::~ComputeNSCDContacts()
{
  memory->destroy(array_local);
}

void ComputeNSCDContacts::init()
{
  const auto fixes = modify->get_fix_by_style("^nscd$");
  if (fixes.empty()) error->all(FLERR, "compute nscd/contacts needs fix nscd (it reports its contacts)");
  fix = dynamic_cast<FixNSCD *>(fixes.front());
}

void ComputeNSCDContacts::grow(int n)
{
  if (n <= nmax) return;
  nmax = n;
  memory->destroy(array_local);
  memory->create(array_local, nmax, NCOLUMNS, "nscd/contacts:array_local");
}

/* Rows for contacts whose two grains are in the group (a boundary counts as in the group).
   Atoms are found by ID: when invoked at the start of a run, the contacts are those of the
   last solve while local indices may have changed since. */
void ComputeNSCDContacts::compute_local()
{
  invoked_local = update->ntimestep;
  const auto &contacts = fix->contacts();
  const double dt = fix->timestep();
  grow((int) contacts.size());
  auto in_group = [this](std::int64_t tag) {
    const int i = atom->map((tagint) tag);
    return i >= 0 && (atom->mask[i] & groupbit);
  };
  int rows = 0;
  for (size_t k = 0; k < contacts.size(); k++) {
    const nscd::Contact &c = contacts[k];
    const int boundary = fix->boundary_of(k);
    if (!in_group(c.key.tag_i) || (boundary == 0 && !in_group(c.key.tag_j))) continue;
    const double fn = c.impulse.dot(c.normal) / dt;
    if (active_only && !(fn > 0.0)) continue;
    const nscd::Vec3 f = c.impulse / dt;
    double *row = array_local[rows++];
    row[ID_I] = (double) c.key.tag_i;
    row[ID_J] = boundary == 0 ? (double) c.key.tag_j : -(double) boundary;
    for (int d = 0; d < 3; d++) {
      row[PX + d] = c.point[d];
      row[NX + d] = c.normal[d];
      row[FX + d] = f[d];
    }
    row[FN] = fn;
    row[FT] = (f - fn * c.normal).norm();
    row[GAP] = c.gap;
    row[STATUS] = (double) static_cast<int>(c.regime);
  }
  size_local_rows = rows;
}

double ComputeNSCDContacts::memory_usage()
{
  return (double) nmax * NCOLUMNS * sizeof(double);
}
