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

/* compute nscd/stress/atom: per grain, the Love-Weber stress of its contact forces,
   sigma_i = (1/V_i) sum_c sym(f_c (x) (x_c - x_i)), from fix nscd's last solve (grains,
   walls, plate) and fix wire's last step (wire-grain contacts). See
   doc/compute_nscd_stress_atom.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(nscd/stress/atom,ComputeNSCDStressAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_NSCD_STRESS_ATOM_H
#define LMP_COMPUTE_NSCD_STRESS_ATOM_H

#include "compute_nscd_grain_sums.h"

namespace LAMMPS_NS {

class ComputeNSCDStressAtom : public ComputeNSCDGrainSums {
 public:
  ComputeNSCDStressAtom(class LAMMPS *, int, char **);
  void compute_peratom() override;

 private:
  bool per_volume;                // volume grain (default): a stress | none: stress x volume

  void add_force(double tag, const double *force, const double *point);
  void add_grain_contacts();
  void add_wire_contacts();
  void finish_owned();
};

}    // namespace LAMMPS_NS

#endif
#endif
