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

/* fix nscd/plate: a horizontal loading plate above the grains: a rigid body with its own
   mass that moves only along z (no rotation), pushed down by a load that grows linearly in
   time (or stays constant). Takes part in fix nscd's contact problem. See
   doc/fix_nscd_plate.rst. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nscd/plate,FixNSCDPlate);
// clang-format on
#else

#ifndef LMP_FIX_NSCD_PLATE_H
#define LMP_FIX_NSCD_PLATE_H

#include "fix.h"
#include "nscd_boundary_fix.h"

#include <memory>

namespace LAMMPS_NS {

class FixNSCDPlate : public Fix, public NSCD_NS::NSCDBoundaryFix {
 public:
  FixNSCDPlate(class LAMMPS *, int, char **);
  ~FixNSCDPlate() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

  NSCD_NS::NSCDBoundary &boundary() override;

 private:
  class Plate;    // motion, load, contacts and reaction (fix_nscd_plate.cpp)
  std::unique_ptr<Plate> plate;
};

}    // namespace LAMMPS_NS

#endif
#endif
