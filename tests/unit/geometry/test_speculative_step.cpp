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

// One time step of a grain turning about its first contact onto a neighbour: the contact
// geometry feeds the solver, the pose is advanced, and the overlap after the step is
// measured with the exact geometry. The speculative points (contact_grains'
// speculative_distance) must hold the turning grain at the surface.
#include "bar_across_block.h"
#include "geometry/contact.h"
#include "shape/spheropolyhedron.h"
#include "solver/contact_problem.h"
#include "solver/rigid_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace nscd {
namespace {

struct StepResult {
  double overlap = 0.0;     // largest overlap after the step (0 if none)
  int points = 0;           // contact points given to the solver
};

// A bar resting edge-first across a fixed block (lower crossing touching, the upper one
// `upper` higher), turning about the lower crossing at `spin` so that the upper crossing
// comes down by 2 half_width spin dt within the step, far more than its gap. The contacts
// are activated as pair_style nscd does: within 1.5 times what the pair can close
// (|v| + |w| R) dt, speculative points as far when `speculative`, else none.
StepResult step_bar_turning_onto_block(double upper, double spin, double dt, bool speculative)
{
  test::BarAcrossBlock scene;
  scene.tilt = std::asin(upper / (2 * scene.half_width));
  Pose bar = scene.bar_pose();
  const Pose block = scene.block_pose();
  const Vec3 pivot(-scene.half_width, 0.0, 0.5 + 2 * scene.radius);
  const Vec3 w(0.0, spin, 0.0);    // lowers the +x end
  const Vec3 v = w.cross(bar.position - pivot);
  const GrainInertia inertia = grain_inertia_from_density(scene.bar, 1.0);

  ContactProblem problem;
  SolverBody moving;
  moving.position = bar.position;
  moving.velocity = v;
  moving.angular_velocity = w;
  moving.inv_mass = 1.0 / inertia.mass;
  moving.inv_inertia = world_inverse_inertia(inertia.inertia, bar.orientation);
  moving.external_angular_impulse = dt * gyroscopic_torque(inertia.inertia, bar.orientation, w);
  SolverBody fixed;
  fixed.position = block.position;
  problem.bodies = {moving, fixed};

  const double closing = v.norm() + w.norm() * scene.bar.bounding_radius;
  const double activation = 1.5 * closing * dt;
  ContactWorkspace ws;
  const ContactSet set = contact_grains(scene.bar, bar, scene.block, block, activation, ws,
                                        speculative ? activation : 0.0);
  for (const ContactPoint &p : set) {
    Contact c;
    c.body_i = 0;
    c.body_j = 1;
    c.point = p.point;
    c.normal = p.normal;
    c.gap = p.gap;
    c.friction = 0.5;
    c.key = {1, 2, p.key};
    problem.contacts.push_back(c);
  }
  SolverOptions options;
  options.dt = dt;
  options.theta = 1.0;
  options.tolerance = 1e-12;
  options.max_sweeps = 100000;
  EXPECT_TRUE(solve(problem, options).converged);

  const SolverBody &after = problem.bodies[0];
  advance_pose(bar, v, w, after.velocity, after.angular_velocity, dt, 1.0);
  StepResult out;
  out.points = set.count;
  for (const ContactPoint &p : contact_grains(scene.bar, bar, scene.block, block, 0.0, ws, 0.0))
    out.overlap = std::max(out.overlap, -p.gap);
  return out;
}

// The bar's upper crossing is 1e-3 above the block and comes down at 6 per unit time
// (0.06 in the step of 0.01). With the speculative crossing point the solver stops it at
// the surface (the bar then pivots about it, lifting its lower crossing): no overlap beyond
// 1e-6 of the grain's size. Without it, the crossing sinks in by nearly the whole 0.06.
TEST(SpeculativeStep, GrainTurningAboutAnEdgeCrossingStopsAtTheSurface)
{
  const double upper = 1e-3, spin = 10.0, dt = 0.01, size = 2.0;
  const StepResult held = step_bar_turning_onto_block(upper, spin, dt, true);
  EXPECT_EQ(held.points, 2);
  EXPECT_LE(held.overlap, 1e-6 * size);

  const StepResult unseen = step_bar_turning_onto_block(upper, spin, dt, false);
  EXPECT_EQ(unseen.points, 1);
  EXPECT_GT(unseen.overlap, 0.5 * 2 * 0.3 * spin * dt);    // the test can fail
}

}    // namespace
}    // namespace nscd
