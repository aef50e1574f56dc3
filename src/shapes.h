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

/* The `shapes` command: loads, generates, writes and assigns the grain shapes of
   atom_style spheropolyhedron. See doc/shapes.rst. */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(shapes,Shapes);
// clang-format on
#else

#ifndef LMP_NSCD_SHAPES_H
#define LMP_NSCD_SHAPES_H

#include "command.h"

#include <string>

namespace LAMMPS_NS {

class AtomVecSpheropolyhedron;

class Shapes : public Command {
 public:
  Shapes(class LAMMPS *lmp) : Command(lmp), avec(nullptr) {}
  void command(int, char **) override;

 private:
  AtomVecSpheropolyhedron *avec;

  void read(int, char **);
  void random(int, char **);
  void write(int, char **);
  void info(int, char **);
  void assign(int, char **);
  void check_mass_properties(int lo, int hi, double density, double mass);
  void broadcast(std::string &text);    // from rank 0 to all
};

}    // namespace LAMMPS_NS

#endif
#endif
