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

/* compute nscd/column: measures of a granular column around a vertical axis: its height
   from the true grain surfaces and the fraction of grains it retains. See
   doc/compute_nscd_column.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(nscd/column,ComputeNSCDColumn);
// clang-format on
#else

#ifndef LMP_COMPUTE_NSCD_COLUMN_H
#define LMP_COMPUTE_NSCD_COLUMN_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeNSCDColumn : public Compute {
 public:
  ComputeNSCDColumn(class LAMMPS *, int, char **);
  ~ComputeNSCDColumn() override;
  void init() override;
  void compute_vector() override;

 private:
  double axis_x, axis_y, radius;                      // the column: within radius of the axis
  double floor_z;                                      // retained: centre above this
  double percentile;                                   // height: this percentile of the grains' tops
  class AtomVecSpheropolyhedron *avec;

  double height_of(const std::vector<double> &my_tops);
};

}    // namespace LAMMPS_NS

#endif
#endif
