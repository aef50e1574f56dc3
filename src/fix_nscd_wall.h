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

/* fix nscd/wall: a plane or the inside of a cylinder as a boundary of infinite mass in
   fix nscd's contact problem; may move with a prescribed velocity and be removed (unfix).
   See doc/fix_nscd_wall.rst. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nscd/wall,FixNSCDWall);
// clang-format on
#else

#ifndef LMP_FIX_NSCD_WALL_H
#define LMP_FIX_NSCD_WALL_H

#include "fix.h"
#include "nscd_boundary_fix.h"

#include <memory>

namespace LAMMPS_NS {

class FixNSCDWall : public Fix, public NSCD_NS::NSCDBoundaryFix {
 public:
  FixNSCDWall(class LAMMPS *, int, char **);
  ~FixNSCDWall() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  int modify_param(int, char **) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

  NSCD_NS::NSCDBoundary &boundary() override;

 private:
  class Wall;    // geometry, motion, contacts and reaction (fix_nscd_wall.cpp)
  std::unique_ptr<Wall> wall;

  int parse_option(int narg, char **arg, int iarg);
  void warn_about_grains_in_the_wall();
};

}    // namespace LAMMPS_NS

#endif
#endif
