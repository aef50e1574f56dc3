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

// fix nscd + pair_style nscd + fix nscd/wall against closed-form statics and dynamics.
// Units are LJ-like: g = 1 unless stated; boxes are unit cubes of density 1 (m = 1).
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"
#include "compute.h"
#include "fix_nscd.h"
#include "force.h"
#include "info.h"
#include "modify.h"
#include "nscd_restart.h"
#include "output.h"
#include "pair_nscd.h"
#include "thermo.h"

#include "solver/contact_problem.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>

using namespace LAMMPS_NS;

namespace {
const char *kShapes = R"(# a unit cube, a flat 4 x 4 x 0.5 plate and a unit cube rounded by 0.05
shape cube
radius 0
vertices 8
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
1 0 1
0 1 1
1 1 1
end
shape plate
radius 0
vertices 8
0 0 0
4 0 0
0 4 0
4 4 0
0 0 0.5
4 0 0.5
0 4 0.5
4 4 0.5
end
shape rounded_cube
radius 0.05
vertices 8
-0.5 -0.5 -0.5
0.5 -0.5 -0.5
-0.5 0.5 -0.5
0.5 0.5 -0.5
-0.5 -0.5 0.5
0.5 -0.5 0.5
-0.5 0.5 0.5
0.5 0.5 0.5
end
shape ball
radius 0.5
vertices 1
0 0 0
end
shape small_ball
radius 0.25
vertices 1
0 0 0
end
)";
}    // namespace

class NSCDTest : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    if (rank() == 0) std::ofstream(scratch("shapes")) << kShapes;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  // A closed box of side 20 with a frictional floor at z = 0; grains added by the caller.
  void scene(double mu = 0.5, const std::string &fix_options = "tolerance 1e-10 max_sweeps 2000")
  {
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
         "shapes read " + scratch("shapes"), "region box block -10 10 -10 10 -1 19",
         "create_box 2 box", "pair_style nscd", "pair_coeff * * " + num(mu),
         "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes", "timestep 0.001",
         "fix floor all nscd/wall plane 0 0 0 0 0 1 friction " + num(mu),
         "fix g all gravity 1.0 vector 0 0 -1", "fix solver all nscd " + fix_options});
  }
  void add_cube(double x, double y, double z, int type = 1)
  {
    run("create_atoms " + std::to_string(type) + " single " + num(x) + " " + num(y) + " " + num(z));
  }

  double fix_value(const std::string &fix_id, int index)
  {
    return lmp->modify->get_fix_by_id(fix_id.c_str())->compute_vector(index);
  }
  FixNSCD *solver() { return dynamic_cast<FixNSCD *>(lmp->modify->get_fix_by_id("solver")); }

  // 27 random grains on a loose lattice above the floor of a 6 x 6 box (poured by the caller)
  std::vector<std::string> small_pile_grains()
  {
    return {"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "shapes random 8 seed 7 vertices 12 20 size 0.8 1.2 axes 0.8 0.6 radius 0.05",
            "lattice sc " + num(1.0 / (1.7 * 1.7 * 1.7)), "region sites block 0 2.99 0 2.99 0 2.99",
            "region box block -0.5 6.5 -0.5 6.5 -1 8 units box", "create_box 1 box",
            "create_atoms 1 region sites", "displace_atoms all move 1.2 1.2 1.2 units box",
            "shapes assign all shape random 1 8 11 density 1 orient random 13",
            "pair_style nscd activation 0.1", "pair_coeff * * 0.5"};
  }
  // its floor (mu = 0.5), frictionless side walls, gravity 1 and the neighbour settings
  std::vector<std::string> small_pile_box()
  {
    return {"neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix xlo all nscd/wall plane 0 0 0 1 0 0", "fix xhi all nscd/wall plane 6 0 0 -1 0 0",
            "fix ylo all nscd/wall plane 0 0 0 0 1 0", "fix yhi all nscd/wall plane 0 6 0 0 -1 0",
            "fix g all gravity 1.0 vector 0 0 -1"};
  }

  // The small pile poured for 1500 steps at dt 0.005 (solved to 1e-5), saved as
  // scratch("pile.restart"); returns the box commands, which a restart does not keep. The
  // pour sweeps every contact (skip_separating no, the loop the tests' bounds were measured
  // with): the pile, chaotic at the solver's tolerance, stays the one they were set on.
  std::vector<std::string> pour_small_pile_to_restart()
  {
    const std::vector<std::string> walls = small_pile_box();
    commands(small_pile_grains());
    run("timestep 0.005");
    commands(walls);
    commands({"fix solver all nscd tolerance 1e-5 max_sweeps 2000 skip_separating no", "run 1500",
              "write_restart " + scratch("pile.restart")});
    return walls;
  }

  // Position, velocity, angular velocity of the atom with this ID (gathered to all ranks).
  std::vector<double> state_of(tagint tag)
  {
    std::vector<double> mine(9, 0.0), all(9, 0.0);
    const int i = lmp->atom->map(tag);
    auto avec = AtomVecSpheropolyhedron::find(lmp, "test");
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int d = 0; d < 3; d++) {
        mine[d] = lmp->atom->x[i][d];
        mine[3 + d] = lmp->atom->v[i][d];
        mine[6 + d] = avec->omega[i][d];
      }
    MPI_Allreduce(mine.data(), all.data(), 9, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }

  // How many ranks own at least one atom.
  int ranks_owning_atoms()
  {
    int mine = lmp->atom->nlocal > 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }

  // Sum of normal forces between atoms a and b (b = 0: any wall), over all ranks.
  double normal_force_between(tagint a, tagint b)
  {
    double mine = 0.0, all = 0.0;
    const double dt = solver()->timestep();
    for (const nscd::Contact &c : solver()->contacts()) {
      const tagint i = c.key.tag_i, j = c.body_j >= 0 ? c.key.tag_j : 0;
      if ((i == a && j == b) || (i == b && j == a)) mine += c.impulse.dot(c.normal) / dt;
    }
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }
};

TEST_F(NSCDTest, BoxRestsOnPlaneWithFourContactsAndNoDrift)
{
  scene();
  add_cube(0.3, -0.2, 0.5);
  commands({"shapes assign all shape 1 density 1", "run 2000"});
  const std::vector<double> s = state_of(1);
  EXPECT_EQ(fix_value("solver", 3), 4.0);                  // four corner contacts
  EXPECT_NEAR(fix_value("floor", 2), -1.0, 1e-9);          // reaction on the floor = -m g
  EXPECT_NEAR(s[2], 0.5, 1e-9);                            // no sinking, no drift
  EXPECT_NEAR(s[0], 0.3, 1e-12);
  EXPECT_NEAR(s[1], -0.2, 1e-12);
  for (int d = 3; d < 9; d++) EXPECT_NEAR(s[d], 0.0, 1e-9);    // at rest, no spurious spin
  EXPECT_EQ(fix_value("solver", 7), 1.0);                  // converged
}

// Gravity tilted by theta stands for an incline: the block sticks for tan(theta) < mu and
// otherwise slides with a = g (sin(theta) - mu cos(theta)).
TEST_F(NSCDTest, BlockOnInclineSticksBelowAndSlidesAboveTheFrictionAngle)
{
  const double mu = 0.5;
  for (double theta : {0.4, 0.6}) {    // tan 0.4 = 0.42 < 0.5 < tan 0.6 = 0.68
    restart_instance();
    scene(mu);
    add_cube(0.0, 0.0, 0.5);
    commands({"shapes assign all shape 1 density 1", "unfix g",
         "fix g all gravity 1.0 vector " + num(std::sin(theta)) + " 0 " + num(-std::cos(theta)),
         "run 500"});
    const std::vector<double> s = state_of(1);
    const double t = 0.5;
    if (std::tan(theta) < mu) {
      EXPECT_NEAR(s[3], 0.0, 1e-9) << "theta " << theta;
      EXPECT_NEAR(s[0], 0.0, 1e-9) << "theta " << theta;
    } else {
      const double a = std::sin(theta) - mu * std::cos(theta);
      EXPECT_NEAR(s[3], a * t, 1e-6 * a * t) << "theta " << theta;
      EXPECT_NEAR(s[2], 0.5, 1e-9);          // stays on the plane
      for (int d = 6; d < 9; d++) EXPECT_NEAR(s[d], 0.0, 1e-6);    // slides without tipping
    }
  }
}

TEST_F(NSCDTest, StackOfBoxesCarriesTheWeightAboveAtEachLevel)
{
  scene();
  for (int k = 0; k < 4; k++) add_cube(0.1 * k, 0.0, 0.5 + k);    // staggered, still stable
  commands({"shapes assign all shape 1 density 1", "run 1000"});
  EXPECT_NEAR(fix_value("floor", 2), -4.0, 1e-8);
  for (int k = 1; k <= 3; k++)    // contact between cube k and k+1 carries 4 - k weights
    EXPECT_NEAR(normal_force_between(k, k + 1), 4.0 - k, 1e-7) << "level " << k;
  for (int k = 1; k <= 4; k++) {
    const std::vector<double> s = state_of(k);
    EXPECT_NEAR(s[2], 0.5 + (k - 1), 1e-8);
    EXPECT_NEAR(s[0], 0.1 * (k - 1), 1e-9);
  }
}

// Speculative contacts: a cube thrown down at 50 activation distances per step stops on the
// floor, and another one on a resting cube, without sinking in (gap closed to 1e-6 of its
// size; restitution 0). With `reach 0` the pair's contact is found only after the top cube
// has gone into the bottom one: the same check fails.
TEST_F(NSCDTest, FastGrainsStopAtTheSurface)
{
  for (const char *reach : {"7.0", "0"}) {
    restart_instance();
    scene();
    run(std::string("pair_style nscd reach ") + reach);
    run("pair_coeff * * 0.5");
    add_cube(3.0, 0.0, 0.5 + 3.0);          // above the floor
    add_cube(-3.0, 0.0, 0.5);               // resting
    add_cube(-3.0, 0.0, 1.5 + 3.0);         // above it
    const double activation = 0.1 * std::sqrt(0.75);    // 10 % of the cube's bounding radius
    const double speed = 50.0 * activation / 0.001;
    commands({"shapes assign all shape 1 density 1", "group thrown id 1 3",
              "velocity thrown set 0 0 " + num(-speed), "run 5"});
    EXPECT_NEAR(state_of(1)[2], 0.5, 1e-6) << "onto the floor, reach " << reach;
    EXPECT_NEAR(state_of(1)[5], 0.0, 1e-6);
    EXPECT_NEAR(state_of(2)[2], 0.5, 1e-6);
    if (std::string(reach) == "0") {
      EXPECT_LT(state_of(3)[2], 1.5 - 0.1) << "found late, it sank in";
      continue;
    }
    EXPECT_NEAR(state_of(3)[2], 1.5, 1e-6) << "onto a cube";
    EXPECT_NEAR(state_of(3)[5], 0.0, 1e-6);
  }
}

// Cubes placed overlapping by 0.05 side by side on the floor: kept so by default; with
// overlap_speed 0.2 pushed apart (neither faster than the cap) until they touch, then
// stopped by floor friction.
TEST_F(NSCDTest, OverlapSpeedPushesPlacedOverlapApartAtMostAtItsSpeed)
{
  for (const char *speed : {"0", "0.2"}) {
    restart_instance();
    scene(0.5, std::string("tolerance 1e-10 max_sweeps 2000 overlap_speed ") + speed);
    add_cube(-0.475, 0.0, 0.5);
    add_cube(0.475, 0.0, 0.5);
    commands({"shapes assign all shape 1 density 1", "run 1"});
    double fastest = 0.0;
    for (int k = 0; k < 80; k++) {
      run("run 10");
      fastest = std::max({fastest, std::abs(state_of(1)[3]), std::abs(state_of(2)[3])});
    }
    const double apart = state_of(2)[0] - state_of(1)[0];
    if (std::string(speed) == "0") {
      EXPECT_NEAR(apart, 0.95, 1e-12);
      EXPECT_LT(fastest, 1e-12);
      continue;
    }
    // How floor friction shares the push between the two is not unique (they part at
    // about 0.08 and 0.12): the separation speed is what the cap bounds.
    EXPECT_GE(apart, 1.0 - 1e-9);
    EXPECT_LT(apart, 1.0 + 0.05);    // friction stops each within v^2 / (2 mu g) <= 0.04
    EXPECT_LE(fastest, 0.2 + 1e-9);
    EXPECT_NEAR(state_of(1)[3], 0.0, 1e-9);
    EXPECT_NEAR(state_of(2)[3], 0.0, 1e-9);
  }
}

// Two rounded cubes placed overlapping by 0.1 face to face, no gravity, no other force, pushed
// apart by overlap_speed: once the push is done no impulse is needed, and a solve whose
// impulses are all round-off has converged. The default (accelerated) method left a 1e-17
// impulse there and reported error / scale = 0.29, a ratio of two round-offs, for 1000
// sweeps (step 3).
TEST_F(NSCDTest, PairPushedApartWithoutOtherForcesConvergesEveryStep)
{
  for (const char *method : {"gs", "nesterov", "nncg"}) {
    restart_instance();
    scene(0.5, std::string("tolerance 1e-6 max_sweeps 1000 overlap_speed 0.2 method ") + method);
    add_cube(0.0, 0.0, 5.0);
    add_cube(0.0, 0.0, 6.0);    // rounded cubes of size 1.1: overlapping by 0.1
    commands({"unfix g", "timestep 0.005", "shapes assign all shape 3 density 1", "run 0"});
    for (int k = 0; k < 10; k++) {
      run("run 1");
      EXPECT_EQ(fix_value("solver", 7), 1.0) << method << ", step " << k + 1 << ": residual "
                                             << fix_value("solver", 1);
      EXPECT_LT(fix_value("solver", 0), 100.0) << method << ", step " << k + 1;
    }
  }
}

TEST_F(NSCDTest, PyramidOfBoxesStaysStanding)
{
  scene();
  add_cube(-0.55, 0.0, 0.5);
  add_cube(0.55, 0.0, 0.5);
  add_cube(0.0, 0.0, 1.5);
  commands({"shapes assign all shape 1 density 1", "run 1000"});
  EXPECT_NEAR(fix_value("floor", 2), -3.0, 1e-8);
  // How the top block's weight splits over its two supports is statically indeterminate
  // (each support is a patch, friction carries horizontal forces): only the total is fixed.
  const double left = normal_force_between(1, 0), right = normal_force_between(2, 0);
  EXPECT_NEAR(left + right, 3.0, 1e-8);
  EXPECT_NEAR(normal_force_between(1, 3) + normal_force_between(2, 3), 1.0, 1e-8);
  for (double support : {left, right}) {
    EXPECT_GT(support, 1.0);
    EXPECT_LT(support, 2.0);
  }
  const std::vector<double> top = state_of(3);
  EXPECT_NEAR(top[0], 0.0, 1e-8);
  EXPECT_NEAR(top[2], 1.5, 1e-8);
}

// A plate 200 times heavier than each of four cubes under it: no blow-up, the floor
// carries everything, and the solver converges or says it did not.
TEST_F(NSCDTest, HeavyPlateOnLightGrainsStaysBounded)
{
  scene(0.5, "tolerance 1e-8 max_sweeps 5000");
  add_cube(-1.2, -1.2, 0.5);
  add_cube(1.2, -1.2, 0.5);
  add_cube(-1.2, 1.2, 0.5);
  add_cube(1.2, 1.2, 0.5);
  add_cube(0.0, 0.0, 1.25, 2);
  commands({"group cubes type 1", "group plate type 2", "shapes assign cubes shape 1 density 1",
       "shapes assign plate shape 2 mass 800", "run 500"});
  const double weight = 4.0 + 800.0;
  EXPECT_NEAR(fix_value("floor", 2), -weight, 1e-6 * weight);
  const std::vector<double> plate = state_of(5);
  EXPECT_NEAR(plate[2], 1.25, 1e-6);
  for (int d = 3; d < 9; d++) EXPECT_TRUE(std::isfinite(plate[d]));
  EXPECT_LT(fix_value("solver", 2), 1e-6);    // max interpenetration
  EXPECT_EQ(fix_value("solver", 7), 1.0);
}

TEST_F(NSCDTest, RunContinuedFromRestartFollowsTheUninterruptedRun)
{
  auto setup_and_drop = [&]() {
    scene();
    for (int k = 0; k < 3; k++) add_cube(0.2 * k, 0.1 * k, 0.6 + 1.2 * k);
    commands({"shapes assign all shape 1 density 1 orient random 5", "run 300"});
  };
  setup_and_drop();
  commands({"write_restart " + scratch("mid.restart"), "run 300"});
  std::vector<std::vector<double>> straight;
  for (int k = 1; k <= 3; k++) straight.push_back(state_of(k));

  restart_instance();
  commands({"read_restart " + scratch("mid.restart"), "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
       "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1",
       "fix solver all nscd tolerance 1e-10 max_sweeps 2000", "run 300"});
  for (int k = 1; k <= 3; k++) {
    const std::vector<double> s = state_of(k);
    for (int d = 0; d < 3; d++) EXPECT_NEAR(s[d], straight[k - 1][d], 1e-6) << "atom " << k;
  }
}

TEST_F(NSCDTest, MovingWallPushesAndUnfixRemovesIt)
{
  scene(0.0);
  add_cube(0.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1",
       "fix pusher all nscd/wall plane -1.0 0 0 1 0 0 velocity 0.5 0 0", "run 2000"});
  // The wall meets the cube's face (x = -0.5) at t = 1, then pushes it (frictionless floor)
  // at its own speed; at t = 2 the wall is at x = 0 and the cube's face with it.
  const std::vector<double> s = state_of(1);
  EXPECT_NEAR(s[3], 0.5, 1e-8);
  EXPECT_NEAR(s[0], 0.5, 2e-3);
  EXPECT_NEAR(fix_value("pusher", 3), 0.0, 1e-12);
  commands({"unfix pusher", "run 100"});
  EXPECT_NEAR(state_of(1)[3], 0.5, 1e-8);    // no wall: keeps its velocity
}

TEST_F(NSCDTest, BadInputNamesTheProblem)
{
  commands({"units lj", "atom_style spheropolyhedron", "boundary f f f", "shapes read " + scratch("shapes"),
       "region box block -5 5 -5 5 -5 5", "create_box 1 box"});
  EXPECT_NE(error_of("fix s all nscd theta 0").find("theta"), std::string::npos);
  EXPECT_NE(error_of("fix s all nscd bogus 1").find("bogus"), std::string::npos);
  EXPECT_NE(error_of("fix w all nscd/wall plane 0 0 0 0 0 0").find("no direction"), std::string::npos);
  EXPECT_NE(error_of("fix w all nscd/wall cylinder 0 0 0 0 0 1 -2").find("radius"), std::string::npos);
  const std::string no_pair_style = error_of("pair_coeff * * 0.5");    // LAMMPS' own message
  EXPECT_TRUE(std::regex_search(no_pair_style, std::regex("[Pp]air[_ ]style"))) << no_pair_style;
  run("pair_style nscd");
  EXPECT_NE(error_of("pair_coeff * * -0.5").find("-0.5"), std::string::npos);
  commands({"create_atoms 1 single 0 0 0", "fix s all nscd", "timestep 0.001"});
  EXPECT_NE(error_of("run 1").find("pair coeffs are not set"), std::string::npos);
  commands({"pair_coeff * * 0.3"});
  EXPECT_NE(error_of("run 1").find("point (shape 0)"), std::string::npos);
}

// The plate (mass 2, weight 2) on four cubes, loaded at a constant rate: quasi-static, so
// the grains carry load + plate weight, the floor that plus their own weight.
TEST_F(NSCDTest, PlateLoadedAtConstantRateIsCarriedByTheGrains)
{
  scene();
  for (double x : {-1.2, 1.2})
    for (double y : {-1.2, 1.2}) add_cube(x, y, 0.5);
  commands({"shapes assign all shape 1 density 1",
            "fix plate all nscd/plate 1.0 mass 2 rate 10 gravity 1 friction 0.5", "run 1000"});
  const double load = 10.0 * 1.0;    // rate x time
  EXPECT_NEAR(fix_value("plate", 3), load, 1e-9);
  EXPECT_NEAR(fix_value("plate", 2), load + 2.0, 1e-3);           // reaction on the plate
  EXPECT_NEAR(fix_value("floor", 2), -(load + 2.0 + 4.0), 1e-3);
  EXPECT_NEAR(fix_value("plate", 0), 1.0, 1e-7);                  // rigid grains: no sinking
  for (tagint k = 1; k <= 4; k++) {
    const std::vector<double> s = state_of(k);
    EXPECT_NEAR(s[2], 0.5, 1e-7);
    for (int d = 3; d < 9; d++) EXPECT_NEAR(s[d], 0.0, 1e-6);
  }
}

// A slump between two looks: a small ball squeezed off a big one by the plate, on top of a
// held tower of 6 cubes (frictionless). The plate drops 0.5 within a few dozen steps and
// rests again on the big ball. The deck's old check (every 200 steps: plate sinking faster
// than 0.2, or by more than 0.15 x the column's height) misses it; the sink over a sliding
// window of 50 steps (fail_sink 0.1) finds it. On the tower alone it stays silent.
TEST_F(NSCDTest, SlidingWindowCatchesASlumpTheChunkedCheckMisses)
{
  for (bool with_ball : {true, false}) {
    SCOPED_TRACE(with_ball ? "slump" : "stable tower");
    if (!with_ball) {
      stop();
      start();
    }
    scene(0.0);
    for (int k = 0; k < 6; k++) add_cube(0.0, 0.0, 0.5 + k);
    add_cube(0.0, 0.0, 6.5);                             // the big ball, held
    const double dz = std::sqrt(0.75 * 0.75 - 0.2 * 0.2);
    const double top = with_ball ? 6.5 + dz + 0.25 : 7.0;
    if (with_ball) add_cube(0.2, 0.0, 6.5 + dz, 2);      // the small ball, off its top
    commands({"group cubes id 1:6", "group big id 7", "group loose type 2",
              "shapes assign cubes shape 1 density 1", "shapes assign big shape 4 density 1",
              "timestep 0.005", "unfix solver", "fix solver loose nscd tolerance 1e-8 max_sweeps 2000",
              "fix plate all nscd/plate " + num(top + 0.001) + " mass 1 load 20 gravity 1 fail_sink 0.1 fail_window 50"});
    if (with_ball) run("shapes assign loose shape 5 density 1");
    bool old_check_failed = false;
    for (int chunk = 0; chunk < 3; chunk++) {    // 3 time units: the ball, off at 2.8, stays in the box
      run("run 200");
      old_check_failed = old_check_failed || fix_value("plate", 1) < -0.2 ||
                         -fix_value("plate", 4) > 0.15 * top;
    }
    EXPECT_FALSE(old_check_failed);
    if (with_ball) {
      EXPECT_NEAR(fix_value("plate", 0), 7.0, 1e-3);    // now on the big ball
      EXPECT_EQ(fix_value("plate", 8), 1.0);
      EXPECT_NEAR(fix_value("plate", 9), 20.0, 1e-12);
    } else {
      EXPECT_NEAR(fix_value("plate", 4), -0.001, 1e-6);    // the gap it started above the tower
      EXPECT_EQ(fix_value("plate", 8), 0.0);
    }
    EXPECT_GT(fix_value("plate", 6), 20.0);            // the peak force: at least the load
  }
}

// A plate 800 times heavier than each cube: bounded, converged, reactions right.
TEST_F(NSCDTest, HeavyLoadingPlateOnFewGrains)
{
  scene(0.5, "tolerance 1e-8 max_sweeps 5000");
  for (double x : {-1.2, 1.2})
    for (double y : {-1.2, 1.2}) add_cube(x, y, 0.5);
  commands({"shapes assign all shape 1 density 1",
            "fix plate all nscd/plate 1.0 mass 800 gravity 1 friction 0.5", "run 300"});
  EXPECT_NEAR(fix_value("floor", 2), -804.0, 1e-5 * 804.0);
  EXPECT_NEAR(fix_value("plate", 2), 800.0, 1e-5 * 800.0);
  EXPECT_NEAR(fix_value("plate", 0), 1.0, 1e-7);
  EXPECT_EQ(fix_value("solver", 7), 1.0);
  EXPECT_LT(fix_value("solver", 2), 1e-7);
}

// Virial of a 4-cube stack: sum over contacts of (x_i - x_j)_z F_z = 1 (3 + 2 + 1) between
// cubes plus 0.5 * 4 from the floor = 8, seen by compute pressure and compute stress/atom.
TEST_F(NSCDTest, ContactVirialReachesPressureAndStressPerAtom)
{
  scene();
  for (int k = 0; k < 4; k++) add_cube(0.0, 0.0, 0.5 + k);
  commands({"shapes assign all shape 1 density 1", "compute p all pressure NULL virial",
            "compute s all stress/atom NULL virial", "compute ssum all reduce sum c_s[3]",
            "thermo_style custom step c_p[3] c_ssum", "run 200"});
  const double volume = 20.0 * 20.0 * 20.0;
  auto *p = lmp->modify->get_compute_by_id("p");
  p->compute_vector();
  EXPECT_NEAR(p->vector[2] * volume, 8.0, 1e-7);
  auto *ssum = lmp->modify->get_compute_by_id("ssum");
  EXPECT_NEAR(ssum->compute_scalar(), -8.0, 1e-7);
}

TEST_F(NSCDTest, ContactsComputeListsEveryPointWithItsForce)
{
  scene();
  add_cube(0.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1", "compute c all nscd/contacts active",
            "compute fn all reduce sum c_c[9]" + reduce_local(),
            "compute walls all reduce max c_c[2]" + reduce_local(),
            "thermo_style custom step c_fn c_walls", "run 100"});
  auto *c = lmp->modify->get_compute_by_id("c");
  c->compute_local();
  int rows = c->size_local_rows, all_rows = 0;
  MPI_Allreduce(&rows, &all_rows, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(all_rows, 4);
  for (int r = 0; r < rows; r++) {
    EXPECT_EQ(c->array_local[r][1], -1.0);      // the first boundary fix: the floor
    EXPECT_NEAR(c->array_local[r][7], 1.0, 1e-12);    // normal +z
    EXPECT_GT(c->array_local[r][8], 0.0);
  }
  auto *fn = lmp->modify->get_compute_by_id("fn");
  EXPECT_NEAR(fn->compute_scalar(), 1.0, 1e-9);
}

// The compute reports the last solve's contacts also when the pair style has found newer
// ones at a run's setup (here a grain moved onto another between runs): it used to take
// wall contacts for grain pairs, skip them and read their unset atom IDs (a crash of
// `dump local` at the setup of a run in a pour).
TEST_F(NSCDTest, ContactsComputeBetweenRunsNamesTheLastSolvesBoundaries)
{
  scene();
  add_cube(0.0, 0.0, 0.5);
  add_cube(4.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1", "compute c all nscd/contacts", "run 10",
            "group second id 2", "displace_atoms second move -4.0 0.0 1.0 units box", "run 0"});
  auto *c = lmp->modify->get_compute_by_id("c");
  c->compute_local();
  int rows = c->size_local_rows, all_rows = 0;
  MPI_Allreduce(&rows, &all_rows, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(all_rows, 8);                      // 4 corners of each cube on the floor
  for (int r = 0; r < rows; r++) EXPECT_EQ(c->array_local[r][1], -1.0);
}

// A cube pushed sideways by gravity against the inside of a cylinder (a silo wall).
TEST_F(NSCDTest, CylinderWallHoldsAGrainPushedAgainstIt)
{
  scene(0.0);
  add_cube(2.4, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1", "unfix floor",
            "fix silo all nscd/wall cylinder 0 0 0 0 0 1 3.0", "unfix g",
            "fix g all gravity 1.0 vector 1 0 0", "run 500"});
  EXPECT_NEAR(fix_value("silo", 0), 1.0, 1e-8);    // the grain's weight on the wall, along +x
  const std::vector<double> s = state_of(1);
  // Two vertical edges touch the cylinder: x = sqrt(9 - 0.25) - 0.5
  EXPECT_NEAR(s[0], std::sqrt(9.0 - 0.25) - 0.5, 1e-7);
  EXPECT_NEAR(s[1], 0.0, 1e-9);
}

TEST_F(NSCDTest, GrainsOutsideTheGroupStayPutAndCarryTheOthers)
{
  scene();
  add_cube(0.0, 0.0, 0.5);
  add_cube(0.2, 0.0, 1.5, 2);
  commands({"shapes assign all shape 1 density 1", "group top type 2", "unfix solver",
            "fix solver top nscd tolerance 1e-10", "run 500"});
  const std::vector<double> bottom = state_of(1), top = state_of(2);
  EXPECT_NEAR(bottom[2], 0.5, 0.0);
  EXPECT_NEAR(top[2], 1.5, 1e-9);
  EXPECT_NEAR(normal_force_between(1, 2), 1.0, 1e-9);
}

TEST_F(NSCDTest, PeriodicImagesOnOneRankActAsNeighbours)
{

  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary p p f",
            "shapes read " + scratch("shapes"), "region box block -10 10 -10 10 -1 19",
            "create_box 2 box", "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1", "fix solver all nscd tolerance 1e-10"});
  add_cube(9.8, 0.0, 0.5);     // straddles the periodic boundary at x = +-10
  add_cube(-9.9, 0.0, 1.5);    // rests on the image of the first
  commands({"shapes assign all shape 1 density 1", "run 500"});
  EXPECT_NEAR(fix_value("floor", 2), -2.0, 1e-8);
  EXPECT_NEAR(state_of(2)[2], 1.5, 1e-8);
  EXPECT_NEAR(normal_force_between(1, 2), 1.0, 1e-8);
}

TEST_F(NSCDTest, RunZeroAndAnEmptyDumpWork)
{
  scene();
  add_cube(0.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1", "group nobody empty",
            "dump d nobody grains/vtk 1 " + scratch("empty.*.vtk"), "run 0", "run 2"});
  if (rank() == 0) {
    std::ifstream in(scratch("empty.2.vtk"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("POINTS 0"), std::string::npos);
    EXPECT_EQ(text.find("# vtk"), text.rfind("# vtk"));    // one header, not one per rank
  }
}

// Restart carries the warm start: the first step after read_restart needs as few sweeps as
// the uninterrupted run's (a cold start of this frictional stack needs hundreds).
TEST_F(NSCDTest, RestartCarriesTheWarmStart)
{
  const std::string solver = "fix solver all nscd tolerance 1e-9 max_sweeps 5000 check 1";
  scene(0.5, "tolerance 1e-9 max_sweeps 5000 check 1");
  for (int k = 0; k < 4; k++) add_cube(0.1 * k, 0.05 * k, 0.5 + k);
  commands({"shapes assign all shape 1 density 1", "run 300",
            "write_restart " + scratch("stack.restart"), "run 1"});
  const double sweeps_straight = fix_value("solver", 0);
  restart_instance();
  commands({"read_restart " + scratch("stack.restart"), "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1", solver, "run 1"});
  EXPECT_LE(fix_value("solver", 0), sweeps_straight + 2);
  // and without the stored impulses (a new fix ID), the same step is a cold start
  restart_instance();
  commands({"read_restart " + scratch("stack.restart"), "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1",
            "fix cold all nscd tolerance 1e-9 max_sweeps 5000 check 1", "run 1"});
  EXPECT_GT(fix_value("cold", 0), 10 * (sweeps_straight + 2));
}

// Impulses scale with the step: a run continued from a restart at half the timestep starts
// from the same contact forces (half the stored impulses), so its first step needs about
// as many sweeps as the first step at the old timestep. A pile of 27 random grains poured
// at 1e-5, each first step solved to 1e-6: from impulses twice too large Gauss-Seidel
// needs several times more.
TEST_F(NSCDTest, RestartAtAnotherTimestepStartsFromTheSameForces)
{
  const std::vector<std::string> walls = pour_small_pile_to_restart();
  const auto first_step_sweeps = [&](const std::string &timestep) {
    restart_instance();
    commands({"read_restart " + scratch("pile.restart"), "timestep " + timestep});
    commands(walls);
    commands({"fix solver all nscd tolerance 1e-6 max_sweeps 20000 check 1", "run 1"});
    return fix_value("solver", 0);
  };
  const double same = first_step_sweeps("0.005"), half = first_step_sweeps("0.0025");
  std::cout << "[ info ] first step after the restart: " << same << " sweeps at the same "
            << "timestep, " << half << " at half of it\n";
  EXPECT_LE(half, 1.5 * same + 4);
}

// Minimisers and r-RESPA would skip or garble the Moreau-Jean step: refused by name.
TEST_F(NSCDTest, RespaAndMinimizeAreRefused)
{
  scene();
  add_cube(0.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1"});
  EXPECT_NE(error_of("minimize 1e-4 1e-6 10 100").find("minimize"), std::string::npos);
  run("run_style respa 2 2");
  EXPECT_NE(error_of("run 1").find("respa"), std::string::npos);
}

// fix nscd hands its warm-start records to the grains in pre_exchange, by the indices of the
// last solve: a fix that moves atoms between ranks in its own pre_exchange must come after.
TEST_F(NSCDTest, FixBalanceBeforeFixNscdIsRefused)
{
  scene();
  add_cube(0.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1", "unfix solver", "fix lb all balance 100 1.0 shift x 10 1.0",
            "fix solver all nscd"});
  const std::string message = error_of("run 1");
  EXPECT_NE(message.find("must be defined before fix balance lb"), std::string::npos) << message;
  commands({"unfix lb", "fix lb all balance 100 1.0 shift x 10 1.0", "run 1"});    // after it: fine
}

TEST_F(NSCDTest, MovedWallComesBackFromRestart)
{
  scene(0.0);
  add_cube(0.0, 0.0, 0.5);
  commands({"shapes assign all shape 1 density 1",
            "fix pusher all nscd/wall plane -3.0 0 0 1 0 0 velocity 0.5 0 0", "run 1000",
            "write_restart " + scratch("wall.restart")});
  restart_instance();
  commands({"read_restart " + scratch("wall.restart"), "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "fix floor all nscd/wall plane 0 0 0 0 0 1",
            "fix pusher all nscd/wall plane -3.0 0 0 1 0 0 velocity 0.5 0 0",
            "fix g all gravity 1.0 vector 0 0 -1", "fix solver all nscd", "run 0"});
  EXPECT_NEAR(fix_value("pusher", 3), -2.5, 1e-12);
}

// A small pile of random grains poured into a box comes to rest with little overlap and
// the floor carries its weight. Each rank count pours a different (chaotic) pile: on 4 ranks
// the last grain stops at step ~2300 (1 rank: ~1800), hence 3000 steps before the window.
TEST_F(NSCDTest, SmallPileComesToRestOnTheFloor)
{
  commands(small_pile_grains());
  commands(small_pile_box());
  commands({"timestep 0.005", "fix solver all nscd tolerance 1e-6 max_sweeps 2000",
            "compute m all property/atom mass", "compute weight all reduce sum c_m",
            "thermo_style custom step c_weight", "thermo_modify norm no", "run 3000",
            // the per-step floor force jitters with 1e-4 velocity noise: average it
            "fix floor_mean all ave/time 1 500 3500 f_floor[3]", "run 500"});
  auto *w = lmp->modify->get_compute_by_id("weight");
  const double weight = w->compute_scalar();
  const double kinetic = fix_value("solver", 8) + fix_value("solver", 9);
  EXPECT_LT(kinetic, 1e-4 * weight);                        // at rest (started ~ weight x 3)
  EXPECT_NEAR(lmp->modify->get_fix_by_id("floor_mean")->compute_scalar(),
              -weight, 0.005 * weight);
  EXPECT_LT(fix_value("solver", 2), 0.01);                  // overlap < 1% of a grain
  EXPECT_EQ(lmp->atom->natoms, 27);
}

// A restart written on all ranks of this run continues on a single rank and follows the
// continuation on all ranks (to the Gauss-Seidel ordering's round-off on a frictional stack).
TEST_F(NSCDTest, RestartWrittenOnAllRanksContinuesOnOne)
{
  const std::vector<std::string> redefine = {
      "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
      "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1",
      "fix solver all nscd tolerance 1e-10 max_sweeps 5000"};
  scene(0.5, "tolerance 1e-10 max_sweeps 5000");
  for (int k = 0; k < 4; k++) add_cube(0.1 * k, 0.05 * k, 0.6 + 1.1 * k);    // falls, then rests
  commands({"shapes assign all shape 1 density 1 orient random 3", "run 300",
            "write_restart " + scratch("all_ranks.restart"), "run 200"});
  std::vector<std::vector<double>> on_all_ranks;
  for (tagint k = 1; k <= 4; k++) on_all_ranks.push_back(state_of(k));

  // rank 0 alone reads the file and continues
  on_first_ranks(1, [&](MPI_Comm) {
    run("read_restart " + scratch("all_ranks.restart"));
    commands(redefine);
    run("run 200");
    for (tagint k = 1; k <= 4; k++) {
      const int i = lmp->atom->map(k);
      ASSERT_GE(i, 0);
      for (int d = 0; d < 3; d++)
        EXPECT_NEAR(lmp->atom->x[i][d], on_all_ranks[k - 1][d], 1e-6) << "atom " << k;
    }
  });
  MPI_Barrier(MPI_COMM_WORLD);
}

// Moving the sub-domain boundary (balance) hands the grains of a resting pyramid, and so
// their contacts, to another rank; their warm start goes with them. The cut at x = 0 (no
// grain centred on it) moves to x = -4: every grain ends on the last rank. Sweeps to 1e-9
// (check 1), measured: np 2: resting 0, first step after balance 1, cold start 524; without
// the hand-over 613. np 1: nothing to move, but the new run re-sorts the atoms and rebuilds
// the lists: resting 1, then 1, cold 483. With pairs computed in neighbour-list order instead
// of ID order the step after balance took 603 (np 1) and 614 (np 2).
TEST_F(NSCDTest, WarmStartFollowsContactsToAnotherRank)
{
  const std::string solver = "fix solver all nscd tolerance 1e-9 max_sweeps 5000 check 1";
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "processors * 1 1", "shapes read " + scratch("shapes"),
            "region box block -10 10 -10 10 -1 19", "create_box 1 box", "pair_style nscd",
            "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1", solver});
  for (int level = 0; level < 4; level++)    // 4 + 3 + 2 + 1 cubes, across x = 0
    for (int k = 0; k < 4 - level; k++) add_cube(-1.4 + 0.55 * level + 1.1 * k, 0.0, 0.5 + level);
  commands({"shapes assign all shape 1 density 1", "run 300"});
  const double resting = fix_value("solver", 0);

  std::string cuts;    // fractions of the box: the last cut at x = -10 + 0.3 * 20 = -4
  for (int k = 1; k < ranks(); k++) cuts += " " + num(0.3 * k / (ranks() - 1));
  if (ranks() > 1) run("balance 1.0 x" + cuts);
  else std::printf("[ INFO     ] 1 rank: no sub-domain boundary to move; a new run only\n");
  const bool moved_all = rank() == ranks() - 1 || lmp->atom->nlocal == 0;
  EXPECT_TRUE(moved_all) << "rank " << rank() << " still owns " << lmp->atom->nlocal << " grains";
  run("run 1");
  const double after_balance = fix_value("solver", 0);

  commands({"unfix solver", solver, "run 1"});    // a new fix: no stored impulses
  const double cold = fix_value("solver", 0);
  if (rank() == 0)
    std::printf("[ INFO     ] %d ranks: sweeps resting %g, after balance %g, cold %g\n", ranks(),
                resting, after_balance, cold);
  EXPECT_GT(cold, 10 * (resting + 2));
  EXPECT_LE(after_balance, resting + 2);
}

// The reverse: a restart written by a single rank (rank 0 alone, on its own communicator)
// continues on all ranks of this run and follows the single rank's own continuation.
TEST_F(NSCDTest, RestartWrittenOnOneRankContinuesOnAll)
{
  const std::vector<std::string> redefine = {
      "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
      "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1",
      "fix solver all nscd tolerance 1e-10 max_sweeps 5000"};
  std::vector<double> on_one_rank(3 * 4, 0.0);    // positions of atoms 1..4
  on_first_ranks(1, [&](MPI_Comm) {
    scene(0.5, "tolerance 1e-10 max_sweeps 5000");
    for (int k = 0; k < 4; k++) add_cube(0.1 * k, 0.05 * k, 0.6 + 1.1 * k);    // falls, then rests
    commands({"shapes assign all shape 1 density 1 orient random 3", "run 300",
              "write_restart " + scratch("one_rank.restart"), "run 200"});
    for (tagint k = 1; k <= 4; k++) {
      const int i = lmp->atom->map(k);
      EXPECT_GE(i, 0);    // (no ASSERT: the other ranks wait in MPI_Bcast below)
      if (i < 0) continue;
      for (int d = 0; d < 3; d++) on_one_rank[3 * (k - 1) + d] = lmp->atom->x[i][d];
    }
  });
  MPI_Bcast(on_one_rank.data(), (int) on_one_rank.size(), MPI_DOUBLE, 0, MPI_COMM_WORLD);

  run("read_restart " + scratch("one_rank.restart"));
  commands(redefine);
  run("run 200");
  for (tagint k = 1; k <= 4; k++) {
    const std::vector<double> s = state_of(k);
    for (int d = 0; d < 3; d++) EXPECT_NEAR(s[d], on_one_rank[3 * (k - 1) + d], 1e-6) << "atom " << k;
  }
}

// ---- warm-start impulses kept with their atoms (doc/fix_nscd.rst, "Restart") ----

// Warm-start records held by the ranks of `world`: {summed, most on one rank, summed of
// those concerning no atom of the holding rank}.
static std::array<double, 3> warm_start_holdings(FixNSCD *fix, MPI_Comm world)
{
  const double held = (double) fix->warm_start_records_held();
  const double foreign = (double) fix->warm_start_records_of_other_ranks();
  std::array<double, 3> out{};
  MPI_Allreduce(&held, &out[0], 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&held, &out[1], 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&foreign, &out[2], 1, MPI_DOUBLE, MPI_SUM, world);
  return out;
}

// A stack of two cubes slides at constant speed on a frictionless floor across the
// sub-domain cut at x = 0 (processors * 1 1): both atoms, and so the four floor contacts
// and the four cube-cube contacts (static friction), change rank in the middle of a run.
// The impulses do not change from step to step, so with the warm start every step needs
// few sweeps (check 1, tolerance 1e-9). Measured: resting 0; sliding at most 3 per step,
// the same sequence on 1, 2 and 4 ranks; cold start 46. With the records left behind when
// atoms migrate (pack_exchange sending none) the step after the crossing took 46 on 2
// ranks. Before the impulses were kept with the atoms this held too (the leftovers gather).
TEST_F(NSCDTest, WarmStartSurvivesItsAtomsChangingRankMidRun)
{
  const std::string solver = "fix solver all nscd tolerance 1e-9 max_sweeps 5000 check 1";
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "processors * 1 1", "shapes read " + scratch("shapes"), "region box block -10 10 -10 10 -1 19",
            "create_box 1 box", "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin",
            "neigh_modify every 1 delay 0 check yes", "timestep 0.001",
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0", "fix g all gravity 1.0 vector 0 0 -1", solver});
  add_cube(-1.0, 0.0, 0.5);
  add_cube(-1.0, 0.0, 1.5);
  commands({"shapes assign all shape 1 density 1", "run 300"});
  const double resting = fix_value("solver", 0);
  const int owner_before = owner_of(lmp, 1, MPI_COMM_WORLD);
  // 400 steps at 5: x from -1 to +1, every step's sweeps written to a file
  commands({"velocity all set 5 0 0", "fix sweeps all print 1 \"$(f_solver[1])\" file " + scratch("sweeps") +
                                          " screen no",
            "run 400", "unfix sweeps"});
  const int owner_after = owner_of(lmp, 1, MPI_COMM_WORLD);
  if (ranks() > 1) {
    EXPECT_NE(owner_before, owner_after) << "the stack did not change rank";
    EXPECT_EQ(owner_of(lmp, 2, MPI_COMM_WORLD), owner_after);
  }
  EXPECT_NEAR(position_of(1)[0], 1.0, 1e-6);
  EXPECT_NEAR(normal_force_between(1, 2), 1.0, 1e-6);    // the top cube's weight
  std::ifstream in(scratch("sweeps"));
  std::string line;
  double most = 0.0;
  int steps = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') most = std::max(most, std::stod(line)), steps++;
  EXPECT_EQ(steps, 401);    // the run's setup and 400 steps
  commands({"unfix solver", solver, "run 1"});    // a new fix: no stored impulses
  const double cold = fix_value("solver", 0);
  if (rank() == 0)
    std::printf("[ INFO     ] %d ranks: rank of atom 1 %d -> %d; sweeps resting %g, at most %g per step while "
                "sliding, cold %g\n", ranks(), owner_before, owner_after, resting, most, cold);
  EXPECT_LE(most, 3);
  EXPECT_GT(cold, 10 * 3);
}

// A restart written on all ranks of this run (4, or 2) is read on fewer ranks (2 and 1, on
// their own communicators). Right after read_restart no rank holds a record of a contact
// none of whose atoms it owns, the ranks hold as many records between them as the writers
// did, and none holds all when several own grains; the first step needs no more sweeps than
// the uninterrupted run's, and 100 steps on, the grains are where the uninterrupted run put
// them (to the solver's round-off: the Gauss-Seidel order differs with the rank count).
// Before the impulses were kept with the atoms every rank held every record after
// read_restart: the count of other ranks' records was (ranks - 1) x all.
TEST_F(NSCDTest, RestartWrittenOnAllRanksContinuesOnFewerWithOnlyTheirOwnContacts)
{
  const std::vector<std::string> redefine = {
      "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
      "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1",
      "fix solver all nscd tolerance 1e-10 max_sweeps 5000 check 1"};
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "processors * 1 1", "shapes read " + scratch("shapes"), "region box block -10 10 -10 10 -1 19",
            "create_box 1 box", "pair_style nscd", "pair_coeff * * 0.5", "timestep 0.001"});
  commands(redefine);
  for (int level = 0; level < 4; level++)    // a pyramid of 10 cubes across x = 0, dropped from 0.05
    for (int k = 0; k < 4 - level; k++) add_cube(-1.4 + 0.55 * level + 1.1 * k, 0.0, 0.55 + 1.01 * level);
  commands({"shapes assign all shape 1 density 1 orient random 3", "run 150",
            "write_restart " + scratch("written.restart")});
  const std::array<double, 3> written = warm_start_holdings(solver(), MPI_COMM_WORLD);
  EXPECT_EQ(written[2], 0.0);
  run("run 1");
  const double first_sweeps = fix_value("solver", 0);
  run("run 99");
  std::vector<std::array<double, 3>> straight;
  for (tagint k = 1; k <= 10; k++) straight.push_back(position_of(k));
  EXPECT_GT(written[0], 40.0);    // floor and cube-cube contacts: 4 points each, most twice

  for (int size : {2, 1}) {
    if (size >= ranks()) continue;
    on_first_ranks(size, [&](MPI_Comm fewer) {
      commands({"processors * 1 1", "read_restart " + scratch("written.restart")});
      commands(redefine);
      const std::array<double, 3> read = warm_start_holdings(solver(), fewer);
      int owning = lmp->atom->nlocal > 0, ranks_owning = 0;
      MPI_Allreduce(&owning, &ranks_owning, 1, MPI_INT, MPI_SUM, fewer);
      EXPECT_EQ(read[2], 0.0) << size << " ranks: records of other ranks' contacts";
      EXPECT_EQ(read[0], written[0]) << size << " ranks";
      if (ranks_owning > 1) {
        EXPECT_LT(read[1], read[0]) << size << " ranks";
      }
      run("run 1");
      EXPECT_LE(fix_value("solver", 0), first_sweeps + 2) << size << " ranks";
      run("run 99");
      for (tagint k = 1; k <= 10; k++) {
        const int i = lmp->atom->map(k);
        double mine[3] = {0.0, 0.0, 0.0}, x[3];
        if (i >= 0 && i < lmp->atom->nlocal)
          for (int d = 0; d < 3; d++) mine[d] = lmp->atom->x[i][d];
        MPI_Allreduce(mine, x, 3, MPI_DOUBLE, MPI_SUM, fewer);
        for (int d = 0; d < 3; d++) EXPECT_NEAR(x[d], straight[k - 1][d], 1e-6) << size << " ranks, cube " << k;
      }
      if (rank() == 0)
        std::printf("[ INFO     ] written on %d ranks: %g records held; read on %d: %g held, at most %g "
                    "on one rank, %g of other ranks' contacts; first step %g sweeps (uninterrupted %g)\n",
                    ranks(), written[0], size, read[0], read[1], read[2], fix_value("solver", 0), first_sweeps);
    });
    MPI_Barrier(MPI_COMM_WORLD);
  }
}

// A restart file of format 3 (every contact's record in the global block, written before
// the impulses were kept with the atoms: data/in.stack_format3, 5 resting cubes, 28
// contacts, whose next step took 1 sweep) is still read: each rank keeps its own atoms'
// records and none of other ranks' contacts, and the next step is warm (a new fix ID,
// cold, takes many more).
TEST_F(NSCDTest, RestartOfFormat3IsReadIntoTheAtoms)
{
  const std::vector<std::string> redefine = {
      "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
      "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1"};
  const std::string file = std::string(NSCD_TEST_DATA_DIR) + "/stack_format3.restart";
#if defined(LAMMPS_BIGBIG)
  // The file comes from a default (smallbig) build, and LAMMPS reads no restart file of other
  // integer sizes: under -DLAMMPS_SIZES=bigbig this checks that refusal instead.
  run("processors * 1 1");
  EXPECT_NE(error_of("read_restart " + file).find("Imageint setting"), std::string::npos);
  return;
#endif
  commands({"processors * 1 1", "read_restart " + file});
  commands(redefine);
  run("fix solver all nscd tolerance 1e-9 max_sweeps 5000 check 1");
  const std::array<double, 3> held = warm_start_holdings(solver(), MPI_COMM_WORLD);
  EXPECT_EQ(held[2], 0.0);
  // the 2 upper cubes on 2 lower ones each and the 3 lower on the floor, 4 points each: 28
  // contacts, the 16 between cubes kept by both cubes
  EXPECT_EQ(held[0], 2 * 16 + 12);
  if (ranks_owning_atoms() > 1) {
    EXPECT_LT(held[1], held[0]);
  }
  run("run 1");
  const double warm = fix_value("solver", 0);
  commands({"unfix solver", "fix cold all nscd tolerance 1e-9 max_sweeps 5000 check 1", "run 1"});
  const double cold = fix_value("cold", 0);
  if (rank() == 0)
    std::printf("[ INFO     ] %d ranks: %g records held, at most %g on a rank; first step %g sweeps, cold %g\n",
                ranks(), held[0], held[1], warm, cold);
  EXPECT_LE(warm, 3);
  EXPECT_GT(cold, 10 * 3);
}

// ---- fix nscd method / coarse: lib/solver's accelerated iterations (doc/Howto_nscd_solver.rst) --

// Sum over ranks of the contact forces between each pair of grains (key: smaller ID, larger
// ID; walls are 0), the sum of the pair's contact points, on the grain of the smaller ID.
static std::map<std::pair<tagint, tagint>, std::vector<double>> pair_forces(FixNSCD *fix)
{
  std::map<std::pair<tagint, tagint>, std::vector<double>> mine;
  for (const nscd::Contact &c : fix->contacts()) {
    tagint i = c.key.tag_i, j = c.body_j >= 0 ? c.key.tag_j : 0;
    double sign = 1.0;
    if (j != 0 && j < i) std::swap(i, j), sign = -1.0;
    std::vector<double> &f = mine[{i, j}];
    f.resize(3, 0.0);
    for (int d = 0; d < 3; d++) f[d] += sign * c.impulse[d] / fix->timestep();
  }
  // gather: every rank sends its pairs (a, b, fx, fy, fz) to all
  std::vector<double> flat;
  for (const auto &[key, f] : mine)
    flat.insert(flat.end(), {(double) key.first, (double) key.second, f[0], f[1], f[2]});
  int n = (int) flat.size(), size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < size; r++) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(offsets[size - 1] + counts[size - 1]);
  MPI_Allgatherv(flat.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 MPI_COMM_WORLD);
  std::map<std::pair<tagint, tagint>, std::vector<double>> total;
  for (size_t k = 0; k < all.size(); k += 5) {
    std::vector<double> &f = total[{(tagint) all[k], (tagint) all[k + 1]}];
    f.resize(3, 0.0);
    for (int d = 0; d < 3; d++) f[d] += all[k + 2 + d];
    // a pair split over ranks has its points on both: the sum is the pair's force
  }
  return total;
}

// fix_modify sets any solver keyword of the fix line for the next runs (the column deck
// deposits at one tolerance and relaxes at another): a pour solved to 1e-3 stops its steps
// there (some above 1e-6), then to 1e-7 every step converges to 1e-7. Without modify_param
// fix_modify refuses the keyword; if it were ignored, the steps would stay at 1e-3.
TEST_F(NSCDTest, FixModifySetsTheSolverOptionsOfTheNextRuns)
{
  commands(small_pile_grains());
  run("timestep 0.005");
  commands(small_pile_box());
  run("fix solver all nscd tolerance 1e-7 max_sweeps 5000");
  run("fix_modify solver tolerance 1e-3");
  double loosest = 0.0;
  for (int k = 0; k < 400; k++) {
    run("run 1");
    const double residual = fix_value("solver", 1);
    EXPECT_LE(residual, 1e-3) << "step " << k + 1;
    loosest = std::max(loosest, residual);
  }
  EXPECT_GT(loosest, 1e-6);    // stopped at the loose tolerance, not at the fix line's
  run("fix_modify solver tolerance 1e-7 check 2");
  for (int k = 0; k < 50; k++) {
    run("run 1");
    EXPECT_LE(fix_value("solver", 1), 1e-7) << "step " << k + 401;
    EXPECT_EQ(fix_value("solver", 7), 1.0) << "step " << k + 401;
  }
  EXPECT_NE(error_of("fix_modify solver tolerance -1").find("tolerance"), std::string::npos);
  EXPECT_NE(error_of("fix_modify solver method cg").find("'cg'"), std::string::npos);
  EXPECT_NE(error_of("fix_modify solver write_problem 5 f").find("fix nscd line"), std::string::npos);
  EXPECT_NE(error_of("fix_modify solver tolerance"), "");
}

TEST_F(NSCDTest, BadMethodAndCoarseAreNamed)
{
  commands({"units lj", "atom_style spheropolyhedron", "boundary f f f", "region box block -5 5 -5 5 -5 5",
            "create_box 1 box"});
  EXPECT_NE(error_of("fix s all nscd method cg").find("'cg'"), std::string::npos);
  EXPECT_NE(error_of("fix s all nscd coarse -1").find("'-1'"), std::string::npos);
  EXPECT_NE(error_of("fix s all nscd coarse maybe").find("'maybe'"), std::string::npos);
  EXPECT_EQ(error_of("fix s all nscd method nncg coarse 1.5"), "");
}

// A staggered stack of 6 cubes solved by each method to 1e-10: the floor carries the total
// weight to 1e-8 and each contact level the weight above it to 1e-7 (the closed form, as
// plain Gauss-Seidel in StackOfBoxesCarriesTheWeightAboveAtEachLevel); the stack ends at
// rest (no energy gained from the momentum steps).
TEST_F(NSCDTest, AcceleratedMethodsCarryTheStackLikeGaussSeidel)
{
  for (const std::string method : {"method nesterov", "method nncg", "method nesterov coarse yes",
                                   "method gs coarse yes"}) {
    restart_instance();
    scene(0.5, "tolerance 1e-10 max_sweeps 20000 " + method);
    for (int k = 0; k < 6; k++) add_cube(0.05 * k, 0.0, 0.5 + k);
    commands({"shapes assign all shape 1 density 1", "run 1000"});
    EXPECT_NEAR(fix_value("floor", 2), -6.0, 1e-8) << method;
    for (int k = 1; k <= 5; k++)
      EXPECT_NEAR(normal_force_between(k, k + 1), 6.0 - k, 1e-7) << method << ", level " << k;
    EXPECT_EQ(fix_value("solver", 7), 1.0) << method;    // converged
    EXPECT_LT(fix_value("solver", 8) + fix_value("solver", 9), 1e-14) << method;
    for (int k = 1; k <= 6; k++) EXPECT_NEAR(state_of(k)[2], 0.5 + (k - 1), 1e-8) << method;
  }
}

// One step of a small random pile (27 grains, settled by plain Gauss-Seidel to 1e-5) solved
// by each method to 1e-9 from the same restart (warm start included): every grain gets the
// same total contact force as with plain Gauss-Seidel, to 1e-3 of the mean grain weight,
// and every grain pair the same force (the sum over its contact points) to 2e-3. Measured
// on 1 rank: grains 4e-5, pairs 2e-4 at most. Pair forces are statically indeterminate in a
// pile (friction, several neighbours), so they agree only because both solves start from
// the same warm start; at 1e-9 (plain Gauss-Seidel stalls near 2e-7 on this pile) pairs
// differed by up to 0.3 mean weights while the grains' totals agreed to 1.3e-5. The coarse
// correction moves the impulses of whole groups of contacts at once and so can leave the
// warm start's neighbourhood for another solution of the same pile: since the speculative
// edge crossings (which settle this pour into a harder pile: 15231 sweeps of plain GS from
// the warm start, 948 before) its pairs differ from plain GS by 1.7e-2 (1 rank) and 1.3e-2
// (2 ranks) mean weights while its grains' totals agree to 2e-5, so for it only the grains'
// totals are compared. The unique answers (the stack above; stack, incline and pyramid in
// tests/unit/solver/test_acceleration.cpp) are compared for every method.
TEST_F(NSCDTest, AcceleratedMethodsGiveGaussSeidelsPileForces)
{
  const std::vector<std::string> walls = pour_small_pile_to_restart();
  double mass_mine = 0.0, mass = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++) mass_mine += lmp->atom->rmass[i];
  MPI_Allreduce(&mass_mine, &mass, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  const double mean_weight = mass / 27.0;

  using Forces = std::map<std::pair<tagint, tagint>, std::vector<double>>;
  const auto per_grain = [](const Forces &pairs) {    // total contact force on each grain
    std::map<tagint, std::vector<double>> total;
    for (const auto &[key, f] : pairs)
      for (int d = 0; d < 3; d++) {
        total[key.first].resize(3, 0.0);
        total[key.first][d] += f[d];
        if (key.second == 0) continue;
        total[key.second].resize(3, 0.0);
        total[key.second][d] -= f[d];
      }
    return total;
  };
  const auto largest_difference = [](const auto &a, const auto &b) {
    double worst = 0.0;
    for (const auto &[key, f] : a) {
      auto other = b.find(key);
      for (int d = 0; d < 3; d++)
        worst = std::max(worst, std::fabs((other == b.end() ? 0.0 : other->second[d]) - f[d]));
    }
    return worst;
  };
  std::map<std::string, Forces> forces;
  for (const std::string method : {"method gs", "method nesterov", "method nncg",
                                   "method nesterov coarse yes"}) {
    restart_instance();
    run("read_restart " + scratch("pile.restart"));
    commands(walls);
    commands({"fix solver all nscd tolerance 1e-6 max_sweeps 50000 check 1 " + method, "run 1"});
    EXPECT_EQ(fix_value("solver", 7), 1.0) << method << ": residual " << fix_value("solver", 1);
    forces[method] = pair_forces(solver());
    if (rank() == 0)
      std::printf("[ INFO     ] %s: %g sweeps to 1e-6 from the warm start\n", method.c_str(),
                  fix_value("solver", 0));
  }
  const Forces &reference = forces["method gs"];
  const auto reference_grains = per_grain(reference);
  EXPECT_EQ(reference_grains.size(), 27u);
  for (const auto &[method, found] : forces) {
    const double grains = largest_difference(reference_grains, per_grain(found));
    const double pairs = std::max(largest_difference(reference, found),
                                  largest_difference(found, reference));
    if (rank() == 0)
      std::printf("[ INFO     ] %s: largest difference to gs of a grain's contact force %.2e, "
                  "of a pair's %.2e mean weights\n", method.c_str(), grains / mean_weight,
                  pairs / mean_weight);
    EXPECT_LT(grains, 1e-3 * mean_weight) << method;
    const bool stays_near_the_warm_start = method.find("coarse") == std::string::npos;
    if (stays_near_the_warm_start) {
      EXPECT_LT(pairs, 2e-3 * mean_weight) << method;
    }
  }
}

// A column of 8 aligned cubes under a cube of mass 100 (mass ratio 100), from rest: the
// floor carries the weight, and the accelerated methods need fewer than half the sweeps of
// plain Gauss-Seidel over the first 10 steps (warm-started after the first; tolerance 1e-6).
TEST_F(NSCDTest, AcceleratedMethodsNeedFewerSweepsUnderAHeavyPlate)
{
  std::map<std::string, double> sweeps;
  for (const std::string method : {"method gs", "method nesterov", "method nesterov coarse yes"}) {
    restart_instance();
    scene(0.5, "tolerance 1e-6 max_sweeps 200000 " + method);
    for (int k = 0; k < 9; k++) add_cube(0.0, 0.0, 0.5 + k, k == 8 ? 2 : 1);
    commands({"group cubes type 1", "group heavy type 2", "shapes assign cubes shape 1 density 1",
              "shapes assign heavy shape 1 mass 100",
              "fix mean all ave/time 1 10 10 f_solver[1]", "run 10"});
    sweeps[method] = lmp->modify->get_fix_by_id("mean")->compute_scalar();
    // per step the floor force is the weight to the accuracy of that step's solve: at
    // tolerance 1e-6 measured 6e-6 (gs), 1.5e-3 (nesterov), 1e-4 (with coarse) relative
    EXPECT_NEAR(fix_value("floor", 2), -108.0, 3e-3 * 108.0) << method;
    EXPECT_NEAR(state_of(9)[2], 8.5, 1e-6) << method;    // the column does not sink
    EXPECT_EQ(fix_value("solver", 7), 1.0) << method;
  }
  if (rank() == 0)
    std::printf("[ INFO     ] mean sweeps per step: gs %g, nesterov %g, nesterov coarse %g\n",
                sweeps["method gs"], sweeps["method nesterov"], sweeps["method nesterov coarse yes"]);
  EXPECT_LT(sweeps["method nesterov"], 0.5 * sweeps["method gs"]);
  EXPECT_LT(sweeps["method nesterov coarse yes"], 0.5 * sweeps["method gs"]);
}

// memory_usage(): fix nscd and pair nscd report at least the contact arrays they hold (each
// contact of the problem with its solver row, each found contact), and LAMMPS' "Per MPI rank
// memory allocation" (Info::get_memory_info, in MB) includes them. Fails with the Fix and Pair
// defaults (0 and the per-atom tallies only).
TEST_F(NSCDTest, MemoryUsageCountsTheContactArrays)
{
  scene();
  for (int level = 0; level < 4; level++)    // a resting pyramid of 10 cubes: 4 points per face
    for (int k = 0; k < 4 - level; k++) add_cube(-1.4 + 0.55 * level + 1.1 * k, 0.0, 0.5 + level);
  commands({"shapes assign all shape 1 density 1", "run 50"});
  auto *pair = dynamic_cast<PairNSCD *>(lmp->force->pair);
  ASSERT_NE(pair, nullptr);
  const double contacts = (double) solver()->contacts().size(), found = (double) pair->contacts().size();
  const double fix_least = contacts * (sizeof(nscd::Contact) + sizeof(nscd::detail::ContactRow));
  const double pair_least = found * sizeof(nscd::Contact);
  const double fix_bytes = solver()->memory_usage(), pair_bytes = pair->memory_usage();
  double total_mb[3];
  Info(lmp).get_memory_info(total_mb);
  std::printf("[ INFO     ] rank %d: %g contacts (%g grain pairs): fix nscd %g bytes (at least %g), pair nscd %g "
              "(at least %g), all %g MB\n",
              rank(), contacts, found, fix_bytes, fix_least, pair_bytes, pair_least, total_mb[0]);
  double all_contacts = 0.0;
  MPI_Allreduce(&contacts, &all_contacts, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GE(all_contacts, 4 * 10);    // every cube rests on 4 points at least
  EXPECT_GE(fix_bytes, fix_least);
  EXPECT_GE(pair_bytes, pair_least);
  EXPECT_GE(total_mb[0] * 1024 * 1024, fix_bytes + pair_bytes + lmp->atom->memory_usage());
}

// Load balance: the plate test above with comm_style tiled, a `balance rcb` before the run and
// `fix balance rcb` during it (every 100 steps), so the four cubes, their contacts and their
// warm starts move between ranks: the same forces to the same tolerances.
TEST_F(NSCDTest, PlateOnCubesCarriesTheSameLoadUnderRcbBalance)
{
  scene();
  for (double x : {-1.2, 1.2})
    for (double y : {-1.2, 1.2}) add_cube(x, y, 0.5);
  commands({"shapes assign all shape 1 density 1", "comm_style tiled", "balance 1.0 rcb",
            "fix plate all nscd/plate 1.0 mass 2 rate 10 gravity 1 friction 0.5",
            "fix lb all balance 100 1.0 rcb", "run 1000"});
  EXPECT_EQ(ranks_owning_atoms(), std::min(ranks(), 4));    // rcb gave every rank a cube
  const double load = 10.0 * 1.0;
  EXPECT_NEAR(fix_value("plate", 3), load, 1e-9);
  EXPECT_NEAR(fix_value("plate", 2), load + 2.0, 1e-3);
  EXPECT_NEAR(fix_value("floor", 2), -(load + 2.0 + 4.0), 1e-3);
  EXPECT_NEAR(fix_value("plate", 0), 1.0, 1e-7);
  for (tagint k = 1; k <= 4; k++) {
    const std::vector<double> s = state_of(k);
    EXPECT_NEAR(s[2], 0.5, 1e-7);
    for (int d = 3; d < 9; d++) EXPECT_NEAR(s[d], 0.0, 1e-6);
  }
  EXPECT_EQ(lmp->atom->natoms, 4);
}

// A resting pyramid (10 cubes across x = 0) balanced in the middle of the rest, first with
// `balance shift` on the brick decomposition, then with rcb under comm_style tiled: each
// hands grains with their contacts to other ranks, and the pyramid stays where it rested
// (to the solver's 1e-9 tolerance, 1e-7 in position) with its warm start (a few sweeps).
TEST_F(NSCDTest, RestingPyramidStaysPutThroughShiftAndRcbBalance)
{
  scene(0.5, "tolerance 1e-9 max_sweeps 5000 check 1");
  for (int level = 0; level < 4; level++)
    for (int k = 0; k < 4 - level; k++) add_cube(-1.4 + 0.55 * level + 1.1 * k, 0.0, 0.5 + level);
  commands({"shapes assign all shape 1 density 1", "run 300"});
  std::vector<std::vector<double>> rested;
  for (tagint k = 1; k <= 10; k++) rested.push_back(state_of(k));
  const double resting = fix_value("solver", 0);
  commands({"balance 1.0 shift x 10 1.0", "run 100", "comm_style tiled", "balance 1.0 rcb",
            "fix lb all balance 20 1.0 rcb", "run 100"});
  const double after = fix_value("solver", 0);
  EXPECT_EQ(ranks_owning_atoms(), ranks());    // rcb split the 10 cubes between the ranks
  for (tagint k = 1; k <= 10; k++) {
    const std::vector<double> s = state_of(k);
    for (int d = 0; d < 3; d++) EXPECT_NEAR(s[d], rested[k - 1][d], 1e-7) << "cube " << k;
    for (int d = 3; d < 9; d++) EXPECT_NEAR(s[d], 0.0, 1e-6) << "cube " << k;
  }
  if (rank() == 0) std::printf("[ INFO     ] %d ranks: sweeps resting %g, after balancing %g\n", ranks(), resting, after);
  EXPECT_LE(after, resting + 2);
  EXPECT_EQ(lmp->atom->natoms, 10);
}

// ---- communication between ranks, counted (doc/scaling.md, "Counted") ----

// fix nscd counts what its exchanges carry between ranks as the receiving rank gets it. Two
// cubes rest on the floor on either side of x = 0 (processors * 1 1: the cut on 2 ranks, cuts
// at x = -10, 0, 10 on 4; the ghost cutoff is ~6, from the library's 4 x 4 plate). First in
// a box periodic in y and 8 wide, so that every rank also holds periodic images of the cubes
// it has, copies within the rank and not messages: each cube is a ghost of the other's rank
// and nothing else comes from another rank, so by hand each exchange after a sweep is a
// message each way in the reverse communication (6 doubles per ghost) and again in the
// forward one, 4 messages and 2 x 2 x 6 x 8 = 192 bytes; each step's start sends the ghosts'
// state (12 doubles per ghost) in 2 messages; the rest of the step, their new motion (6) and
// the mass-splitting shares (1 back, 1 forth), in 6 messages; after each neighbour build, the
// plan of the sweeps' exchange on several ranks (nscd_copy_exchange.h): each ghost cube's
// owner and index (2 doubles) and the list of wanted indices back to the owner (1 double per
// cube: its images travel with it), 2 messages. On 1 rank only images: nothing is counted.
// Then in a closed box under comm_style tiled and balance rcb, where every ghost comes from
// another rank: the same per ghost, and on 2 ranks one message per receiving rank
// and communication. Failed with the copies within the rank counted (as fix wire's bytes per
// substep count them): 8 ghosts' worth on 1 rank.
TEST_F(NSCDTest, CommunicationBetweenRanksIsCountedAsByHand)
{
  const double steps = 20;
  for (const std::string layout : {"brick", "tiled"}) {
    if (layout == "tiled") restart_instance();
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array",
              layout == "brick" ? "boundary f p f" : "boundary f f f", "processors * 1 1",
              "shapes read " + scratch("shapes"), "region box block -20 20 -4 4 -1 9", "create_box 1 box",
              "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
              "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
              "fix g all gravity 1.0 vector 0 0 -1", "fix solver all nscd tolerance 1e-10 max_sweeps 2000 check 1",
              "thermo_style custom step", "thermo 1000"});
    add_cube(-0.6, 0.0, 0.5);
    add_cube(0.6, 0.0, 0.5);
    run("shapes assign all shape 1 density 1");
    if (layout == "tiled") commands({"comm_style tiled", "balance 1.0 rcb"});
    run("run " + num(steps));
    const double plans = (double) solver()->exchange_plans();
    const std::vector<NSCD_NS::NSCDCommCount::Tally> all = solver()->comm_count().summed(MPI_COMM_WORLD);
    double mine[2] = {(double) lmp->atom->nghost, lmp->atom->nghost > 0 ? 1.0 : 0.0}, ghosts[2];
    MPI_Allreduce(mine, ghosts, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    const double exchanges = (double) solver()->sweep_exchanges();
    // ghosts from another rank, and the ranks receiving them (one message each, brick and 2-rank tiled)
    const double remote = layout == "tiled" ? ghosts[0] : ranks() > 1 ? 2.0 : 0.0;
    const double receiving = layout == "tiled" ? ghosts[1] : remote;
    if (rank() == 0)
      std::printf("[ INFO     ] %s, %d ranks: %g ghosts, %g sweep exchanges over %g steps; sweeps %g messages %g "
                  "bytes, ghost state %g %g, rest of the step %g %g\n",
                  layout.c_str(), ranks(), ghosts[0], exchanges, steps, all[FixNSCD::COMM_SWEEP].messages,
                  all[FixNSCD::COMM_SWEEP].bytes, all[FixNSCD::COMM_GHOST_STATE].messages,
                  all[FixNSCD::COMM_GHOST_STATE].bytes, all[FixNSCD::COMM_STEP].messages,
                  all[FixNSCD::COMM_STEP].bytes);
    if (layout == "brick") {
      EXPECT_GE(ghosts[0], remote + 4.0);    // the images of both cubes on each side
    }
    if (layout == "tiled" && ranks() > 1) {
      EXPECT_GE(ghosts[0], 2.0);
    }
    EXPECT_GE(exchanges, steps) << layout;
    EXPECT_EQ(all[FixNSCD::COMM_SWEEP].bytes, 96.0 * remote * exchanges) << layout;
    EXPECT_EQ(all[FixNSCD::COMM_GHOST_STATE].atoms, remote * steps) << layout;
    EXPECT_EQ(all[FixNSCD::COMM_GHOST_STATE].bytes, 96.0 * remote * steps) << layout;
    EXPECT_EQ(plans >= 1.0, ranks() > 1) << layout;    // after each neighbour build, on several ranks
    EXPECT_EQ(all[FixNSCD::COMM_STEP].bytes, 64.0 * remote * steps + 24.0 * remote * plans) << layout;
    if (layout == "tiled" && ranks() > 2) continue;    // rcb's 4 sub-domains: ghosts from several ranks
    EXPECT_EQ(all[FixNSCD::COMM_SWEEP].messages, 2.0 * receiving * exchanges) << layout;
    EXPECT_EQ(all[FixNSCD::COMM_GHOST_STATE].messages, receiving * steps) << layout;
    EXPECT_EQ(all[FixNSCD::COMM_STEP].messages, 3.0 * receiving * steps + 2.0 * receiving * plans) << layout;
  }
}

// Points (wire nodes: shape 0, not in fix nscd's group) have no contact in the solver, so
// the exchanges between sweeps leave them out; each step's ghost state still carries them
// (fix wire and the neighbour lists need their motion). The two cubes of the test above, and
// a point above each, ghosts of the other rank too: per sweep exchange 96 bytes per remote
// cube and none per point (before, 96 per point as well), the ghost state 96 per remote ghost
// of either kind, and the cubes' rest as before. On 1 rank nothing comes from another rank.
TEST_F(NSCDTest, PointsAreLeftOutOfTheExchangesBetweenSweeps)
{
  const double steps = 20;
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f p f",
            "processors * 1 1", "shapes read " + scratch("shapes"), "region box block -20 20 -4 4 -1 9",
            "create_box 2 box", "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin",
            "neigh_modify every 1 delay 0 check yes", "timestep 0.001"});
  add_cube(-0.6, 0.0, 0.5);
  add_cube(0.6, 0.0, 0.5);
  add_cube(-0.3, 0.0, 3.0, 2);
  add_cube(0.3, 0.0, 3.0, 2);
  commands({"group grains type 1", "shapes assign grains shape 1 density 1",
            "fix floor grains nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g grains gravity 1.0 vector 0 0 -1",
            "fix solver grains nscd tolerance 1e-10 max_sweeps 2000 check 1", "thermo_style custom step",
            "thermo 1000"});
  run("run " + num(steps));
  const std::vector<NSCD_NS::NSCDCommCount::Tally> all = solver()->comm_count().summed(MPI_COMM_WORLD);
  const double exchanges = (double) solver()->sweep_exchanges();
  const double cubes = ranks() > 1 ? 2.0 : 0.0, points = cubes;    // ghosts from another rank
  EXPECT_GE(exchanges, steps);
  EXPECT_EQ(all[FixNSCD::COMM_SWEEP].bytes, 96.0 * cubes * exchanges);
  EXPECT_EQ(all[FixNSCD::COMM_GHOST_STATE].atoms, (cubes + points) * steps);
  EXPECT_EQ(all[FixNSCD::COMM_GHOST_STATE].bytes, 96.0 * (cubes + points) * steps);
  for (int tag : {1, 2}) {
    EXPECT_NEAR(position_of(tag)[2], 0.5, 1e-6) << "cube " << tag;
    EXPECT_NEAR(velocity_of(tag)[2], 0.0, 1e-6) << "cube " << tag;
  }
  for (int tag : {3, 4}) EXPECT_EQ(position_of(tag)[2], 3.0) << "point " << tag;
}
