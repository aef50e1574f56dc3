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

/* A base for the per-grain computes over the contacts of the last step (compute fabric/atom,
   compute nscd/stress/atom, compute nscd/crush/atom): each contact's share goes to a grain on
   the rank that found the contact, into the owned atom or its ghost copy, and reverse
   communication combines the ghosts' shares with their owners' (a sum, or the largest
   value). Not a style itself. */

#ifndef LMP_COMPUTE_NSCD_GRAIN_SUMS_H
#define LMP_COMPUTE_NSCD_GRAIN_SUMS_H

#include "compute.h"

#include <cstdint>
#include <string>

namespace LAMMPS_NS {

class ComputeNSCDGrainSums : public Compute {
 public:
  enum class Combine { sum, largest };
  // `columns` numbers per grain; `style` names the compute in messages ("fabric/atom").
  ComputeNSCDGrainSums(class LAMMPS *, int, char **, int columns, const char *style,
                       Combine combine = Combine::sum);
  ~ComputeNSCDGrainSums() override;
  void init() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 protected:
  class FixNSCD *fix;
  class FixWire *wire;               // set by init: the fix whose wire-grain contacts count
  const char *style;
  bool with_boundaries;              // boundaries yes|no: wall and plate contacts count
  bool with_wire;                    // wire yes|no: wire-grain contacts count (if there is a fix wire)
  bool wire_asked;                   // 'wire yes' given: a missing fix wire is an error
  const Combine combine;

  // The keywords 'boundaries yes|no' and 'wire yes|no'; false if `key value` is neither.
  bool parse_contact_keyword(const std::string &key, const std::string &value);
  // Zeroes the rows of owned and ghost atoms (growing the array as needed) and counts again.
  void start_sums();
  // Combines `row` with the atom of this ID on this rank (owned or ghost): adds it, or keeps
  // the larger of each value; false if the rank has no such atom.
  bool add(std::int64_t tag, const double *row);
  // Brings the ghosts' shares to their owners; warns once per step about contact ends that
  // named grains this rank no longer holds (between runs: atoms were redistributed).
  void finish_sums();

 private:
  int nmax;
  bigint absent;
  bigint last_warning_step;

  void combine_into(double *into, const double *row) const;
  void find_wire();
};

}    // namespace LAMMPS_NS

#endif
