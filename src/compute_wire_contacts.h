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

/* compute wire/contacts: one row per contact point of the wire (wire-grain, wire-wire,
   wire-wall/plate) in fix wire's last step, forces averaged over its substeps, for
   `dump local` and tools/nscd-analysis wire-contacts. See doc/compute_wire_contacts.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(wire/contacts,ComputeWireContacts);
// clang-format on
#else

#ifndef LMP_COMPUTE_WIRE_CONTACTS_H
#define LMP_COMPUTE_WIRE_CONTACTS_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeWireContacts : public Compute {
 public:
  ComputeWireContacts(class LAMMPS *, int, char **);
  ~ComputeWireContacts() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  class FixWire *fix;
  int nmax;
};

}    // namespace LAMMPS_NS

#endif
#endif
