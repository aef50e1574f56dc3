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

// fix wire's option strength (doc/fix_wire.rst, "Breaking"): a wire clamped at one end and
// pulled at the other by a slowly growing force carries that force as its tension; an element
// breaks in the step its tension reaches its strength, leaves the bond and angle topology on
// every rank, and a restart after the break keeps the broken wire. Serially and on 2 and 4
// ranks ("processors * 1 1" cuts the wire).
#include "lammps_fixture.h"

#include "input.h"
#include "variable.h"

#include "shape/random_draws.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
constexpr double kDt = 0.005;

struct BreakLine {
  long step = -1;
  int a = 0, b = 0;
  double tension = 0.0;
};

std::vector<BreakLine> read_breaks(const std::string &path)
{
  std::vector<BreakLine> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    BreakLine b;
    words >> b.step >> b.a >> b.b >> b.tension;
    out.push_back(b);
  }
  return out;
}
}    // namespace

class WireBreakTest : public LammpsTest {
 protected:
  // A straight wire of `elements` elements along x from 0, node 1 clamped (not in the fix's
  // group), the last node pulled along +x by a force growing at `rate` per time unit.
  void pulled_wire(int elements, double rate, const std::string &strength)
  {
    const double length = 0.1 * elements;
    commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
              "boundary f f f", "processors * 1 1", "region box block -1 " + num(length + 20) + " -1 1 -1 1",
              "create_box 1 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 "
              "extra/special/per/atom 6",
              "bond_style wire", "bond_coeff 1 100 0.1", "angle_style wire", "angle_coeff 1 0.001",
              "special_bonds lj 0 0 0",
              "create_wire 1 line 0 0 0 " + num(length) + " 0 0 bond 1 angle 1 mass 0.01 radius 0.02",
              "variable free atom \"id > 1\"", "group free variable free",
              "group last id " + std::to_string(elements + 1), "timestep " + num(kDt),
              "variable F equal " + num(rate) + "*time", "fix pull last addforce v_F 0 0",
              "fix w free wire damp 0.05 " + strength + (strength.empty() ? "" : " breaks " + scratch("breaks.txt"))});
  }
  double value(const std::string &formula) { return lmp->input->variable->compute_equal(formula); }
  std::vector<BreakLine> breaks()
  {
    MPI_Barrier(MPI_COMM_WORLD);
    return read_breaks(scratch("breaks.txt"));
  }
};

// One element: its tension follows the pull (node mass 0.01, sqrt(k / l / m) = 316: no lag
// within a step), so it breaks in the step the force reaches the strength.
TEST_F(WireBreakTest, OneElementBreaksWhenThePullReachesItsStrength)
{
  pulled_wire(1, 0.5, "strength 1.0");
  run("run 410");
  const auto b = breaks();
  ASSERT_EQ(b.size(), 1u);
  const double predicted_step = 1.0 / 0.5 / kDt;    // 400
  EXPECT_NEAR((double) b[0].step, predicted_step, 2.0);
  EXPECT_GE(b[0].tension, 1.0);
  EXPECT_LT(b[0].tension, 1.0 + 0.5 * 2 * kDt);    // at most two steps of the ramp past it
  EXPECT_EQ(value("bonds"), 0.0);
  EXPECT_EQ(value("f_w[14]"), 1.0);
}

// Without a strength fix wire still reports the largest element tension, at each step's start
// (f_w[15]) and over every step so far (f_w[16]): the slowly pulled wire carries the pull in
// every element; once the pull is gone the present tension falls while the largest stays the
// largest of the values each step showed (the same numbers, so equal to the last bit).
TEST_F(WireBreakTest, LargestTensionNowAndSoFarFollowThePull)
{
  pulled_wire(20, 0.5, "");
  run("run 400");    // the pull grows to 0.5 * 400 * dt = 1
  const double pull = value("v_F");
  EXPECT_NEAR(value("f_w[15]") / pull, 1.0, 1e-2);
  EXPECT_NEAR(value("f_w[16]") / pull, 1.0, 1e-2);
  double largest = value("f_w[16]");
  run("variable F equal 0.0");
  for (int step = 0; step < 400; step++) {
    run("run 1 pre no post no");
    largest = std::max(largest, value("f_w[15]"));
  }
  std::printf("[ largest tension ] pull %.6g; 400 steps after its release: now %.3g, largest so far %.6g\n", pull,
              value("f_w[15]"), value("f_w[16]"));
  EXPECT_LT(value("f_w[15]"), 0.1 * pull);
  EXPECT_EQ(value("f_w[16]"), largest);
  EXPECT_EQ(value("f_w[14]"), 0.0);    // nothing breaks without a strength
  EXPECT_EQ(value("bonds"), 20.0);
}

// 20 elements with Weibull strengths (scale 1, modulus 20, seed 7): the weakest breaks first,
// when the pull (= the tension, slow ramp) reaches its strength; its two joints go with it.
TEST_F(WireBreakTest, WeakestElementBreaksFirstAtItsStrength)
{
  pulled_wire(20, 0.1, "strength 1.0 strength_spread 20 seed 7");
  int weakest = 0;
  double lowest = INFINITY;
  for (int a = 1; a <= 20; a++) {
    const double s = std::pow(-std::log1p(-nscd::hashed_uniform(7, a, a + 1)), 1.0 / 20);
    if (s < lowest) lowest = s, weakest = a;
  }
  const long predicted = (long) std::ceil(lowest / 0.1 / kDt);
  run("run " + std::to_string(predicted + 20));
  const auto b = breaks();
  ASSERT_GE(b.size(), 1u);
  EXPECT_EQ(std::min(b[0].a, b[0].b), weakest);
  EXPECT_EQ(std::max(b[0].a, b[0].b), weakest + 1);
  EXPECT_NEAR(b[0].tension, lowest, 0.003 * lowest);
  EXPECT_NEAR((double) b[0].step, (double) predicted, 0.003 * lowest / 0.1 / kDt + 2);
  const double broken = (double) b.size();
  EXPECT_EQ(value("bonds"), 20.0 - broken);
  EXPECT_EQ(value("f_w[14]"), broken);
  if (b.size() == 1) {
    const bool at_end = weakest == 1 || weakest == 20;
    EXPECT_EQ(value("angles"), 19.0 - (at_end ? 1.0 : 2.0));
  }
}

// A restart written after a break holds the broken wire and the run goes on from it.
TEST_F(WireBreakTest, RestartAfterABreakKeepsTheWireBroken)
{
  pulled_wire(4, 0.5, "strength 1.0");
  commands({"run 420", "write_restart " + scratch("broken.restart")});
  const double bonds = value("bonds"), angles = value("angles");
  ASSERT_LT(bonds, 4.0);
  restart_instance();
  commands({"read_restart " + scratch("broken.restart"), "bond_style wire", "bond_coeff 1 100 0.1",
            "angle_style wire", "angle_coeff 1 0.001", "special_bonds lj 0 0 0", "variable free atom \"id > 1\"",
            "group free variable free", "timestep " + num(kDt), "fix w free wire damp 0.05 strength 1.0",
            "run 50"});
  EXPECT_EQ(value("bonds"), bonds);
  EXPECT_EQ(value("angles"), angles);
  EXPECT_EQ(lmp->atom->natoms, 5);
}

// examples/units/in.units (grains, a double loop, floor, cylinder, plate) with a weak wire:
// elements break among grains on any rank count without losing atoms or producing NaN (a
// special-list rebuild in the middle of a step once shot a grain out of the box on 2 ranks).
TEST_F(WireBreakTest, WireBreaksAmongGrainsWithoutLosingAtoms)
{
  commands({"variable wire_extra index \"strength 0.3 strength_spread 5 seed 3\"", "variable steps index 400",
            "include " + std::string(NSCD_EXAMPLES_DIR) + "/units/in.units"});
  EXPECT_EQ(lmp->atom->natoms, 136);
  EXPECT_GT(value("f_w[14]"), 10.0);
  EXPECT_EQ(value("bonds"), 122.0 - value("f_w[14]"));    // 123 nodes, 122 elements
  for (tagint tag = 1; tag <= 136; tag++) {
    const auto x = position_of(tag);
    ASSERT_TRUE(std::isfinite(x[0] + x[1] + x[2])) << tag;
    EXPECT_LT(std::hypot(x[0], x[1]), 3.6) << tag;    // inside the cylinder
  }
}

TEST_F(WireBreakTest, BadOptionsAreRefused)
{
  commands({"units lj", "atom_style hybrid spheropolyhedron angle", "region box block -1 1 -1 1 -1 1",
            "create_box 1 box bond/types 1 angle/types 1"});
  EXPECT_NE(error_of("fix w all wire strength 0").find("strength 0 must be > 0"), std::string::npos);
  EXPECT_NE(error_of("fix w all wire strength 1 strength_spread 5").find("give all three"), std::string::npos);
  EXPECT_NE(error_of("fix w all wire strength 1 strength_spread 5 seed 2.5").find("seed 2.5 must be a positive integer"),
            std::string::npos);
  EXPECT_NE(error_of("fix w all wire breaks " + scratch("b.txt")).find("no 'strength' makes any break"),
            std::string::npos);
}
