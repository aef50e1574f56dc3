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

/* compute fabric/atom: per grain, the fabric tensor F_i = (1/N_i) sum n (x) n over its
   contacting pairs (one normal per pair) and the number N_i of such pairs, from fix nscd's
   last solve. See doc/compute_fabric_atom.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(fabric/atom,ComputeFabricAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_FABRIC_ATOM_H
#define LMP_COMPUTE_FABRIC_ATOM_H

#include "compute_nscd_grain_sums.h"

namespace LAMMPS_NS {

class ComputeFabricAtom : public ComputeNSCDGrainSums {
 public:
  ComputeFabricAtom(class LAMMPS *, int, char **);
  void compute_peratom() override;

 private:
  bool active_only;                // contacts active (default) | all

  void normalise_owned();
};

}    // namespace LAMMPS_NS

#endif
#endif
