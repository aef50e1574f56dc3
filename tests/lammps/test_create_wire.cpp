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

// create_wire: geometry against closed forms (node count, positions, bond and angle counts,
// rest lengths, gap), every refusal, and wires laid between runs moving with fix wire.
// Runs serially and under mpirun -np 2 and -np 4: the nodes land on whichever rank owns
// their position, the result must not depend on it.
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"
#include "fix.h"
#include "modify.h"

#include "angle.h"
#include "bond.h"
#include "force.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
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

  static double summed(double mine)
  {
    double all;
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }

  // Every bond (as an ordered pair of IDs, with its type) and angle (with its type) from all
  // ranks, each once.
  std::set<std::array<tagint, 3>> bonds()
  {
    std::vector<tagint> mine;
    for (int i = 0; i < lmp->atom->nlocal; i++)
      for (int m = 0; m < lmp->atom->num_bond[i]; m++) {
        const tagint a = lmp->atom->tag[i], b = lmp->atom->bond_atom[i][m];
        mine.insert(mine.end(), {std::min(a, b), std::max(a, b), (tagint) lmp->atom->bond_type[i][m]});
      }
    std::set<std::array<tagint, 3>> all;
    const std::vector<tagint> everything = gathered(mine);
    for (size_t k = 0; k < everything.size(); k += 3) all.insert({everything[k], everything[k + 1], everything[k + 2]});
    return all;
  }
  std::set<std::array<tagint, 4>> angles()
  {
    std::vector<tagint> mine;
    for (int i = 0; i < lmp->atom->nlocal; i++)
      for (int m = 0; m < lmp->atom->num_angle[i]; m++)
        mine.insert(mine.end(), {lmp->atom->angle_atom1[i][m], lmp->atom->angle_atom2[i][m],
                                 lmp->atom->angle_atom3[i][m], (tagint) lmp->atom->angle_type[i][m]});
    std::set<std::array<tagint, 4>> all;
    const std::vector<tagint> everything = gathered(mine);
    for (size_t k = 0; k < everything.size(); k += 4)
      all.insert({everything[k], everything[k + 1], everything[k + 2], everything[k + 3]});
    return all;
  }
  std::vector<tagint> gathered(const std::vector<tagint> &mine)
  {
    const int count = (int) mine.size();
    std::vector<int> counts(ranks()), offsets(ranks(), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (int r = 1; r < ranks(); r++) offsets[r] = offsets[r - 1] + counts[r - 1];
    std::vector<tagint> all(offsets.back() + counts.back());
    MPI_Allgatherv(mine.data(), count, MPI_LMP_TAGINT, all.data(), counts.data(), offsets.data(), MPI_LMP_TAGINT,
                   MPI_COMM_WORLD);
    return all;
  }
  // The rank that owns atom `tag`.
  int owner(tagint tag)
  {
    const int i = lmp->atom->map(tag);
    int mine = i >= 0 && i < lmp->atom->nlocal ? rank() : -1, found;
    MPI_Allreduce(&mine, &found, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return found;
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
    if (tag > 1) {
      EXPECT_NEAR(distance(node, all.at(tag - 1)), 0.2, 1e-12);
    }
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

// ---------------------------------------------------------------- continuing a wire ('from')

// A straight line continued straight from its end, across the cuts of 2 and 4 ranks (the
// join element crosses x = 0, y = 0 and z = 2 at once): one chain of 21 nodes, 20 bonds and
// 19 angles, the join at the rest length, and a straight wire at rest: no force on any node,
// no stretching or bending energy (closed form: zero).
TEST_F(CreateWireTest, StraightLineContinuedStraightIsOneWireAtRest)
{
  box();
  const double u = 0.2 / std::sqrt(3.0);    // a chord along (1, 1, 1)
  auto point = [&](double k) {              // k chords from the end node
    return num(-0.1 + k * u) + " " + num(-0.1 + k * u) + " " + num(1.9 + k * u);
  };
  run("create_wire 1 line " + point(-10) + " " + point(0) + " bond 1 angle 1 mass 0.01 radius 0.02");
  ASSERT_EQ(lmp->atom->natoms, 11);
  const std::string log = log_of("create_wire 1 line " + point(0) + " " + point(10) + " from last radius 0.02");
  EXPECT_NE(log.find("continuing molecule 1 from its end node ID 11"), std::string::npos) << log;
  ASSERT_EQ(lmp->atom->natoms, 21);
  EXPECT_EQ(lmp->atom->nbonds, 20);
  EXPECT_EQ(lmp->atom->nangles, 19);
  const auto all = nodes();
  for (auto &[tag, node] : all) {
    EXPECT_EQ(node.molecule, 1) << tag;
    EXPECT_EQ(node.type, 1) << tag;
    EXPECT_DOUBLE_EQ(node.mass, 0.01) << tag;    // the end's mass
    if (tag > 1) {
      EXPECT_NEAR(distance(node, all.at(tag - 1)), 0.2, 1e-12) << tag;
    }
  }
  const auto b = bonds();
  EXPECT_EQ(b.size(), 20u);
  EXPECT_TRUE(b.count({11, 12, 1})) << "the join bond";
  const auto a = angles();
  EXPECT_EQ(a.size(), 19u);
  EXPECT_TRUE(a.count({10, 11, 12, 1})) << "the joint at the end";
  EXPECT_TRUE(a.count({11, 12, 13, 1})) << "the joint at the first new node";
  if (ranks() > 1) {
    EXPECT_NE(owner(11), owner(12)) << "the join should cross a rank cut";
  }
  // special lists rebuilt: the end has two 1-2 neighbours now
  const int i = lmp->atom->map(11);
  if (i >= 0 && i < lmp->atom->nlocal) {
    EXPECT_EQ(lmp->atom->nspecial[i][0], 2);
  }

  commands({"special_bonds lj 0 0 0", "run 0 post no"});
  EXPECT_NEAR(summed(lmp->force->bond->energy), 0.0, 1e-20);
  EXPECT_NEAR(summed(lmp->force->angle->energy), 0.0, 1e-20);
  for (tagint t = 1; t <= 21; t++) {
    const auto f = vector_of(t, lmp->atom->f);
    EXPECT_LT(std::hypot(f[0], f[1], f[2]), 1e-10) << "node " << t;
  }
}

// Continued at a right angle: the joint at the end carries the bending energy of an inner
// joint bent by pi/2, k_rot (pi/2)^2 / 2 (angle_style wire's closed form); every other
// joint is straight.
TEST_F(CreateWireTest, JoinBendsLikeAnInnerJoint)
{
  box();
  commands({"create_wire 1 line -2 0.5 1 0 0.5 1 bond 1 angle 1 mass 0.01 radius 0.02",
            "create_wire 1 line 0 0.5 1 0 2.5 1 from 11 radius 0.02", "special_bonds lj 0 0 0", "run 0 post no"});
  EXPECT_EQ(lmp->atom->natoms, 21);
  EXPECT_NEAR(summed(lmp->force->angle->energy), 0.5 * 0.01 * std::pow(kPi / 2, 2), 1e-12);
  EXPECT_NEAR(summed(lmp->force->bond->energy), 0.0, 1e-20);
  // the bridge: a line that starts away from the end is reached by a straight piece first
  run("create_wire 1 line 0.5 2.5 1 2 2.5 1 from last radius 0.02");
  auto all = nodes();
  EXPECT_EQ(lmp->atom->natoms, 31);    // 0.5 of bridge + 1.5 of line: 10 elements
  EXPECT_NEAR(all.at(22).x[0], 0.2, 1e-12);
  EXPECT_NEAR(all.at(31).x[0], 2.0, 1e-12);
  EXPECT_EQ(lmp->atom->nbonds, 30);
  EXPECT_EQ(lmp->atom->nangles, 29);
}

// A helix continued from its end by the next layer's riser and helix, as a layered string
// is laid (doc/create_wire.rst): one molecule, one chain, every element at the rest length.
TEST_F(CreateWireTest, HelixRiserHelixIsOneChain)
{
  box();
  run("create_wire 1 helix 0 0 0.5 2 0.1 turns 2 gap 20 bond 1 angle 1 mass 0.01 radius 0.02");
  const bigint first = lmp->atom->natoms;
  commands({"create_wire 1 line 2 0 1 2 0 2 from last radius 0.02",
            "create_wire 1 helix 0 0 2 2 0.1 turns 2 gap 20 from last radius 0.02"});
  const bigint n = lmp->atom->natoms;
  EXPECT_GT(n, 2 * first);
  EXPECT_EQ(lmp->atom->nbonds, n - 1);
  EXPECT_EQ(lmp->atom->nangles, n - 2);
  const auto all = nodes();
  for (auto &[tag, node] : all) {
    EXPECT_EQ(node.molecule, 1) << tag;
    if (tag > 1) {
      EXPECT_NEAR(distance(node, all.at(tag - 1)), 0.2, 1e-9) << tag;
    }
  }
}

TEST_F(CreateWireTest, ContinuingFromAnythingButAFreeEndIsRefused)
{
  box();
  commands({"create_wire 1 line -2 0.5 1 0 0.5 1 bond 1 angle 1 mass 0.01 radius 0.02",
            "bond_coeff 2 100 " + num(2 * 0.5 * std::sin(kPi / 16)),
            "create_wire 1 loop 0 -2 1 0.5 bond 2 angle 1 mass 0.01 radius 0.02",    // a ring, IDs 12..27
            "create_atoms 1 single 2 2 2", "group grain id 28", "shapes assign grain shape 1 density 1"});
  auto refused = [&](const std::string &args, const std::vector<std::string> &parts) {
    const std::string message = error_of("create_wire " + args);
    for (const std::string &part : parts) EXPECT_NE(message.find(part), std::string::npos) << args << " -> " << message;
  };
  refused("1 line 0 0.5 1 1 0.5 1 from 5 radius 0.02", {"node ID 5 is not a free end", "joins 2 elements",
                                                         "free ends of molecule 1: ID(s) 1 11"});
  refused("1 line 0 0.5 1 1 0.5 1 from 15 radius 0.02", {"node ID 15 is not a free end", "closed ring"});
  refused("1 line 0 0.5 1 1 0.5 1 from 28 radius 0.02", {"atom ID 28 is a grain"});
  refused("1 line 0 0.5 1 1 0.5 1 from 999 radius 0.02", {"no atom has ID 999"});
  refused("2 line 0 0.5 1 1 0.5 1 from 11 radius 0.02", {"atom type 2 differs", "give 1"});
  refused("1 line 0 0.5 1 1 0.5 1 from 11 bond 2 radius 0.02", {"bond type 2 differs"});
  refused("1 line 0 0.5 1 1 0.5 1 from 11 mol 5 radius 0.02", {"molecule 5 differs"});
  refused("1 line 0 0.5 1 1 0.5 1 from 11 nodes 6 radius 0.02", {"'nodes' cannot be combined"});
  refused("1 loop 0 0.5 3 1 from 11 radius 0.02", {"closed ring", "cannot continue"});
  // back along itself: the new elements lie on the old ones
  refused("1 line 0 0.5 1 -1.5 0.5 1 from 11 radius 0.02", {"overlaps"});
  // the wire's first node stores its first bond: the join needs room for a second
  refused("1 line -2 0.5 1 -2 0.5 2 from 1 radius 0.02", {"node ID 1 stores 1 bond(s)", "extra/bond/per/atom 2"});
  EXPECT_EQ(lmp->atom->natoms, 28);
}

// With room for two bonds per atom, a wire continues from its first node just as well.
TEST_F(CreateWireTest, ContinuesFromEitherEnd)
{
  commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
            "region box block -4 4 -4 4 -1 5",
            "create_box 1 box bond/types 1 angle/types 1 extra/bond/per/atom 2 extra/angle/per/atom 1 "
            "extra/special/per/atom 6",
            "bond_style wire", "bond_coeff 1 100 0.2", "angle_style wire", "angle_coeff 1 0.01",
            "create_wire 1 line -2 0.5 1 0 0.5 1 bond 1 angle 1 mass 0.01 radius 0.02",
            "create_wire 1 line -2 0.5 1 -2 0.5 2 from 1 radius 0.02", "special_bonds lj 0 0 0", "run 0 post no"});
  EXPECT_EQ(lmp->atom->natoms, 16);
  EXPECT_EQ(lmp->atom->nbonds, 15);
  EXPECT_EQ(lmp->atom->nangles, 14);
  EXPECT_TRUE(bonds().count({1, 12, 1}));
  EXPECT_TRUE(angles().count({2, 1, 12, 1}));
  EXPECT_NEAR(summed(lmp->force->angle->energy), 0.5 * 0.01 * std::pow(kPi / 2, 2), 1e-12);
}

// fix wire warns at setup about an element far from its rest length (two wires joined by
// create_bonds with one long element flung a grain), naming it and its length ratio; wires
// laid by create_wire, continued or strained by a few %, start silent.
TEST_F(CreateWireTest, FixWireWarnsAboutAnElementFarFromItsRestLength)
{
  box();
  commands({"create_wire 1 helix 0 0 0.5 2 0.1 turns 2 gap 20 bond 1 angle 1 mass 0.01 radius 0.02",
            "create_wire 1 line 2 0 1 2 0 2 from last radius 0.02",
            "create_wire 1 helix 0 0 2 2 0.1 turns 2 gap 20 from last radius 0.02",
            "bond_coeff 2 100 " + num(2 * 0.5 * std::sin(kPi / 16) / 1.03),    // 3 % short of the ring's chord
            "create_wire 1 loop 0 0 3 0.5 bond 2 angle 1 mass 0.01 radius 0.02 strained yes",
            "pair_style nscd", "pair_coeff * * 0.5", "timestep 0.001",
            "fix w all wire radius 0.02 k_n 200 gamma_n 2 k_t 150 gamma_t 1 mu_s 0.5 mu_d 0.4",
            "group grains empty", "fix solver grains nscd"});
  std::string log = log_of("run 0 post no");
  EXPECT_EQ(log.find("rest length"), std::string::npos) << log;

  // a second wire joined to the first by one element 4 x the rest length
  const tagint n = (tagint) lmp->atom->natoms;
  commands({"create_wire 1 line -3 3 4 -1 3 4 bond 1 angle 1 mass 0.01 radius 0.02",
            "create_wire 1 line -0.2 3 4 1.8 3 4 bond 1 angle 1 mass 0.01 radius 0.02",
            "create_bonds single/bond 1 " + std::to_string(n + 11) + " " + std::to_string(n + 12)});
  log = log_of("run 0 post no");
  EXPECT_NE(log.find("1 elements start over 10 % from rest length, worst 4 x (IDs " + std::to_string(n + 11) +
                     "-" + std::to_string(n + 12) + ")"), std::string::npos) << log;
}

// 'drop yes' lowers the wire as laid out until it touches what lies below: a floor (the
// nodes' centres one wire radius above it), a wire already there (the second ring's
// centre line one diameter above the first's), a grain (touching: 0.01 lower overlaps it).
// Nothing below and 'from' are refused.
TEST_F(CreateWireTest, DropLaysTheWireOnWhatLiesBelow)
{
  const double r = 0.02;
  box();
  commands({"pair_style nscd", "pair_coeff * * 0.5", "fix floor all nscd/wall plane 0 0 0 0 0 1"});
  const std::string lowered = log_of("create_wire 1 loop 0 0 3 1 bond 1 mass 0.01 radius 0.02 drop yes gap 10");
  EXPECT_NE(lowered.find("dropped 2.98 onto what lies below"), std::string::npos) << lowered;
  const tagint first_ring = (tagint) nodes().size();
  for (const auto &[tag, node] : nodes()) EXPECT_NEAR(node.x[2], r, 1e-6 * r) << tag;
  run("create_wire 1 loop 0 0 2 1 bond 1 mass 0.01 radius 0.02 drop yes gap 10");
  for (const auto &[tag, node] : nodes()) EXPECT_NEAR(node.x[2], tag <= first_ring ? r : 3 * r, 1e-5 * r) << tag;
  commands({"group wire type 1", "delete_atoms group wire bond yes", "unfix floor"});

  commands({"create_atoms 2 single 0 0 1", "shapes assign all shape 1 density 1"});
  const std::string on_grain = log_of("create_wire 1 loop 0 0 3 0.3 bond 1 mass 0.01 radius 0.02 drop yes gap 10");
  const size_t at = on_grain.find("dropped ");
  ASSERT_NE(at, std::string::npos) << on_grain;
  const double drop = std::stod(on_grain.substr(at + 8));
  EXPECT_GT(drop, 0.5);
  EXPECT_LT(drop, 2.0 - r);    // above the grain's centre
  for (const auto &[tag, node] : nodes()) {
    if (node.type != 1) continue;
    EXPECT_NEAR(node.x[2], 3.0 - drop, 1e-5) << tag;    // the log's 6 digits
  }
  commands({"group wire type 1", "delete_atoms group wire bond yes"});
  std::ostringstream lower;
  lower.precision(17);
  lower << "create_wire 1 loop 0 0 " << 3.0 - drop - 0.01 << " 0.3 bond 1 mass 0.01 radius 0.02 overlap 0 gap 10";
  EXPECT_NE(error_of(lower.str()).find("overlaps grain ID"), std::string::npos);

  EXPECT_NE(error_of("create_wire 1 loop 2.5 2.5 3 0.3 bond 1 mass 0.01 radius 0.02 drop yes gap 10")
                .find("nothing below the wire"),
            std::string::npos);
  run("create_wire 1 line 3 -3 4 3 -2 4 bond 1 mass 0.01 radius 0.02");
  EXPECT_NE(error_of("create_wire 1 line 3 -2 4 3 -1 4 from last drop yes").find("'drop' cannot be combined"),
            std::string::npos);
}

// Across a periodic boundary: a ring centred 0.2 inside the box's +x face, half of it
// wrapped to the -x side, drops onto a grain standing just inside the -x face (seen through
// its periodic image), not onto the floor.
TEST_F(CreateWireTest, DropFindsAGrainThroughThePeriodicBoundary)
{
  const double r = 0.02;
  box("p p f");
  commands({"pair_style nscd", "pair_coeff * * 0.5", "fix floor all nscd/wall plane 0 0 0 0 0 1",
            "create_atoms 2 single -3.9 0 0.6", "shapes assign all shape 1 density 1"});
  run("create_wire 1 loop 3.8 0 3 0.5 bond 1 mass 0.01 radius 0.02 drop yes gap 10");
  double lowest = 1e300;
  for (const auto &[tag, node] : nodes())
    if (node.type == 1) lowest = std::min(lowest, node.x[2]);
  EXPECT_GT(lowest, r + 0.1);    // held above the floor by the grain's image
  EXPECT_LT(lowest, 3.0);
}
