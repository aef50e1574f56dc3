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

/* The boundaries' shared start-of-run check (nscd_boundary.h). */

#include "nscd_boundary.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "lammps.h"

#include "shape/spheropolyhedron.h"

#include <mpi.h>

namespace LAMMPS_NS {
namespace NSCD_NS {

GrainInBoundary deepest_grain_in(LAMMPS *lmp, NSCDBoundary &boundary, const AtomVecSpheropolyhedron &avec,
                                 int groupbit)
{
  Atom *atom = lmp->atom;
  struct {
    double share;
    int rank;
  } mine{0.0, lmp->comm->me}, worst{0.0, 0};
  double found[3] = {0.0, 0.0, 0.0};    // depth, atom ID, bounding radius
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || avec.shape[i] == 0) continue;
    const nscd::Spheropolyhedron &shape = avec.shape_of(i);
    const double depth = boundary.deepest_overlap(shape, avec.pose(i), 0.0);
    if (depth / shape.bounding_radius > mine.share) {
      mine.share = depth / shape.bounding_radius;
      found[0] = depth, found[1] = (double) atom->tag[i], found[2] = shape.bounding_radius;
    }
  }
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, lmp->world);
  if (!(worst.share > 0.0)) return {0.0, 0.0, 0.0, 0};
  MPI_Bcast(found, 3, MPI_DOUBLE, worst.rank, lmp->world);
  return {worst.share, found[0], found[2], (tagint) found[1]};
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS
