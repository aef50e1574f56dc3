/* -*- c++ -*- ----------------------------------------------------------
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

/* Creating atoms at positions every rank knows (create_wire, create_grains): each rank
   creates those in its own sub-domain, then all check that every one found a rank. */
#ifndef LMP_NSCD_NEW_ATOMS_H
#define LMP_NSCD_NEW_ATOMS_H

#include "atom.h"
#include "atom_vec.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"

#include <mpi.h>

#include <string>

namespace LAMMPS_NS {
namespace NSCD_NS {

// Before creating: new atoms take the slots of the last run's ghosts (as in create_atoms);
// the next run's setup rebuilds them.
inline void drop_ghosts_for_new_atoms(LAMMPS *lmp)
{
  lmp->atom->nghost = 0;
  lmp->atom->avec->clear_bonus();
}

// Whether this rank's sub-domain holds position x (box coordinates); lower faces in, upper out.
inline bool in_my_subdomain(Domain *domain, const double x[3])
{
  double lamda[3];
  const double *coord = x;
  if (domain->triclinic) {
    domain->x2lamda(const_cast<double *>(x), lamda);
    coord = lamda;
  }
  const double *lo = domain->triclinic ? domain->sublo_lamda : domain->sublo;
  const double *hi = domain->triclinic ? domain->subhi_lamda : domain->subhi;
  return coord[0] >= lo[0] && coord[0] < hi[0] && coord[1] >= lo[1] && coord[1] < hi[1] && coord[2] >= lo[2] &&
      coord[2] < hi[2];
}

// After creating: the new atoms' fix data, the global count (every one of `created` must have
// found a rank, else the error `lost` names the way out), tags and the atom map.
inline void finish_new_atoms(LAMMPS *lmp, bigint natoms_before, int nlocal_before, bigint created,
                             const std::string &lost)
{
  Atom *atom = lmp->atom;
  atom->data_fix_compute_variable(nlocal_before, atom->nlocal);
  bigint nlocal = atom->nlocal;
  MPI_Allreduce(&nlocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  if (atom->natoms != natoms_before + created)
    lmp->error->all(FLERR, "{} of {} {}", natoms_before + created - atom->natoms, created, lost);
  atom->tag_check();
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
