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

// Bad input through the deck: every case of the probe in issue 16 that reaches LAMMPS gets a
// clear error naming the value (or, for legal but suspicious decks, a warning), never a
// crash, a hang or garbage. The shape library's own cases are unit-tested in lib/
// (tests/unit/shape/test_shape_robustness.cpp); here they are checked to arrive as LAMMPS
// errors. Runs serially and under mpirun -np 2.
#include "lammps_fixture.h"

#include "fix.h"
#include "modify.h"
#include "nscd_restart.h"
#include "nscd_restart_blocks.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>

namespace {
const char *kCube = "shape cube\nradius 0\nvertices 8\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\nend\n";
}

class BadInputTest : public LammpsTest {
 protected:
  // A shape file holding `text` (written by rank 0).
  std::string shape_file(const std::string &name, const std::string &text)
  {
    const std::string path = scratch(name);
    if (rank() == 0) std::ofstream(path) << text;
    MPI_Barrier(MPI_COMM_WORLD);
    return path;
  }

  // A box with the cube loaded, no atoms yet.
  void box(const std::string &boundary = "f f f", const std::string &extent = "-5 5 -5 5 -5 5")
  {
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array",
              "boundary " + boundary, "shapes read " + shape_file("cube.shapes", kCube),
              "region box block " + extent, "create_box 2 box"});
  }

  // Cubes resting on a floor with fix nscd, ready to run (fix nscd defined last).
  void resting_cubes(const std::string &solver = "fix solver all nscd")
  {
    box();
    commands({"create_atoms 1 single 0 0 0.5", "create_atoms 1 single 2 0 0.5",
              "shapes assign all shape 1 density 1", "pair_style nscd", "pair_coeff * * 0.5",
              "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes", "timestep 0.001",
              "fix floor all nscd/wall plane 0 0 0 0 0 1", "fix g all gravity 1.0 vector 0 0 -1",
              solver});
  }

  static bool has(const std::string &message, const std::string &part)
  {
    return message.find(part) != std::string::npos;
  }

  // The last warning LAMMPS printed to the screen is not kept: read it from a log file.
  std::string log_of(const std::vector<std::string> &lines)
  {
    const std::string log = scratch("log");
    run("log " + log);
    commands(lines);
    run("log none");
    MPI_Barrier(MPI_COMM_WORLD);    // rank 0 writes the log: the others read it when it is closed
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // and rank 0 truncates it in the next call only once every rank has read it
    MPI_Barrier(MPI_COMM_WORLD);
    return text;
  }
};

TEST_F(BadInputTest, ShapeLibraryProblemsArriveAsErrorsNamingTheValue)
{
  commands({"units lj", "atom_style spheropolyhedron", "region box block -5 5 -5 5 -5 5",
            "create_box 1 box"});
  const std::string tiny = shape_file("tiny", "shape t\nradius 0\nvertices 4\n0 0 0\n1e-90 0 0\n0 1e-90 0\n0 0 1e-90\nend\n");
  EXPECT_TRUE(has(error_of("shapes read " + tiny), "below the supported"));
  const std::string huge = shape_file("huge", "shape h\nradius 0\nvertices 4\n0 0 0\n1e300 0 0\n0 1 0\n0 0 1\nend\n");
  EXPECT_TRUE(has(error_of("shapes read " + huge), "1e+300"));
  const std::string round = shape_file("round", "shape r\nradius 1e300\nvertices 1\n0 0 0\nend\n");
  EXPECT_TRUE(has(error_of("shapes read " + round), "1e+300"));
  EXPECT_TRUE(has(error_of(std::string("shapes read ") + NSCD_TEST_SCRATCH), "is a directory"));
  EXPECT_TRUE(has(error_of("shapes write " + scratch("empty.shapes")), "empty"));
  EXPECT_TRUE(has(error_of("shapes random 100000000 seed 1"), "100000000"));
  EXPECT_TRUE(has(error_of("shapes random 2 seed 1 vertices 4 99999999999"), "99999999999"));
  EXPECT_TRUE(has(error_of("shapes random 2 seed 1 size 1e300 1e300"), "1e+300"));
  run("shapes read " + shape_file("cube.shapes", kCube));
  EXPECT_TRUE(has(error_of("shapes read " + scratch("cube.shapes")), "'cube' is already used"));
  run("shapes random 2 seed 9");
  EXPECT_TRUE(has(error_of("shapes random 2 seed 9"), "seed 9 was used before"));
}

TEST_F(BadInputTest, ShapeNameTakenAfterReadRestartIsRefused)
{
  box();
  commands({"create_atoms 1 single 0 0 0", "shapes assign all shape 1 density 1",
            "write_restart " + scratch("r.restart")});
  restart_instance();
  run("read_restart " + scratch("r.restart"));
  EXPECT_TRUE(has(error_of("shapes read " + scratch("cube.shapes")), "'cube' is already used"));
}

TEST_F(BadInputTest, ShapesAssignRefusesImpossibleDensitiesAndRanges)
{
  box();
  run("create_atoms 1 single 0 0 0");
  EXPECT_TRUE(has(error_of("shapes assign all shape 1 density 1e400"), "density"));
  EXPECT_TRUE(has(error_of("shapes assign all shape 1 density 1e-320"), "1e-320"));
  EXPECT_TRUE(has(error_of("shapes assign all shape 1 mass 1e400"), "mass"));
  EXPECT_TRUE(has(error_of("shapes assign all shape random 3 1 5"), "IMIN"));
}

TEST_F(BadInputTest, PeriodicBoxNarrowerThanAGrainIsRefused)
{
  box("p p f", "-0.6 0.6 -5 5 -1 5");    // 1.2 wide; the cube is 1.73 across
  commands({"create_atoms 1 single 0 0 0.5", "shapes assign all shape 1 density 1",
            "pair_style nscd", "pair_coeff * * 0.5", "fix solver all nscd", "timestep 0.001"});
  const std::string message = error_of("run 1");
  EXPECT_TRUE(has(message, "periodic box is 1.2 wide in x")) << message;
}

TEST_F(BadInputTest, ActivationBeyondTheGrainsIsRefused)
{
  box();
  EXPECT_TRUE(has(error_of("pair_style nscd activation/fraction 1e6"), "1000000 must be in [0, 1]"));
  EXPECT_TRUE(has(error_of("pair_style nscd activation 1e400"), "1e400"));    // LAMMPS: out of range
  commands({"create_atoms 1 single 0 0 0.5", "shapes assign all shape 1 density 1",
            "pair_style nscd activation 100", "pair_coeff * * 0.5", "fix solver all nscd",
            "timestep 0.001"});
  EXPECT_TRUE(has(error_of("run 1"), "activation 100"));
}

// One distance given twice (in its two forms, or one keyword twice) is refused naming both
// (before: the later one won silently).
TEST_F(BadInputTest, PairStyleDistancesGivenTwiceAreRefused)
{
  box();
  std::string message = error_of("pair_style nscd activation 0.1 activation/fraction 0.2");
  EXPECT_TRUE(has(message, "'activation 0.1' and 'activation/fraction 0.2' both set the activation distance")) << message;
  message = error_of("pair_style nscd reach/fraction 1 reach 0.3");
  EXPECT_TRUE(has(message, "'reach/fraction 1' and 'reach 0.3' both set the reach distance")) << message;
  EXPECT_TRUE(has(error_of("pair_style nscd reach 0.1 reach 0.2"), "'reach 0.1' and 'reach 0.2'"));
  EXPECT_EQ(error_of("pair_style nscd activation 0.1 reach/fraction 1"), "");
}

TEST_F(BadInputTest, NonFiniteTimestepOrLoadIsRefused)
{
  resting_cubes();
  run("timestep 0");
  EXPECT_TRUE(has(error_of("run 1"), "timestep 0"));
  run("timestep -0.001");
  EXPECT_TRUE(has(error_of("run 1"), "timestep -0.001"));
  run("timestep 0.001");
  EXPECT_TRUE(has(error_of("fix plate all nscd/plate 3 mass 1 rate 1e400"), "rate"));
  // finite but absurd: the impulses overflow; the step stops naming the plate
  run("fix plate all nscd/plate 3 mass 1 rate 1e300");
  const std::string message = error_of("run 10");
  EXPECT_TRUE(has(message, "no finite solution")) << message;
  EXPECT_TRUE(has(message, "fix plate")) << message;
}

// A cylinder narrower than the grain: warned at the start of the run naming the radius
// (before: the run went on with a 0.41 overlap and no message).
TEST_F(BadInputTest, CylinderNarrowerThanAGrainIsWarnedAbout)
{
  resting_cubes();
  run("group first id 1");    // the cube at the origin
  run("fix silo first nscd/wall cylinder 0 0 0 0 0 1 0.3");
  const std::string log = log_of({"run 0"});
  EXPECT_TRUE(has(log, "fix nscd/wall silo: grain ID 1 reaches 0.4071 into the cylinder wall of radius 0.3")) << log;
  EXPECT_TRUE(has(log, "(narrower than the grain)")) << log;
  run("unfix silo");
  run("fix silo first nscd/wall cylinder 0 0 0 0 0 1 1");    // holds the cube
  EXPECT_FALSE(has(log_of({"run 0"}), "into the cylinder wall"));
}

// Masses the solver cannot square are refused naming them (before: a cube of mass 1e-300 on
// another ran 1000 unconverged sweeps every step, and the warnings never named the mass).
TEST_F(BadInputTest, MassesBeyondWhatTheSolverSquaresAreRefused)
{
  resting_cubes();
  run("group top id 2");
  std::string message = error_of("shapes assign top shape 1 mass 1e-300");
  EXPECT_TRUE(has(message, "mass 1e-300 gives a grain of mass 1e-300, outside the solver's 1e-100 to 1e+100")) << message;
  EXPECT_TRUE(has(message, "change the mass unit")) << message;
  message = error_of("fix plate all nscd/plate 3 mass 1e-300");
  EXPECT_TRUE(has(message, "fix nscd/plate: mass 1e-300 is outside the 1e-100 to 1e+100")) << message;
  EXPECT_EQ(error_of("shapes assign top shape 1 mass 1e-100"), "");
}

// A load rate the scene cannot take: the plate sinking into the grains stops the run, naming
// load and rate (before: 1e9 put it 0.58 bounding radii deep silently, 1e12 through the
// grains with only "Lost atoms" at the end).
TEST_F(BadInputTest, PlateSinkingUnderAHugeLoadRateStopsTheRun)
{
  resting_cubes();
  commands({"fix plate all nscd/plate 1.5 mass 1 rate 1e9"});
  const std::string message = error_of("run 20");
  EXPECT_TRUE(has(message, "fix nscd/plate plate: step 2: the plate is 0.577 of a grain's bounding radius deep")) << message;
  EXPECT_TRUE(has(message, "rate 1e+09")) << message;
  commands({"unfix plate", "fix plate all nscd/plate 1.5 mass 1 rate 1e3"});
  EXPECT_EQ(error_of("run 20"), "");
}

// A plate put into a grain whose centre is below it (a grain leaning on a column's side,
// higher than the column's top): refused at the start, naming the grain that reaches deepest
// and the way out (before: the first step stopped with "the plate is 0.363 of a grain's
// bounding radius deep; lower the load 0 or rate 0", examples/string with a round-off change).
TEST_F(BadInputTest, PlatePutIntoAGrainIsRefusedNamingIt)
{
  resting_cubes();
  commands({"group second id 2", "displace_atoms second move 0 0 0.1"});    // tops at 1.0 and 1.1
  commands({"fix plate all nscd/plate 0.8 mass 1"});    // 0.2 and 0.3 into the cubes
  const std::string message = error_of("run 0");
  EXPECT_TRUE(has(message, "fix nscd/plate plate: grain ID 2 reaches 0.3 into the plate at z = 0.8; put it above")) << message;
  // 0.05 into the higher cube (0.058 of its bounding radius): a contact to resolve, not an error
  commands({"unfix plate", "fix plate all nscd/plate 1.05 mass 1"});
  EXPECT_EQ(error_of("run 0"), "");
}

// Numbers of the package's keywords: nan, inf, a fraction for a count, a word, a number
// beyond doubles: each refused naming the command, the keyword and the value (before:
// LAMMPS' parser named only the value, "Expected floating point parameter instead of 'nan'").
TEST_F(BadInputTest, BadNumbersNameTheCommandAndKeyword)
{
  box();
  EXPECT_TRUE(has(error_of("fix solver all nscd tolerance nan"), "fix nscd: tolerance 'nan' is not a finite number"));
  EXPECT_TRUE(has(error_of("fix solver all nscd max_sweeps 2.5"), "fix nscd: max_sweeps 2.5 must be a whole number"));
  EXPECT_TRUE(has(error_of("fix solver all nscd theta -inf"), "fix nscd: theta '-inf' is not a finite number"));
  EXPECT_TRUE(has(error_of("fix solver all nscd relaxation abc"), "fix nscd: relaxation 'abc' is not a number"));
  EXPECT_TRUE(has(error_of("pair_style nscd reach 1e400"), "pair_style nscd: reach 1e400 is beyond the range"));
  run("pair_style nscd");
  EXPECT_TRUE(has(error_of("pair_coeff * * nan"), "pair_coeff nscd: friction 'nan' is not a finite number"));
  EXPECT_TRUE(has(error_of("fix w all nscd/wall plane 0 0 nan 0 0 1"), "fix nscd/wall: plane point z 'nan'"));
  EXPECT_TRUE(has(error_of("fix p all nscd/plate 3 mass inf"), "fix nscd/plate: mass 'inf' is not a finite number"));
  EXPECT_TRUE(has(error_of("shapes assign all shape 1 density nan"), "shapes assign: density 'nan'"));
  EXPECT_TRUE(has(error_of("shapes random 2.5 seed 1"), "shapes random: count 2.5 must be a whole number"));
}

// A misspelled keyword is named as such, before its value is read (before: pair_style nscd,
// fix nscd/plate and compute nscd/column read the value first, and 'flor abc' was refused as
// "flor 'abc' is not a number"); a keyword without a value says so.
TEST_F(BadInputTest, UnknownKeywordsAreNamedBeforeTheirValues)
{
  box();
  std::string message = error_of("pair_style nscd reech abc");
  EXPECT_TRUE(has(message, "pair_style nscd: unknown keyword 'reech' (expected activation, activation/fraction, "
                           "reach, reach/fraction)")) << message;
  EXPECT_TRUE(has(error_of("pair_style nscd reach"), "pair_style nscd: keyword 'reach' needs a value"));
  run("pair_style nscd");
  message = error_of("fix p all nscd/plate 3 mass 1 lod abc");
  EXPECT_TRUE(has(message, "fix nscd/plate: unknown keyword 'lod' (expected load, rate")) << message;
  EXPECT_TRUE(has(error_of("fix p all nscd/plate 3 mass 1 load"), "fix nscd/plate: keyword 'load' needs a value"));
  message = error_of("compute c all nscd/column 0 0 1 flor abc");
  EXPECT_TRUE(has(message, "compute nscd/column: unknown keyword 'flor' (expected floor, percentile)")) << message;
  EXPECT_TRUE(has(error_of("compute c all nscd/column 0 0 1 floor"), "compute nscd/column: keyword 'floor' needs a value"));
}

// Pushing overlapping grains apart faster than contacts are looked for ahead is refused,
// naming the speed that fits (before: overlap_speed 1e6 ended in "Lost atoms").
TEST_F(BadInputTest, OverlapSpeedBeyondTheLookAheadIsRefused)
{
  resting_cubes("fix solver all nscd overlap_speed 1e6");
  const std::string message = error_of("run 1");
  EXPECT_TRUE(has(message, "fix nscd: overlap_speed 1000000 separates grains by up to 1000 per step")) << message;
  EXPECT_TRUE(has(message, "use at most 519.6")) << message;    // (activation 0.0866 + reach 0.433) / 0.001
  run("unfix solver");
  run("fix solver all nscd overlap_speed 0.05");
  EXPECT_EQ(error_of("run 1"), "");
}

TEST_F(BadInputTest, AnotherIntegratorOfTheGrainsIsRefused)
{
  resting_cubes();
  run("fix twice all nve");
  const std::string message = error_of("run 1");
  EXPECT_TRUE(has(message, "fix twice (nve) also moves grain ID 1")) << message;
}

TEST_F(BadInputTest, BondsOnGrainsAreRefused)
{
  commands({"units lj", "atom_style hybrid spheropolyhedron bond", "atom_modify map array",
            "boundary f f f", "shapes read " + shape_file("cube.shapes", kCube),
            "region box block -5 5 -5 5 -5 5", "create_box 1 box bond/types 1 extra/bond/per/atom 1",
            "create_atoms 1 single 0 0 0.5", "create_atoms 1 single 2 0 0.5",
            "shapes assign all shape 1 density 1", "pair_style nscd", "pair_coeff * * 0.5",
            "bond_style harmonic", "bond_coeff 1 1.0 2.0", "create_bonds single/bond 1 1 2",
            "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1", "fix solver all nscd"});
  const std::string message = error_of("run 1");
  EXPECT_TRUE(has(message, "grain ID 1 is in a bond or angle (with atom ID 2)")) << message;
}

TEST_F(BadInputTest, GrainsPlacedInsideEachOtherGetAWarning)
{
  resting_cubes();
  run("create_atoms 1 single 0 0 0.5");    // on top of atom 1
  run("shapes assign all shape 1 density 1");
  const std::string log = log_of({"run 0"});
  EXPECT_TRUE(has(log, "overlap by")) << log;
  EXPECT_TRUE(has(log, "grains ID 1 and 3")) << log;
}

// A heavily loaded stack: 20 cubes rounded by 0.00025 under a plate carrying 1000 (50 times
// their weight). At tolerance 1e-4 the leftover impulse errors let them sink into each other
// step after step: 2.0e-4 deep after 1000 steps (0.78 of the rounding radius), past the
// default warning at 0.2 from step 126 on; at 1e-5 they stay ~1e-5 deep and nothing is said.
// (The small pile of 27 grains under a plate of 3000 stayed ~1e-4 deep at either tolerance
// after its landing: too few layers for the error to add up in a short test.)
TEST_F(BadInputTest, InterpenetrationPastAFifthOfTheRoundingWarnsNamingTheTolerance)
{
  const std::string shapes = shape_file("tiny.shapes", "shape tiny_rounded\nradius 0.00025\nvertices 8\n"
                                        "-0.5 -0.5 -0.5\n0.5 -0.5 -0.5\n-0.5 0.5 -0.5\n0.5 0.5 -0.5\n"
                                        "-0.5 -0.5 0.5\n0.5 -0.5 0.5\n-0.5 0.5 0.5\n0.5 0.5 0.5\nend\n");
  const double side = 1.0005;    // the core plus twice the rounding
  for (const std::string tolerance : {"1e-4", "1e-5"}) {
    SCOPED_TRACE("tolerance " + tolerance);
    restart_instance();
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
              "shapes read " + shapes, "region box block -5 5 -5 5 -1 30", "create_box 1 box"});
    for (int k = 0; k < 20; k++) run("create_atoms 1 single 0 0 " + num((k + 0.5) * side));
    commands({"shapes assign all shape 1 density 1", "pair_style nscd", "pair_coeff * * 0.5",
              "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes", "timestep 0.001",
              "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1",
              "fix solver all nscd tolerance " + tolerance + " max_sweeps 2000",
              "fix plate all nscd/plate " + num(20 * side + 0.001) + " mass 10 load 1000 gravity 1 friction 0.5"});
    const std::string log = log_of({"run 1000"});
    if (tolerance == "1e-4") {
      EXPECT_TRUE(has(log, "grains interpenetrate by")) << log;
      EXPECT_TRUE(has(log, "smallest rounding radius 0.00025")) << log;
      EXPECT_TRUE(has(log, "use tolerance 1e-05")) << log;
      // once, then again only each time the depth has grown by half (measured: 0.20, 0.30, 0.45
      // and 0.68 of the rounding at steps 126, 180, 280, 592): a handful, not one per step
      size_t warnings = 0;
      for (size_t at = log.find("interpenetrate by"); at != std::string::npos;
           at = log.find("interpenetrate by", at + 1))
        warnings++;
      EXPECT_GE(warnings, 1u) << log;
      EXPECT_LE(warnings, 5u) << log;
    } else {
      EXPECT_FALSE(has(log, "interpenetrate")) << log;
    }
  }
}

// Sharp cubes (rounding 0) overlapping by 0.1, less than a fifth of their bounding radius
// (0.17) but deeper than their rounding: their cores intersect, the contact normals are not
// reliable, so this warns too.
TEST_F(BadInputTest, GrainsWhoseCoresIntersectGetAWarning)
{
  resting_cubes();
  run("create_atoms 1 single 0 0 1.4");    // on top of atom 1, 0.1 into it
  run("shapes assign all shape 1 density 1");
  const std::string log = log_of({"run 0"});
  EXPECT_TRUE(has(log, "grains ID 1 and 3 overlap by 0.1 (0.115 of the smaller one's bounding radius)"))
      << log;
}

// exchange N > 1 leaves the accelerated methods' extrapolation on stale ghost velocities:
// on the papers' column exchange 2 took 1.6 times the sweeps and exchange 4 stalled at
// max_sweeps (doc/fix_nscd.rst, "Ghost exchange"). fix nscd says so where it applies: on
// several ranks with nesterov (the default), nncg or anderson, not with gs, not on one rank.
TEST_F(BadInputTest, FewerExchangesWithAnAcceleratedMethodWarnOnSeveralRanks)
{
  box();
  commands({"pair_style nscd", "pair_coeff * * 0.5"});
  const std::string warning = "exchange 2 with an accelerated method needs more sweeps";
  EXPECT_EQ(has(log_of({"fix a all nscd exchange 2"}), warning), ranks() > 1);
  EXPECT_EQ(has(log_of({"fix b all nscd exchange 2 method anderson"}), warning), ranks() > 1);
  EXPECT_FALSE(has(log_of({"fix c all nscd exchange 2 method gs"}), warning));
  EXPECT_FALSE(has(log_of({"fix d all nscd exchange 1"}), warning));
  EXPECT_EQ(has(log_of({"fix_modify d exchange 2"}), warning), ranks() > 1);
}

// ---------------------------------------------------------------- wires

class WireInputTest : public BadInputTest {
 protected:
  // A box (periodic as given) with one cube resting at the origin and the wire styles set up
  // (elements 0.2 long, radius 0.02), no wire yet.
  void wire_box(const std::string &boundary = "f f f")
  {
    commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
              "boundary " + boundary, "shapes read " + shape_file("cube.shapes", kCube),
              "region box block -5 5 -5 5 -1 5",
              "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 "
              "extra/special/per/atom 6",
              "create_atoms 1 single 0 0 0.5", "shapes assign all shape 1 density 1", "bond_style wire",
              "bond_coeff 1 100 0.2", "angle_style wire", "angle_coeff 1 0.01", "pair_style nscd",
              "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
              "timestep 0.001", "group grains type 1"});
  }
  std::string create_wire(const std::string &path, const std::string &more = "")
  {
    return error_of("create_wire 2 " + path + " bond 1 angle 1 mass 0.01 radius 0.02 " + more);
  }
};

// Lines of a polyline file that are not points stop the command naming the line (before:
// a line whose first number could not be read was skipped as a comment, silently).
TEST_F(WireInputTest, PolylineLinesThatAreNotPointsAreRefusedByLine)
{
  wire_box();
  const std::pair<const char *, const char *> cases[] = {
      {"0 -2 1\nnan -1 1\n1 -2 1\n", ":2: 'nan' is not a number"},
      {"0 -2 1\ninf -1 1\n1 -2 1\n", ":2: 'inf' is not a number"},
      {"0 -2 1\n1e400 -1 1\n1 -2 1\n", ":2: 1e400 is beyond the range"},
      {"x y z\n0 -2 1\n1 -2 1\n", ":1: 'x' is not a number"},
  };
  for (const auto &c : cases) {
    const std::string message = create_wire("polyline " + shape_file("path.txt", c.first), "strained yes");
    EXPECT_TRUE(has(message, c.second)) << c.first << ": " << message;
  }
  const std::string path = shape_file("path.txt", "# x y z\n0 -2 1\n\n1 -2 1 # end\n");
  EXPECT_EQ(create_wire("polyline " + path), "");
}

// A wire laid into itself or into another wire is refused, naming the overlap and why
// (before: all three were accepted and the contacts blew the wires apart at the first step).
TEST_F(WireInputTest, OverlappingWiresAreRefused)
{
  wire_box("p p f");
  std::string message = create_wire("loop 0 0 2 2.5 turns 2 pitch 0.01");
  EXPECT_TRUE(has(message, "overlaps itself by 0.03")) << message;
  EXPECT_TRUE(has(message, "the pitch 0.01 is below the wire's diameter 0.04")) << message;
  message = create_wire("loop 0 0 2 4.995", "strained yes");    // 10 wide, periodic in x and y
  EXPECT_TRUE(has(message, "reaches its periodic image")) << message;
  EXPECT_EQ(create_wire("loop 0 0 2 2.5 turns 2 pitch 0.05"), "");    // atoms 2.. : the first wire
  // across its turns at angle 0 (z = 2 and 2.05), 0.02 above the first
  message = create_wire("line 2.5 -4 2.02 2.5 4 2.02");
  EXPECT_TRUE(has(message, "overlaps the wire element between atoms ID")) << message;
  EXPECT_TRUE(has(message, "between atoms ID 2 and 3 by 0.020")) << message;    // (the chord dips 6e-5)
  EXPECT_EQ(create_wire("line 2.5 -4 2.2 2.5 4 2.2"), "");    // 0.1 above its end (z = 2.1): free
  EXPECT_EQ(create_wire("line 2.5 -4 2.02 2.5 4 2.02", "overlap ignore"), "");
}

// A wire that can touch nothing in a scene with grains or walls: refused when k_n was not
// given, warned about for 'k_n 0'; compute wire/contacts has nothing to report then (before:
// the wire fell through the floor and the cube without a word).
TEST_F(WireInputTest, AWireWithoutContactsAmongGrainsIsRefusedOrWarned)
{
  wire_box();
  commands({"create_wire 2 line -3 -2 1 3 -2 1 bond 1 angle 1 mass 0.01 radius 0.02", "group wire type 2",
            "fix floor all nscd/wall plane 0 0 0 0 0 1", "fix g all gravity 1.0 vector 0 0 -1",
            "fix solver grains nscd", "fix w wire wire radius 0.02"});
  std::string message = error_of("run 1");
  EXPECT_TRUE(has(message, "fix wire w: no k_n given")) << message;
  EXPECT_TRUE(has(message, "grains, walls and plate")) << message;
  commands({"unfix w", "fix w wire wire radius 0.02 k_n 0"});
  EXPECT_TRUE(has(log_of({"run 1"}), "fix wire w: k_n 0: the wire has no contacts"));
  run("compute wc all wire/contacts");
  message = error_of("run 1");
  EXPECT_TRUE(has(message, "compute wire/contacts wc: fix wire w has no contacts (k_n 0)")) << message;
  commands({"uncompute wc", "unfix w", "fix w wire wire radius 0.02 k_n 200", "compute wc all wire/contacts"});
  EXPECT_EQ(error_of("run 1"), "");
}

// An element inside a grain at the start of a run is warned about, naming nodes, grain and
// depth (before: no word, and the wire was blown out at ~70 velocity units here).
TEST_F(WireInputTest, AWireInsideAGrainAtTheStartOfARunIsWarnedAbout)
{
  wire_box();
  commands({"create_wire 2 line -3 0 0.5 3 0 0.5 bond 1 angle 1 mass 0.01 radius 0.02 overlap ignore",
            "group wire type 2", "fix solver grains nscd", "fix w wire wire radius 0.02 k_n 200"});
  const std::string log = log_of({"run 0"});
  EXPECT_TRUE(has(log, "lies inside grain ID 1 by 0.52 (26 wire radii) at the start (doc/fix_wire.rst, Errors)")) << log;
  // a wire resting on the cube (0.001 into it): no warning
  commands({"delete_atoms group wire bond yes", "create_wire 2 line -3 0 1.019 3 0 1.019 bond 1 angle 1 mass 0.01",
            "group wire type 2"});
  EXPECT_FALSE(has(log_of({"run 0"}), "lies inside grain"));
}

// fix wire's numbers name the keyword (before: "Expected integer parameter instead of '2.5'").
TEST_F(WireInputTest, FixWireNumbersNameTheKeyword)
{
  wire_box();
  run("group wire type 2");
  EXPECT_TRUE(has(error_of("fix w wire wire radius 0.02 k_n 200 substeps 2.5"), "fix wire: substeps 2.5 must be a whole number"));
  EXPECT_TRUE(has(error_of("fix w wire wire radius nan"), "fix wire: radius 'nan' is not a finite number"));
  EXPECT_TRUE(has(error_of("create_wire 2 loop 0 0 1 inf bond 1 mass 0.01 radius 0.02"), "create_wire loop: radius R 'inf' is not a finite number"));
  EXPECT_TRUE(has(error_of("create_wire 2 line 0 0 1 1 0 1 bond 1 mass 0.01 radius 0.02 nodes 7.5"), "create_wire: nodes 7.5 must be a whole number"));
}

// create_wire's radius defaults to fix wire's (before: fix wire did not hand it over, and
// create_wire asked for a radius although fix wire was defined).
TEST_F(WireInputTest, CreateWireTakesTheRadiusOfFixWire)
{
  wire_box();
  commands({"group wire type 2", "fix w wire wire radius 0.02 k_n 200"});
  EXPECT_EQ(error_of("create_wire 2 line -3 -2 1 3 -2 1 bond 1 angle 1 mass 0.01"), "");
  // and with fix wire's radius 0.5 the 0.2 elements are below the diameter
  commands({"unfix w", "fix w wire wire radius 0.5 k_n 200"});
  EXPECT_TRUE(has(error_of("create_wire 2 line -3 -3 1 3 -3 1 bond 1 angle 1 mass 0.01"), "below the wire's diameter 1"));
}

// ---------------------------------------------------------------- damaged restart files

// A restart file of a scene with every style that writes restart data (pair nscd, fix nscd,
// a wall, the plate, fix wire with contact memories, bond and angle wire, the atom style),
// and ways to damage the blocks in it. Blocks are found as LAMMPS writes a global fix
// block: the fix's ID and style as counted strings, LAMMPS' size field, then our mark.
class RestartDamageTest : public BadInputTest {
 protected:
  std::string original;    // the restart file's bytes (on rank 0)

  const std::vector<std::string> fixes = {
      "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
      "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0.1 0 -1",
      "fix plate all nscd/plate 3 mass 1",
      "fix w wire wire radius 0.02 k_n 200 gamma_n 2 k_t 150 gamma_t 1 mu_s 0.5 mu_d 0.4",
      "fix solver grains nscd"};

  // The wire lies over the cube (atom 1, mass 1.2345678901234567): after 60 steps the
  // cube rests on the floor (solver contacts) and the wire on the cube (friction memories:
  // gravity is tilted).
  void write_scene()
  {
    commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
              "boundary f f f", "shapes read " + shape_file("cube.shapes", kCube),
              "region box block -5 5 -5 5 -1 5",
              "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 "
              "extra/special/per/atom 6",
              "create_atoms 1 single 0 0 0.5", "shapes assign all shape 1 mass 1.2345678901234567",
              "bond_style wire", "bond_coeff 1 100 0.1", "angle_style wire", "angle_coeff 1 0.01",
              "create_wire 2 line -0.8 0 1.0201 0.8 0 1.0201 bond 1 angle 1 mass 0.01 radius 0.02",
              "pair_style nscd", "pair_coeff * * 0.5", "timestep 0.001", "group grains type 1",
              "group wire type 2"});
    commands(fixes);
    commands({"run 60", "write_restart " + scratch("scene.restart")});
    if (rank() == 0) original = read_bytes(scratch("scene.restart"));
  }

  static std::string read_bytes(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  static std::string counted(const std::string &text)
  {
    const std::int32_t n = static_cast<std::int32_t>(text.size() + 1);
    return std::string(reinterpret_cast<const char *>(&n), sizeof(n)) + text + '\0';
  }
  // Offset of the global block of fix `id` (just after LAMMPS' size field), or npos.
  static size_t fix_block(const std::string &bytes, const std::string &id, const std::string &style)
  {
    const std::string marker = counted(id) + counted(style);
    const std::int32_t magic = LAMMPS_NS::NSCD_NS::MAGIC;
    for (size_t at = bytes.find(marker); at != std::string::npos; at = bytes.find(marker, at + 1)) {
      const size_t block = at + marker.size() + sizeof(int);
      if (block + 4 <= bytes.size() && std::memcmp(&bytes[block], &magic, 4) == 0) return block;
    }
    return std::string::npos;
  }
  template <class T> static void put(std::string &bytes, size_t at, T value)
  {
    std::memcpy(&bytes[at], &value, sizeof(T));
  }
  template <class T> static T get(const std::string &bytes, size_t at)
  {
    T value;
    std::memcpy(&value, &bytes[at], sizeof(T));
    return value;
  }

  // The file damaged by `damage` (run on rank 0), in a new LAMMPS instance: its path.
  std::string damaged_file(const std::function<void(std::string &)> &damage)
  {
    if (rank() == 0) {
      std::string bytes = original;
      damage(bytes);
      std::ofstream(scratch("damaged.restart"), std::ios::binary) << bytes;
    }
    MPI_Barrier(MPI_COMM_WORLD);
    restart_instance();
    return scratch("damaged.restart");
  }
  // The message of reading the damaged file back, then redefining every fix; "" if all went through.
  std::string error_after(const std::function<void(std::string &)> &damage)
  {
    std::string message = error_of("read_restart " + damaged_file(damage));
    for (size_t k = 0; k < fixes.size() && message.empty(); k++) message = error_of(fixes[k]);
    return message;
  }
  // The log of the same, which must go through.
  std::string log_after(const std::function<void(std::string &)> &damage)
  {
    run("read_restart " + damaged_file(damage));
    return log_of(fixes);
  }
};

// Every global fix block: a foreign mark, a count too large, a stated size that does not
// match the counts, a newer format, a value no run writes. Each is refused naming the fix,
// its ID and what is wrong (before: a count too large ended in std::bad_alloc, a segfault
// or reads far past the block; an unknown mark was read as "format 0").
TEST_F(RestartDamageTest, DamagedFixBlocksAreRefusedByName)
{
  write_scene();
  size_t solver = 0, wire = 0, wall = 0, plate = 0;
  if (rank() == 0) {
    solver = fix_block(original, "solver", "nscd");
    wire = fix_block(original, "w", "wire");
    wall = fix_block(original, "floor", "nscd/wall");
    plate = fix_block(original, "plate", "nscd/plate");
    ASSERT_NE(solver, std::string::npos);
    ASSERT_NE(wire, std::string::npos);
    ASSERT_NE(wall, std::string::npos);
    ASSERT_NE(plate, std::string::npos);
    EXPECT_EQ(get<std::int64_t>(original, solver + 16), 0) << "contact records (per atom since format 4)";
    EXPECT_EQ(get<std::int64_t>(original, wire + 24), 0) << "wire memories (per atom since format 4)";
  }
  // header: mark (8 bytes), payload size (8); fix nscd: count (8), dt (8), records;
  // fix wire: dt (8), count (8), records
  struct Case {
    const char *what;
    std::function<void(std::string &)> damage;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {"fix nscd: foreign mark", [&](std::string &b) { b[solver] ^= 0x5a; },
       {"fix nscd solver", "no package mark"}},
      {"fix nscd: count too large", [&](std::string &b) { put<std::int64_t>(b, solver + 16, 1000000000); },
       {"fix nscd solver", "counts 1000000000 contact records"}},
      {"fix nscd: count negative", [&](std::string &b) { put<std::int64_t>(b, solver + 16, -3); },
       {"fix nscd solver", "counts -3 contact records"}},
      {"fix nscd: size larger", [&](std::string &b) { put<std::int64_t>(b, solver + 8, get<std::int64_t>(b, solver + 8) + 48); },
       {"fix nscd solver", "bytes left"}},
      {"fix nscd: size smaller", [&](std::string &b) { put<std::int64_t>(b, solver + 8, 20); },
       {"fix nscd solver", "4 bytes left after its contents"}},    // no records since format 4
      {"fix nscd: format 1000", [&](std::string &b) { put<std::int32_t>(b, solver + 4, 1000); },
       {"fix nscd solver", "format 1000 is newer than this build's 4"}},
      {"fix nscd: format -7", [&](std::string &b) { put<std::int32_t>(b, solver + 4, -7); },
       {"fix nscd solver", "format number -7"}},
      {"fix nscd: a denormal timestep", [&](std::string &b) { put<double>(b, solver + 24, 5e-315); },
       {"fix nscd solver", "the impulses' timestep is 5.00000000228"}},
      {"fix wire: foreign mark", [&](std::string &b) { b[wire + 1] ^= 0x11; },
       {"fix wire w", "no package mark"}},
      {"fix wire: count too large", [&](std::string &b) { put<std::int64_t>(b, wire + 24, 1ll << 40); },
       {"fix wire w", "counts 1099511627776 contact memories"}},
      {"fix wire: format 5", [&](std::string &b) { put<std::int32_t>(b, wire + 4, 5); },
       {"fix wire w", "format 5 is newer than this build's 4"}},
      {"fix wire: a NaN substep", [&](std::string &b) { put<double>(b, wire + 16, NAN); },
       {"fix wire w", "substep is nan"}},
      {"fix wire: a denormal substep", [&](std::string &b) { put<double>(b, wire + 16, 5e-315); },
       {"fix wire w", "substep is 5.00000000228"}},
      {"fix nscd/wall: foreign mark", [&](std::string &b) { put<std::int32_t>(b, wall, 12345); },
       {"fix nscd/wall floor", "no package mark"}},
      {"fix nscd/wall: format 3", [&](std::string &b) { put<std::int32_t>(b, wall + 4, 3); },
       {"fix nscd/wall floor", "format 3 is newer than this build's 2"}},
      {"fix nscd/wall: kind 2", [&](std::string &b) { put<double>(b, wall + 16, 2.0); },
       {"fix nscd/wall floor", "kind is 2"}},
      {"fix nscd/wall: size 0", [&](std::string &b) { put<std::int64_t>(b, wall + 8, 0); },
       {"fix nscd/wall floor", "ends inside the wall's kind"}},
      {"fix nscd/plate: format 3", [&](std::string &b) { put<std::int32_t>(b, plate + 4, 3); },
       {"fix nscd/plate plate", "format 3 is newer than this build's 2"}},
      {"fix nscd/plate: an infinite z", [&](std::string &b) { put<double>(b, plate + 16, INFINITY); },
       {"fix nscd/plate plate", "the plate's z is inf"}},
      {"fix nscd/plate: a negative loading time", [&](std::string &b) { put<double>(b, plate + 32, -1.0); },
       {"fix nscd/plate plate", "loading time is -1"}},
  };
  for (const Case &c : cases) {
    const std::string message = error_after(c.damage);
    for (const std::string &part : c.expected) EXPECT_TRUE(has(message, part)) << c.what << ": " << message;
  }
  // and the undamaged file reads and runs on
  EXPECT_EQ(error_after([](std::string &) {}), "");
  EXPECT_EQ(error_of("run 2"), "");
}

// fix nscd's per-atom warm start (format 1: {format, count, 6 values per record}), as
// read_restart hands it to the fix per atom: a newer format, a count that does not fit the
// values, a record of another atom, of one body, a NaN impulse are refused naming the atom.
// (fix nscd stops with error->one on the rank owning the atom; here the reader directly.)
TEST(AtomWarmStartDamage, DamagedAtomRecordsAreRefusedByName)
{
  using namespace LAMMPS_NS::NSCD_NS;
  nscd::ImpulseRecord a, b;
  a.tag_i = b.tag_i = 7;
  a.tag_j = 9, b.tag_j = -3;
  a.feature = 5, b.feature = 6;
  a.impulse[2] = 1.5, b.impulse[0] = -0.5;
  std::vector<double> good(atom_impulses_values(2));
  write_atom_impulses({a, b}, good.data());
  const std::vector<nscd::ImpulseRecord> back = read_atom_impulses(good.data(), good.size(), 7);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].tag_j, -3);
  EXPECT_EQ(back[0].impulse[2], 1.5);
  auto contains = [](const std::string &message, const std::string &part) {
    return message.find(part) != std::string::npos;
  };
  auto refusal = [](std::vector<double> values, std::int64_t tag) {
    try {
      read_atom_impulses(values.data(), values.size(), tag);
    } catch (Damaged &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  auto with = [&](int at, double value) {
    std::vector<double> v = good;
    v[at] = value;
    return v;
  };
  auto with_bytes = [&](int at, std::int64_t value) {
    std::vector<double> v = good;
    std::memcpy(&v[at], &value, sizeof(value));
    return v;
  };
  EXPECT_TRUE(contains(refusal(with(0, 2.0), 7), "atom ID 7 holds its warm-start impulses in format 2, this build reads format 1; use a newer build"));
  EXPECT_TRUE(contains(refusal(with(0, 0.5), 7), "which no build writes"));
  EXPECT_TRUE(contains(refusal(with(1, 3.0), 7), "atom ID 7 states 3 warm-start records in 14 values"));
  EXPECT_TRUE(contains(refusal(with(1, -1.0), 7), "states -1 warm-start records"));
  EXPECT_TRUE(contains(refusal(good, 8), "atom ID 8's warm-start record 1 belongs to atom ID 7"));
  EXPECT_TRUE(contains(refusal(with_bytes(2 + 1, 7), 7), "contact record 1 joins the bodies 7 and 7"));
  EXPECT_TRUE(contains(refusal(with(2 + 6 + 3, NAN), 7), "contact record 2's impulse is nan"));
  EXPECT_TRUE(contains(refusal(std::vector<double>(good.begin(), good.begin() + 1), 7), "fewer than the 2 of its header"));
}

// The previous formats: fix nscd's format 2 and fix wire's format 2 had no size (their
// counts cannot be checked): they are not read, with a warning naming the format; the
// wall's and the plate's format 1 (fixed size) still read.
TEST_F(RestartDamageTest, PreviousFormatsAreReadOrSkippedByName)
{
  write_scene();
  auto to_previous = [&](std::string &b) {
    // fix nscd 3 -> 2: {mark 2, int32 count, dt, records}
    size_t at = fix_block(b, "solver", "nscd");
    const std::int64_t count = get<std::int64_t>(b, at + 16);
    const double dt = get<double>(b, at + 24);
    std::string old;
    old.append(b, at, 4);
    const std::int32_t two = 2, count32 = (std::int32_t) count;
    old.append(reinterpret_cast<const char *>(&two), 4).append(reinterpret_cast<const char *>(&count32), 4);
    old.append(reinterpret_cast<const char *>(&dt), 8).append(b, at + 32, count * 48);
    put<int>(b, at - 4, (int) old.size());
    b.replace(at, 32 + count * 48, old);
    // fix wire 4 -> 2: {-2.0, dt, count as a double, records}
    at = fix_block(b, "w", "wire");
    const std::int64_t memories = get<std::int64_t>(b, at + 24);
    const double header[3] = {-2.0, get<double>(b, at + 16), (double) memories};
    old.assign(reinterpret_cast<const char *>(header), sizeof(header)).append(b, at + 32, memories * 112);
    put<int>(b, at - 4, (int) old.size());
    b.replace(at, 32 + memories * 112, old);
    // walls and plate 2 -> 1: {mark 1, 4 doubles}
    for (const auto &fix : {std::make_pair("floor", "nscd/wall"), std::make_pair("plate", "nscd/plate")}) {
      at = fix_block(b, fix.first, fix.second);
      put<std::int32_t>(b, at + 4, 1);
      b.erase(at + 8, 8);
      put<int>(b, at - 4, 40);
    }
  };
  const std::string log = log_after(to_previous);
  EXPECT_TRUE(has(log, "fix nscd solver: restart file's warm start in old format 2 not read")) << log;
  EXPECT_TRUE(has(log, "fix wire w: restart file's wire contacts in old format 2 not read")) << log;
  EXPECT_FALSE(has(log, "ERROR")) << log;
  EXPECT_NEAR(lmp->modify->get_fix_by_id("plate")->compute_vector(0), 3.0, 1e-9);    // read: the plate's z
  EXPECT_EQ(error_of("run 2"), "");
}

// pair_style nscd, bond_style and angle_style wire read their part of the file themselves:
// a foreign mark, a coefficient no command accepts, a file cut inside them.
TEST_F(RestartDamageTest, DamagedForceFieldSettingsAreRefusedByName)
{
  write_scene();
  size_t pair = 0, bond = 0, angle = 0;
  if (rank() == 0) {
    const std::int32_t magic = LAMMPS_NS::NSCD_NS::MAGIC;
    pair = original.find(std::string(reinterpret_cast<const char *>(&magic), 4));    // written first
    const double bond_row[3] = {100.0, 0.1, 0.0};
    bond = original.find(std::string(reinterpret_cast<const char *>(bond_row), sizeof(bond_row)));
    const double k_rot = 0.01;
    angle = original.find(std::string(reinterpret_cast<const char *>(&k_rot), 8), bond + 24);
    ASSERT_NE(pair, std::string::npos);
    ASSERT_NE(bond, std::string::npos);
    ASSERT_NE(angle, std::string::npos);
  }
  // pair: mark (8), 4 doubles (32), then per type pair (1 1), (1 2), (2 2): flag, mu, e
  std::string message = error_after([&](std::string &b) { b[pair + 2] = 'X'; });
  EXPECT_TRUE(has(message, "pair_style nscd: restart file's settings refused")) << message;
  EXPECT_TRUE(has(message, "mark")) << message;
  message = error_after([&](std::string &b) { put<std::int32_t>(b, pair + 4, 2); });
  EXPECT_TRUE(has(message, "the settings' format 2 is newer than this build's 1")) << message;
  message = error_after([&](std::string &b) { put<double>(b, pair + 8 + 8, 3.0); });
  EXPECT_TRUE(has(message, "activation fraction 3")) << message;
  message = error_after([&](std::string &b) { put<double>(b, pair + 40 + 4, -0.5); });
  EXPECT_TRUE(has(message, "type pair 1 1: a friction coefficient is -0.5")) << message;
  message = error_after([&](std::string &b) { put<std::int32_t>(b, pair + 40 + 20, 9); });
  EXPECT_TRUE(has(message, "type pair 1 2: a type pair's flag is 9")) << message;
  message = error_after([&](std::string &b) { put<double>(b, bond, NAN); });
  EXPECT_TRUE(has(message, "coefficients of bond type 1 are damaged (k_elo = nan")) << message;
  message = error_after([&](std::string &b) { put<double>(b, angle, -1.0); });
  EXPECT_TRUE(has(message, "k_rot = -1 of angle type 1 is damaged")) << message;
}

// Per-atom values: the grain's mass and fix wire's per-atom Gear state. read_restart stops on
// the rank owning the atom (error->one), so this runs on one rank only.
TEST_F(RestartDamageTest, DamagedPerAtomValuesAreRefusedNamingTheAtom)
{
  if (ranks() > 1) GTEST_SKIP() << "error->one on the owning rank: serial check";
  write_scene();
  // fix wire's values of a node: its count (20, + 2 + 14 per memory from wire format 4 on),
  // its Gear state (beginning with its position), then its friction memories {format,
  // count, records}: node 2 is off the cube and holds none, the lowest node ID on the cube
  // (`held`) computes a contact with it and holds its memory
  LAMMPS_NS::Fix *fix_wire = lmp->modify->get_fix_by_id("w");
  auto values_of = [&](LAMMPS_NS::tagint id) {
    const int k = lmp->atom->map(id);
    return std::array<double, 4>{(double) fix_wire->size_restart(k), lmp->atom->x[k][0], lmp->atom->x[k][1],
                                 lmp->atom->x[k][2]};
  };
  const std::array<double, 4> node_2 = values_of(2);
  EXPECT_EQ(node_2[0], 20 + 2);
  LAMMPS_NS::tagint held = 3;
  while (held < lmp->atom->natoms && values_of(held)[0] < 20 + 2 + 14) held++;
  const std::array<double, 4> node_held = values_of(held);
  ASSERT_GE(node_held[0], 20 + 2 + 14) << "no node holds a friction memory";
  const double mass = 1.2345678901234567;
  const size_t at_mass = original.find(std::string(reinterpret_cast<const char *>(&mass), 8));
  ASSERT_NE(at_mass, std::string::npos);
  std::string message = error_after([&](std::string &b) { put<double>(b, at_mass, -2.0); });
  EXPECT_TRUE(has(message, "read_restart: atom ID 1: mass -2 must be a finite number > 0")) << message;
  message = error_after([&](std::string &b) { put<double>(b, at_mass, NAN); });
  EXPECT_TRUE(has(message, "atom ID 1: mass nan")) << message;

  auto find = [&](const std::array<double, 4> &values) {
    return original.find(std::string(reinterpret_cast<const char *>(values.data()), sizeof(values)));
  };
  const size_t gear = find(node_2);
  ASSERT_NE(gear, std::string::npos);
  message = error_after([&](std::string &b) { put<double>(b, gear, 1e9); });
  EXPECT_TRUE(has(message, "fix wire w: restart per-atom values of atom ID 2 are damaged")) << message;
  message = error_after([&](std::string &b) { put<double>(b, gear, 21.0); });    // a memory header cut short
  EXPECT_TRUE(has(message, "per-atom values of atom ID 2 are damaged (a count of 21 where 20 or 22 to")) << message;
  message = error_after([&](std::string &b) { put<double>(b, gear + 8 * 5, NAN); });
  EXPECT_TRUE(has(message, "Gear state of atom ID 2 holds nan (value 5 of 19)")) << message;
  const size_t memories = find(node_held) + 8 * 20;    // after the count and the Gear state
  ASSERT_NE(memories, std::string::npos + 8 * 20);
  const std::string atom = "atom ID " + std::to_string(held);
  message = error_after([&](std::string &b) { put<double>(b, memories, 2.0); });
  EXPECT_TRUE(has(message, "fix wire w: restart file's friction memories refused: " + atom +
                           " holds its wire friction memories in format 2, this build reads format 1")) << message;
  message = error_after([&](std::string &b) { put<double>(b, memories + 8 * (2 + 4 + 8), 7.0); });    // weight[0]
  EXPECT_TRUE(has(message, "wire contact memory 1 has an end weight 7 outside [0, 1]")) << message;
  message = error_after([&](std::string &b) { put<std::int64_t>(b, memories + 8 * 2, held + 1); });    // key[0]
  EXPECT_TRUE(has(message, atom + "'s wire friction memory 1 belongs to atom ID " + std::to_string(held + 1))) << message;
  // and the undamaged file reads and runs on
  EXPECT_EQ(error_after([](std::string &) {}), "");
  EXPECT_EQ(error_of("run 2"), "");
}
