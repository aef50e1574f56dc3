// Bad input through the deck: every case of the probe in issue 16 that reaches LAMMPS gets a
// clear error naming the value (or, for legal but suspicious decks, a warning), never a
// crash, a hang or garbage. The shape library's own cases are unit-tested in lib/
// (tests/unit/shape/test_shape_robustness.cpp); here they are checked to arrive as LAMMPS
// errors. Runs serially and under mpirun -np 2.
#include "lammps_fixture.h"

#include "modify.h"

#include <fstream>
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
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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
