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

// Invariants of fix nscd's collisions, across periodic boundaries and rank boundaries, with
// the number of ghost atoms changing during the run, with and without walls and the plate
// defined (idle, out of reach):
//  * total momentum conserved to round-off (contact impulses are equal and opposite, and
//    mass splitting across ranks applies exactly M^-1 times their sum);
//  * angular momentum in free space conserved to round-off, for grains of isotropic inertia
//    (cubes and balls: free flight leaves their spin unchanged, so only contacts act);
//  * kinetic energy never grows in frictionless collisions with restitution e <= 1 (by more
//    than 1e-8 of itself per 10 steps: e = 1 conserves it to the solver's tolerance).
// Runs serially and under mpirun -np 2 and -np 4.
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"
#include "fix.h"
#include "modify.h"

#include <array>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

enum SolverOutput { CONTACTS = 3, KE_TRANSLATION = 8, KE_ROTATION = 9 };

// The body-frame vector v turned by the orientation q = (w, x, y, z).
std::array<double, 3> rotate(const double *q, const std::array<double, 3> &v)
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  std::array<double, 3> r{};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) r[a] += R[a][b] * v[b];
  return r;
}

struct Invariants {
  std::array<double, 3> momentum{}, angular{};    // angular: about the origin
  double momentum_scale = 0.0;    // sum of m |v|: what round-off in the momentum is relative to
  double angular_scale = 0.0;     // sum of |x| m |v| + |I w|
  double kinetic = 0.0;
};

}    // namespace

class ConservationTest : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    if (rank() == 0) std::ofstream(scratch("shapes")) << kIsotropicShapes;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  Invariants measure()
  {
    auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
    double mine[9] = {};
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      const double m = avec->rmass[i], *x = lmp->atom->x[i], *v = lmp->atom->v[i];
      const double *q = avec->quat[i], *w = avec->omega[i];
      const double q_inverse[4] = {q[0], -q[1], -q[2], -q[3]};
      std::array<double, 3> spin = rotate(q_inverse, {w[0], w[1], w[2]});    // body frame
      for (int k = 0; k < 3; k++) spin[k] *= avec->inertia[i][k];
      const std::array<double, 3> Iw = rotate(q, spin);                        // world frame
      const double xv[3] = {x[1] * v[2] - x[2] * v[1], x[2] * v[0] - x[0] * v[2],
                            x[0] * v[1] - x[1] * v[0]};
      const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      for (int k = 0; k < 3; k++) {
        mine[k] += m * v[k];
        mine[3 + k] += m * xv[k] + Iw[k];
      }
      mine[6] += m * speed;
      mine[7] += r * m * speed + std::sqrt(Iw[0] * Iw[0] + Iw[1] * Iw[1] + Iw[2] * Iw[2]);
      mine[8] += 0.5 * m * speed * speed + 0.5 * (w[0] * Iw[0] + w[1] * Iw[1] + w[2] * Iw[2]);
    }
    double all[9];
    MPI_Allreduce(mine, all, 9, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    Invariants s;
    for (int k = 0; k < 3; k++) {
      s.momentum[k] = all[k];
      s.angular[k] = all[3 + k];
    }
    s.momentum_scale = all[6];
    s.angular_scale = all[7];
    s.kinetic = all[8];
    return s;
  }

  double solver_output(int index) { return lmp->modify->get_fix_by_id("solver")->compute_vector(index); }

  // Grains on a simple cubic lattice of the given spacing inside [-2.5, 2.5]^3 (27 at
  // spacing 2) in a box of half-width `half`, random velocities and spins, no gravity;
  // `isotropic`: cubes and balls, else random ballast.
  void grains(const std::string &boundary, double half, bool isotropic, double mu, double e,
              double spacing = 2.0)
  {
    const std::string h = num(half);
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array",
              "boundary " + boundary,
              isotropic ? "shapes read " + scratch("shapes")
                        : "shapes random 3 seed 7 vertices 8 14 size 0.8 1.2 radius 0.05",
              "region box block -" + h + " " + h + " -" + h + " " + h + " -" + h + " " + h,
              "create_box 1 box", "lattice sc " + num(1.0 / (spacing * spacing * spacing)), "region middle block -2.5 2.5 -2.5 2.5 -2.5 2.5 units box",
              "create_atoms 1 region middle",
              "shapes assign all shape random 1 3 11 density 1 orient random 5", "pair_style nscd",
              "pair_coeff * * " + num(mu) + " restitution " + num(e), "neighbor 0.3 bin",
              "neigh_modify every 1 delay 0 check yes", "timestep 0.002",
              "velocity all create 1.0 4711 dist gaussian mom yes rot no",
              "variable wx atom normal(0,1,12)", "variable wy atom normal(0,1,13)",
              "variable wz atom normal(0,1,14)", "set group all omega v_wx v_wy v_wz"});
  }

  // Idle boundaries, out of reach: they take part in fix nscd's body and contact bookkeeping.
  void idle_boundaries(double half)
  {
    commands({"fix floor all nscd/wall plane 0 0 " + num(-10 * half) + " 0 0 1 friction 0.5",
              "fix side all nscd/wall cylinder 0 0 0 0 0 1 " + num(10 * half),
              "fix plate all nscd/plate " + num(10 * half) + " mass 1000 friction 0.5"});
  }
};

// The reproducer of the plate bug: two frictionless cubes sliding apart on a frictionless
// floor meet across the periodic boundary and stop together (e = 0). With an idle plate
// defined, the slot its body took on an earlier step (x and y locked) was reused for a grain
// once the ghost count grew, and that grain could not move in x through contacts: the total
// x momentum jumped from -0.2 to -2.0.
TEST_F(ConservationTest, CubesMeetingAcrossThePeriodicBoundaryKeepTheirMomentum)
{
  for (bool with_plate : {false, true}) {
    restart_instance();
    // away from the periodic boundary at first: the ghost count grows as they approach it
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary p p f",
              "shapes read " + scratch("shapes"), "region box block -5 5 -5 5 -1 10",
              "create_box 1 box", "create_atoms 1 single -2.5 0 0.5", "create_atoms 1 single 2.5 0 0.5",
              "shapes assign all shape 1 density 1", "pair_style nscd", "pair_coeff * * 0.0",
              "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes", "timestep 0.001",
              "fix floor all nscd/wall plane 0 0 0 0 0 1", "fix g all gravity 1.0 vector 0 0 -1"});
    if (with_plate) run("fix plate all nscd/plate 9 mass 1");
    commands({"fix solver all nscd tolerance 1e-12 max_sweeps 5000", "set atom 1 vx -1.0",
              "set atom 2 vx 0.8", "run 0"});
    const std::string label = with_plate ? "with the plate" : "without the plate";
    for (int chunk = 0; chunk < 20; chunk++) {    // they meet at step ~2300
      run("run 200");
      ASSERT_NEAR(measure().momentum[0], -0.2, 1e-12) << label << ", step " << 200 * (chunk + 1);
    }
    EXPECT_NEAR(velocity_of(1)[0], -0.1, 1e-9) << label;
    EXPECT_NEAR(velocity_of(2)[0], -0.1, 1e-9) << label;
  }
}

// Random ballast in a periodic box: grains collide, cross the periodic boundaries and (on 2
// and 4 ranks) the rank boundaries; the total momentum stays zero to round-off for every
// friction and restitution, with and without idle walls and plate.
TEST_F(ConservationTest, MomentumOfCollidingGrainsIsConservedAcrossBoundaries)
{
  for (bool with_boundaries : {false, true})
    for (double mu : {0.0, 0.5})
      for (double e : {0.0, 0.8}) {
        restart_instance();
        grains("p p p", 2.6, false, mu, e, 1.6);    // 27 grains in a box of side 5.2: a dense gas
        if (with_boundaries) idle_boundaries(2.6);
        run("fix solver all nscd tolerance 1e-8 max_sweeps 2000");
        const std::string label = "mu " + num(mu) + " e " + num(e) +
            (with_boundaries ? " with walls and plate" : "");
        const double scale = measure().momentum_scale;
        int steps_with_contacts = 0;
        for (int chunk = 0; chunk < 50; chunk++) {
          run("run 10");
          if (solver_output(CONTACTS) > 0) steps_with_contacts++;
          const Invariants now = measure();
          for (int k = 0; k < 3; k++)
            ASSERT_NEAR(now.momentum[k], 0.0, 1e-13 * scale) << label << ", step " << 10 * (chunk + 1);
        }
        EXPECT_GE(steps_with_contacts, 20) << label << ": too few collisions to test anything";
      }
}

// Cubes and balls (isotropic inertia) flying into each other in free space: momentum and
// angular momentum conserved to round-off through the collisions, across rank boundaries;
// frictionless, the kinetic energy never grows (e = 0 and e = 1 included).
TEST_F(ConservationTest, FreeClusterKeepsMomentumAngularMomentumAndDoesNotGainEnergy)
{
  for (double mu : {0.0, 0.5})
    for (double e : {0.0, 0.8, 1.0}) {
      restart_instance();
      grains("f f f", 12.0, true, mu, e);
      // converging: v = -0.5 x plus the random part
      commands({"variable vx atom vx-0.5*x", "variable vy atom vy-0.5*y", "variable vz atom vz-0.5*z",
                "velocity all set v_vx v_vy v_vz", "fix solver all nscd tolerance 1e-10 max_sweeps 5000",
                "run 0"});
      const std::string label = "mu " + num(mu) + " e " + num(e);
      const Invariants start = measure();
      double previous_kinetic = start.kinetic;
      int steps_with_contacts = 0;
      for (int chunk = 0; chunk < 100; chunk++) {
        run("run 10");
        if (solver_output(CONTACTS) > 0) steps_with_contacts++;
        const Invariants now = measure();
        for (int k = 0; k < 3; k++) {
          ASSERT_NEAR(now.momentum[k], start.momentum[k], 1e-13 * start.momentum_scale) << label;
          ASSERT_NEAR(now.angular[k], start.angular[k], 1e-12 * start.angular_scale) << label;
        }
        if (mu == 0.0) {
          // (e = 1 conserves it up to what the solver tolerance 1e-10 leaves)
          ASSERT_LE(now.kinetic, previous_kinetic * (1.0 + 1e-8)) << label << ", step " << 10 * (chunk + 1);
          // no energy appears from nowhere: the solver's own measure agrees
          EXPECT_NEAR(solver_output(KE_TRANSLATION) + solver_output(KE_ROTATION), now.kinetic,
                      1e-10 * now.kinetic);
        }
        previous_kinetic = now.kinetic;
      }
      EXPECT_GE(steps_with_contacts, 10) << label << ": too few collisions to test anything";
      if (e == 0.0) {
        EXPECT_LT(measure().kinetic, 0.9 * start.kinetic) << label << ": inelastic";
      }
    }
}
