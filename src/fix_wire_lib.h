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

/* fix wire's private state (not a style header): the lib/wire objects behind FixWire's
   pointer, shared by fix_wire.cpp (setup, the step) and fix_wire_io.cpp
   (communication, per-atom arrays, restart, reports). */
#ifndef LMP_FIX_WIRE_LIB_H
#define LMP_FIX_WIRE_LIB_H

#include "fix_wire.h"
#include "nscd_atom_records.h"
#include "nscd_boundary.h"
#include "wire/contact_model.h"
#include "wire/wire_step.h"

#include <array>
#include <memory>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

// A wall or the plate as the wire's contact model sees it.
struct BoundaryView final : nscd::wire::NodeBoundary {
  NSCDBoundary *boundary = nullptr;
  int groupbit = 0;    // the nodes it touches: those of its fix group
  nscd::wire::BoundaryLink link{};
  nscd::ContactPoint touch_sphere(const nscd::Vec3 &c, double r, double tau) const override
  {
    return boundary->touch_sphere(c, r, tau);
  }
  nscd::Vec3 surface_velocity() const override { return boundary->surface_velocity(); }
};

}    // namespace NSCD_NS

struct FixWire::Lib : nscd::wire::Exchange {
  FixWire *fix;
  nscd::wire::SoftContactLaw law;
  std::unique_ptr<nscd::wire::ContactModel> contacts;
  nscd::wire::SubcyclePlan plan;
  std::array<double, 6> corrector = nscd::wire::gear5_corrector_coefficients(nscd::wire::GearCorrector::ThreeSixteenths);
  nscd::wire::WireStep step;    // owned nodes, then their ghost copies; this rank's elements and joints
  nscd::wire::StepTiming timing;
  std::vector<NSCD_NS::BoundaryView> boundaries;
  std::vector<nscd::Vec3> step_start;
  // The friction memories kept with the atoms (owned atoms, by the key's first ID) while
  // atoms move between ranks and in restart files; memories_with_atoms says when.
  NSCD_NS::NSCDAtomRecords<nscd::wire::StoredContact> atom_memories;
  explicit Lib(FixWire *f) : fix(f) {}
  // The subcycle's communication, wire nodes only: positions and velocities to the ghost
  // copies, their forces back to the owners.
  void share_copies(nscd::wire::WireNodeSet &) override { fix->exchange_copies(false); }
  void return_copy_forces(nscd::wire::WireNodeSet &) override { fix->exchange_copies(true); }
};

}    // namespace LAMMPS_NS

#endif
