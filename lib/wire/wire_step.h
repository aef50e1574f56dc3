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

// One grain step of a wire: n Gear-5 substeps (subcycle.h) with, in each, the elastic
// forces of the wire's elements and joints (elastic_forces.h), its soft contacts
// (contact_model.h), constant external forces and a viscous drag on the nodes.
//
// The caller may hold copies of nodes it does not integrate (ghost atoms of other MPI
// ranks): they sit after the integrated nodes in nodes.positions / velocities / forces
// (nodes.copies of them), and the caller's Exchange fills them in before the forces of a
// substep are computed and hands their forces back afterwards. A caller without copies
// passes an Exchange that does nothing.
#pragma once

#include "wire/contact_model.h"
#include "wire/elastic_forces.h"
#include "wire/subcycle.h"

#include <array>
#include <vector>

namespace nscd::wire {

class Exchange {
 public:
  // Positions and velocities of the copies, from their owners.
  virtual void share_copies(WireNodeSet &nodes) = 0;
  // The copies' forces added to their owners' (on other callers).
  virtual void return_copy_forces(WireNodeSet &nodes) = 0;

 protected:
  ~Exchange() = default;
};

// Wall-clock seconds spent in each part of the steps so far, and node-substeps done.
struct StepTiming {
  double contacts = 0.0, elastic = 0.0, integration = 0.0, exchange = 0.0;
  double node_substeps = 0.0;
};

// Energies and contact counts of the last substep.
struct StepTotals {
  ElasticEnergy elastic;
  ContactTotals contacts;
};

class WireStep {
 public:
  WireNodeSet nodes;               // integrated nodes, then copies (nodes.copies)
  WireTopology topology;           // elements and joints, indices into the nodes and copies
  std::vector<Vec3> external;      // per integrated node, held over the step
  double damping = 0.0;            // drag -damping * v on every node
  ContactModel *contacts = nullptr;    // none: no contacts
  GrainForceAccumulator reactions;     // filled by the contacts

  // Elastic forces at nodes.positions (integrated nodes and copies) into nodes.forces,
  // which are zeroed first; for the caller's measurement of the external forces.
  ElasticEnergy elastic_forces_now();

  // Runs the subcycle of one grain step; tau of each substep is its time into the step.
  StepTotals run(const SubcyclePlan &plan, const std::array<double, 6> &corrector, Exchange &exchange,
                 StepTiming &timing);

  // Largest distance an integrated, free node moved from `start` (its position before the
  // step, per integrated node).
  double largest_displacement(const std::vector<Vec3> &start) const;

 private:
  ElasticKernel elastic_;    // the topology's elastic forces, prepared when it changes
};

}    // namespace nscd::wire
