/* compute nscd/contacts: one row per contact point of fix nscd's last solve, for
   `dump local` and analysis (force networks, fabric). See doc/compute_nscd_contacts.md. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(nscd/contacts,ComputeNSCDContacts);
// clang-format on
#else

#ifndef LMP_COMPUTE_NSCD_CONTACTS_H
#define LMP_COMPUTE_NSCD_CONTACTS_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeNSCDContacts : public Compute {
 public:
  ComputeNSCDContacts(class LAMMPS *, int, char **);
  ~ComputeNSCDContacts() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  class FixNSCD *fix = nullptr;
  int nmax = 0;
  bool active_only = false;
  void grow(int n);
};

}    // namespace LAMMPS_NS

#endif
#endif
