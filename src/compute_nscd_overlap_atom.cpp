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

/* compute nscd/overlap/atom: the deepest overlap of each grain with another grain. */

#include "compute_nscd_overlap_atom.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair_nscd.h"
#include "update.h"

#include "solver/contact_problem.h"

using namespace LAMMPS_NS;

namespace {
enum Column { DEPTH, PARTNER, NCOLUMNS };
}

/* compute ID group nscd/overlap/atom */
ComputeNSCDOverlapAtom::ComputeNSCDOverlapAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), pair(nullptr), nmax(0)
{
  if (narg != 3)
    error->all(FLERR, "compute nscd/overlap/atom takes no keywords, got '{}'; expected "
               "'compute ID group nscd/overlap/atom'", arg[3]);
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  comm_reverse = NCOLUMNS;
}

ComputeNSCDOverlapAtom::~ComputeNSCDOverlapAtom()
{
  memory->destroy(array_atom);
}

void ComputeNSCDOverlapAtom::init()
{
  pair = dynamic_cast<PairNSCD *>(force->pair_match("nscd", 1));
  if (!pair)
    error->all(FLERR, "compute nscd/overlap/atom needs pair_style nscd (its contacts give the "
               "overlaps)");
}

/* The contact points of pair nscd's last detection (a run's setup, or its last step: after
   `run 0` they describe the current positions). A pair's overlap reaches both grains, on
   the rank that found it, into the owned atom or a ghost copy; reverse communication takes
   the deeper of the copies to the owner. Atoms are found by ID: local indices may have
   changed since the detection when atoms were redistributed. */
void ComputeNSCDOverlapAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  const int n = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(array_atom);
    memory->create(array_atom, nmax, NCOLUMNS, "nscd/overlap/atom:array_atom");
  }
  for (int i = 0; i < n; i++) array_atom[i][DEPTH] = array_atom[i][PARTNER] = 0.0;
  for (const nscd::Contact &c : pair->contacts()) {
    if (c.gap >= 0.0) continue;
    keep_deeper(index_of(c.key.tag_i), -c.gap, (double) c.key.tag_j);
    keep_deeper(index_of(c.key.tag_j), -c.gap, (double) c.key.tag_i);
  }
  comm->reverse_comm(this);
  for (int i = 0; i < atom->nlocal; i++)
    if (!(atom->mask[i] & groupbit)) array_atom[i][DEPTH] = array_atom[i][PARTNER] = 0.0;
}

/* -1 for an atom this rank no longer holds (deleted since the detection: the array map
   can keep its old index, hence the check of the tag there). */
int ComputeNSCDOverlapAtom::index_of(std::int64_t tag) const
{
  const int i = atom->map((tagint) tag);
  return i >= 0 && i < atom->nlocal + atom->nghost && atom->tag[i] == (tagint) tag ? i : -1;
}

/* The deeper overlap wins; of two equally deep, the smaller partner ID, so that the result
   does not depend on which rank found which contact. */
void ComputeNSCDOverlapAtom::keep_deeper(int i, double depth, double partner)
{
  if (i < 0) return;
  double *row = array_atom[i];
  if (depth > row[DEPTH] || (depth == row[DEPTH] && depth > 0.0 && partner < row[PARTNER]))
    row[DEPTH] = depth, row[PARTNER] = partner;
}

int ComputeNSCDOverlapAtom::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) buf[m++] = array_atom[i][DEPTH], buf[m++] = array_atom[i][PARTNER];
  return m;
}

void ComputeNSCDOverlapAtom::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) keep_deeper(list[k], buf[2 * k], buf[2 * k + 1]);
}

double ComputeNSCDOverlapAtom::memory_usage()
{
  return (double) nmax * NCOLUMNS * sizeof(double);
}
