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

/* A fix that is a boundary of fix nscd's contact problem (fix nscd/wall, fix nscd/plate).
   fix nscd and fix wire find such fixes among the defined ones and work with their
   boundary() (nscd_boundary.h). Only LAMMPS-free declarations here: the style headers that
   include this one are pulled into LAMMPS' core by style_fix.h. */

#ifndef LMP_NSCD_BOUNDARY_FIX_H
#define LMP_NSCD_BOUNDARY_FIX_H

namespace LAMMPS_NS {
namespace NSCD_NS {

class NSCDBoundary;

class NSCDBoundaryFix {
 public:
  virtual NSCDBoundary &boundary() = 0;

 protected:
  // Not virtual, so that the fix's destructor keeps the exception specification of LAMMPS'
  // Fix (which differs between LAMMPS versions); LAMMPS deletes the Fix, not this.
  ~NSCDBoundaryFix() = default;
};

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
