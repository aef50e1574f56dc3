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

/* create_wire: lays a wire (nodes, bond_style wire elements, angle_style wire joints) along
   a loop, helix, line or polyline, on any number of ranks, as a new wire or continuing one
   from its free end ('from ID|last'). The path geometry is
   lib/wire/wire_path.h. See doc/create_wire.rst. */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(create_wire,CreateWire);
// clang-format on
#else

#ifndef LMP_CREATE_WIRE_H
#define LMP_CREATE_WIRE_H

#include "command.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class CreateWire : public Command {
 public:
  CreateWire(class LAMMPS *);
  ~CreateWire() override;
  void command(int, char **) override;

 private:
  struct Request;    // the parsed command (create_wire.cpp)
  std::unique_ptr<Request> request;

  void parse(int narg, char **arg);
  void find_end();       // the free end that 'from' continues, and the wire's types there
  void check_room_at_end();
  void check_types();
  void lay_out();
  void check_nodes_in_box();
  void drop_onto_what_is_below();    // 'drop yes'
  void check_overlaps();
  void check_wire_overlaps();
  void create_nodes();
  void create_bonds_and_angles();
  void broadcast(std::string &text);    // from rank 0 to all
};

}    // namespace LAMMPS_NS

#endif
#endif
