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

/* compute wire/local: per-element strain, tension and energy from bond_style wire. */

#include "compute_wire_local.h"

#include "atom.h"
#include "bond_wire.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"

#include "wire/elastic_forces.h"

using namespace LAMMPS_NS;

namespace {
enum Column { ID1, ID2, STRAIN, TENSION, ENERGY, NCOLUMNS };
}

/* compute ID group wire/local   (columns: id1 id2 strain tension energy) */
ComputeWireLocal::ComputeWireLocal(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), rows_allocated(0), bond(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "compute wire/local takes no arguments (got {}); its columns are id1 id2 "
               "strain tension energy", narg - 3);
  if (!atom->molecular)
    error->all(FLERR, "compute wire/local needs bonds: use 'atom_style hybrid spheropolyhedron angle'");
  local_flag = 1;
  size_local_cols = NCOLUMNS;
}

ComputeWireLocal::~ComputeWireLocal()
{
  memory->destroy(array_local);
}

void ComputeWireLocal::init()
{
  bond = dynamic_cast<BondWire *>(force->bond);
  if (!bond)
    error->all(FLERR, "compute wire/local needs bond_style wire (bond_style is '{}')",
               force->bond_style ? force->bond_style : "none");
}

/* Elements whose first node is in the group, one row each (bond list: each element once). */
void ComputeWireLocal::compute_local()
{
  invoked_local = update->ntimestep;
  double **x = atom->x;
  int rows = 0;
  for (int n = 0; n < neighbor->nbondlist; n++)
    if (atom->mask[neighbor->bondlist[n][0]] & groupbit) rows++;
  if (rows > rows_allocated) {
    memory->destroy(array_local);
    rows_allocated = rows;
    memory->create(array_local, rows_allocated, NCOLUMNS, "wire/local:array");
  }
  size_local_rows = rows;
  int row = 0;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int *b = neighbor->bondlist[n];
    if (!(atom->mask[b[0]] & groupbit)) continue;
    const nscd::wire::AxialForces e = bond->element(b[2], x[b[0]], x[b[1]]);
    double *out = array_local[row++];
    out[ID1] = atom->tag[b[0]];
    out[ID2] = atom->tag[b[1]];
    out[STRAIN] = e.strain;
    out[TENSION] = e.tension;
    out[ENERGY] = e.energy;
  }
}

double ComputeWireLocal::memory_usage()
{
  return (double) rows_allocated * NCOLUMNS * sizeof(double);
}
