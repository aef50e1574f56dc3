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

/* create_grains: fills a region with grains of random shapes from the shape library, on two
   staggered lattices or at random positions, without overlap with each other or with the
   grains already there. Every placement is decided from global data, so the same atoms
   (IDs, positions, shapes, orientations) come out on any number of ranks. See
   doc/create_grains.rst. */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(create_grains,CreateGrains);
// clang-format on
#else

#ifndef LMP_CREATE_GRAINS_H
#define LMP_CREATE_GRAINS_H

#include "command.h"

#include <memory>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {
class NSCDBoundary;
}

class CreateGrains : public Command {
 public:
  CreateGrains(class LAMMPS *);
  ~CreateGrains() override;
  void command(int, char **) override;

 private:
  struct Request;      // the parsed command (create_grains.cpp)
  struct Placed;       // a grain for the overlap test: shape id and pose
  struct Candidate;    // a site with its drawn shape and orientation
  std::unique_ptr<Request> request;
  class AtomVecSpheropolyhedron *avec;

  void parse(int narg, char **arg);
  std::vector<Placed> gather_grains_near_region() const;
  std::vector<Candidate> lattice_sites() const;
  Candidate draw(long index, const double x[3]) const;
  bool random_site(long index, double x[3]) const;
  double deepest_overlap(const Candidate &c, const std::vector<Placed> &grains) const;
  std::vector<NSCD_NS::NSCDBoundary *> walls_of_new_grains() const;
  double deepest_wall_overlap(const Candidate &c, const std::vector<NSCD_NS::NSCDBoundary *> &walls) const;
  struct NearWire;    // the wire elements near the region and their thickness
  NearWire wire_elements_near_region() const;
  bool touches_wire(const Candidate &c, const NearWire &wire) const;
  void create(const std::vector<Candidate> &accepted);
};

}    // namespace LAMMPS_NS

#endif
#endif
