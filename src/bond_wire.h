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

/* bond_style wire: the tensile spring of one wire element, f = k_elo * strain
   (lib/wire/elastic_forces.h). k_elo is a force (EA of the continuum wire); the rest length
   r0 is given per bond type. With `string yes` the element carries no compression.
   fix wire calls the same kernel through law() inside its subcycle. See doc/bond_style_wire.rst. */

#ifdef BOND_CLASS
// clang-format off
BondStyle(wire,BondWire);
// clang-format on
#else

#ifndef LMP_BOND_WIRE_H
#define LMP_BOND_WIRE_H

#include "bond.h"

#include <vector>

// Spelled out, not nscd::wire: LAMMPS core includes this header and may compile as C++11.
namespace nscd {
namespace wire {
struct AxialLaw;
struct AxialForces;
}    // namespace wire
}    // namespace nscd

namespace LAMMPS_NS {

class BondWire : public Bond {
 public:
  BondWire(class LAMMPS *);
  ~BondWire() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;

  // The axial law and rest length of bond type `type` (what fix wire's subcycle uses).
  nscd::wire::AxialLaw law(int type) const;
  double rest_length(int type) const { return r0[type]; }

  // Forces on the two nodes of a bond of type `type` between positions a and b; a LAMMPS
  // error naming the bond if the element has zero length.
  nscd::wire::AxialForces element(int type, const double *a, const double *b) const;

 private:
  // per bond type, index 1..nbondtypes (lib/wire's AxialLaw; kept as plain numbers so that
  // this header, which style_bond.h pulls into LAMMPS' core, needs no lib/ header)
  std::vector<double> k_elo, r0;
  std::vector<char> is_string;    // 1: no force in compression

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
#endif
