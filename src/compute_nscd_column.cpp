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

/* compute nscd/column: per grain of the group, the top of its true surface (lib/shape
   extent); reduced over the ranks into the column's height and retained fraction. */

#include "compute_nscd_column.h"
#include "nscd_args.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "error.h"
#include "nscd_arrays.h"
#include "update.h"

#include "shape/spheropolyhedron.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
enum Output { HEIGHT, RETAINED_FRACTION, RETAINED, GRAINS, TOP, NOUTPUTS };
}

/* compute ID group nscd/column X Y R [floor Z] [percentile P] */
ComputeNSCDColumn::ComputeNSCDColumn(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), axis_x(0.0), axis_y(0.0), radius(0.0), floor_z(-1e300), percentile(100.0),
    avec(nullptr)
{
  if (narg < 6)
    error->all(FLERR, "Illegal compute nscd/column command: expected 'compute ID group nscd/column "
               "X Y R [floor Z] [percentile P]'");
  axis_x = NSCD_NS::number(lmp, "compute nscd/column", "axis X", arg[3]);
  axis_y = NSCD_NS::number(lmp, "compute nscd/column", "axis Y", arg[4]);
  radius = NSCD_NS::number(lmp, "compute nscd/column", "radius", arg[5]);
  if (!(radius > 0.0) || !std::isfinite(radius) || !std::isfinite(axis_x) || !std::isfinite(axis_y))
    error->all(FLERR, "compute nscd/column: the axis ({}, {}) must be finite and the radius {} positive",
               arg[3], arg[4], arg[5]);
  for (int iarg = 6; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    const std::string text =
        NSCD_NS::keyword_value(lmp, "compute nscd/column", narg, arg, iarg, {"floor", "percentile"});
    const double value = NSCD_NS::number(lmp, "compute nscd/column", key, text);
    if (key == "floor") {
      if (!std::isfinite(value)) error->all(FLERR, "compute nscd/column: floor {} must be finite", arg[iarg + 1]);
      floor_z = value;
    } else if (key == "percentile") {
      if (!(value > 0.0 && value <= 100.0))
        error->all(FLERR, "compute nscd/column: percentile {} must be in (0, 100]", arg[iarg + 1]);
      percentile = value;
    }
  }
  avec = AtomVecSpheropolyhedron::find(lmp, "compute nscd/column");    // (also for use before a run)
  vector_flag = 1;
  size_vector = NOUTPUTS;
  extvector = 0;
  vector = new double[NOUTPUTS];
}

ComputeNSCDColumn::~ComputeNSCDColumn()
{
  delete[] vector;
}

void ComputeNSCDColumn::init()
{
  avec = AtomVecSpheropolyhedron::find(lmp, "compute nscd/column");
}

/* The given percentile of all ranks' tops (100: the highest); 0 without grains. Gathered
   on every rank: one double per grain of the column, once per output step. */
double ComputeNSCDColumn::height_of(const std::vector<double> &my_tops)
{
  int mine = (int) my_tops.size();
  std::vector<int> counts(comm->nprocs), offsets(comm->nprocs, 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int r = 1; r < comm->nprocs; r++) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> tops(offsets.back() + counts.back());
  MPI_Allgatherv(my_tops.data(), mine, MPI_DOUBLE, tops.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, world);
  if (tops.empty()) return 0.0;
  // nearest rank: the smallest top with at least `percentile` % of the tops at or below it
  const size_t rank = (size_t) std::max(0.0, std::ceil(percentile / 100.0 * tops.size()) - 1.0);
  std::nth_element(tops.begin(), tops.begin() + rank, tops.end());
  return tops[rank];
}

void ComputeNSCDColumn::compute_vector()
{
  invoked_vector = update->ntimestep;
  std::vector<double> tops;
  double counts[2] = {0.0, 0.0}, highest = -INFINITY;    // retained, grains
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || avec->shape[i] == 0) continue;
    const double *x = atom->x[i];
    const double top = x[2] + nscd::extent(avec->shape_of(i), quat_of(avec->quat[i]), nscd::Vec3::UnitZ());
    highest = std::max(highest, top);
    counts[1] += 1.0;
    if (std::hypot(x[0] - axis_x, x[1] - axis_y) > radius) continue;
    tops.push_back(top);
    if (x[2] > floor_z) counts[0] += 1.0;
  }
  double all[2];
  MPI_Allreduce(counts, all, 2, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&highest, &vector[TOP], 1, MPI_DOUBLE, MPI_MAX, world);
  vector[HEIGHT] = height_of(tops);
  vector[RETAINED] = all[0];
  vector[GRAINS] = all[1];
  vector[RETAINED_FRACTION] = all[1] > 0.0 ? all[0] / all[1] : 0.0;
  if (all[1] == 0.0) vector[TOP] = 0.0;    // no grains yet
}
