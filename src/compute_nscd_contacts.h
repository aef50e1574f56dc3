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

/* compute nscd/contacts: one row per contact point of fix nscd's last solve, or per
   contacting pair of bodies (keyword pairs), for `dump local` and analysis (force networks,
   fabric). See doc/compute_nscd_contacts.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(nscd/contacts,ComputeNSCDContacts);
// clang-format on
#else

#ifndef LMP_COMPUTE_NSCD_CONTACTS_H
#define LMP_COMPUTE_NSCD_CONTACTS_H

#include "compute.h"

#include <cstdint>

namespace LAMMPS_NS {

class ComputeNSCDContacts : public Compute {
 public:
  ComputeNSCDContacts(class LAMMPS *, int, char **);
  ~ComputeNSCDContacts() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  class FixNSCD *fix;
  int nmax;
  bool active_only;
  bool per_pair;
  void grow(int n);
  bool in_group(std::int64_t tag) const;
  void fill_point_rows();
  void fill_pair_rows();
};

}    // namespace LAMMPS_NS

#endif
#endif
