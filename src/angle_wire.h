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

/* angle_style wire: the rotational spring at a wire node, moment M = k_rot * (nu - nu0) with
   nu = pi - theta (theta = LAMMPS' angle, so nu = 0 for a straight wire) and nu0 = pi - theta0
   the turn at rest (0 unless angle_coeff gives theta0), energy k_rot (nu - nu0)^2 / 2
   (lib/wire/elastic_forces.h). k_rot = EI / l for element length l.
   fix wire calls the same kernel through joint() in its subcycle. See doc/angle_style_wire.rst. */

#ifdef ANGLE_CLASS
// clang-format off
AngleStyle(wire,AngleWire);
// clang-format on
#else

#ifndef LMP_ANGLE_WIRE_H
#define LMP_ANGLE_WIRE_H

#include "angle.h"

#include <vector>

// Spelled out, not nscd::wire: LAMMPS core includes this header and may compile as C++11.
namespace nscd {
namespace wire {
struct BendingForces;
}    // namespace wire
}    // namespace nscd

namespace LAMMPS_NS {

class AngleWire : public Angle {
 public:
  AngleWire(class LAMMPS *);
  ~AngleWire() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  double equilibrium_angle(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, int, int, int) override;

  double k_rot(int type) const { return stiffness[type]; }
  double rest_turn(int type) const { return rest[type]; }    // nu0 = pi - theta0, radians

  // Forces of the joint a-b-c (b = the node carrying the spring) of angle type `type`;
  // a LAMMPS error if an element has zero length.
  nscd::wire::BendingForces joint(int type, const double *a, const double *b, const double *c) const;

 private:
  std::vector<double> stiffness;    // k_rot per angle type, index 1..nangletypes
  std::vector<double> rest;         // nu0 per angle type (0: straight at rest)

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
#endif
