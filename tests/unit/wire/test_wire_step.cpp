/* ----------------------------------------------------------------------
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

// WireStep (lib/wire/wire_step.h): one grain step of the wire with external forces, drag,
// elastic forces and the caller's exchange of node copies.
#include "wire/wire_step.h"

#include <gtest/gtest.h>

#include <cmath>

namespace nscd::wire {
namespace {

// Counts the calls; a copy of node 0 follows it (as a ghost of another rank would), and
// the force on the copy is handed back to node 0.
struct CopyOfFirstNode final : Exchange {
  int shared = 0, returned = 0;
  void share_copies(WireNodeSet &nodes) override
  {
    ++shared;
    if (nodes.copies == 0) return;
    nodes.positions[nodes.size()] = nodes.positions[0];
    nodes.velocities[nodes.size()] = nodes.velocities[0];
  }
  void return_copy_forces(WireNodeSet &nodes) override
  {
    ++returned;
    if (nodes.copies > 0) nodes.forces[0] += nodes.forces[nodes.size()];
  }
};

// Two nodes joined by an element through a copy: node 1's partner is the copy of node 0
// (index 2). Pulled apart by equal and opposite external forces F with drag c, the pair
// reaches the elongation F L0 / k_elo and the drag stops it: dx -> F L0 / k_elo, v -> 0.
// The same pair through the node itself gives the same positions to round-off.
TEST(WireStep, CopiesAreSharedAndTheirForcesReturnedEverySubstep)
{
  const double k_elo = 10.0, L0 = 1.0, F = 0.1, m = 0.01, c = 0.2;
  double positions[2][2];
  for (int through_copy = 0; through_copy < 2; ++through_copy) {
    WireStep step;
    step.nodes.reset({Vec3(0, 0, 0), Vec3(L0, 0, 0)}, m, 1e-3);
    step.nodes.copies = through_copy;
    step.topology.elements.push_back({through_copy ? 2 : 0, 1, L0, AxialLaw{k_elo, true}});
    step.external = {Vec3(-F, 0, 0), Vec3(F, 0, 0)};
    step.damping = c;
    step.reactions.reset(0);
    const SubcyclePlan plan{20, 1e-3};
    CopyOfFirstNode exchange;
    StepTiming timing;
    for (int s = 0; s < 200; ++s) step.run(plan, gear5_corrector_coefficients(GearCorrector::ThreeSixteenths), exchange, timing);
    EXPECT_EQ(exchange.shared, 4000);
    EXPECT_EQ(exchange.returned, 4000);
    EXPECT_EQ(timing.node_substeps, 2.0 * 4000);
    const double dx = step.nodes.state[1].position().x() - step.nodes.state[0].position().x();
    EXPECT_NEAR(dx - L0, F * L0 / k_elo, 1e-6) << "through copy " << through_copy;
    for (int k = 0; k < 2; ++k) positions[through_copy][k] = step.nodes.state[k].position().x();
  }
  EXPECT_NEAR(positions[0][0], positions[1][0], 1e-14);
  EXPECT_NEAR(positions[0][1], positions[1][1], 1e-14);
}

}    // namespace
}    // namespace nscd::wire
