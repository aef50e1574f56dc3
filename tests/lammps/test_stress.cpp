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

// compute nscd/stress/atom and nscd/crush/atom against closed forms
// (doc/compute_nscd_stress_atom.rst, doc/compute_nscd_crush_atom.rst): a rounded
// cube pressed between floor and plate carries sigma_zz V = -(plate force + m g / 2) x its
// height; a pile at rest on a floor (frictionless side walls) has sum_i sigma_zz,i V_i =
// -g sum_i m_i z_i (internal contacts cancel, the floor's points lie at z = 0); a ball
// hanging on a wire carries -m g r along z from the wire's contacts. Serially and on 2 and
// 4 ranks ("processors" puts a rank cut through the cube and the pile). The crushing index
// of the cube is its floor contact's force over d^2 over the strength at its size.
#include "lammps_fixture.h"

#include "input.h"
#include "variable.h"

#include <cmath>
#include <fstream>
#include <string>

using namespace LAMMPS_NS;

namespace {
// shape 2 of kIsotropicShapes: a cube of side 0.8 rounded by 0.1 (height 1)
constexpr double kCore = 0.8, kRounding = 0.1;
const double kRoundedCubeVolume = kCore * kCore * kCore + 6 * kCore * kCore * kRounding +
    3 * M_PI * kCore * kRounding * kRounding + 4.0 / 3.0 * M_PI * kRounding * kRounding * kRounding;
}    // namespace

class StressTest : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    if (rank() == 0) std::ofstream(scratch("shapes")) << kIsotropicShapes;
    MPI_Barrier(MPI_COMM_WORLD);
  }
  double value(const std::string &formula) { return lmp->input->variable->compute_equal(formula); }
};

// sigma_zz V = -(P + W_plate) h/2 - (P + W_plate + m g) h/2 = -(P + W_plate + m g/2) h, h = 1;
// the other components vanish (frictionless, symmetric); volume none = sigma x V.
TEST_F(StressTest, RoundedCubeBetweenFloorAndPlateCarriesTheUniaxialStress)
{
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "processors * * 1", "region box block -3 3 -3 3 -1 5", "create_box 1 box",
            "shapes read " + scratch("shapes"), "create_atoms 1 single 0 0 0.5",
            "shapes assign all shape 2 density 2", "pair_style nscd", "pair_coeff * * 0.0",
            "neighbor 0.3 bin", "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1",
            "fix plate all nscd/plate 1.0 mass 1 load 3 gravity 1.0", "fix g all gravity 1.0 vector 0 0 -1",
            "fix nscd all nscd tolerance 1e-10", "compute s all nscd/stress/atom",
            "compute sv all nscd/stress/atom volume none", "compute sb all nscd/stress/atom boundaries no",
            "compute r all reduce sum c_s[*]", "compute rv all reduce sum c_sv[3]",
            "compute rb all reduce sum c_sb[3]", "thermo_style custom step c_r[1] c_rv c_rb", "run 500"});
  const double mass = 2 * kRoundedCubeVolume, plate_force = value("f_plate[3]");
  EXPECT_NEAR(plate_force, 4.0, 1e-8);    // load 3 + the plate's weight
  const double expected = -(plate_force + mass / 2) * 1.0;
  EXPECT_NEAR(value("c_rv"), expected, 1e-8 * std::abs(expected));
  EXPECT_NEAR(value("c_r[3]"), expected / kRoundedCubeVolume, 1e-8 * std::abs(expected));
  for (int k : {1, 2, 4, 5, 6}) EXPECT_NEAR(value("c_r[" + std::to_string(k) + "]"), 0.0, 1e-8) << k;
  EXPECT_EQ(value("c_rb"), 0.0);    // a grain touching only boundaries

  // the largest contact force is the floor's: P + W_plate + m g
  commands({"compute crush all nscd/crush/atom 2.0 size 0.5 weibull 3",
            "compute uniform all nscd/crush/atom 2.0", "compute c all reduce max c_crush[*] c_uniform[4]",
            "thermo_style custom step c_c[1]", "run 0"});
  const double d = std::cbrt(6 * kRoundedCubeVolume / M_PI), force = plate_force + mass;
  const double sigma = force / (d * d), strength = 2.0 * std::pow(d / 0.5, -1.0);
  EXPECT_NEAR(value("c_c[1]"), force, 1e-8 * force);
  EXPECT_NEAR(value("c_c[2]"), d, 1e-12);
  EXPECT_NEAR(value("c_c[3]"), sigma, 1e-8 * sigma);
  EXPECT_NEAR(value("c_c[4]"), sigma / strength, 1e-8 * sigma / strength);
  EXPECT_NEAR(value("c_c[5]"), sigma / 2.0, 1e-8 * sigma);
}

// Static equilibrium of every grain: sum_c f_c + m_i g = 0, so sum_i sum_c f_c (x) (x_c - x_i)
// = sum over boundary points of f (x) x_c + sum_i m_i g (x) x_i; along zz the floor's points
// (z = 0) and the frictionless side walls (f_z = 0) add nothing.
TEST_F(StressTest, PileAtRestSumsToItsWeightTimesItsCentreHeight)
{
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "processors * * 1", "region box block -2.5 2.5 -2.5 2.5 -1 8", "create_box 1 box",
            "shapes random 6 seed 31 vertices 8 12 size 0.8 1.0 radius 0.05",
            "lattice sc $(1/1.4^3)", "region fill block -1.75 1.75 -1.75 1.75 0.7 4.9 units box",
            "create_atoms 1 region fill", "shapes assign all shape random 1 6 5 density 1 orient random 9",
            "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "timestep 0.005", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix xlo all nscd/wall plane -2.2 0 0 1 0 0", "fix xhi all nscd/wall plane 2.2 0 0 -1 0 0",
            "fix ylo all nscd/wall plane 0 -2.2 0 0 1 0", "fix yhi all nscd/wall plane 0 2.2 0 0 -1 0",
            "fix g all gravity 1.0 vector 0 0 -1", "fix nscd all nscd tolerance 1e-6 max_sweeps 2000",
            "compute s all nscd/stress/atom volume none", "compute r all reduce sum c_s[3]",
            "variable mz atom mass*z", "compute weight all reduce sum v_mz", "compute ke all ke",
            "thermo_style custom step c_r c_weight c_ke", "run 1500"});
  const double grains = lmp->atom->natoms;
  ASSERT_GE(grains, 20);
  // When the last grain stops depends on the path (1750-3500 steps on 1 and 4 ranks, with and
  // without fix nscd's skip_separating): run on until the pile is at rest, at most 6000 steps.
  for (int chunk = 0; chunk < 9 && !(value("c_ke") / grains < 1e-8); ++chunk) commands({"run 500"});
  EXPECT_LT(value("c_ke") / grains, 1e-8) << "the pile is not at rest";
  const double expected = -value("c_weight");    // g = 1
  EXPECT_NEAR(value("c_r"), expected, 1e-4 * std::abs(expected));
}

// A ball of radius 0.5 hanging on a straight wire clamped at both ends: the wire's
// contacts carry its weight at its bottom, sigma_zz V = -m g r (r = 0.5 to the overlap);
// the ball still sways, so the mean over 2000 steps is compared; 'wire no' leaves it out.
TEST_F(StressTest, WireContactsCarryTheHangingBallsWeight)
{
  commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
            "boundary f f f", "processors * * 1", "region box block -3 3 -3 3 -3 3",
            "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 "
            "extra/special/per/atom 6",
            "shapes read " + scratch("shapes"), "bond_style wire", "bond_coeff 1 500 0.1",
            "angle_style wire", "angle_coeff 1 0.001", "special_bonds lj 0 0 0",
            "create_wire 2 line -2 0 0 2 0 0 bond 1 angle 1 mass 0.01 radius 0.02",
            "create_atoms 1 single 0 0 0.53", "group ball type 1", "shapes assign ball shape 3 density 1",
            "variable inner atom \"type == 2 && abs(x) < 1.95\"", "group free variable inner",
            "pair_style nscd", "pair_coeff * * 0.3", "neighbor 0.2 bin", "neigh_modify every 1 delay 0 check yes",
            "timestep 0.002", "fix g all gravity 1.0 vector 0 0 -1",
            "fix w free wire radius 0.02 k_n 2000 gamma_n 2 k_t 1500 gamma_t 1 mu_s 0.3 damp 0.05",
            "fix nscd ball nscd", "compute s all nscd/stress/atom volume none",
            "compute sn all nscd/stress/atom volume none wire no", "compute r all reduce sum c_s[3] c_s[1]",
            "compute rn all reduce sum c_sn[3]", "compute crush all nscd/crush/atom 1.0",
            "compute f all reduce max c_crush[1]", "fix mean all ave/time 1 2000 5000 c_r[1] c_r[2] c_f",
            "thermo_style custom step c_r[1] c_rn f_mean[1]", "run 5000"});
  const double weight = value("mass(ball)");
  EXPECT_NEAR(value("f_mean[1]"), -weight * 0.5, 0.01 * weight * 0.5);
  EXPECT_NEAR(value("f_mean[2]"), 0.0, 0.01 * weight * 0.5);
  EXPECT_EQ(value("c_rn"), 0.0);
  // the ball sits on the node at x = 0: each of its two elements carries half the weight
  // (along normals within 5 degrees of the vertical)
  EXPECT_NEAR(value("f_mean[3]"), weight / 2, 0.02 * weight / 2);
}

TEST_F(StressTest, BadArgumentsAreRefusedNamingTheValue)
{
  commands({"units lj", "atom_style spheropolyhedron", "region box block -3 3 -3 3 -1 5", "create_box 1 box"});
  EXPECT_NE(error_of("compute c all nscd/crush/atom").find("the strength S0 is missing"), std::string::npos);
  EXPECT_NE(error_of("compute c all nscd/crush/atom -1").find("strength -1 must be > 0"), std::string::npos);
  EXPECT_NE(error_of("compute c all nscd/crush/atom 1 size 0.5").find("needs both 'size D0'"), std::string::npos);
  EXPECT_NE(error_of("compute c all nscd/crush/atom 1 weibull 0").find("weibull 0 must be > 0"), std::string::npos);
  EXPECT_NE(error_of("compute s all nscd/stress/atom volume mean").find("unknown keyword or value 'volume mean'"),
            std::string::npos);
  EXPECT_NE(error_of("compute s all nscd/stress/atom wire").find("keyword 'wire' needs a value"), std::string::npos);
}
