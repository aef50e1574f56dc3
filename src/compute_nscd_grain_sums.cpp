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

/* The shared part of the per-grain computes over fix nscd's contacts (see the header). */

#include "compute_nscd_grain_sums.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_nscd.h"
#include "fix_wire.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;

ComputeNSCDGrainSums::ComputeNSCDGrainSums(LAMMPS *lmp, int narg, char **arg, int columns, const char *style,
                                           Combine combine) :
    Compute(lmp, narg, arg), fix(nullptr), wire(nullptr), style(style), with_boundaries(true),
    with_wire(true), wire_asked(false), combine(combine), nmax(0), absent(0), last_warning_step(-1)
{
  peratom_flag = 1;
  size_peratom_cols = columns;
  comm_reverse = columns;
}

ComputeNSCDGrainSums::~ComputeNSCDGrainSums()
{
  memory->destroy(array_atom);
}

void ComputeNSCDGrainSums::init()
{
  const auto fixes = modify->get_fix_by_style("^nscd$");
  if (fixes.empty()) error->all(FLERR, "compute {} needs fix nscd (it reads that fix's contacts)", style);
  fix = dynamic_cast<FixNSCD *>(fixes.front());
  find_wire();
}

bool ComputeNSCDGrainSums::parse_contact_keyword(const std::string &key, const std::string &value)
{
  if (value != "yes" && value != "no") return false;
  if (key == "boundaries") with_boundaries = value == "yes";
  else if (key == "wire") wire_asked = with_wire = value == "yes";
  else return false;
  return true;
}

/* After the fixes' init: the fix wire whose contacts count, asked to record its contact
   points (it records them only when asked). */
void ComputeNSCDGrainSums::find_wire()
{
  wire = nullptr;
  if (!with_wire) return;
  for (Fix *f : modify->get_fix_list())
    if (auto *w = dynamic_cast<FixWire *>(f)) wire = w;
  if (!wire && wire_asked)
    error->all(FLERR, "compute {} {}: 'wire yes' needs a fix wire; drop the keyword or define fix wire first",
               style, id);
  if (wire) wire->record_contacts();
}

void ComputeNSCDGrainSums::start_sums()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(array_atom);
    memory->create(array_atom, nmax, size_peratom_cols, "nscd/grain_sums:array_atom");
  }
  for (int i = 0; i < atom->nlocal + atom->nghost; i++)
    for (int k = 0; k < size_peratom_cols; k++) array_atom[i][k] = 0.0;
  absent = 0;
}

/* Atoms are found by ID: at a run's start the contacts are the last solve's and local
   indices may have changed since. */
bool ComputeNSCDGrainSums::add(std::int64_t tag, const double *row)
{
  const int i = atom->map((tagint) tag);
  if (i < 0) {
    absent++;
    return false;
  }
  combine_into(array_atom[i], row);
  return true;
}

void ComputeNSCDGrainSums::combine_into(double *into, const double *row) const
{
  for (int k = 0; k < size_peratom_cols; k++)
    into[k] = combine == Combine::sum ? into[k] + row[k] : std::max(into[k], row[k]);
}

void ComputeNSCDGrainSums::finish_sums()
{
  comm->reverse_comm(this);
  bigint all = 0;
  MPI_Allreduce(&absent, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all == 0 || comm->me != 0 || last_warning_step == update->ntimestep) return;
  last_warning_step = update->ntimestep;
  error->warning(FLERR, "compute {} {}: {} contacts left out at step {}: their grains left this "
                 "rank (doc/compute_fabric_atom.rst, Errors)", style, id, all, update->ntimestep);
}

int ComputeNSCDGrainSums::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < size_peratom_cols; k++) buf[m++] = array_atom[i][k];
  return m;
}

void ComputeNSCDGrainSums::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int i = 0; i < n; i++) combine_into(array_atom[list[i]], buf + (size_t) i * size_peratom_cols);
}

double ComputeNSCDGrainSums::memory_usage()
{
  return (double) nmax * size_peratom_cols * sizeof(double);
}
