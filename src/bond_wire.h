/* bond_style wire: the tensile spring of one wire element, f = k_elo * strain
   (lib/wire/elastic_forces.h). k_elo is a force (EA of the continuum wire); the rest length
   r0 is given per bond type. With `string yes` the element carries no compression.
   fix wire calls the same kernel through law() inside its subcycle. See doc/bond_style_wire.md. */

#ifdef BOND_CLASS
// clang-format off
BondStyle(wire,BondWire);
// clang-format on
#else

#ifndef LMP_BOND_WIRE_H
#define LMP_BOND_WIRE_H

#include "bond.h"

#include "wire/elastic_forces.h"

#include <vector>

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
  const nscd::wire::AxialLaw &law(int type) const { return laws[type]; }
  double rest_length(int type) const { return r0[type]; }

  // Forces on the two nodes of a bond of type `type` between positions a and b; a LAMMPS
  // error naming the bond if the element has zero length.
  nscd::wire::AxialForces element(int type, const nscd::Vec3 &a, const nscd::Vec3 &b) const;

 private:
  std::vector<nscd::wire::AxialLaw> laws;    // per bond type, index 1..nbondtypes
  std::vector<double> r0;

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
#endif
