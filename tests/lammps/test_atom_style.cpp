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

// atom_style spheropolyhedron, the shapes command and dump grains/vtk, driven through
// LAMMPS. Runs serially and under `mpirun -np 2` (see CMakeLists.txt).
#include "lammps_fixture.h"

#include "atom_vec_spheropolyhedron.h"
#include "compute.h"
#include "domain.h"
#include "modify.h"
#include "shape/shape_library.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace LAMMPS_NS;

namespace {

// A 1 x 2 x 3 box (sharp) and a sphere of radius 0.5: closed-form mass properties.
const char *kTwoShapes = R"(# test shapes
shape box123
radius 0
vertices 8
0 0 0
1 0 0
0 2 0
1 2 0
0 0 3
1 0 3
0 2 3
1 2 3
end
shape ball
radius 0.5
vertices 1
0 0 0
end
)";

struct AtomRecord {
  int type, shape;
  double x[3], quat[4], inertia[3], radius, mass, omega[3];
};

}    // namespace

class AtomStyleTest : public LammpsTest {
 protected:
  std::string shape_file;

  void SetUp() override
  {
    LammpsTest::SetUp();
    shape_file = scratch("shapes.txt");
    if (rank() == 0) std::ofstream(shape_file) << kTwoShapes;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  AtomVecSpheropolyhedron *avec() { return AtomVecSpheropolyhedron::find(lmp, "test"); }

  // A box of grains on a lattice with random shapes and orientations.
  void make_grains(const std::string &style = "spheropolyhedron")
  {
    commands({"units lj", "atom_style " + style, "atom_modify map array", "boundary p p p",
         "shapes read " + shape_file, "lattice sc 4.0", "region box block 0 4 0 3 0 2",
         "create_box 2 box", "create_atoms 1 box",
         "shapes assign all shape random 1 2 4711 density 2.5 orient random 99"});
  }

  // Every atom's record by ID, gathered from all ranks.
  std::map<tagint, AtomRecord> all_atoms()
  {
    std::map<tagint, AtomRecord> local;
    AtomVecSpheropolyhedron *a = avec();
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      AtomRecord r;
      r.type = lmp->atom->type[i];
      r.shape = a->shape[i];
      for (int k = 0; k < 3; k++) {
        r.x[k] = lmp->atom->x[i][k];
        r.inertia[k] = a->inertia[i][k];
        r.omega[k] = a->omega[i][k];
      }
      for (int k = 0; k < 4; k++) r.quat[k] = a->quat[i][k];
      r.radius = a->radius[i];
      r.mass = a->rmass[i];
      local[lmp->atom->tag[i]] = r;
    }
    // Gather as raw bytes: ranks send their records to all.
    std::vector<char> mine;
    for (auto &kv : local) {
      const char *p = reinterpret_cast<const char *>(&kv.first);
      mine.insert(mine.end(), p, p + sizeof(tagint));
      p = reinterpret_cast<const char *>(&kv.second);
      mine.insert(mine.end(), p, p + sizeof(AtomRecord));
    }
    int n = (int) mine.size();
    std::vector<int> sizes(ranks()), offsets(ranks(), 0);
    MPI_Allgather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (int r = 1; r < ranks(); r++) offsets[r] = offsets[r - 1] + sizes[r - 1];
    std::vector<char> all(offsets.back() + sizes.back());
    MPI_Allgatherv(mine.data(), n, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR,
                   MPI_COMM_WORLD);
    std::map<tagint, AtomRecord> result;
    const size_t row = sizeof(tagint) + sizeof(AtomRecord);
    for (size_t off = 0; off + row <= all.size(); off += row) {
      tagint tag;
      AtomRecord r;
      std::memcpy(&tag, &all[off], sizeof(tagint));
      std::memcpy(&r, &all[off + sizeof(tagint)], sizeof(AtomRecord));
      result[tag] = r;
    }
    return result;
  }

  static void expect_same_atoms(const std::map<tagint, AtomRecord> &a,
                                const std::map<tagint, AtomRecord> &b, double tol = 0.0,
                                bool compare_positions = true)
  {
    ASSERT_EQ(a.size(), b.size());
    for (auto &kv : a) {
      auto other = b.find(kv.first);
      ASSERT_NE(other, b.end()) << "atom " << kv.first << " lost";
      const AtomRecord &p = kv.second, &q = other->second;
      EXPECT_EQ(p.type, q.type);
      EXPECT_EQ(p.shape, q.shape) << "atom " << kv.first;
      for (int k = 0; k < 3; k++) {
        if (compare_positions) {
          EXPECT_NEAR(p.x[k], q.x[k], tol);
        }
        EXPECT_NEAR(p.inertia[k], q.inertia[k], tol * std::abs(p.inertia[k]));
        EXPECT_NEAR(p.omega[k], q.omega[k], tol);
      }
      for (int k = 0; k < 4; k++) EXPECT_NEAR(p.quat[k], q.quat[k], tol);
      EXPECT_NEAR(p.radius, q.radius, tol);
      EXPECT_NEAR(p.mass, q.mass, tol * p.mass);
    }
  }
};

TEST_F(AtomStyleTest, ShapesGiveClosedFormMassInertiaAndRadius)
{
  make_grains();
  auto atoms = all_atoms();
  ASSERT_EQ(atoms.size(), 4u * 3u * 2u);
  int boxes = 0, balls = 0;
  for (auto &kv : atoms) {
    const AtomRecord &r = kv.second;
    double qnorm = 0.0;
    for (double c : r.quat) qnorm += c * c;
    EXPECT_NEAR(qnorm, 1.0, 1e-14);
    if (r.shape == 1) {    // 1 x 2 x 3 box, density 2.5: m = 15, I = m (b^2 + c^2) / 12 ...
      boxes++;
      EXPECT_NEAR(r.mass, 15.0, 1e-12);
      // principal moments ascending: about the long axis (3) first
      EXPECT_NEAR(r.inertia[0], 15.0 * (1 + 4) / 12.0, 1e-10);
      EXPECT_NEAR(r.inertia[1], 15.0 * (1 + 9) / 12.0, 1e-10);
      EXPECT_NEAR(r.inertia[2], 15.0 * (4 + 9) / 12.0, 1e-10);
      EXPECT_NEAR(r.radius, 0.5 * std::sqrt(1.0 + 4.0 + 9.0), 1e-12);
    } else {
      balls++;
      ASSERT_EQ(r.shape, 2);
      const double m = 2.5 * 4.0 / 3.0 * M_PI * 0.125;
      EXPECT_NEAR(r.mass, m, 1e-12);
      for (double I : r.inertia) EXPECT_NEAR(I, 0.4 * m * 0.25, 1e-12);
      EXPECT_NEAR(r.radius, 0.5, 1e-14);
    }
  }
  EXPECT_GT(boxes, 3);    // the random choice used both shapes
  EXPECT_GT(balls, 3);
}

TEST_F(AtomStyleTest, RandomAssignmentDoesNotDependOnRankCount)
{
  make_grains();
  auto atoms = all_atoms();
  // Shapes, masses and orientations come from (seed, atom ID) only: a fresh instance with
  // another processor grid gives each ID the same values. (Which lattice site gets which
  // ID does depend on the grid: that is create_atoms' numbering, not ours.)
  restart_instance();
  run("processors * * * map xyz");
  make_grains();
  expect_same_atoms(atoms, all_atoms(), 0.0, false);
}

TEST_F(AtomStyleTest, DataFileRoundTripIsExact)
{
  make_grains();
  commands({"velocity all create 1.0 12345 loop geom", "write_data " + scratch("grains.data"),
       "shapes write " + scratch("written.shapes")});
  auto before = all_atoms();
  restart_instance();
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array",
       "shapes read " + scratch("written.shapes"), "read_data " + scratch("grains.data")});
  auto after = all_atoms();
  // write_data prints 17 significant digits; the shape library is rebuilt from the written
  // body-frame vertices, so inertia agrees to round-off.
  expect_same_atoms(before, after, 1e-13);
}

TEST_F(AtomStyleTest, RestartRoundTripIsExactAndCarriesTheShapes)
{
  make_grains();
  commands({"velocity all create 1.0 12345 loop geom", "write_restart " + scratch("grains.restart")});
  auto before = all_atoms();
  const int nshapes = avec()->shapes().size();
  restart_instance();
  run("read_restart " + scratch("grains.restart"));    // no `shapes` command needed
  EXPECT_EQ(avec()->shapes().size(), nshapes);
  EXPECT_NEAR(avec()->shapes().shape(1).volume, 6.0, 1e-12);
  expect_same_atoms(before, all_atoms(), 0.0);
  // and the restarted library survives a second generation
  run("write_restart " + scratch("again.restart"));
  restart_instance();
  run("read_restart " + scratch("again.restart"));
  expect_same_atoms(before, all_atoms(), 0.0);
}

TEST_F(AtomStyleTest, HybridWithAngleKeepsShapesThroughRestart)
{
  commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
       "boundary p p p", "shapes read " + shape_file, "region box block 0 10 0 10 0 10",
       "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 2 "
       "extra/angle/per/atom 1",
       "create_atoms 1 single 2 2 2", "create_atoms 2 single 5 5 5",
       "shapes assign all shape 1 density 1.0", "group node type 2",
       "shapes assign node shape 0 mass 0.25"});
  auto before = all_atoms();
  run("write_restart " + scratch("hybrid.restart"));
  restart_instance();
  run("read_restart " + scratch("hybrid.restart"));
  EXPECT_EQ(avec()->shapes().size(), 2);
  auto after = all_atoms();
  expect_same_atoms(before, after, 0.0);
  EXPECT_EQ(after.at(2).shape, 0);    // the wire node is a point
  EXPECT_EQ(after.at(2).mass, 0.25);
  EXPECT_EQ(after.at(2).radius, 0.0);
}

TEST_F(AtomStyleTest, AtomsMigrateWithTheirData)
{
  make_grains();
  auto before = all_atoms();
  // Move everything by half the box: on 2+ ranks most atoms change owner.
  commands({"displace_atoms all move 8.0 6.0 4.0 units box"});
  auto after = all_atoms();
  ASSERT_EQ(after.size(), before.size());
  for (auto &kv : before) {
    AtomRecord moved = after.at(kv.first);
    for (int k = 0; k < 3; k++) {    // undo the periodic shift before comparing
      const double L = lmp->domain->prd[k];
      double d = moved.x[k] - kv.second.x[k] - (k == 0 ? 8.0 : k == 1 ? 6.0 : 4.0);
      d -= L * std::round(d / L);
      EXPECT_NEAR(d, 0.0, 1e-12);
      moved.x[k] = kv.second.x[k];
    }
    std::map<tagint, AtomRecord> a{{kv.first, kv.second}}, b{{kv.first, moved}};
    expect_same_atoms(a, b, 0.0);
  }
}

TEST_F(AtomStyleTest, DumpWritesTrueShapesInWorldCoordinates)
{
  commands({"units lj", "atom_style spheropolyhedron", "boundary f f f", "shapes read " + shape_file,
       "region box block -10 10 -10 10 -10 10", "create_box 1 box",
       "create_atoms 1 single 1 2 3", "shapes assign all shape 1 density 1 orient quat 0 0 0 1",
       "dump d all grains/vtk 1 " + scratch("grain.*.vtk"), "run 0"});
  if (rank() != 0) return;
  std::ifstream in(scratch("grain.0.vtk"));
  ASSERT_TRUE(in.good());
  std::string word;
  std::vector<double> xs, ys, zs;
  int npolygons = 0;
  while (in >> word) {
    if (word == "POINTS") {
      int n;
      in >> n >> word;
      ASSERT_EQ(n, 8);
      for (int k = 0; k < n; k++) {
        double x, y, z;
        in >> x >> y >> z;
        xs.push_back(x), ys.push_back(y), zs.push_back(z);
      }
    }
    if (word == "POLYGONS") in >> npolygons;
  }
  EXPECT_EQ(npolygons, 6);    // a box: six quadrilaterals, not twelve triangles
  // Centred at (1,2,3) with half-extents (0.5, 1, 1.5) in some axis order: after any
  // rotation by a principal frame the extents along x, y, z are a permutation of those.
  std::vector<double> extents;
  for (auto *c : {&xs, &ys, &zs}) {
    auto [lo, hi] = std::minmax_element(c->begin(), c->end());
    extents.push_back(*hi - *lo);
  }
  EXPECT_NEAR((*std::minmax_element(xs.begin(), xs.end()).first + *std::minmax_element(xs.begin(), xs.end()).second) / 2, 1.0, 1e-7);
  EXPECT_NEAR((*std::minmax_element(ys.begin(), ys.end()).first + *std::minmax_element(ys.begin(), ys.end()).second) / 2, 2.0, 1e-7);
  EXPECT_NEAR((*std::minmax_element(zs.begin(), zs.end()).first + *std::minmax_element(zs.begin(), zs.end()).second) / 2, 3.0, 1e-7);
  std::sort(extents.begin(), extents.end());
  EXPECT_NEAR(extents[0], 1.0, 1e-7);
  EXPECT_NEAR(extents[1], 2.0, 1e-7);
  EXPECT_NEAR(extents[2], 3.0, 1e-7);
}

// Grains keep their orientation in LAMMPS' own per-atom quat: `set quat` turns a grain, and
// (LAMMPS 29 Aug 2024 and newer) `displace_atoms rotate` turns it along with its position
// and `compute property/atom quatw ...` reads it. A private entry named "quat" would leave
// the core commands working on another array.
TEST_F(AtomStyleTest, CoreOrientationCommandsActOnGrains)
{
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
            "shapes read " + shape_file, "region box block -10 10 -10 10 -10 10",
            "create_box 1 box", "create_atoms 1 single 1 0 0",
            "shapes assign all shape 1 density 1", "set atom 1 quat 0 0 1 90"});
  const double c = std::sqrt(0.5);
  auto quat_of_atom1 = [&]() {
    std::vector<double> q(4, 0.0), all(4, 0.0);
    const int i = lmp->atom->map(1);
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int k = 0; k < 4; k++) q[k] = avec()->quat[i][k];
    MPI_Allreduce(q.data(), all.data(), 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  };
  std::vector<double> q = quat_of_atom1();
  const double turned_90[4] = {c, 0.0, 0.0, c};
  for (int k = 0; k < 4; k++) EXPECT_NEAR(q[k], turned_90[k], 1e-12) << k;
  if (lmp->num_ver < 20240829) GTEST_SKIP() << "displace_atoms/compute property/atom know no per-atom quat";

  run("displace_atoms all rotate 0 0 0 0 0 1 90");    // another 90 degrees about z
  q = quat_of_atom1();
  const double turned_180[4] = {0.0, 0.0, 0.0, 1.0};
  for (int k = 0; k < 4; k++) EXPECT_NEAR(q[k], turned_180[k], 1e-12) << k;
  double x[3] = {0.0, 0.0, 0.0}, all_x[3];
  const int i = lmp->atom->map(1);
  if (i >= 0 && i < lmp->atom->nlocal)
    for (int k = 0; k < 3; k++) x[k] = lmp->atom->x[i][k];
  MPI_Allreduce(x, all_x, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_NEAR(all_x[0], 0.0, 1e-12);
  EXPECT_NEAR(all_x[1], 1.0, 1e-12);

  commands({"compute q all property/atom quatw quati quatj quatk", "compute qz all reduce sum c_q[4]",
            "thermo_style custom step c_qz", "run 0"});
  EXPECT_NEAR(lmp->modify->get_compute_by_id("qz")->compute_scalar(), 1.0, 1e-12);
}

TEST_F(AtomStyleTest, BadInputGivesErrorsThatNameTheProblem)
{
  EXPECT_NE(error_of("shapes read x").find("needs atom_style spheropolyhedron"), std::string::npos);
  commands({"units lj", "atom_style spheropolyhedron"});
  EXPECT_NE(error_of("atom_style spheropolyhedron extra").find("takes no arguments"), std::string::npos);
  run("atom_style spheropolyhedron");
  EXPECT_NE(error_of("shapes read /nonexistent/file.shapes").find("/nonexistent/file.shapes"), std::string::npos);
  EXPECT_NE(error_of("shapes frobnicate").find("frobnicate"), std::string::npos);
  commands({"shapes read " + shape_file, "region box block 0 4 0 4 0 4", "create_box 1 box",
       "create_atoms 1 single 1 1 1"});
  EXPECT_NE(error_of("shapes assign all shape 3").find("outside the library"), std::string::npos);
  EXPECT_NE(error_of("shapes assign all shape 0 density 2").find("give its 'mass'"), std::string::npos);
  EXPECT_NE(error_of("shapes assign nogroup shape 1").find("nogroup"), std::string::npos);
  EXPECT_NE(error_of("dump d all grains/vtk 1 nostar.vtk").find("needs a '*'"), std::string::npos);
}

TEST_F(AtomStyleTest, DataFileWithUnknownShapeIdIsRejected)
{
  // read_data reports bad lines with error->one on the owning rank, as LAMMPS does;
  // with exceptions on, the other ranks would wait for it: check serially only.
  if (ranks() > 1) GTEST_SKIP() << "serial-only check";
  if (rank() == 0) {
    std::ofstream out(scratch("bad.data"));
    out << "bad shape id\n\n1 atoms\n1 atom types\n\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\n"
           "Atoms # spheropolyhedron\n\n1 1 7 1.0 5 5 5 1 0 0 0\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  commands({"units lj", "atom_style spheropolyhedron", "shapes read " + shape_file});
  const std::string message = error_of("read_data " + scratch("bad.data"));
  EXPECT_NE(message.find("shape id 7"), std::string::npos) << message;
  EXPECT_NE(message.find("is outside 0..2"), std::string::npos) << message;    // the library's 2 shapes
}
