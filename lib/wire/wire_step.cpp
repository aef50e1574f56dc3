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

#include "wire/wire_step.h"

#include <algorithm>
#include <chrono>

namespace nscd::wire {

namespace {
double seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}    // namespace

ElasticEnergy WireStep::elastic_forces_now()
{
  std::fill(nodes.forces.begin(), nodes.forces.end(), Vec3::Zero());
  if (!elastic_.prepared_for(topology)) elastic_.prepare(topology);
  return elastic_.add_forces(nodes.positions, nodes.forces, true);
}

StepTotals WireStep::run(const SubcyclePlan &plan, const std::array<double, 6> &corrector, Exchange &exchange,
                         StepTiming &timing)
{
  StepTotals totals;
  double in_forces = 0.0;
  const double start = seconds();
  if (!elastic_.prepared_for(topology)) elastic_.prepare(topology);
  const Eigen::Index owned = 3 * static_cast<Eigen::Index>(nodes.size());
  using Flat = Eigen::Map<Eigen::ArrayXd>;
  using ConstFlat = Eigen::Map<const Eigen::ArrayXd>;
  run_subcycle(plan, corrector, nodes, reactions,
               [&](const SubstepInfo &info, const std::vector<Vec3> &x, const std::vector<Vec3> &v,
                   std::vector<Vec3> &f, GrainForceAccumulator &) {
                 const double t0 = seconds();
                 exchange.share_copies(nodes);
                 const double t1 = seconds();
                 // (the energies are those of the last substep)
                 totals.elastic = elastic_.add_forces(x, f, info.index + 1 == plan.substeps);
                 const double t2 = seconds();
                 if (contacts) totals.contacts = contacts->add_forces(x, v, info.time, info.dt, f, reactions);
                 const double t3 = seconds();
                 exchange.return_copy_forces(nodes);
                 if (owned > 0)    // f += external - damping v, as numbers in a row
                   Flat(f[0].data(), owned) += ConstFlat(external[0].data(), owned) - damping * ConstFlat(v[0].data(), owned);
                 const double t4 = seconds();
                 timing.exchange += (t1 - t0) + (t4 - t3);
                 timing.elastic += t2 - t1;
                 timing.contacts += t3 - t2;
                 in_forces += t4 - t0;
               });
  timing.integration += seconds() - start - in_forces;
  timing.node_substeps += static_cast<double>(nodes.size()) * plan.substeps;
  return totals;
}

double WireStep::largest_displacement(const std::vector<Vec3> &start) const
{
  double largest = 0.0;
  for (int k = 0; k < nodes.size(); ++k)
    if (!nodes.fixed[k]) largest = std::max(largest, (nodes.state[k].position() - start[k]).norm());
  return largest;
}

}    // namespace nscd::wire
