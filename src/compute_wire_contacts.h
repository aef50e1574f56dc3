/* compute wire/contacts: one row per contact point of the wire (wire-grain, wire-wire,
   wire-wall/plate) in fix wire's last step, forces averaged over its substeps, for
   `dump local` and tools/nscd-analysis wire-contacts. See doc/compute_wire_contacts.md. */

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
  class FixWire *fix = nullptr;
  int nmax = 0;
};

}    // namespace LAMMPS_NS

#endif
#endif
