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

/* compute nscd/crush/atom: per grain, how close its contact forces bring it to crushing: the
   largest contact force F on it, its volume-equivalent diameter d, the characteristic tensile
   stress F / d^2 and that over a size-dependent strength. See doc/compute_nscd_crush_atom.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(nscd/crush/atom,ComputeNSCDCrushAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_NSCD_CRUSH_ATOM_H
#define LMP_COMPUTE_NSCD_CRUSH_ATOM_H

#include "compute_nscd_grain_sums.h"

namespace LAMMPS_NS {

class ComputeNSCDCrushAtom : public ComputeNSCDGrainSums {
 public:
  ComputeNSCDCrushAtom(class LAMMPS *, int, char **);
  void compute_peratom() override;

 private:
  double strength;                // sigma_0: the strength of a grain of size d_0
  double reference_size;          // d_0 (size keyword)
  double weibull;                 // Weibull modulus m (0: no size effect)

  void parse(int narg, char **arg);
  void add_largest(double tag, double force);
  void add_grain_contacts();
  void add_wire_contacts();
  void finish_owned();
};

}    // namespace LAMMPS_NS

#endif
#endif
