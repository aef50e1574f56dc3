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

/* pair_style nscd: finds the contacts between neighbouring grains (rigid spheropolyhedra)
   and holds the per type-pair contact laws (friction, restitution). It adds no force of its
   own: fix nscd solves the contact impulses (and carries their virial). See
   doc/pair_nscd.rst. */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(nscd,PairNSCD);
// clang-format on
#else

#ifndef LMP_PAIR_NSCD_H
#define LMP_PAIR_NSCD_H

#include "pair.h"

#include <memory>
#include <string>
#include <vector>

namespace nscd {
struct Contact;
}

namespace LAMMPS_NS {

class PairNSCD : public Pair {
 public:
  PairNSCD(class LAMMPS *);
  ~PairNSCD() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;
  // Cutoff of `neighbor multi` collections. Overrides Pair::radii2cut of LAMMPS up to
  // 29 Aug 2024 / 4 Feb 2025 (no `override`: LAMMPS 4 Jul 2026 dropped it and sums the two
  // radii itself, so there the activation distance must fit in the neighbour skin).
  double radii2cut(double, double);

  // Grain-grain contacts found by the last compute(): body indices are local atom
  // indices (owned or ghost), keys are (tag, tag, feature) canonical for warm starting.
  const std::vector<nscd::Contact> &contacts() const;
  double activation_distance() const { return activation; }    // the smallest, for every pair
  // How far past `activation` the speculative activation of a pair may reach: the
  // neighbour cutoff includes it, so every pair that close is in the list.
  double reach_distance() const { return reach; }

 protected:
  double activation_given;           // from `activation D`; < 0: use the fraction
  double activation_fraction;        // of the smallest bounding radius in the library
  double activation;                 // in use, set by init_style()
  double reach_given;                // from `reach D`; < 0: use reach_fraction
  double reach_fraction;             // of the smallest bounding radius in the library
  double reach;                      // in use, set by init_style()
  double **mu, **restitution_coeff;
  class AtomVecSpheropolyhedron *avec;
  // The contacts of the last compute() and the geometry's scratch space, behind a pointer:
  // style_pair.h pulls this header into LAMMPS' core, which need not compile lib/ and Eigen.
  struct Found;
  std::unique_ptr<Found> found;

  void allocate();
  void add_grain_contacts(int i, int j);
  void check_periodic_box_holds_grains();
  void stop_if_damaged(std::string problem);
};

}    // namespace LAMMPS_NS

#endif
#endif
