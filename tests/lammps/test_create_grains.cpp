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

// create_grains: the same grains (IDs, positions, shapes, orientations) on 1, 2 and 4 ranks
// and processor grids; no overlap (compute nscd/overlap/atom, the contact detection's own
// distance) in dense fills, with grains already there and in a cylinder; every refusal.
// Runs serially and under mpirun -np 2 and -np 4.
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"
#include "input.h"
#include "modify.h"
#include "compute.h"
#include "geometry/contact.h"
#include "shape/shape_library.h"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
constexpr int kFields = 9;    // x y z, quat w x y z, shape, type
}

class CreateGrainsTest : public LammpsTest {
 protected:
  // The column's library: bounding radii up to 0.84.
  static std::vector<std::string> box_lines(const std::string &grid)
  {
    return {"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f", grid,
            "region box block -4 4 -4 4 -1 8", "create_box 1 box",
            "shapes random 24 seed 2026 vertices 10 20 size 0.8 1.0 axes 0.8 0.6 radius 0.05",
            "pair_style nscd", "pair_coeff * * 0.5"};
  }

  // Every atom's row by ID (kFields each), on every rank of `comm`.
  static std::vector<double> rows(LAMMPS *instance, MPI_Comm comm)
  {
    auto *avec = AtomVecSpheropolyhedron::find(instance, "test");
    Atom *atom = instance->atom;
    const bigint n = atom->natoms;
    std::vector<double> mine(kFields * n, 0.0), all(kFields * n);
    for (int i = 0; i < atom->nlocal; i++) {
      double *row = &mine[kFields * (atom->tag[i] - 1)];
      for (int d = 0; d < 3; d++) row[d] = atom->x[i][d];
      for (int d = 0; d < 4; d++) row[3 + d] = avec->quat[i][d];
      row[7] = avec->shape[i];
      row[8] = atom->type[i];
    }
    MPI_Allreduce(mine.data(), all.data(), (int) mine.size(), MPI_DOUBLE, MPI_SUM, comm);
    return all;
  }

  // Deepest overlap between any two grains after `run 0` (0 when none overlap).
  double deepest_overlap()
  {
    commands({"compute ov all nscd/overlap/atom", "compute deepest all reduce max c_ov[1]", "run 0 post no"});
    Compute *c = lmp->modify->get_compute_by_id("deepest");
    const double d = c->compute_scalar();
    commands({"uncompute deepest", "uncompute ov"});
    return d;
  }

  std::string log_of(const std::string &line)
  {
    const std::string log = scratch("log");
    commands({"log " + log, line, "log none"});
    MPI_Barrier(MPI_COMM_WORLD);
    std::ifstream in(log);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
};

// A lattice layer, grains at random above it and a cylinder fill: rank 0 alone (a LAMMPS
// of its own) and all ranks on two processor grids must make the same atoms, to round-off 0.
TEST_F(CreateGrainsTest, SameGrainsOnAnyRankCountAndGrid)
{
  const std::vector<std::string> fills = {
      "region a block -3 3 -3 3 0.9 2.5 units box", "create_grains 1 a shape 1 24 density 1 seed 7 lattice 1.6",
      "region b block -3 3 -3 3 2.6 4.5 units box", "create_grains 1 b shape 1 24 density 1 seed 9 random 40 50",
      "region c cylinder z 0 0 2 4.6 6.5 units box", "create_grains 1 c shape 3 10 density 2 seed 11 lattice 1.2"};
  // the serial reference, on rank 0's own communicator
  std::vector<double> reference;
  bigint count = 0;
  on_first_ranks(1, [&](MPI_Comm alone) {
    commands(box_lines("processors * * *"));
    commands(fills);
    count = lmp->atom->natoms;
    reference = rows(lmp, alone);
  });
  MPI_Bcast(&count, 1, MPI_LMP_BIGINT, 0, MPI_COMM_WORLD);
  reference.resize(kFields * count);
  MPI_Bcast(reference.data(), (int) reference.size(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  ASSERT_GT(count, 60);

  for (const std::string grid : {"processors * * *", "processors 1 * *"}) {
    restart_instance();
    commands(box_lines(grid));
    commands(fills);
    ASSERT_EQ(lmp->atom->natoms, count) << grid;
    const std::vector<double> mine = rows(lmp, MPI_COMM_WORLD);
    for (size_t k = 0; k < mine.size(); k++)
      ASSERT_EQ(mine[k], reference[k]) << grid << ": atom ID " << k / kFields + 1 << " field " << k % kFields;
  }
}

// Spacing 1.2, well below twice the largest bounding radius (1.67): neighbouring sites
// would overlap often, the exact test rejects them and keeps the others.
TEST_F(CreateGrainsTest, DenseLatticeFillHasNoOverlap)
{
  commands(box_lines("processors * * *"));
  run("region a block -3 3 -3 3 0.9 3.3 units box");
  const std::string log = log_of("create_grains 1 a shape 1 24 density 1 seed 5 lattice 1.2");
  EXPECT_NE(log.find("overlapping grains placed now"), std::string::npos) << log;
  EXPECT_EQ(log.find("0 overlapping grains placed now"), std::string::npos) << "nothing rejected: " << log;
  EXPECT_GT(lmp->atom->natoms, 30);
  EXPECT_EQ(deepest_overlap(), 0.0);
}

// A second fill overlapping the first one's region must avoid the grains already there, and
// count them as the reason; random positions in a cylinder stay inside it.
TEST_F(CreateGrainsTest, GrainsBelowAreRespectedInACylinder)
{
  commands(box_lines("processors * * *"));
  commands({"region low cylinder z 0 0 2.5 0.9 2.5 units box",
            "create_grains 1 low shape 1 24 density 1 seed 3 lattice 1.6"});
  const bigint below = lmp->atom->natoms;
  ASSERT_GT(below, 5);
  run("region high cylinder z 0 0 2.5 1.5 5 units box");
  const std::string log = log_of("create_grains 1 high shape 1 24 density 1 seed 4 random 60 200");
  EXPECT_EQ(log.find(" 0 overlapping grains already there"), std::string::npos) << log;
  EXPECT_GT(lmp->atom->natoms, below + 20);
  EXPECT_EQ(deepest_overlap(), 0.0);
  const std::vector<double> all = rows(lmp, MPI_COMM_WORLD);
  for (bigint t = below; t < lmp->atom->natoms; t++) {
    const double *row = &all[kFields * t];
    EXPECT_LE(std::hypot(row[0], row[1]), 2.5) << "atom ID " << t + 1;
    EXPECT_GE(row[2], 1.5);
    EXPECT_LE(row[2], 5.0);
  }
}

// A gap keeps every pair of surfaces at least that far apart: the smallest distance between
// any two grains, from the contact geometry on every pair, is at least the gap.
TEST_F(CreateGrainsTest, GapKeepsSurfacesApart)
{
  commands(box_lines("processors * * *"));
  commands({"region a block -3 3 -3 3 0.9 4 units box",
            "create_grains 1 a shape 1 24 density 1 seed 5 random 40 100 gap 0.1"});
  const bigint n = lmp->atom->natoms;
  ASSERT_GT(n, 10);
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
  const std::vector<double> all = rows(lmp, MPI_COMM_WORLD);
  auto pose = [&](bigint t) {
    const double *row = &all[kFields * t];
    nscd::Pose p;
    p.position = nscd::Vec3(row[0], row[1], row[2]);
    p.orientation = nscd::Quat(row[3], row[4], row[5], row[6]);
    return p;
  };
  nscd::ContactWorkspace workspace;
  double smallest = 1e30;
  int near_pairs = 0;
  for (bigint i = 0; i < n; i++)
    for (bigint j = i + 1; j < n; j++) {
      const auto &si = avec->shapes().shape((int) all[kFields * i + 7]);
      const auto &sj = avec->shapes().shape((int) all[kFields * j + 7]);
      for (const auto &p : nscd::contact_grains(si, pose(i), sj, pose(j), 0.3, workspace, 0.0)) {
        smallest = std::min(smallest, p.gap);
        near_pairs++;
      }
    }
  EXPECT_GT(near_pairs, 0) << "no pair within 0.3: the test shows nothing";
  EXPECT_GE(smallest, 0.1);
}

// Walls of group all (fix nscd/wall, plane and cylinder) defined before create_grains: a
// grain reaching into one is left out, counted as such, and every grain made has its
// surface in front of every wall (the walls' own contact geometry, on every grain). The same
// fills without the walls do make grains reaching through them (else the test shows
// nothing), and a wall of another group is not tested.
TEST_F(CreateGrainsTest, GrainsAreNotPlacedIntoWalls)
{
  const nscd::PlaneWall side{nscd::Vec3(2.0, 0.0, 0.0), nscd::Vec3(-1.0, 0.0, 0.0)};
  const nscd::CylinderWall silo{nscd::Vec3(0.0, 0.0, 0.0), nscd::Vec3(0.0, 0.0, 1.0), 2.2};
  const std::vector<std::string> fills = {
      "region a block -3 3 -3 3 0.9 2.5 units box", "create_grains 1 a shape 1 24 density 1 seed 7 lattice 1.6",
      "region c cylinder z 0 0 2.2 2.6 4.5 units box", "create_grains 1 c shape 1 24 density 1 seed 9 lattice 1.2"};
  // the deepest reach of a created grain (by ID range) into the wall
  auto deepest_into = [&](auto contact, bigint from, bigint to) {
    auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
    const std::vector<double> all = rows(lmp, MPI_COMM_WORLD);
    nscd::ContactWorkspace workspace;
    double deepest = -1e30;
    for (bigint t = from; t < to; t++) {
      const double *row = &all[kFields * t];
      nscd::Pose pose;
      pose.position = nscd::Vec3(row[0], row[1], row[2]);
      pose.orientation = nscd::Quat(row[3], row[4], row[5], row[6]);
      for (const auto &p : contact(avec->shapes().shape((int) row[7]), pose, workspace)) deepest = std::max(deepest, -p.gap);
    }
    return deepest;
  };
  auto into_side = [&](const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, nscd::ContactWorkspace &ws) {
    return nscd::contact_grain_plane(shape, pose, side, 0.0, ws);
  };
  auto into_silo = [&](const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, nscd::ContactWorkspace &ws) {
    return nscd::contact_grain_cylinder(shape, pose, silo, 0.0, ws);
  };

  // without walls: grains reach through where the walls will stand
  commands(box_lines("processors * * *"));
  commands({fills[0], fills[1]});
  const bigint layer_without = lmp->atom->natoms;
  commands({fills[2], fills[3]});
  EXPECT_GT(deepest_into(into_side, 0, layer_without), 0.1);
  EXPECT_GT(deepest_into(into_silo, layer_without, lmp->atom->natoms), 0.1);

  // with them: left out, counted, none reaching in
  restart_instance();
  commands(box_lines("processors * * *"));
  commands({"fix side all nscd/wall plane 2 0 0 -1 0 0", "fix silo all nscd/wall cylinder 0 0 0 0 0 1 2.2",
            "group other type 2", "fix elsewhere other nscd/wall plane 0 0 1.8 0 0 1", fills[0]});
  const std::string log = log_of(fills[1]);
  EXPECT_EQ(log.find(" 0 overlapping a wall"), std::string::npos) << log;
  EXPECT_NE(log.find("overlapping a wall"), std::string::npos) << log;
  const bigint layer = lmp->atom->natoms;
  ASSERT_GT(layer, 10);
  EXPECT_LT(layer, layer_without);
  commands({fills[2], fills[3]});
  ASSERT_GT(lmp->atom->natoms, layer + 5);
  EXPECT_LE(deepest_into(into_side, 0, lmp->atom->natoms), 0.0);
  EXPECT_LE(deepest_into(into_silo, layer, lmp->atom->natoms), 0.0);
  // the floor of group `other` (at z 1.8, inside the first layer) did not keep grains out
  auto below_floor = [&](const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, nscd::ContactWorkspace &ws) {
    return nscd::contact_grain_plane(shape, pose, nscd::PlaneWall{nscd::Vec3(0.0, 0.0, 1.8), nscd::Vec3(0.0, 0.0, 1.0)}, 0.0, ws);
  };
  EXPECT_GT(deepest_into(below_floor, 0, layer), 0.1);
}

// The loading plate is a boundary too: no grain is made reaching above it.
TEST_F(CreateGrainsTest, GrainsAreNotPlacedIntoThePlate)
{
  commands(box_lines("processors * * *"));
  commands({"fix plate all nscd/plate 2 mass 1", "region a block -3 3 -3 3 0.9 2.5 units box"});
  const std::string log = log_of("create_grains 1 a shape 1 24 density 1 seed 7 lattice 1.6");
  EXPECT_EQ(log.find(" 0 overlapping a wall"), std::string::npos) << log;
  ASSERT_GT(lmp->atom->natoms, 5);    // the lower plane's grains (the upper plane, at z 1.7, reaches it)
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
  const std::vector<double> all = rows(lmp, MPI_COMM_WORLD);
  const nscd::PlaneWall face{nscd::Vec3(0.0, 0.0, 2.0), nscd::Vec3(0.0, 0.0, -1.0)};
  nscd::ContactWorkspace workspace;
  for (bigint t = 0; t < lmp->atom->natoms; t++) {
    const double *row = &all[kFields * t];
    nscd::Pose pose;
    pose.position = nscd::Vec3(row[0], row[1], row[2]);
    pose.orientation = nscd::Quat(row[3], row[4], row[5], row[6]);
    for (const auto &p : nscd::contact_grain_plane(avec->shapes().shape((int) row[7]), pose, face, 0.0, workspace))
      EXPECT_GE(p.gap, 0.0) << "atom ID " << t + 1;
  }
}

// A wire already there is kept clear as grains and walls are: no grain is made within the gap
// of an element as thick as fix wire's radius (the wire-grain contact's own distance), the
// sites left out counted; the same fill without the wire puts grains through it.
TEST_F(CreateGrainsTest, GrainsAreNotPlacedOntoAWire)
{
  const double r_w = 0.05;
  const std::vector<std::string> wired_box = {
      "units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array", "boundary f f f",
      "processors * * *", "region box block -4 4 -4 4 -1 8",
      "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 1 extra/angle/per/atom 1 extra/special/per/atom 6",
      "shapes random 24 seed 2026 vertices 10 20 size 0.8 1.0 axes 0.8 0.6 radius 0.05", "pair_style nscd",
      "pair_coeff * * 0.5", "bond_style wire", "bond_coeff 1 100 0.2", "angle_style wire", "angle_coeff 1 0.01",
      "region a block -3 3 -3 3 0.9 2.5 units box"};
  // two straight wires through both planes of lattice sites (z 0.9 and 1.7) and between them
  const std::vector<std::string> wires = {"create_wire 2 line -3.5 0.1 1.75 3.5 0.1 1.75 bond 1 angle 1 mass 0.01 radius 0.05",
                                          "create_wire 2 line 0.7 -3.5 1.2 0.7 3.5 1.2 bond 1 angle 1 mass 0.01 radius 0.05"};
  const std::string fill = "create_grains 1 a shape 1 24 density 1 seed 7 lattice 1.6";
  const nscd::Segment along_x{nscd::Vec3(-3.5, 0.1, 1.75), nscd::Vec3(3.5, 0.1, 1.75), r_w};
  const nscd::Segment along_y{nscd::Vec3(0.7, -3.5, 1.2), nscd::Vec3(0.7, 3.5, 1.2), r_w};
  // the smallest surface distance of the grains (type 1) to either wire
  auto closest = [&]() {
    auto *avec = AtomVecSpheropolyhedron::find(lmp, "test");
    const std::vector<double> all = rows(lmp, MPI_COMM_WORLD);
    nscd::ContactWorkspace workspace;
    double nearest = 1e30;
    for (bigint t = 0; t < lmp->atom->natoms; t++) {
      const double *row = &all[kFields * t];
      if ((int) row[7] == 0) continue;    // a wire node
      nscd::Pose pose;
      pose.position = nscd::Vec3(row[0], row[1], row[2]);
      pose.orientation = nscd::Quat(row[3], row[4], row[5], row[6]);
      for (const nscd::Segment &wire : {along_x, along_y})
        for (const auto &p : nscd::contact_segment_grain(wire, avec->shapes().shape((int) row[7]), pose, 1.0, workspace))
          nearest = std::min(nearest, p.gap);
    }
    return nearest;
  };
  auto grains = [&]() {
    bigint n = 0;
    const std::vector<double> all = rows(lmp, MPI_COMM_WORLD);
    for (bigint t = 0; t < lmp->atom->natoms; t++) n += (int) all[kFields * t + 7] != 0;
    return n;
  };

  // points without bonds (an atom style without them) are no wire
  commands(box_lines("processors * * *"));
  commands({"create_atoms 1 single 0.1 0.1 1.75 units box", "region a block -3 3 -3 3 0.9 2.5 units box"});
  ASSERT_EQ(lmp->atom->num_bond, nullptr);    // the style has no bond arrays to read
  const std::string points = log_of(fill);
  EXPECT_NE(points.find(" 0 overlapping a wire"), std::string::npos) << points;

  // without the wires: grains are made through where they will lie
  restart_instance();
  commands(wired_box);
  commands({fill});
  const bigint without = grains();
  EXPECT_LT(closest(), -r_w);    // the wire's axis inside a grain

  // with them (fix wire's radius 0.05): left out, counted, none within the wire
  restart_instance();
  commands(wired_box);
  commands(wires);
  commands({"fix w all wire radius 0.05 k_n 200 gamma_n 2 k_t 150 gamma_t 1 mu_s 0.5 mu_d 0.4"});
  std::string log = log_of(fill);
  EXPECT_EQ(log.find(" 0 overlapping a wire"), std::string::npos) << log;
  EXPECT_NE(log.find("overlapping a wire"), std::string::npos) << log;
  const bigint with = grains();
  ASSERT_GT(with, 5);
  EXPECT_LT(with, without);
  EXPECT_GE(closest(), 0.0);

  // a gap keeps them that far from the wire's surface too
  restart_instance();
  commands(wired_box);
  commands(wires);
  commands({"fix w all wire radius 0.05 k_n 200 gamma_n 2 k_t 150 gamma_t 1 mu_s 0.5 mu_d 0.4", fill + " gap 0.2"});
  ASSERT_GT(grains(), 3);
  EXPECT_GE(closest(), 0.2);
}

TEST_F(CreateGrainsTest, RefusalsNameTheValue)
{
  commands(box_lines("processors * * *"));
  run("region a block -3 3 -3 3 0.9 2.5 units box");
  auto refused = [&](const std::string &args, const std::string &part) {
    const std::string message = error_of("create_grains " + args);
    EXPECT_NE(message.find(part), std::string::npos) << args << " -> " << message;
  };
  refused("1 nowhere shape 1 24 density 1 seed 1 lattice 1.6", "region 'nowhere' does not exist");
  refused("2 a shape 1 24 density 1 seed 1 lattice 1.6", "atom type 2");
  refused("1 a density 1 seed 1 lattice 1.6", "shape IMIN IMAX");
  refused("1 a shape 1 25 density 1 seed 1 lattice 1.6", "1..25");
  refused("1 a shape 5 2 density 1 seed 1 lattice 1.6", "IMIN <= IMAX");
  refused("1 a shape 1 24 seed 1 lattice 1.6", "density RHO");
  refused("1 a shape 1 24 density -1 seed 1 lattice 1.6", "density -1");
  refused("1 a shape 1 24 density 1 seed 0 lattice 1.6", "seed 0");
  refused("1 a shape 1 24 density 1 seed -3 lattice 1.6", "seed -3");
  refused("1 a shape 1 24 density 1 lattice 1.6", "seed SEED");
  refused("1 a shape 1 24 density 1 seed 1", "lattice SPACING");
  refused("1 a shape 1 24 density 1 seed 1 lattice 0", "spacing 0");
  refused("1 a shape 1 24 density 1 seed 1 random 0 10", "random N 0");
  refused("1 a shape 1 24 density 1 seed 1 random 10 0", "TRIES 0");
  refused("1 a shape 1 24 density 1 seed 1 lattice 1.6 gap -1", "gap -1");
  refused("1 a shape 1 24 density 1 seed 1 lattice 1.6 colour red", "unknown keyword 'colour'");
  refused("1 a shape 1 24 density 1 seed 1 lattice", "needs 1 value");
  run("region big block -3 3 -3 3 0 20 units box");
  refused("1 big shape 1 24 density 1 seed 1 lattice 1.6", "outside the box in z");
  EXPECT_EQ(lmp->atom->natoms, 0);
}

// An empty library is refused with the way out.
TEST_F(CreateGrainsTest, NoShapesIsRefused)
{
  commands({"units lj", "atom_style spheropolyhedron", "region box block -4 4 -4 4 -1 8", "create_box 1 box",
            "region a block -3 3 -3 3 0.9 2.5 units box"});
  const std::string message = error_of("create_grains 1 a shape 1 1 density 1 seed 1 lattice 1.6");
  EXPECT_NE(message.find("shape library is empty"), std::string::npos) << message;
}
