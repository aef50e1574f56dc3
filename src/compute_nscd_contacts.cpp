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

/* compute nscd/contacts: contact points, normals and forces (impulse / dt) per row, or the
   same summed per contacting pair of bodies (keyword pairs). */

#include "compute_nscd_contacts.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_nscd.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "nscd_arrays.h"
#include "nscd_contact_pairs.h"

#include "solver/contact_problem.h"

#include <cstdint>
#include <cstring>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
// one row per contact point
enum Column { ID_I, ID_J, PX, PY, PZ, NX, NY, NZ, FN, FT, FX, FY, FZ, GAP, STATUS, NCOLUMNS };
// one row per contacting pair (keyword pairs)
enum PairColumn {
  P_ID_I, P_ID_J, XI, YI, ZI, XJ, YJ, ZJ, P_FN, P_FX, P_FY, P_FZ, P_POINTS, P_NX, P_NY, P_NZ, NPAIRCOLUMNS
};
}    // namespace

/* compute ID group nscd/contacts [active] [pairs] : with `active`, only contacts that carry a
   force; with `pairs`, one row per contacting pair instead of per point. */
ComputeNSCDContacts::ComputeNSCDContacts(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), fix(nullptr), nmax(0), active_only(false), per_pair(false)
{
  for (int iarg = 3; iarg < narg; iarg++) {
    if (strcmp(arg[iarg], "active") == 0) active_only = true;
    else if (strcmp(arg[iarg], "pairs") == 0) per_pair = true;
    else
      error->all(FLERR, "Illegal compute nscd/contacts command: unknown keyword '{}' (expected "
                 "'compute ID group nscd/contacts [active] [pairs]')", arg[iarg]);
  }
  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = per_pair ? (int) NPAIRCOLUMNS : (int) NCOLUMNS;
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
  memory->create(array_local, nmax, size_local_cols, "nscd/contacts:array_local");
}

/* Atoms are found by ID: when invoked at the start of a run, the contacts are those of the
   last solve while local indices may have changed since. */
bool ComputeNSCDContacts::in_group(std::int64_t tag) const
{
  const int i = atom->map((tagint) tag);
  return i >= 0 && (atom->mask[i] & groupbit);
}

void ComputeNSCDContacts::compute_local()
{
  invoked_local = update->ntimestep;
  if (per_pair) fill_pair_rows();
  else fill_point_rows();
}

/* Rows for contacts whose two grains are in the group (a boundary counts as in the group). */
void ComputeNSCDContacts::fill_point_rows()
{
  const auto &contacts = fix->contacts();
  const double dt = fix->timestep();
  grow((int) contacts.size());
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

/* One row per pair of bodies in contact (nscd_contact_pairs.h), with both grains' centres as
   they are now: j's image nearest to i, so that x_i - x_j is the branch vector also across a
   periodic boundary. For a boundary, "centre of j" is the mean contact point. A pair is on
   the rank that found it, so each appears once. */
void ComputeNSCDContacts::fill_pair_rows()
{
  const auto pairs = group_contact_pairs(fix->contacts(), fix->timestep(),
                                         [this](size_t k) { return fix->boundary_of(k); });
  grow((int) pairs.size());
  int rows = 0;
  for (const ContactPair &p : pairs) {
    if (!in_group(p.tag_i) || (p.boundary == 0 && !in_group(p.tag_j))) continue;
    if (active_only && !p.carries_force()) continue;
    const double *xi = atom->x[atom->map((tagint) p.tag_i)];
    double xj[3];
    if (p.boundary == 0) domain->closest_image(xi, atom->x[atom->map((tagint) p.tag_j)], xj);
    else store(p.point, xj);
    double *row = array_local[rows++];
    row[P_ID_I] = (double) p.tag_i;
    row[P_ID_J] = p.boundary == 0 ? (double) p.tag_j : -(double) p.boundary;
    for (int d = 0; d < 3; d++) {
      row[XI + d] = xi[d];
      row[XJ + d] = xj[d];
      row[P_FX + d] = p.force[d];
      row[P_NX + d] = p.normal[d];
    }
    row[P_FN] = p.normal_force;
    row[P_POINTS] = p.points;
  }
  size_local_rows = rows;
}

double ComputeNSCDContacts::memory_usage()
{
  return (double) nmax * size_local_cols * sizeof(double);
}
