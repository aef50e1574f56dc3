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

// examples/units/in.units in LJ, SI and CGS units (doc/Howto_nscd_units.rst): the package has no
// hidden dimensional constant. With scales that are powers of two (grain size, mass and time
// units 2^k) every product and quotient of the run is exact in binary, so a unit system
// changes no bit of the dimensionless trajectory: grains falling with a wire loop onto a
// frictional floor in a cylinder under a pressing plate, 500 steps (the grains land at step ~200,
// the plate at ~290), compared to 1e-12 (it is
// identical; any length, speed or force compared to an absolute constant anywhere in the
// geometry, solver, wire or boundaries would show here). With the ballast's scales (55 mm,
// 2700 kg/m^3, 9.81 m/s^2) round-off differs from LJ's at 1e-16 and the dynamics amplify it
// like any other perturbation: the trajectories agree to 1e-9 for the first 200 steps (1e-13
// measured), then part at contact events (step ~300), as LJ's does from itself with a grain
// size 1 ulp larger. Units with force conversion factors (real, metal) are refused.
#include "lammps_fixture.h"

#include "atom.h"

#include <cmath>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

struct Scene {
  std::string units;
  double d, rho, g;    // grain size, density, gravity: L = d, M = rho d^3, T = sqrt(d / g)
  double length() const { return d; }
  double time() const { return std::sqrt(d / g); }
};

// Positions over L and velocities times T / L of atoms 1..n, in ID order.
struct Dimensionless {
  std::vector<double> x, v;
};

}    // namespace

class UnitsTest : public LammpsTest {
 protected:
  Dimensionless run_scene(const Scene &s, int steps)
  {
    commands({"variable units index " + s.units, "variable d index " + num(s.d),
              "variable rho index " + num(s.rho), "variable g index " + num(s.g),
              "variable steps index " + std::to_string(steps),
              "include " + std::string(NSCD_EXAMPLES_DIR) + "/units/in.units"});
    Dimensionless out;
    const auto n = static_cast<tagint>(lmp->atom->natoms);
    for (tagint tag = 1; tag <= n; tag++) {
      const auto x = position_of(tag), v = velocity_of(tag);
      for (int k = 0; k < 3; k++) {
        out.x.push_back(x[k] / s.length());
        out.v.push_back(v[k] * s.time() / s.length());
      }
    }
    return out;
  }

  static double largest_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    EXPECT_EQ(a.size(), b.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); i++) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
  }

  void expect_same(const Dimensionless &lj, const Dimensionless &other, double dx, double dv)
  {
    ASSERT_GT(lj.x.size(), 3u * 100);    // 13 grains and the wire's nodes
    EXPECT_LE(largest_difference(lj.x, other.x), dx);
    EXPECT_LE(largest_difference(lj.v, other.v), dv);
  }
};

TEST_F(UnitsTest, PowerOfTwoScalesGiveTheSameTrajectoryInSiAndCgs)
{
  const auto lj = run_scene({"lj", 1, 1, 1}, 500);
  restart_instance();
  // L = 1/16 m, M = 1/4 kg, T = 1/8 s
  expect_same(lj, run_scene({"si", 0.0625, 1024, 4}, 500), 1e-12, 1e-12);
  restart_instance();
  // L = 4 cm, M = 4 g, T = 1/8 s
  expect_same(lj, run_scene({"cgs", 4, 0.0625, 256}, 500), 1e-12, 1e-12);
}

TEST_F(UnitsTest, BallastInSiFollowsLjUntilContactsAmplifyRoundOff)
{
  const auto lj = run_scene({"lj", 1, 1, 1}, 200);
  restart_instance();
  expect_same(lj, run_scene({"si", 0.055, 2700, 9.81}, 200), 1e-9, 1e-7);
}

TEST_F(UnitsTest, UnitsWithForceConversionFactorsAreRefused)
{
  for (const char *units : {"real", "metal"}) {
    const std::string error = [&] {
      try {
        commands({std::string("variable units index ") + units, "variable steps index 1",
                  "include " + std::string(NSCD_EXAMPLES_DIR) + "/units/in.units"});
      } catch (LAMMPSException &e) {
        return std::string(e.what());
      }
      return std::string();
    }();
    EXPECT_NE(error.find(std::string("units ") + units + " convert force"), std::string::npos) << error;
    EXPECT_NE(error.find("use units lj, si, cgs, micro or nano"), std::string::npos) << error;
    restart_instance();
  }
}
