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

// Newton's impact law wherever in a step an impact falls (doc/Howto_nscd_solver.rst, "Which
// contacts act: the Signorini rule"), through fix nscd, pair_style nscd's speculative
// contacts and fix nscd/wall, at the default theta = 1: grains head-on (unit cubes face to
// face, balls) and a cube dropped flat on a plane wall, frictionless, e = 1, 0.5, 0, the
// impact at 20 phases spread over one step. "processors * 1 1" puts the ranks' cut at x = 0,
// through the pairs' contact and the dropped cube, under mpirun -np 2.
//
// Tolerance on the rebound speed: 1 % of e v (the issue's), far above what the scheme
// leaves here: head-on without gravity Newton's law holds at the impact step to the solver
// tolerance; under gravity the rebound may miss the velocity gravity adds within the step
// of the impact, g dt = 0.1 % of v, because the scheme does not resolve when in the step
// the impact falls. On main 8e85fb1 e = 1 cubes parted at 2.5 % to 100 % of v, balls at
// 5 % to 100 %, depending on the phase.
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"

#include <cmath>
#include <fstream>
#include <string>

using namespace LAMMPS_NS;

namespace {

constexpr double kDt = 0.001;
constexpr int kPhases = 20;
constexpr double kRelativeTolerance = 0.01;
// Energy may grow by this fraction per step: e = 1 keeps it to the solver tolerance (1e-12).
constexpr double kEnergyRoundOff = 1e-9;

}    // namespace

class RestitutionTest : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    if (rank() == 0) std::ofstream(scratch("shapes")) << kIsotropicShapes;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  void scene(double e, const char *shape)
  {
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array",
              "boundary f f f", "processors * 1 1", "shapes read " + scratch("shapes"),
              "region box block -5 5 -5 5 -5 5", "create_box 1 box", "pair_style nscd",
              "pair_coeff * * 0.0 restitution " + num(e), "neigh_modify every 1 delay 0 check yes",
              "timestep " + num(kDt)});
    shape_ = shape;
  }
  void add(double x, double y, double z)
  {
    run("create_atoms 1 single " + num(x) + " " + num(y) + " " + num(z));
  }
  void start_solver()
  {
    commands({"shapes assign all shape " + shape_ + " density 1",
              "fix solver all nscd tolerance 1e-12 max_sweeps 10000", "run 0"});
  }

  // Kinetic plus potential energy (gravity g along -z) minus 1/2 m g dt v_z: what the
  // theta = 1 step (x += dt v_new, symplectic Euler) keeps exactly in free flight.
  double step_energy(double g)
  {
    auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
    double mine = 0.0, all = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      const double m = avec->rmass[i], *v = lmp->atom->v[i], *w = avec->omega[i];
      // isotropic inertia (cube, ball): the world spin's energy needs no rotation
      const double I = avec->inertia[i][0];
      mine += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
          0.5 * I * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) +
          m * g * lmp->atom->x[i][2] - 0.5 * m * g * kDt * v[2];
    }
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }

  // Two grains head-on along x at +-1, their gap closed at `phase` of the third step; after
  // the impact they part at e times 2. Energy never grows, momentum is kept.
  void head_on(const char *shape, const char *name, double e, int phase)
  {
    const std::string what = std::string(name) + ", e " + num(e) + ", phase " +
        std::to_string(phase) + "/" + std::to_string(kPhases);
    scene(e, shape);
    const double approach = 2.0;
    const double gap = approach * kDt * (2.0 + static_cast<double>(phase) / kPhases);
    add(-0.5 - 0.5 * gap, 0.0, 0.0);
    add(0.5 + 0.5 * gap, 0.0, 0.0);
    commands({"set atom 1 vx 1.0", "set atom 2 vx -1.0"});
    start_solver();
    const double start = step_energy(0.0);
    double energy = start;
    for (int step = 0; step < 8; step++) {
      run("run 1 pre no post no");
      const double now = step_energy(0.0);
      ASSERT_LE(now, energy + kEnergyRoundOff * start) << what << ", step " << step;
      energy = now;
    }
    const double v1 = velocity_of(1)[0], v2 = velocity_of(2)[0];
    EXPECT_NEAR(v2 - v1, e * approach, kRelativeTolerance * approach) << what;
    EXPECT_NEAR(v1 + v2, 0.0, 1e-12) << what;
  }

  void drop_on_wall(double e, int phase)
  {
    const std::string what = "e " + num(e) + ", phase " + std::to_string(phase) + "/" +
        std::to_string(kPhases);
    const double g = 1.0, v_start = 1.0, wall = -5.0;
    scene(0.0, "1");    // the unit cube
    const double gap = v_start * kDt * (2.0 + static_cast<double>(phase) / kPhases);
    add(0.0, 0.0, wall + 0.5 + gap);    // straddles the ranks' cut x = 0
    commands({"fix floor all nscd/wall plane 0 0 " + num(wall) + " 0 0 1 restitution " + num(e),
              "fix gravity all gravity " + num(g) + " vector 0 0 -1",
              "set atom 1 vz " + num(-v_start)});
    start_solver();
    // time and speed of the impact in continuous time: gap = v t + g t^2 / 2
    const double t_impact = (std::sqrt(v_start * v_start + 2.0 * g * gap) - v_start) / g;
    const double v_impact = v_start + g * t_impact;
    const double start = step_energy(g);
    double energy = start, rebound = -1.0;
    for (int step = 0; step < 20; step++) {
      const double before = velocity_of(1)[2];
      run("run 1 pre no post no");
      const double now = step_energy(g), after = velocity_of(1)[2];
      ASSERT_LE(now, energy + kEnergyRoundOff * std::abs(start)) << what << ", step " << step;
      ASSERT_GE(position_of(1)[2] - 0.5 - wall, -1e-9) << what << ", step " << step;
      energy = now;
      if (rebound < 0.0 && before < 0.0 && after >= 0.0) rebound = after;
    }
    ASSERT_GE(rebound, 0.0) << what << ": no impact";
    EXPECT_NEAR(rebound, e * v_impact, kRelativeTolerance * v_impact) << what;
    if (e == 0.0) {
      EXPECT_NEAR(velocity_of(1)[2], 0.0, 1e-9) << what;
    }
  }

  std::string shape_;
};

TEST_F(RestitutionTest, HeadOnCubesPartAtEWhereverTheImpactFallsInTheStep)
{
  for (const double e : {1.0, 0.5, 0.0})
    for (int phase = 0; phase < kPhases; phase++) {
      restart_instance();
      head_on("1", "cubes", e, phase);
    }
}

// The one-vertex shape (a ball: the solver's sphere fast path) the same way.
TEST_F(RestitutionTest, HeadOnBallsPartAtEWhereverTheImpactFallsInTheStep)
{
  for (const double e : {1.0, 0.5, 0.0})
    for (int phase = 0; phase < kPhases; phase++) {
      restart_instance();
      head_on("3", "balls", e, phase);
    }
}

// A unit cube falling flat at 1 under g = 1 onto fix nscd/wall (restitution e), the impact
// at 20 phases of the third step: it leaves at e times its speed at the impact (in
// continuous time), the energy of the time stepping never grows, it never sinks into the
// wall, and with e = 0 it stays on the wall at rest.
TEST_F(RestitutionTest, CubeDroppedOnAWallLeavesAtEWhereverTheImpactFallsInTheStep)
{
  for (const double e : {1.0, 0.5, 0.0})
    for (int phase = 0; phase < kPhases; phase++) {
      restart_instance();
      drop_on_wall(e, phase);
    }
}
