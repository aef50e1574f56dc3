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

/* compute wire/local: one row per wire element (bond of bond_style wire) with the IDs of its
   two nodes, strain, tension and elastic energy, evaluated by the bond style's kernel at
   the current positions. For `dump local`. See doc/compute_wire_local.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(wire/local,ComputeWireLocal);
// clang-format on
#else

#ifndef LMP_COMPUTE_WIRE_LOCAL_H
#define LMP_COMPUTE_WIRE_LOCAL_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeWireLocal : public Compute {
 public:
  ComputeWireLocal(class LAMMPS *, int, char **);
  ~ComputeWireLocal() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  int rows_allocated;
  class BondWire *bond;
};

}    // namespace LAMMPS_NS

#endif
#endif
