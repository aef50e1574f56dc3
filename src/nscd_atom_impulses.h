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

/* The warm-start impulses kept with the atoms (fix nscd): per atom, the records of its
   contacts seen from it (nscd::ImpulseRecord with tag_i = the atom's ID). A contact between
   two grains is kept by both of its atoms, a boundary contact by its grain, so the rank that
   solves a contact after the atoms moved owns at least one atom that holds its record. */

#ifndef LMP_NSCD_ATOM_IMPULSES_H
#define LMP_NSCD_ATOM_IMPULSES_H

#include "nscd_atom_records.h"
#include "nscd_restart_blocks.h"

#include "solver/warm_start.h"

namespace LAMMPS_NS {
namespace NSCD_NS {

using NSCDAtomImpulses = NSCDAtomRecords<nscd::ImpulseRecord>;
static_assert(NSCDAtomImpulses::VALUES_PER_RECORD == NSCD_NS::VALUES_PER_IMPULSE_RECORD,
              "an impulse record's doubles in restart files and in exchange buffers");

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
