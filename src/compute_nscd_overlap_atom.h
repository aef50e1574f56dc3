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

/* compute nscd/overlap/atom: per grain, its deepest overlap with another grain and that
   grain's atom ID, from pair nscd's last contact detection. Finds grains placed inside each
   other (e.g. by create_atoms on a lattice), so that a deck can delete them.
   See doc/compute_nscd_overlap_atom.rst. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(nscd/overlap/atom,ComputeNSCDOverlapAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_NSCD_OVERLAP_ATOM_H
#define LMP_COMPUTE_NSCD_OVERLAP_ATOM_H

#include "compute.h"

#include <cstdint>

namespace LAMMPS_NS {

class ComputeNSCDOverlapAtom : public Compute {
 public:
  ComputeNSCDOverlapAtom(class LAMMPS *, int, char **);
  ~ComputeNSCDOverlapAtom() override;
  void init() override;
  void compute_peratom() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  class PairNSCD *pair;
  int nmax;

  int index_of(std::int64_t tag) const;
  void keep_deeper(int i, double depth, double partner);
};

}    // namespace LAMMPS_NS

#endif
#endif
