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

/* The unit systems this package integrates in. Its integrators (fix nscd for the grains and
   the plate, fix wire for the nodes) take force = mass x acceleration and energy = mass x
   speed^2 without LAMMPS' conversion factors force->ftm2v and force->mvv2e, which are 1 in
   units lj, si, cgs, micro and nano but not in real, metal or electron: there a grain would
   fall thousands of times faster or slower than under fix nve. Refused rather than converted:
   the package's scenes (grains of millimetres to metres) have no use for molecular units.
   For the .cpp files of this package (not style headers: LAMMPS compiles those into its core). */

#ifndef LMP_NSCD_UNITS_H
#define LMP_NSCD_UNITS_H

#include "error.h"
#include "force.h"
#include "lammps.h"
#include "update.h"

namespace LAMMPS_NS {
namespace NSCD_NS {

inline void require_plain_mechanics(LAMMPS *lmp, const char *style)
{
  if (lmp->force->ftm2v == 1.0 && lmp->force->mvv2e == 1.0) return;
  lmp->error->all(FLERR, "{}: units {} convert force to mass x accel by {:.6g}; use units lj, si, cgs, "
                  "micro or nano (doc/Howto_nscd_units.rst)",
                  style, lmp->update->unit_style, lmp->force->ftm2v);
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
