/* compute fabric/atom: the fabric tensor of each grain (the papers' Eq. 3). */

#include "compute_fabric_atom.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_nscd.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "nscd_contact_pairs.h"

#include <string>

using namespace LAMMPS_NS;

namespace {
enum Column { XX, YY, ZZ, XY, XZ, YZ, COUNT, NCOLUMNS };
}

/* compute ID group fabric/atom [contacts active|all] [boundaries no|yes] [wire no] */
ComputeFabricAtom::ComputeFabricAtom(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  const char *usage = "expected 'compute ID group fabric/atom [contacts active|all] "
                      "[boundaries no|yes] [wire no]'";
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, "compute fabric/atom: keyword '{}' needs a value; {}", key, usage);
    const std::string value = arg[iarg + 1];
    if (key == "contacts" && (value == "active" || value == "all")) {
      active_only = value == "active";
    } else if (key == "boundaries" && (value == "yes" || value == "no")) {
      with_boundaries = value == "yes";
    } else if (key == "wire" && value == "no") {
      // the default; wire contacts need compute wire/contacts' data, which fix wire does not
      // publish yet
    } else if (key == "wire" && value == "yes") {
      error->all(FLERR, "compute fabric/atom: 'wire yes' is not available yet: fix wire does "
                 "not publish its wire-grain contacts; use 'wire no' (the default)");
    } else {
      error->all(FLERR, "compute fabric/atom: unknown keyword or value '{} {}'; {}", key, value, usage);
    }
  }
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  comm_reverse = NCOLUMNS;
}

ComputeFabricAtom::~ComputeFabricAtom()
{
  memory->destroy(array_atom);
}

void ComputeFabricAtom::init()
{
  const auto fixes = modify->get_fix_by_style("^nscd$");
  if (fixes.empty()) error->all(FLERR, "compute fabric/atom needs fix nscd (its contacts make the fabric)");
  fix = dynamic_cast<FixNSCD *>(fixes.front());
}

void ComputeFabricAtom::clear(int n)
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(array_atom);
    memory->create(array_atom, nmax, NCOLUMNS, "fabric/atom:array_atom");
  }
  for (int i = 0; i < n; i++)
    for (int k = 0; k < NCOLUMNS; k++) array_atom[i][k] = 0.0;
}

/* Each contacting pair adds n (x) n and 1 to both its grains (to the grain only, for a
   boundary), on the rank that found it: into the owned atom or a ghost copy, whose share
   reverse communication takes to the owner. Atoms are found by ID, as at a run's start the
   contacts are the last solve's and local indices may have changed since. */
void ComputeFabricAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  clear(atom->nlocal + atom->nghost);
  const auto pairs = group_contact_pairs(fix->contacts(), fix->timestep(),
                                         [this](size_t k) { return fix->boundary_of(k); });
  bigint absent = 0;
  for (const ContactPair &p : pairs) {
    if (p.boundary != 0 && !with_boundaries) continue;
    if (active_only && !p.carries_force()) continue;
    const nscd::Vec3 &n = p.normal;
    const double nn[NCOLUMNS] = {n.x() * n.x(), n.y() * n.y(), n.z() * n.z(),
                                 n.x() * n.y(), n.x() * n.z(), n.y() * n.z(), 1.0};
    if (!add(p.tag_i, nn)) absent++;
    if (p.boundary == 0 && !add(p.tag_j, nn)) absent++;
  }
  comm->reverse_comm(this);
  normalise_owned();
  warn_about_absent_grains(absent);
}

bool ComputeFabricAtom::add(std::int64_t tag, const double *nn)
{
  const int i = atom->map((tagint) tag);
  if (i < 0) return false;
  for (int k = 0; k < NCOLUMNS; k++) array_atom[i][k] += nn[k];
  return true;
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

/* Only between runs: a grain of the last solve's contacts may have left this rank's atoms
   and ghosts when the run's setup redistributed them. Its contacts are then missing. */
void ComputeFabricAtom::warn_about_absent_grains(bigint absent)
{
  bigint all = 0;
  MPI_Allreduce(&absent, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all == 0 || comm->me != 0 || last_warning_step == update->ntimestep) return;
  last_warning_step = update->ntimestep;
  error->warning(FLERR, "compute fabric/atom {}: {} contact ends of fix nscd's last solve name "
                 "grains this rank no longer holds (atoms were redistributed since, at the start "
                 "of a run); their contacts are left out at step {}", id, all, update->ntimestep);
}

int ComputeFabricAtom::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < NCOLUMNS; k++) buf[m++] = array_atom[i][k];
  return m;
}

void ComputeFabricAtom::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < NCOLUMNS; k++) array_atom[list[i]][k] += buf[m++];
}

double ComputeFabricAtom::memory_usage()
{
  return (double) nmax * NCOLUMNS * sizeof(double);
}
