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

// compute fabric/atom and compute nscd/contacts pairs against closed-form contact geometry,
// and their bookkeeping across ranks: a pair's share of the fabric reaches both grains from
// whichever rank found it (reverse communication), each pair is one row on one rank, the
// pair rows carry the same force as the point rows. Runs serially and on 2 and 4 ranks.
#include "lammps_fixture.h"

#include "compute.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace {
const char *kShapes = R"(shape cube
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
shape ball
radius 0.5
vertices 1
0 0 0
end
shape rounded_cube
radius 0.1
vertices 8
0 0 0
0.8 0 0
0 0.8 0
0.8 0.8 0
0 0 0.8
0.8 0 0.8
0 0.8 0.8
0.8 0.8 0.8
end
)";

enum FabricColumn { XX, YY, ZZ, XY, XZ, YZ, COUNT };
enum PairColumn { ID_I, ID_J, XI, YI, ZI, XJ, YJ, ZJ, FN, FX, FY, FZ, POINTS, NX, NY, NZ, PAIR_COLUMNS };
enum PointColumn { P_ID_I, P_ID_J, P_FN = 8, P_FX = 10 };
}    // namespace

class AnalysisTest : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    if (rank() == 0) std::ofstream(scratch("shapes")) << kShapes;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  // A closed box, every rank owning a slab in z (so that stacked grains sit on different
  // ranks); gravity -z; grains added by the caller.
  void scene(double mu, const std::string &zlo_zhi = "-1 19", const std::string &boundary = "f f f")
  {
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array",
              "boundary " + boundary, "processors 1 1 *", "shapes read " + scratch("shapes"),
              "region box block -10 10 -10 10 " + zlo_zhi, "create_box 3 box", "pair_style nscd",
              "pair_coeff * * " + num(mu), "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
              "timestep 0.001"});
  }
  void add_atom(double x, double y, double z)
  {
    run("create_atoms 1 single " + num(x) + " " + num(y) + " " + num(z));
  }

  // The fabric row (7 values) of the atom with this ID, from its owner, on every rank.
  std::array<double, 7> fabric_of(const std::string &compute_id, tagint tag)
  {
    Compute *c = lmp->modify->get_compute_by_id(compute_id);
    if (c->invoked_peratom != lmp->update->ntimestep) c->compute_peratom();
    std::array<double, 7> mine{}, all{};
    const int i = lmp->atom->map(tag);
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int k = 0; k < 7; k++) mine[k] = c->array_atom[i][k];
    MPI_Allreduce(mine.data(), all.data(), 7, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }

  double z_of(tagint tag)
  {
    double mine = 0.0, all = 0.0;
    const int i = lmp->atom->map(tag);
    if (i >= 0 && i < lmp->atom->nlocal) mine = lmp->atom->x[i][2];
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }

  // All rows of a local compute, gathered to every rank.
  std::vector<std::vector<double>> all_rows(const std::string &compute_id)
  {
    Compute *c = lmp->modify->get_compute_by_id(compute_id);
    c->compute_local();
    const int cols = c->size_local_cols, rows = c->size_local_rows;
    std::vector<double> mine;
    for (int r = 0; r < rows; r++) mine.insert(mine.end(), c->array_local[r], c->array_local[r] + cols);
    int count = (int) mine.size();
    std::vector<int> counts(ranks()), offsets(ranks(), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (int r = 1; r < ranks(); r++) offsets[r] = offsets[r - 1] + counts[r - 1];
    std::vector<double> flat(offsets.back() + counts.back());
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, flat.data(), counts.data(), offsets.data(),
                   MPI_DOUBLE, MPI_COMM_WORLD);
    std::vector<std::vector<double>> out;
    for (size_t r = 0; r < flat.size() / cols; r++)
      out.emplace_back(flat.begin() + r * cols, flat.begin() + (r + 1) * cols);
    return out;
  }

  double reduced_scalar(const std::string &compute_id)
  {
    Compute *c = lmp->modify->get_compute_by_id(compute_id);
    return c->compute_scalar();
  }

  double reduced(const std::string &compute_id, int index)
  {
    Compute *c = lmp->modify->get_compute_by_id(compute_id);
    return c->compute_vector(), c->vector[index];
  }

  static void expect_fabric(const std::array<double, 7> &f, const std::array<double, 6> &expected,
                            double count, double tolerance)
  {
    for (int k = 0; k < 6; k++) EXPECT_NEAR(f[k], expected[k], tolerance) << "component " << k;
    EXPECT_EQ(f[COUNT], count);
  }
};

// Two unit cubes stacked on a floor, the upper one on another rank: each has one contacting
// pair with the vertical normal, F = ez ez and N = 1; with the boundaries the lower cube
// has two contacts (the floor's normal is vertical too) and the same tensor.
TEST_F(AnalysisTest, CubeOnCubeHasOneVerticalNormal)
{
  scene(0.5);
  add_atom(0.2, 0.1, 8.5);
  add_atom(0.3, 0.1, 9.5);    // the contact is at z = 9, a cut between ranks' slabs
  commands({"shapes assign all shape 1 density 1",
            "fix floor all nscd/wall plane 0 0 8 0 0 1 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1", "fix solver all nscd tolerance 1e-10",
            "compute fab all fabric/atom", "compute fabw all fabric/atom boundaries yes",
            "compute geo all fabric/atom contacts all", "run 50"});
  const std::array<double, 6> vertical = {0, 0, 1, 0, 0, 0};
  for (tagint tag : {1, 2}) {
    expect_fabric(fabric_of("fab", tag), vertical, 1.0, 1e-12);
    expect_fabric(fabric_of("geo", tag), vertical, 1.0, 1e-12);
  }
  expect_fabric(fabric_of("fabw", 1), vertical, 2.0, 1e-12);
  expect_fabric(fabric_of("fabw", 2), vertical, 1.0, 1e-12);
}

// A frictionless ball (radius R = 0.5) resting on three fixed balls at 120 degrees, their
// centres a distance d from its axis and h = sqrt(4R^2 - d^2) below it: the three contact
// normals give F_xx = F_yy = d^2 / 8R^2, F_zz = h^2 / 4R^2, no off-diagonal terms, trace 1.
// Each fixed ball has one normal n = (its centre - the top's) / 2R: F = n n.
TEST_F(AnalysisTest, BallOnThreeBallsHasTheTripodsFabric)
{
  const double R = 0.5, d = 0.6, h = std::sqrt(4 * R * R - d * d);
  const double cx = 0.3, cy = 0.2, base = 8.0;    // off the cuts, so the balls spread over ranks
  scene(0.0);
  std::vector<std::array<double, 3>> centres;
  for (int k = 0; k < 3; k++) {
    const double a = 2.0 * M_PI * k / 3.0 + 0.1;
    centres.push_back({cx + d * std::cos(a), cy + d * std::sin(a), base});
    add_atom(centres.back()[0], centres.back()[1], base);
  }
  add_atom(cx, cy, base + h);
  commands({"shapes assign all shape 2 density 1", "group top id 4",
            "fix g top gravity 1.0 vector 0 0 -1", "fix solver top nscd tolerance 1e-12 max_sweeps 5000",
            "compute fab all fabric/atom", "compute sum all reduce sum c_fab[1] c_fab[2] c_fab[3] c_fab[7]",
            "run 20"});
  const double tripod_xx = d * d / (8 * R * R), tripod_zz = h * h / (4 * R * R);
  const std::array<double, 7> top = fabric_of("fab", 4);
  expect_fabric(top, {tripod_xx, tripod_xx, tripod_zz, 0, 0, 0}, 3.0, 1e-6);
  EXPECT_NEAR(top[XX] + top[YY] + top[ZZ], 1.0, 1e-12);
  EXPECT_NEAR(z_of(4), base + h, 1e-6);    // the top ball rests where it was placed
  for (int k = 0; k < 3; k++) {
    const double n[3] = {(centres[k][0] - cx) / (2 * R), (centres[k][1] - cy) / (2 * R), -h / (2 * R)};
    expect_fabric(fabric_of("fab", k + 1),
                  {n[0] * n[0], n[1] * n[1], n[2] * n[2], n[0] * n[1], n[0] * n[2], n[1] * n[2]}, 1.0, 1e-6);
  }
  // compute reduce over the per-atom array: four traces of 1, N = 3 + 1 + 1 + 1
  EXPECT_NEAR(reduced("sum", 0) + reduced("sum", 1) + reduced("sum", 2), 4.0, 1e-12);
  EXPECT_EQ(reduced("sum", 3), 6.0);
}

// A cube held against a fixed cube across the periodic x boundary: the pair row has the
// branch vector through the boundary (length 1, not 3), the normal +x (from the pushing
// cube to the fixed one), the weight as its force; both fabrics are ex ex.
TEST_F(AnalysisTest, PairAcrossAPeriodicBoundaryHasTheShortBranch)
{
  commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary p f f",
            "shapes read " + scratch("shapes"), "region box block -2 2 -10 10 -10 10",
            "create_box 3 box", "pair_style nscd", "pair_coeff * * 0.5", "neighbor 0.3 bin",
            "neigh_modify every 1 delay 0 check yes", "timestep 0.001"});
  add_atom(-1.5, 0.0, 0.0);    // fixed (not in fix nscd's group)
  add_atom(1.5, 0.0, 0.0);     // pushed along +x onto the first one's image
  commands({"shapes assign all shape 1 density 1", "group pushed id 2",
            "fix g pushed gravity 1.0 vector 1 0 0", "fix solver pushed nscd tolerance 1e-10",
            "compute pairs all nscd/contacts pairs active", "compute fab all fabric/atom", "run 20"});
  const auto rows = all_rows("pairs");
  ASSERT_EQ(rows.size(), 1u);
  const std::vector<double> &p = rows[0];
  EXPECT_EQ(p[ID_I], 1.0);
  EXPECT_EQ(p[ID_J], 2.0);
  EXPECT_NEAR(p[XI] - p[XJ], 1.0, 1e-9);
  EXPECT_NEAR(p[YI] - p[YJ], 0.0, 1e-9);
  EXPECT_NEAR(p[ZI] - p[ZJ], 0.0, 1e-9);
  EXPECT_NEAR(p[FN], 1.0, 1e-8);
  EXPECT_NEAR(p[FX], 1.0, 1e-8);
  EXPECT_NEAR(p[NX], 1.0, 1e-12);
  EXPECT_EQ(p[POINTS], 4.0);
  for (tagint tag : {1, 2}) expect_fabric(fabric_of("fab", tag), {1, 0, 0, 0, 0, 0}, 1.0, 1e-12);
}

// A poured heap of mixed grains in a silo, on 1, 2 or 4 ranks (different piles, same laws):
// * every grain with contacts has a symmetric positive semi-definite fabric of trace 1;
// * sum of N_i = 2 x grain pairs (+ boundary pairs with `boundaries yes`), pairs from the
//   pair rows: each pair reaches both grains whichever rank found it;
// * one pair row per contacting pair over all ranks, its force and point count the sums
//   of its point rows (all points of a pair that carries force, also those without);
// * dump custom writes the per-atom array.
TEST_F(AnalysisTest, HeapFabricAndPairRowsAgreeWithThePointRows)
{
  scene(0.5, "-1 7");
  int n = 0;
  for (int layer = 0; layer < 3; layer++)
    for (int ix = -1; ix <= 1; ix++)
      for (int iy = -1; iy <= 1; iy++)
        if (ix * ix + iy * iy < 2 || layer == 1)
          add_atom(1.2 * ix + 0.1 * layer, 1.2 * iy, 0.7 + 1.3 * layer), n++;
  commands({"shapes assign all shape random 1 3 77 density 1 orient random 5",
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
            "fix silo all nscd/wall cylinder 0 0 0 0 0 1 2.2 friction 0.5",
            "fix g all gravity 1.0 vector 0 0 -1", "fix solver all nscd tolerance 1e-8 max_sweeps 2000",
            "compute fab all fabric/atom", "compute fabw all fabric/atom boundaries yes",
            "compute pairs all nscd/contacts pairs active", "compute points all nscd/contacts",
            "compute n all reduce sum c_fab[7] c_fabw[7]",
            "dump d all custom 1500 " + scratch("fabric.dump") + " id x y z c_fab[*]",
            "dump_modify d sort id", "run 1500"});
  // symmetric (by construction: 6 components), PSD, trace 1
  Compute *fab = lmp->modify->get_compute_by_id("fab");
  int checked = 0;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const double *f = fab->array_atom[i];
    if (f[COUNT] == 0.0) continue;
    checked++;
    EXPECT_NEAR(f[XX] + f[YY] + f[ZZ], 1.0, 1e-12);
    EXPECT_LE(f[XY] * f[XY], f[XX] * f[YY] + 1e-14);    // 2 x 2 minors of a PSD matrix
    EXPECT_LE(f[XZ] * f[XZ], f[XX] * f[ZZ] + 1e-14);
    EXPECT_LE(f[YZ] * f[YZ], f[YY] * f[ZZ] + 1e-14);
    const double det = f[XX] * (f[YY] * f[ZZ] - f[YZ] * f[YZ]) - f[XY] * (f[XY] * f[ZZ] - f[YZ] * f[XZ]) +
        f[XZ] * (f[XY] * f[YZ] - f[YY] * f[XZ]);
    EXPECT_GE(det, -1e-14);
  }
  int all_checked = 0;
  MPI_Allreduce(&checked, &all_checked, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(all_checked, n / 2);

  const auto pairs = all_rows("pairs"), points = all_rows("points");
  std::map<std::pair<double, double>, std::vector<double>> by_pair;    // fn, fx, fy, fz, points
  int grain_pairs = 0, boundary_pairs = 0;
  for (const auto &p : pairs) {
    const auto key = std::make_pair(p[ID_I], p[ID_J]);
    EXPECT_EQ(by_pair.count(key), 0u) << "pair " << p[ID_I] << " " << p[ID_J] << " twice";
    by_pair[key] = {p[FN], p[FX], p[FY], p[FZ], p[POINTS]};
    (p[ID_J] > 0 ? grain_pairs : boundary_pairs)++;
  }
  EXPECT_GT(grain_pairs, n / 2);
  EXPECT_GT(boundary_pairs, 0);
  std::map<std::pair<double, double>, std::vector<double>> summed;
  for (const auto &q : points) {
    auto &s = summed[std::make_pair(q[P_ID_I], q[P_ID_J])];
    s.resize(5, 0.0);
    s[0] += q[P_FN];
    for (int d = 0; d < 3; d++) s[1 + d] += q[P_FX + d];
    s[4] += 1.0;
  }
  for (auto it = summed.begin(); it != summed.end();) it = it->second[0] > 0.0 ? std::next(it) : summed.erase(it);
  EXPECT_EQ(summed.size(), by_pair.size());
  for (const auto &[key, s] : summed) {
    ASSERT_EQ(by_pair.count(key), 1u) << "no pair row for " << key.first << " " << key.second;
    for (int k = 0; k < 4; k++) EXPECT_NEAR(by_pair[key][k], s[k], 1e-12 * (1.0 + std::abs(s[0])));
    EXPECT_EQ(by_pair[key][4], s[4]);
  }
  EXPECT_EQ(reduced("n", 0), 2.0 * grain_pairs);
  EXPECT_EQ(reduced("n", 1), 2.0 * grain_pairs + boundary_pairs);

  // the dump's last snapshot (step 1500; step 0 comes first): its N column sums to the same
  if (rank() == 0) {
    std::ifstream in(scratch("fabric.dump"));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    size_t header = lines.size();
    while (header > 0 && lines[header - 1].rfind("ITEM: ATOMS", 0) != 0) header--;
    ASSERT_GT(header, 0u);
    EXPECT_EQ(lines[header - 1], "ITEM: ATOMS id x y z c_fab[1] c_fab[2] c_fab[3] c_fab[4] c_fab[5] c_fab[6] c_fab[7]");
    double dumped = 0.0;
    for (size_t k = header; k < lines.size(); k++) {
      std::istringstream row(lines[k]);
      std::vector<double> v((std::istream_iterator<double>(row)), std::istream_iterator<double>());
      ASSERT_EQ(v.size(), 11u);
      dumped += v[10];
    }
    EXPECT_EQ(lines.size() - header, (size_t) n);
    EXPECT_EQ(dumped, 2.0 * grain_pairs);
  }
}

// compute nscd/overlap/atom on unit cubes placed inside each other: A (ID 1) and B (ID 2)
// overlap by 0.2 face to face across the ranks' cut at z = 9, D (ID 4) overlaps A by 0.1
// side by side, C (ID 3) touches nothing. Each grain gets its deepest overlap and its
// partner; a group leaves others at zero; the deck pattern of examples/column (delete the
// later grain of each overlapping pair: B and D) leaves A and C, and no overlap.
TEST_F(AnalysisTest, OverlapAtomNamesTheDeepestPartnerAndDeletesThePair)
{
  scene(0.5);
  add_atom(0.0, 0.0, 8.5);
  add_atom(0.1, 0.0, 9.3);
  add_atom(5.0, 5.0, 8.5);
  add_atom(-0.9, 0.0, 8.5);
  commands({"shapes assign all shape 1 density 1", "group top id 2", "fix solver all nscd",
            "compute ov all nscd/overlap/atom", "compute ovtop top nscd/overlap/atom",
            "compute deepest all reduce max c_ov[1]", "run 0 post no"});
  const auto row = [this](const std::string &id, tagint tag) {
    Compute *c = lmp->modify->get_compute_by_id(id);
    if (c->invoked_peratom != lmp->update->ntimestep) c->compute_peratom();
    std::array<double, 2> mine{}, all{};
    const int i = lmp->atom->map(tag);
    if (i >= 0 && i < lmp->atom->nlocal) mine = {c->array_atom[i][0], c->array_atom[i][1]};
    MPI_Allreduce(mine.data(), all.data(), 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  };
  const std::map<tagint, std::array<double, 2>> expected = {
      {1, {0.2, 2}}, {2, {0.2, 1}}, {3, {0.0, 0}}, {4, {0.1, 1}}};
  for (const auto &[tag, depth_partner] : expected) {
    const std::array<double, 2> got = row("ov", tag);
    EXPECT_NEAR(got[0], depth_partner[0], 1e-12) << "grain " << tag;
    EXPECT_EQ(got[1], depth_partner[1]) << "grain " << tag;
  }
  EXPECT_EQ(row("ovtop", 1)[0], 0.0);    // not in the group
  EXPECT_NEAR(row("ovtop", 2)[0], 0.2, 1e-12);
  commands({"variable inside atom \"c_ov[1] > 0 && id > c_ov[2]\"", "group inside variable inside",
            "delete_atoms group inside compress no", "run 0 post no"});
  EXPECT_EQ(lmp->atom->natoms, 2);
  for (tagint tag : {1, 2, 3, 4}) {
    const int i = lmp->atom->map(tag);
    // (the array map can keep a deleted atom's old index: check the tag there)
    double mine = i >= 0 && i < lmp->atom->nlocal && lmp->atom->tag[i] == tag ? 1.0 : 0.0, owners = 0;
    MPI_Allreduce(&mine, &owners, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(owners, tag == 1 || tag == 3 ? 1.0 : 0.0) << "grain " << tag;
  }
  EXPECT_EQ(reduced_scalar("deepest"), 0.0);
}

TEST_F(AnalysisTest, BadKeywordsAreNamed)
{
  scene(0.5);
  EXPECT_NE(error_of("compute f all fabric/atom contacts some").find("'contacts some'"), std::string::npos);
  EXPECT_NE(error_of("compute f all fabric/atom boundaries").find("needs a value"), std::string::npos);
  EXPECT_NE(error_of("compute f all fabric/atom wire yes").find("the fabric has no wire-grain contacts"), std::string::npos);
  EXPECT_NE(error_of("compute f all fabric/atom wire no").find("'wire no'"), std::string::npos);
  EXPECT_NE(error_of("compute c all nscd/contacts pair").find("unknown keyword 'pair'"), std::string::npos);
  EXPECT_NE(error_of("compute o all nscd/overlap/atom deep").find("takes no keywords, got 'deep'"),
            std::string::npos);
  run("compute f all fabric/atom");
  run("compute c all nscd/contacts pairs active");
  EXPECT_NE(error_of("run 0").find("needs fix nscd"), std::string::npos);
}
