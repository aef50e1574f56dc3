/* compute fabric/atom: per grain, the fabric tensor F_i = (1/N_i) sum n (x) n over its
   contacting pairs (one normal per pair) and the number N_i of such pairs, from fix nscd's
   last solve. See doc/compute_fabric_atom.md. */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(fabric/atom,ComputeFabricAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_FABRIC_ATOM_H
#define LMP_COMPUTE_FABRIC_ATOM_H

#include "compute.h"

#include <cstdint>

namespace LAMMPS_NS {

class ComputeFabricAtom : public Compute {
 public:
  ComputeFabricAtom(class LAMMPS *, int, char **);
  ~ComputeFabricAtom() override;
  void init() override;
  void compute_peratom() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  class FixNSCD *fix = nullptr;
  int nmax = 0;
  bool active_only = true;         // contacts active (default) | all
  bool with_boundaries = false;    // boundaries no (default) | yes
  bigint last_warning_step = -1;

  void clear(int n);
  bool add(std::int64_t tag, const double *nn);
  void normalise_owned();
  void warn_about_absent_grains(bigint absent);
};

}    // namespace LAMMPS_NS

#endif
#endif
