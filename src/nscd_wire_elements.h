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

/* The wire elements already in the box, gathered on every rank, for the setup commands that
   must not lay anything into them (create_wire, create_grains). */
#ifndef LMP_NSCD_WIRE_ELEMENTS_H
#define LMP_NSCD_WIRE_ELEMENTS_H

#include "lmptype.h"

#include "wire/wire_overlap.h"

#include <array>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
namespace NSCD_NS {

struct WireElements {
  nscd::wire::WirePieces pieces;                // one element per bond between wire nodes
  std::vector<std::array<tagint, 2>> bonds;     // its nodes' atom IDs
};

// Every bond between two wire nodes (points of atom style spheropolyhedron) but those in
// `skip` (either order), from every rank, each element with its second node at the image
// nearest to its first. Collective: a setup command's, not a step's.
WireElements gather_wire_elements(LAMMPS *lmp, const char *caller,
                                  const std::vector<std::array<tagint, 2>> &skip = {});

// The radius of the wires' elements: fix wire's, else `fallback` (no fix wire defined yet).
double wire_radius_of_fix_wire(LAMMPS *lmp, double fallback);

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
