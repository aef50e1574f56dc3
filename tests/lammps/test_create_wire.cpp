// create_wire: geometry against closed forms (node count, positions, bond and angle counts,
// rest lengths, gap), every refusal, and wires laid between runs moving with fix wire.
// Runs serially and under mpirun -np 2 and -np 4: the nodes land on whichever rank owns
// their position, the result must not depend on it.
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"
#include "fix.h"
#include "modify.h"

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
constexpr double kPi = 3.141592653589793;

struct Node {
  double x[3];
  double mass;
  int type, shape;
  tagint molecule;
};
}    // namespace

class CreateWireTest : public LammpsTest {
 protected:
  // A box for wires: bonds of rest length 0.2 (type 1) and 0.25 (type 2), bending type 1.
  void box(const std::string &boundary = "f f f")
  {
    commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
              "boundary " + boundary, "region box block -4 4 -4 4 -1 5",
              "create_box 2 box bond/types 2 angle/types 1 extra/bond/per/atom 1 "
              "extra/angle/per/atom 1 extra/special/per/atom 6",
              "shapes random 2 seed 3 size 0.8 1 radius 0.02", "bond_style wire", "bond_coeff 1 100 0.2",
              "bond_coeff 2 100 0.25", "angle_style wire", "angle_coeff 1 0.01"});
  }

  // Every atom by ID, from all ranks.
  std::map<tagint, Node> nodes()
  {
    auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
    const tagint n = (tagint) lmp->atom->natoms;
    std::vector<double> mine(7 * n, 0.0), all(7 * n);
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      double *row = &mine[7 * (lmp->atom->tag[i] - 1)];
      for (int d = 0; d < 3; d++) row[d] = lmp->atom->x[i][d];
      row[3] = avec->rmass[i];
      row[4] = lmp->atom->type[i];
      row[5] = avec->shape[i];
      row[6] = (double) lmp->atom->molecule[i];
    }
    MPI_Allreduce(mine.data(), all.data(), 7 * n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    std::map<tagint, Node> result;
    for (tagint t = 1; t <= n; t++) {
      const double *row = &all[7 * (t - 1)];
      result[t] = Node{{row[0], row[1], row[2]}, row[3], (int) row[4], (int) row[5], (tagint) row[6]};
    }
    return result;
  }

  static double distance(const Node &a, const Node &b)
  {
    return std::sqrt(std::pow(a.x[0] - b.x[0], 2) + std::pow(a.x[1] - b.x[1], 2) + std::pow(a.x[2] - b.x[2], 2));
  }

  std::string log_of(const std::string &line)
  {
    const std::string log = scratch("log");
    commands({"log " + log, line, "log none"});
    MPI_Barrier(MPI_COMM_WORLD);    // rank 0 writes the log: the others read it when it is closed
    std::ifstream in(log);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
};

// A double loop with a gap around the z axis: equal chords of 0.2 are equal angles on the
// helix; nodes, bonds and angles as the closed form says, on every rank count.
TEST_F(CreateWireTest, DoubleLoopWithGapFollowsTheHelix)
{
  box();
  run("create_wire 1 loop 0.5 -0.5 1 2.5 turns 2 pitch 0.05 gap 20 bond 1 angle 1 mass 0.01 radius 0.02");
  // angle step d with (2 R sin(d/2))^2 + (p d / 2 pi)^2 = 0.2^2
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; k++) {
    const double d = 0.5 * (lo + hi);
    (std::hypot(5.0 * std::sin(0.5 * d), 0.05 * d / (2 * kPi)) < 0.2 ? lo : hi) = d;
  }
  const double step = lo;
  const int expected = (int) std::floor((4 * kPi - 20 * kPi / 180) / step) + 1;
  ASSERT_EQ(lmp->atom->natoms, expected);
  EXPECT_EQ(lmp->atom->nbonds, expected - 1);
  EXPECT_EQ(lmp->atom->nangles, expected - 2);
  const auto all = nodes();
  for (auto &[tag, node] : all) {
    const double a = (tag - 1) * step;
    EXPECT_NEAR(node.x[0], 0.5 + 2.5 * std::cos(a), 1e-9) << tag;
    EXPECT_NEAR(node.x[1], -0.5 + 2.5 * std::sin(a), 1e-9) << tag;
    EXPECT_NEAR(node.x[2], 1.0 + 0.05 * a / (2 * kPi), 1e-9) << tag;
    EXPECT_DOUBLE_EQ(node.mass, 0.01);
    EXPECT_EQ(node.shape, 0);
    EXPECT_EQ(node.molecule, 1);
    if (tag > 1) EXPECT_NEAR(distance(node, all.at(tag - 1)), 0.2, 1e-12);
  }
  // the ends are at least the requested 20 degrees apart, less than one element more
  const double open = 4 * kPi - (expected - 1) * step;
  EXPECT_GE(open, 20 * kPi / 180 - 1e-12);
  EXPECT_LT(open, 20 * kPi / 180 + step);
}

TEST_F(CreateWireTest, ClosedRingNeedsAMatchingRestLength)
{
  box();
  // 2 pi 0.5 / 0.2 = 15.7: 16 elements of 2 x 0.5 sin(pi / 16) = 0.19509 != 0.2
  const std::string message = error_of("create_wire 1 loop 0 0 1 0.5 bond 1 angle 1 mass 0.01 radius 0.02");
  EXPECT_NE(message.find("0.195090322"), std::string::npos) << message;
  EXPECT_NE(message.find("strain"), std::string::npos) << message;
  // with that rest length it closes: 16 nodes, 16 bonds, 16 angles
  commands({"bond_coeff 2 100 " + num(2 * 0.5 * std::sin(kPi / 16)),
            "create_wire 1 loop 0 0 1 0.5 bond 2 angle 1 mass 0.01 radius 0.02"});
  EXPECT_EQ(lmp->atom->natoms, 16);
  EXPECT_EQ(lmp->atom->nbonds, 16);
  EXPECT_EQ(lmp->atom->nangles, 16);
  // or starts strained on request
  run("create_wire 1 loop 0 0 2 0.5 bond 1 angle 1 mass 0.01 radius 0.02 strained yes");
  EXPECT_EQ(lmp->atom->natoms, 32);
}

TEST_F(CreateWireTest, LineAndPolylineNodesAreOnThePath)
{
  box();
  run("create_wire 2 line -3 -3 0.5 3 -3 0.5 bond 1 mass 0.02 radius 0.02 mol 7");
  EXPECT_EQ(lmp->atom->natoms, 31);    // 6 / 0.2 elements
  EXPECT_EQ(lmp->atom->nangles, 0);    // no angle type given: no bending
  auto all = nodes();
  for (auto &[tag, node] : all) {
    EXPECT_NEAR(node.x[0], -3 + 0.2 * (tag - 1), 1e-12);
    EXPECT_EQ(node.type, 2);
    EXPECT_EQ(node.molecule, 7);
  }
  if (rank() == 0) std::ofstream(scratch("path.txt")) << "# an L\n0 0 2\n1 0 2   # corner\n\n1 1 2\n";
  MPI_Barrier(MPI_COMM_WORLD);
  run("create_wire 1 polyline " + scratch("path.txt") + " bond 1 angle 1 mass 0.01 radius 0.02");
  all = nodes();
  EXPECT_EQ(lmp->atom->natoms, 31 + 11);    // 0, .2, ... 1 along x (the corner), 0.2 .. 1 along y
  EXPECT_NEAR(all.at(31 + 6).x[0], 1.0, 1e-12);
  EXPECT_NEAR(all.at(31 + 7).x[1], 0.2, 1e-12);
  EXPECT_NEAR(all.at(42).x[1], 1.0, 1e-12);
  EXPECT_EQ(all.at(42).molecule, 8);    // the next free molecule ID
  // a given node count: equal chords spanning the whole line, rest length to match
  commands({"bond_coeff 2 100 0.25", "create_wire 1 line -3 3 0.5 -1 3 0.5 bond 2 mass 0.01 radius 0.02 nodes 9"});
  EXPECT_EQ(lmp->atom->natoms, 42 + 9);
}

TEST_F(CreateWireTest, RefusalsNameTheValue)
{
  box();
  auto refused = [&](const std::string &args, const std::string &part) {
    const std::string message = error_of("create_wire " + args);
    EXPECT_NE(message.find(part), std::string::npos) << args << " -> " << message;
  };
  refused("1 loop 0 0 1 5 gap 10 bond 1 mass 0.01 radius 0.02", "outside the box");
  refused("1 loop 0 0 1 1 gap 10 bond 1 mass 0.01 radius 0.2", "below the wire's diameter 0.4");
  refused("1 loop 0 0 1 1 gap 10 bond 3 mass 0.01 radius 0.02", "bond type 3");
  refused("1 loop 0 0 1 1 gap 10 bond 1 angle 2 mass 0.01 radius 0.02", "angle type 2");
  refused("1 loop 0 0 1 1 gap 10 bond 1 mass 0.01", "radius");
  refused("1 loop 0 0 1 1 gap 10 bond 1 mass -1 radius 0.02", "mass -1");
  refused("1 loop 0 0 1 1 gap 10 mass 0.01 radius 0.02", "bond BTYPE");
  refused("1 loop 0 0 1 1 turns 2 bond 1 mass 0.01 radius 0.02", "pitch");
  refused("1 loop 0 0 1 1 gap 400 bond 1 mass 0.01 radius 0.02", "gap");
  refused("1 line 0 0 1 1 0 1 turns 2 bond 1 mass 0.01 radius 0.02", "'turns' applies to a loop");
  refused("1 loop 0 0 1 1 gap 10 bond 1 mass 0.01 radius 0.02 color red", "unknown keyword 'color'");
  refused("1 line 0 0 1 1 0 1 bond 1 mass 0.01 radius 0.02 nodes 3", "strain");
  refused("1 polyline /nonexistent bond 1 mass 0.01 radius 0.02", "cannot open");

  // a grain on the path, and a wall the loop crosses
  commands({"create_atoms 1 single 1.5 0 1", "shapes assign all shape 1 density 1"});
  refused("1 loop 0 0 1 1.5 gap 10 bond 1 mass 0.01 radius 0.02", "overlaps grain ID 1");
  run("create_wire 1 loop 0 0 1 1.5 gap 10 bond 1 mass 0.01 radius 0.02 overlap ignore");
  commands({"pair_style nscd", "pair_coeff * * 0.5", "fix wall all nscd/wall cylinder 0 0 0 0 0 1 2.5"});
  refused("1 loop 0 0 3 3 gap 10 bond 1 mass 0.01 radius 0.02", "fix wall");
}

TEST_F(CreateWireTest, NoBondRoomIsRefused)
{
  commands({"units lj", "atom_style hybrid spheropolyhedron angle", "region box block -4 4 -4 4 -1 5",
            "create_box 1 box bond/types 1 angle/types 1", "bond_style wire", "bond_coeff 1 100 0.2"});
  EXPECT_NE(error_of("create_wire 1 line 0 0 1 1 0 1 bond 1 mass 0.01 radius 0.02").find("extra/bond/per/atom"),
            std::string::npos);
}

// Wires laid before the first run and between runs fall under gravity onto the floor with
// fix wire and rest there: the second one gets fresh Gear states, no NaN, no atom lost.
TEST_F(CreateWireTest, WiresLaidBetweenRunsAreIntegratedByFixWire)
{
  box("p p f");
  commands({"create_wire 1 line -3 -2 0.3 3 -2 0.3 bond 1 angle 1 mass 0.01 radius 0.02",
            "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "timestep 0.001", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1",
            // gamma_n near 2 sqrt(k_n m): the wires land without bouncing for long
            "fix w all wire radius 0.02 k_n 200 gamma_n 2 k_t 150 gamma_t 1 mu_s 0.5 mu_d 0.4",
            "group grains empty", "fix solver grains nscd", "run 3000"});
  auto all = nodes();
  for (auto &[tag, node] : all) EXPECT_NEAR(node.x[2], 0.02, 0.005) << "first wire, node " << tag;
  run("create_wire 1 line -3 2 0.6 3 2 0.6 bond 1 angle 1 mass 0.01 radius 0.02");
  EXPECT_EQ(lmp->atom->natoms, 62);
  run("run 3000");
  all = nodes();
  for (auto &[tag, node] : all) {
    ASSERT_TRUE(std::isfinite(node.x[2])) << tag;
    EXPECT_NEAR(node.x[2], 0.02, 0.005) << "node " << tag;
  }
  EXPECT_EQ(lmp->atom->natoms, 62);
}
