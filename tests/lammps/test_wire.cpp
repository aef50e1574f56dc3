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

// bond_style wire, angle_style wire, fix wire and compute wire/local against closed forms:
// a pulled wire, a cantilever, a hanging chain, a wire resting on a fixed grain, the
// stability-limit error and restart continuation, a wire-bound pyramid of balls. Units are
// LJ-like, g = 1. Every test runs on 1 rank and again on 2 and 4 (CTest), so the same
// closed forms check the wire across rank boundaries.
#include "lammps_fixture.h"

#include "angle.h"
#include "bond.h"
#include "comm.h"
#include "compute.h"
#include "fix.h"
#include "fix_wire_lib.h"
#include "force.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

using namespace LAMMPS_NS;

namespace {
const char *kShapes = R"(# a unit cube
shape cube
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
-0.3 -0.3 -0.3
0.3 -0.3 -0.3
-0.3 0.3 -0.3
0.3 0.3 -0.3
-0.3 -0.3 0.3
0.3 -0.3 0.3
-0.3 0.3 0.3
0.3 0.3 0.3
end
shape slab
radius 0
vertices 8
-1.5 -0.5 -0.5
1.5 -0.5 -0.5
-1.5 0.5 -0.5
1.5 0.5 -0.5
-1.5 -0.5 0.5
1.5 -0.5 0.5
-1.5 0.5 0.5
1.5 0.5 0.5
end
)";

struct Point {
  double x, y, z, mass;
  int type = 1;
  int shape = 0;
};
}    // namespace

class WireTest : public LammpsTest {
 protected:
  std::string boundary = "f f f";    // of the scenes load_scene reads

  // A data file for `atom_style hybrid spheropolyhedron angle`: atoms in order, the first
  // `chain` of them joined into one open wire (bonds, and angles if `angles`).
  void write_data(const std::string &path, const std::vector<Point> &atoms, int chain, bool angles,
                  double box = 5.0)
  {
    std::vector<std::array<int, 3>> joints;
    for (int k = 1; angles && k <= chain - 2; k++) joints.push_back({k, k + 1, k + 2});
    write_topology(path, atoms, chain_bonds(1, chain, false), joints, box);
  }
  // Bonds joining atoms first..last in order (and last to first if `closed`).
  static std::vector<std::array<int, 2>> chain_bonds(int first, int last, bool closed)
  {
    std::vector<std::array<int, 2>> bonds;
    for (int k = first; k < last; k++) bonds.push_back({k, k + 1});
    if (closed) bonds.push_back({last, first});
    return bonds;
  }
  // Joints (angles) of a closed ring of atoms 1..n.
  static std::vector<std::array<int, 3>> ring_joints(int n)
  {
    std::vector<std::array<int, 3>> joints;
    for (int k = 0; k < n; k++) joints.push_back({k + 1, (k + 1) % n + 1, (k + 2) % n + 1});
    return joints;
  }
  // The same for any list of bonds and angles (atom IDs from 1).
  void write_topology(const std::string &path, const std::vector<Point> &atoms,
                      const std::vector<std::array<int, 2>> &bonds,
                      const std::vector<std::array<int, 3>> &joints, double box = 5.0)
  {
    if (rank() != 0) return;
    const int nbonds = (int) bonds.size(), nangles = (int) joints.size();
    std::ofstream out(path);
    out.precision(17);
    out << "wire test\n\n" << atoms.size() << " atoms\n" << nbonds << " bonds\n" << nangles
        << " angles\n2 atom types\n1 bond types\n1 angle types\n\n";
    out << -box << " " << box << " xlo xhi\n" << -box << " " << box << " ylo yhi\n" << -box << " "
        << box << " zlo zhi\n\nAtoms # hybrid\n\n";
    for (size_t k = 0; k < atoms.size(); k++) {
      const Point &p = atoms[k];
      out << k + 1 << " " << p.type << " " << p.x << " " << p.y << " " << p.z << " " << p.shape
          << " " << p.mass << " 1 0 0 0 1\n";
    }
    if (nbonds > 0) out << "\nBonds\n\n";
    for (int k = 0; k < nbonds; k++) out << k + 1 << " 1 " << bonds[k][0] << " " << bonds[k][1] << "\n";
    if (nangles > 0) out << "\nAngles\n\n";
    for (int k = 0; k < nangles; k++)
      out << k + 1 << " 1 " << joints[k][0] << " " << joints[k][1] << " " << joints[k][2] << "\n";
  }

  // Reads the data file with the wire styles set up (no pair interactions between nodes).
  void scene(const std::vector<Point> &atoms, int chain, bool angles, double k_elo, double r0,
             double k_rot = 0.0, const std::string &string_option = "")
  {
    const std::string data = scratch("wire.data");
    write_data(data, atoms, chain, angles);
    load_scene(data, k_elo, r0, k_rot, string_option);
  }
  // Reads a data file written by write_data or write_topology with the wire styles set up
  // (no pair interactions).
  void load_scene(const std::string &data, double k_elo, double r0, double k_rot,
                  const std::string &string_option = "")
  {
    MPI_Barrier(MPI_COMM_WORLD);
    commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
              "boundary " + boundary});
    if (rank() == 0) std::ofstream(scratch("shapes")) << kShapes;
    MPI_Barrier(MPI_COMM_WORLD);
    // ranks side by side in x and y: the wires of these scenes lie mostly flat, so they
    // cross rank boundaries on 2 and 4 ranks
    commands({"processors * * 1", "shapes read " + scratch("shapes"), "read_data " + data, "pair_style zero 1.0",
              "pair_coeff * *", "bond_style wire", "bond_coeff 1 " + num(k_elo) + " " + num(r0) + string_option,
              "angle_style wire", "angle_coeff 1 " + num(k_rot), "neighbor 0.3 bin",
              "comm_modify cutoff 3.0", "timestep 0.001"});
  }

  // Position of atom `tag`, gathered to every rank.
  std::vector<double> position(tagint tag)
  {
    std::vector<double> mine(3, 0.0), all(3, 0.0);
    const int i = lmp->atom->map(tag);
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int d = 0; d < 3; d++) mine[d] = lmp->atom->x[i][d];
    MPI_Allreduce(mine.data(), all.data(), 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }
  std::vector<double> force_on(tagint tag)
  {
    std::vector<double> mine(3, 0.0), all(3, 0.0);
    const int i = lmp->atom->map(tag);
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int d = 0; d < 3; d++) mine[d] = lmp->atom->f[i][d];
    MPI_Allreduce(mine.data(), all.data(), 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }
  double fix_value(const std::string &id, int index)
  {
    return lmp->modify->get_fix_by_id(id.c_str())->compute_vector(index);
  }
  // Rows of the local compute `id` (computed now) of all ranks, sorted.
  std::vector<std::vector<double>> local_rows(const std::string &id)
  {
    Compute *c = lmp->modify->get_compute_by_id(id.c_str());
    c->compute_local();
    const int cols = c->size_local_cols;
    std::vector<double> mine;
    for (int r = 0; r < c->size_local_rows; r++)
      mine.insert(mine.end(), c->array_local[r], c->array_local[r] + cols);
    int count = (int) mine.size();
    std::vector<int> counts(ranks()), offsets(ranks(), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (int r = 1; r < ranks(); r++) offsets[r] = offsets[r - 1] + counts[r - 1];
    std::vector<double> all(offsets.back() + counts.back());
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                   MPI_DOUBLE, MPI_COMM_WORLD);
    std::vector<std::vector<double>> rows;
    for (size_t k = 0; k < all.size(); k += cols) rows.emplace_back(&all[k], &all[k] + cols);
    std::sort(rows.begin(), rows.end());
    return rows;
  }
  static double summed(double mine)
  {
    double all;
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }
  // Kinetic energy of the atoms with tags in [first, last], over all ranks.
  double kinetic_energy(tagint first, tagint last)
  {
    double ke = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (lmp->atom->tag[i] >= first && lmp->atom->tag[i] <= last)
        for (int d = 0; d < 3; d++) ke += 0.5 * lmp->atom->rmass[i] * lmp->atom->v[i][d] * lmp->atom->v[i][d];
    return summed(ke);
  }

  // A straight chain of n nodes along x from x0 with spacing l, each of mass m.
  static std::vector<Point> straight_chain(int n, double l, double m, double x0 = 0.0, double z = 0.0)
  {
    std::vector<Point> nodes;
    for (int k = 0; k < n; k++) nodes.push_back({x0 + k * l, 0.0, z, m});
    return nodes;
  }
};

// ---------------------------------------------------------------- bond and angle styles

TEST_F(WireTest, BondForceEnergyAndSingleFollowTheAxialLaw)
{
  // 2 nodes 1.1 apart, r0 = 1, k_elo = 100: tension 10, energy k_elo L0 strain^2 / 2 = 0.5
  scene({{0, 0, 0, 1}, {1.1, 0, 0, 1}}, 2, false, 100.0, 1.0);
  commands({"compute bl all bond/local dist engpot force", "run 0"});
  EXPECT_NEAR(force_on(1)[0], 10.0, 1e-10);
  EXPECT_NEAR(force_on(2)[0], -10.0, 1e-10);
  EXPECT_NEAR(summed(lmp->force->bond->energy), 0.5, 1e-12);
  // compute bond/local goes through single(): same energy and force
  const auto rows = local_rows("bl");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0][1], 0.5, 1e-12);
  EXPECT_NEAR(std::fabs(rows[0][2]), 10.0, 1e-10);
}

TEST_F(WireTest, StringBondCarriesNoCompressionAndPlainBondDoes)
{
  scene({{0, 0, 0, 1}, {0.9, 0, 0, 1}}, 2, false, 100.0, 1.0, 0.0, " string yes");
  run("run 0");
  EXPECT_EQ(force_on(1)[0], 0.0);
  EXPECT_EQ(summed(lmp->force->bond->energy), 0.0);
  run("bond_coeff 1 100 1 string no");
  run("run 0");
  EXPECT_NEAR(force_on(1)[0], -10.0, 1e-10);    // pushed apart
  EXPECT_NEAR(summed(lmp->force->bond->energy), 0.5, 1e-12);
  EXPECT_NE(error_of("bond_coeff 1 -1 1"), "");
  EXPECT_NE(error_of("bond_coeff 1 1 0"), "");
}

TEST_F(WireTest, AngleMomentIsKrotTimesNodeAngle)
{
  // joint bent by nu = 0.3 at node 2: energy k nu^2 / 2, end forces k nu / l perpendicular
  const double nu = 0.3, k = 2.0, l = 0.5;
  scene({{-l, 0, 0, 1}, {0, 0, 0, 1}, {l * std::cos(nu), l * std::sin(nu), 0, 1}}, 3, true, 0.0, l, k);
  commands({"compute al all angle/local theta eng", "run 0"});
  EXPECT_NEAR(summed(lmp->force->angle->energy), 0.5 * k * nu * nu, 1e-12);
  const std::vector<double> f1 = force_on(1), f3 = force_on(3);
  EXPECT_NEAR(std::hypot(f1[0], f1[1]), k * nu / l, 1e-10);
  EXPECT_NEAR(f1[0], 0.0, 1e-12);    // perpendicular to the first element
  EXPECT_NEAR(std::hypot(f3[0], f3[1]), k * nu / l, 1e-10);
  EXPECT_LT(f1[1], 0.0);    // straightening: end 1 pushed to -y (to follow the bend of 3)
  const auto rows = local_rows("al");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0][0], 180.0 - nu * 180.0 / M_PI, 1e-9);    // LAMMPS angle, degrees
  EXPECT_NEAR(rows[0][1], 0.5 * k * nu * nu, 1e-12);           // single()
}

// theta0 (degrees, as LAMMPS' other angle styles) sets the turn at rest nu0 = pi - theta0: a
// joint bent less than nu0 is bent further, the energy is k (nu - nu0)^2 / 2, and theta0
// survives write_data/read_data and write_restart/read_restart.
TEST_F(WireTest, AngleWithARestAngleBendsTowardItAndKeepsItThroughDataAndRestart)
{
  const double nu = 0.3, nu0 = 0.5, k = 2.0, l = 0.5;
  const std::string theta0 = num(180.0 - nu0 * 180.0 / M_PI);
  scene({{-l, 0, 0, 1}, {0, 0, 0, 1}, {l * std::cos(nu), l * std::sin(nu), 0, 1}}, 3, true, 0.0, l, k);
  commands({"angle_coeff 1 " + num(k) + " " + theta0, "run 0"});
  const double energy = 0.5 * k * (nu - nu0) * (nu - nu0);
  EXPECT_NEAR(summed(lmp->force->angle->energy), energy, 1e-12);
  EXPECT_NEAR(lmp->force->angle->equilibrium_angle(1), M_PI - nu0, 1e-14);
  const std::vector<double> f1 = force_on(1);
  EXPECT_NEAR(std::hypot(f1[0], f1[1]), k * (nu0 - nu) / l, 1e-10);
  EXPECT_GT(f1[1], 0.0);    // bent further: end 1 pushed to +y, away from straightening
  // (the nodes' masses are per atom; the hybrid style's per-type masses must be set for the
  // data file to be read back)
  commands({"mass * 1.0", "write_data " + scratch("rest.data"), "write_restart " + scratch("rest.restart")});

  for (const std::string how : {"data", "restart"}) {
    restart_instance();
    if (how == "data") {
      commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
                "shapes read " + scratch("shapes"), "pair_style zero 1.0", "bond_style wire", "angle_style wire",
                "read_data " + scratch("rest.data")});
    } else {
      commands({"read_restart " + scratch("rest.restart"), "pair_style zero 1.0", "pair_coeff * *"});
    }
    run("run 0");
    EXPECT_NEAR(lmp->force->angle->equilibrium_angle(1), M_PI - nu0, 1e-14) << how;
    EXPECT_NEAR(summed(lmp->force->angle->energy), energy, 1e-12) << how;
  }
  EXPECT_NE(error_of("angle_coeff 1 1.0 0").find("theta0 = 0"), std::string::npos);
  EXPECT_NE(error_of("angle_coeff 1 1.0 190").find("theta0 = 190"), std::string::npos);
  EXPECT_NE(error_of("angle_coeff 1 1.0 120 7").find("[theta0]"), std::string::npos);
}

// ---------------------------------------------------------------- fix wire

// fix wire vector: 1 stretch energy, 2 bending energy, 3 contact energy, 4 wire-wire
// contacts, 5 wire-grain contacts, 6 substeps, 7 dt_SP, 8-10 force on grains, 11 stable dt_SP
TEST_F(WireTest, PulledWireReachesTheTensionAndElongationOfKelo)
{
  // 10 elements of 0.1, node 1 held (not in the group), P = 1 on node 11, k_elo = 100:
  // every element carries P, strain P / k_elo = 0.01, tip moves 10 * 0.1 * 0.01 = 0.01
  const double P = 1.0, k_elo = 100.0;
  scene(straight_chain(11, 0.1, 0.01), 11, true, k_elo, 0.1, 0.0);
  commands({"group wire id 2:11", "group tip id 11", "fix pull tip addforce " + num(P) + " 0 0",
            "fix w wire wire damp 0.5", "compute el all wire/local", "run 1500"});
  EXPECT_NEAR(position(11)[0], 1.0 + 10 * 0.1 * P / k_elo, 1e-7);
  EXPECT_NEAR(position(1)[0], 0.0, 0.0);    // the anchor stays
  const auto rows = local_rows("el");
  ASSERT_EQ(rows.size(), 10u);
  for (const auto &r : rows) {
    EXPECT_NEAR(r[3], P, 1e-6) << "element " << r[0] << "-" << r[1];
    EXPECT_NEAR(r[2], P / k_elo, 1e-8);
    EXPECT_NEAR(r[4], 0.5 * k_elo * 0.1 * (P / k_elo) * (P / k_elo), 1e-10);
  }
  EXPECT_NEAR(fix_value("w", 0), 10 * 0.5 * k_elo * 0.1 * 1e-4, 1e-9);    // stretch energy
  EXPECT_GE(fix_value("w", 5), 2.0);                                    // it did subcycle
  EXPECT_LE(fix_value("w", 6), fix_value("w", 10));                     // below the limit
}

TEST_F(WireTest, CantileverDeflectsLikeTheDiscreteBeam)
{
  // N = 10 elements of l = 0.1, EI = 1 -> k_rot = EI / l = 10; nodes 1, 2 clamp the root.
  // Tip load F: delta = F l^3 / EI * (N-1) N (2N-1) / 6 (doc/Howto_nscd_wire_model.rst section 2).
  const int N = 10;
  const double l = 0.1, EI = 1.0, F = 1e-3;
  scene(straight_chain(N + 1, l, 0.01), N + 1, true, 1e4, l, EI / l);
  commands({"group wire id 3:" + std::to_string(N + 1), "group tip id " + std::to_string(N + 1),
            "fix load tip addforce 0 " + num(F) + " 0", "fix w wire wire damp 0.22", "run 3000"});
  const double discrete = F * l * l * l / EI * (N - 1) * N * (2 * N - 1) / 6.0;
  const double beam = F * std::pow((N - 0.5) * l, 3) / (3 * EI);
  const double delta = position(N + 1)[1];
  EXPECT_NEAR(delta / discrete, 1.0, 1e-4);
  EXPECT_NEAR(delta / beam, 1.0, 5e-3);    // -2.8e-3 discretisation error at N = 10
  std::printf("[ cantilever ] delta %.9g discrete %.9g beam %.9g\n", delta, discrete, beam);
}

// An open arc of a circle laid at its rest turn is at rest: no force anywhere, every node
// stays put (to round-off) through the subcycle. The same arc with a straight rest shape
// opens (its ends move apart), and a straight chain given that rest turn curls onto the
// circle: with damping it comes to rest with each joint at nu0, i.e. every three
// consecutive nodes on a circle of the arc's radius R = l / (2 sin(nu0 / 2)).
TEST_F(WireTest, WireKeepsOrTakesTheCurvatureOfItsRestAngle)
{
  const int n = 13;
  const double R = 1.0, l = 0.2, k_rot = 0.5;
  const double nu0 = 2.0 * std::asin(l / (2.0 * R));
  const std::string theta0 = num(180.0 - nu0 * 180.0 / M_PI);
  std::vector<Point> arc;
  for (int i = 0; i < n; i++) arc.push_back({R * std::cos(i * nu0), R * std::sin(i * nu0), 0.0, 0.01});
  const auto span = [&]() {
    const std::vector<double> a = position(1), b = position(n);
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  };

  scene(arc, n, true, 100.0, l, k_rot);
  commands({"angle_coeff 1 " + num(k_rot) + " " + theta0, "group wire id 1:" + std::to_string(n),
            "fix w wire wire damp 0.1", "run 500"});
  double moved = 0.0;
  for (int i = 0; i < n; i++) {
    const std::vector<double> p = position(i + 1);
    moved = std::max({moved, std::abs(p[0] - arc[i].x), std::abs(p[1] - arc[i].y), std::abs(p[2])});
  }
  EXPECT_LT(moved, 1e-12);
  EXPECT_LT(fix_value("w", 1), 1e-20);    // bending energy

  restart_instance();
  scene(arc, n, true, 100.0, l, k_rot);    // straight at rest
  const double laid = span();
  commands({"group wire id 1:" + std::to_string(n), "fix w wire wire damp 0.1", "run 2000"});
  std::printf("[ INFO     ] arc with a straight rest shape: span %.4f -> %.4f\n", laid, span());
  EXPECT_GT(span(), 1.2 * laid);

  restart_instance();
  std::vector<Point> flat;    // an arc ten times wider: exactly straight, no plane is preferred
  for (int i = 0; i < n; i++) flat.push_back({10 * R * std::sin(i * l / (10 * R)), 10 * R * (1 - std::cos(i * l / (10 * R))), 0.0, 0.01});
  scene(flat, n, true, 100.0, l, k_rot);
  commands({"angle_coeff 1 " + num(k_rot) + " " + theta0, "group wire id 1:" + std::to_string(n),
            "fix w wire wire damp 0.1", "run 20000"});
  std::printf("[ INFO     ] curled: kinetic energy %.3g\n", kinetic_energy(1, n));
  EXPECT_LT(kinetic_energy(1, n), 1e-14);
  for (int i = 1; i + 1 < n; i++) {
    const std::vector<double> a = position(i), b = position(i + 1), c = position(i + 2);
    const double ab = std::hypot(b[0] - a[0], b[1] - a[1]), bc = std::hypot(c[0] - b[0], c[1] - b[1]),
                 ca = std::hypot(a[0] - c[0], a[1] - c[1]);
    const double cross = std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    EXPECT_NEAR(ab * bc * ca / (2.0 * cross), R, 1e-3 * R) << "circumradius at node " << i + 1;
  }
}

TEST_F(WireTest, HangingChainSettlesOnTheCatenary)
{
  // A string of length S = 2 (20 elements of 0.1, rho = 1) hung between supports 1.6 apart,
  // released from a V. Catenary: S/2 = c sinh(a/c), a = 0.8; sag c (cosh(a/c) - 1);
  // horizontal tension H = rho g c = the tension at the lowest point.
  const int N = 20;
  const double l = 0.1, a = 0.8, depth = 0.6;
  std::vector<Point> nodes;
  for (int k = 0; k <= N; k++) {
    const double t = k <= N / 2 ? k / (N / 2.0) : (N - k) / (N / 2.0);
    nodes.push_back({-a + k * (2 * a / N), 0.0, -depth * t, l});
  }
  scene(nodes, N + 1, false, 1e4, l, 0.0, " string yes");
  commands({"group wire id 2:" + std::to_string(N), "fix g wire gravity 1.0 vector 0 0 -1",
            "fix w wire wire damp 0.3", "compute el all wire/local", "run 8000"});
  double c = 0.5;    // solve sinh(a/c) c = 1 by Newton on u = a/c: sinh(u)/u = 1/a
  for (int it = 0; it < 50; it++) {
    const double u = a / c, g = std::sinh(u) / u - 1.0 / a;
    const double dg = (std::cosh(u) * u - std::sinh(u)) / (u * u);
    c = a / (u - g / dg);
  }
  const double sag = c * (std::cosh(a / c) - 1.0);
  const double z_mid = position(N / 2 + 1)[2];
  std::printf("[ catenary ] sag %.6g (continuum %.6g), c %.6g\n", -z_mid, sag, c);
  EXPECT_NEAR(-z_mid / sag, 1.0, 1e-2);
  const auto rows = local_rows("el");
  double lowest = INFINITY;
  for (const auto &r : rows) lowest = std::min(lowest, r[3]);
  std::printf("[ catenary ] lowest tension %.6g, H = %.6g\n", lowest, c);
  EXPECT_NEAR(lowest / c, 1.0, 1e-2);
  // at rest: kinetic energy of the nodes tiny
  EXPECT_LT(kinetic_energy(1, MAXTAGINT), 1e-10);
}

class WireOnGrainTest : public WireTest {
 protected:
  // 5 nodes (mass 0.01) lying along x on top (z = 0.5) of a fixed grain at the origin
  // (atom 6, in no integrator group): shape 1 = unit cube, 2 = ball of radius 0.5;
  // wire radius 0.05.
  void on_grain(double lift = 0.0, int shape = 1)
  {
    std::vector<Point> atoms = straight_chain(5, 0.2, 0.01, -0.4, 0.55 + lift);
    atoms.push_back({0.0, 0.0, 0.0, 1.0, 2, shape});
    scene(atoms, 5, true, 100.0, 0.2, 0.05);
    commands({"group wire id 1:5", "fix g wire gravity 1.0 vector 0 0 -1",
              "fix w wire wire radius 0.05 k_n 1000 gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.5 "
              "mu_d 0.4 damp 0.02"});
  }
};

TEST_F(WireOnGrainTest, WireWeightReachesTheGrainThroughTheAveragedForces)
{
  // On a ball: one smooth contact point per element (flat faces: WireOnBoundaryTest).
  on_grain(0.0, 2);
  run("run 12000");
  const double weight = 5 * 0.01;
  EXPECT_NEAR(fix_value("w", 9), -weight, 1e-5 * weight);    // total force on grains, z;
  // (measured 2.3e-6 relative: the rocking of the wire on the ball still decaying)
  EXPECT_NEAR(fix_value("w", 7), 0.0, 1e-9);
  EXPECT_NEAR(force_on(6)[2], fix_value("w", 9), 1e-15);       // handed to the grain's f
  EXPECT_GE(fix_value("w", 4), 1.0);                          // wire-grain contacts
  EXPECT_EQ(fix_value("w", 3), 0.0);                          // no wire-wire contacts
  for (int k = 1; k <= 5; k++) EXPECT_GT(position(k)[2], 0.45) << "node " << k;    // still on top
  std::printf("[ wire on ball ] force on grain z %.12g, weight %.12g\n", fix_value("w", 9), -weight);
  EXPECT_EQ(position(6)[2], 0.0);                             // the grain did not move
}

TEST_F(WireOnGrainTest, RestartContinuesTheWireRun)
{
  on_grain(0.02);
  commands({"velocity wire set 0.3 0 0", "run 200", "write_restart " + scratch("mid.restart"),
            "run 200"});
  std::vector<std::vector<double>> straight;
  for (int k = 1; k <= 5; k++) straight.push_back(position(k));
  EXPECT_NE(straight[0][0], -0.4);    // it moved

  restart_instance();
  commands({"read_restart " + scratch("mid.restart"), "neighbor 0.3 bin",
            "fix g wire gravity 1.0 vector 0 0 -1",
            "fix w wire wire radius 0.05 k_n 1000 gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.5 "
            "mu_d 0.4 damp 0.02",
            "run 200"});
  for (int k = 1; k <= 5; k++) {
    const std::vector<double> p = position(k);
    for (int d = 0; d < 3; d++) EXPECT_NEAR(p[d], straight[k - 1][d], 1e-12) << "node " << k;
  }
}

// Restarts move between rank counts: written on all ranks and continued on rank 0 alone,
// and written on rank 0 alone and continued on all ranks, each time following the
// continuation without a restart. Gravity tilted by 0.2 (below mu_s = 0.5) keeps the wire
// stuck on the cube face by its tangential springs, so the restart carries contact
// histories (and Gear states) that must reach the right ranks: without the histories the
// continuation differs by about 1e-7.
TEST_F(WireOnGrainTest, RestartMovesBetweenRankCounts)
{
  const std::vector<std::string> redefine = {
      "neighbor 0.3 bin", "fix g wire gravity 1.0 vector 0.2 0 -1",
      "fix w wire wire radius 0.05 k_n 1000 gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.5 mu_d 0.4 "
      "damp 0.02"};
  const std::string all_file = scratch("all_ranks.restart"), alone_file = scratch("alone.restart");
  on_grain(0.0);
  commands({redefine[1], "run 200", "write_restart " + all_file, "run 200"});
  std::vector<double> on_all_ranks;
  for (int k = 1; k <= 5; k++)
    for (double c : position(k)) on_all_ranks.push_back(c);
  EXPECT_GE(fix_value("w", 4), 1.0);    // the wire touches the cube

  // rank 0 alone: continue the all-rank file, then write its own file and go on
  std::vector<double> alone_after(15, 0.0);
  on_first_ranks(1, [&](MPI_Comm) {
    run("read_restart " + all_file);
    commands(redefine);
    commands({"run 100", "write_restart " + alone_file, "run 100"});
    for (int k = 1; k <= 5; k++) {
      const int i = lmp->atom->map(k);
      EXPECT_GE(i, 0);    // (no ASSERT: the other ranks wait in MPI_Bcast below)
      if (i < 0) continue;
      for (int d = 0; d < 3; d++) {
        EXPECT_NEAR(lmp->atom->x[i][d], on_all_ranks[3 * (k - 1) + d], 1e-10) << "node " << k;
        alone_after[3 * (k - 1) + d] = lmp->atom->x[i][d];
      }
    }
  });
  MPI_Bcast(alone_after.data(), 15, MPI_DOUBLE, 0, MPI_COMM_WORLD);

  // all ranks: continue the file rank 0 wrote alone
  restart_instance();
  run("read_restart " + alone_file);
  commands(redefine);
  run("run 100");
  for (int k = 1; k <= 5; k++) {
    const std::vector<double> p = position(k);
    for (int d = 0; d < 3; d++) EXPECT_NEAR(p[d], alone_after[3 * (k - 1) + d], 1e-10) << "node " << k;
  }
}

// ---- friction memories kept with their atoms (doc/fix_wire.rst, "Restart") ----

// Friction memories held by the ranks of `world`: {summed, most on one rank, summed of those
// whose contact the holding rank does not compute (its first node owned elsewhere)}.
static std::array<double, 3> memory_holdings(LAMMPS *lmp, MPI_Comm world)
{
  const auto *fix = dynamic_cast<FixWire *>(lmp->modify->get_fix_by_id("w"));
  const double held = fix ? (double) fix->wire_memories_held() : 0.0;
  const double foreign = fix ? (double) fix->wire_memories_of_other_ranks() : 0.0;
  std::array<double, 3> out{};
  MPI_Allreduce(&held, &out[0], 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&held, &out[1], 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&foreign, &out[2], 1, MPI_DOUBLE, MPI_SUM, world);
  return out;
}

// The positions of atoms 1..n (3 n values), gathered to every rank of `world`.
static std::vector<double> positions_of(LAMMPS *lmp, int n, MPI_Comm world)
{
  std::vector<double> mine(3 * n, 0.0), all(3 * n, 0.0);
  for (int k = 1; k <= n; k++) {
    const int i = lmp->atom->map(k);
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int d = 0; d < 3; d++) mine[3 * (k - 1) + d] = lmp->atom->x[i][d];
  }
  MPI_Allreduce(mine.data(), all.data(), 3 * n, MPI_DOUBLE, MPI_SUM, world);
  return all;
}

static double largest_difference(const std::vector<double> &a, const std::vector<double> &b)
{
  double most = 0.0;
  for (size_t k = 0; k < a.size(); k++) most = std::max(most, std::fabs(a[k] - b[k]));
  return most;
}

// A wire held by friction on a cube that a conveyor (fix move) carries at speed 5 across the
// sub-domain cut at x = 0, wire and cube moving together: every node, and so the first node
// of each element, which computes the element's contact with the cube and keeps its friction
// memory, changes rank in the middle of the run (no node damping: it would brake the wire
// against the conveyor; the contacts' dashpots settle it). Gravity tilted by 0.2 (below mu_s = 0.5)
// stretches the tangential springs; without relative motion they stay as they are, so the
// wire's force on the cube along x stays the weight's x component step after step. A memory
// lost on the way restarts its spring from zero: the element lets go of its share of that
// force and the wire slips back until the spring is stretched again. The memories are as
// many after the crossing as before, and none is held by a rank that does not compute it.
TEST_F(WireOnGrainTest, FrictionHistorySurvivesItsNodeChangingRankMidRun)
{
  std::vector<Point> atoms = straight_chain(5, 0.2, 0.01, -1.4, 0.55);
  for (Point &p : atoms) p.y = 0.25;    // off the cut at y = 0 of 4 ranks
  atoms.push_back({-1.0, 0.25, 0.0, 1.0, 2, 1});
  scene(atoms, 5, true, 100.0, 0.2, 0.05);
  commands({"group wire id 1:5", "group cube id 6", "fix g wire gravity 1.0 vector 0.2 0 -1",
            "fix w wire wire radius 0.05 k_n 1000 gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.5 mu_d 0.4",
            "run 2000"});
  const double resting = fix_value("w", 7);    // the wire's force on the cube along x, at rest
  const std::array<double, 3> before = memory_holdings(lmp, MPI_COMM_WORLD);
  const int owner_before = owner_of(lmp, 1, MPI_COMM_WORLD);
  commands({"velocity wire set 5 0 0", "velocity cube set 5 0 0", "fix conveyor cube move linear 5 0 0",
            "fix fx all print 1 \"$(f_w[8]:%.17g)\" file " + scratch("fx") + " screen no", "run 400", "unfix fx"});
  const std::array<double, 3> after = memory_holdings(lmp, MPI_COMM_WORLD);
  const int owner_after = owner_of(lmp, 1, MPI_COMM_WORLD);
  EXPECT_NEAR(position(6)[0], 1.0, 1e-9);
  for (int k = 1; k <= 5; k++) EXPECT_NEAR(position(k)[0] - position(6)[0], -0.4 + 0.2 * (k - 1), 1e-3) << "node " << k;
  std::ifstream in(scratch("fx"));
  std::string line;
  double most = 0.0;
  int steps = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') most = std::max(most, std::fabs(std::stod(line) - resting)), steps++;
  if (rank() == 0)
    std::printf("[ INFO     ] %d ranks: node 1 on rank %d -> %d; force on the cube along x %.6g at rest, off by "
                "at most %.3g over the crossing; memories %g -> %g (most on one rank %g, of other ranks %g)\n",
                ranks(), owner_before, owner_after, resting, most, before[0], after[0], after[1], after[2]);
  EXPECT_EQ(steps, 401);    // the run's setup and 400 steps
  if (ranks() > 1) {
    EXPECT_NE(owner_before, owner_after) << "the wire did not change rank";
  }
  EXPECT_GT(resting, 0.9 * 0.05 * 0.2 / std::sqrt(1.04));    // friction holds the weight's x component
  EXPECT_LT(most, 1e-6 * resting);
  EXPECT_GE(before[0], 4.0);    // one contact per element at least
  EXPECT_EQ(after[0], before[0]);
  EXPECT_EQ(after[2], 0.0);
  // every node crossed the cut at x = 0 once, carrying its memories with it (fix wire's count
  // of the memories packed with migrating atoms, doc/scaling.md "Counted")
  const auto *fix = dynamic_cast<FixWire *>(lmp->modify->get_fix_by_id("w"));
  const double migrated = summed(fix->memories_migrated()), values = summed(fix->memory_values_migrated());
  if (rank() == 0) std::printf("[ INFO     ] memories migrated %g (%g doubles)\n", migrated, values);
  EXPECT_EQ(migrated, ranks() > 1 ? after[0] : 0.0);
}

// A restart written on all ranks of this run (4, or 2) is read on fewer ranks (2 and 1, on
// their own communicators). Right after read_restart no rank holds a friction memory of a
// contact it does not compute, the ranks hold as many memories between them as the writers
// did, and none holds all when several own nodes that compute contacts; the next step and
// 100 steps on, the nodes are where the uninterrupted run put them (to round-off: the sums
// over ranks go in another order). Gravity tilted by 0.2 keeps the wire stuck on the cube
// face by its springs, so a memory lost or doubled shows in the positions (by ~1e-7).
TEST_F(WireOnGrainTest, RestartWrittenOnAllRanksContinuesOnFewerWithOnlyTheirOwnMemories)
{
  const std::vector<std::string> redefine = {
      "neighbor 0.3 bin", "comm_modify cutoff 3.0", "fix g wire gravity 1.0 vector 0.2 0 -1",
      "fix w wire wire radius 0.05 k_n 1000 gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.5 mu_d 0.4 damp 0.02"};
  on_grain(0.0);
  commands({redefine[2], "run 200", "write_restart " + scratch("written.restart")});
  const std::array<double, 3> written = memory_holdings(lmp, MPI_COMM_WORLD);
  EXPECT_EQ(written[2], 0.0);
  EXPECT_GE(written[0], 4.0);
  run("run 1");
  const std::vector<double> first = positions_of(lmp, 5, MPI_COMM_WORLD);
  run("run 99");
  const std::vector<double> hundredth = positions_of(lmp, 5, MPI_COMM_WORLD);

  for (int size : {2, 1}) {
    if (size >= ranks()) continue;
    on_first_ranks(size, [&](MPI_Comm fewer) {
      commands({"processors * * 1", "read_restart " + scratch("written.restart")});
      commands(redefine);
      const std::array<double, 3> read = memory_holdings(lmp, fewer);
      int owning = 0, ranks_owning = 0;
      for (int i = 0; i < lmp->atom->nlocal; i++) owning |= lmp->atom->tag[i] <= 4;    // first nodes of elements
      MPI_Allreduce(&owning, &ranks_owning, 1, MPI_INT, MPI_SUM, fewer);
      EXPECT_EQ(read[2], 0.0) << size << " ranks: memories of other ranks' contacts";
      EXPECT_EQ(read[0], written[0]) << size << " ranks";
      if (ranks_owning > 1) {
        EXPECT_LT(read[1], read[0]) << size << " ranks";
      }
      run("run 1");
      const double off_first = largest_difference(positions_of(lmp, 5, fewer), first);
      run("run 99");
      const double off_hundredth = largest_difference(positions_of(lmp, 5, fewer), hundredth);
      EXPECT_LT(off_first, 1e-12) << size << " ranks";
      EXPECT_LT(off_hundredth, 1e-10) << size << " ranks";
      if (rank() == 0)
        std::printf("[ INFO     ] written on %d ranks: %g memories held; read on %d: %g held, at most %g on one "
                    "rank, %g of other ranks' contacts; nodes off the uninterrupted run by %.3g after 1 step, "
                    "%.3g after 100\n", ranks(), written[0], size, read[0], read[1], read[2], off_first,
                    off_hundredth);
    });
    MPI_Barrier(MPI_COMM_WORLD);
  }
}

// A restart file of wire format 3 (every contact's friction memory in the global block,
// written before the memories were kept with the atoms: data/in.wire_format3, the wire on
// the cube of WireOnGrainTest with its 4 memories, one per element) is still read: each
// rank keeps the memories of the nodes it owns and none of other ranks' contacts, and 100
// steps on the nodes are where the build that wrote the file put them
// (data/wire_format3.after100; without the memories they differ by ~1e-7).
TEST_F(WireTest, RestartOfFormat3IsReadIntoTheNodes)
{
  const std::string data = NSCD_TEST_DATA_DIR;
  commands({"processors * * 1", "read_restart " + data + "/wire_format3.restart", "neighbor 0.3 bin",
            "comm_modify cutoff 3.0", "fix g wire gravity 1.0 vector 0.2 0 -1",
            "fix w wire wire radius 0.05 k_n 1000 gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.5 mu_d 0.4 damp 0.02"});
  const std::array<double, 3> held = memory_holdings(lmp, MPI_COMM_WORLD);
  int owning = 0, ranks_owning = 0;
  for (int i = 0; i < lmp->atom->nlocal; i++) owning |= lmp->atom->tag[i] >= 2 && lmp->atom->tag[i] <= 5;
  MPI_Allreduce(&owning, &ranks_owning, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(held[2], 0.0);
  EXPECT_EQ(held[0], 4.0);
  if (ranks_owning > 1) {
    EXPECT_LT(held[1], held[0]);
  }
  run("run 100");
  std::ifstream in(data + "/wire_format3.after100");
  std::string line;
  for (int k = 0; k < 9; k++) std::getline(in, line);    // the dump's header
  double most = 0.0;
  int nodes = 0;
  for (tagint id; in >> id;) {
    std::vector<double> expected(3);
    for (double &x : expected) in >> x;
    most = std::max(most, largest_difference(position(id), expected));
    nodes++;
  }
  if (rank() == 0)
    std::printf("[ INFO     ] %d ranks: %g memories held, at most %g on a rank, %g of other ranks' contacts; nodes "
                "off the writing build's by %.3g after 100 steps\n", ranks(), held[0], held[1], held[2], most);
  EXPECT_EQ(nodes, 5);
  EXPECT_LT(most, 1e-10);
}

TEST_F(WireTest, SubstepAboveTheStabilityLimitIsANamedError)
{
  scene(straight_chain(11, 0.1, 0.01), 11, true, 1e4, 0.1, 1.0);
  run("group wire id 2:11");
  run("fix w wire wire substeps 1");
  const std::string message = error_of("run 1");
  EXPECT_NE(message.find("fix wire"), std::string::npos) << message;
  EXPECT_NE(message.find("stability limit"), std::string::npos) << message;
  EXPECT_NE(message.find("substeps"), std::string::npos) << message;
  run("unfix w");
  run("fix w wire wire dt_sp 0.001");
  EXPECT_NE(error_of("run 1").find("stability limit"), std::string::npos);
  run("unfix w");
  run("fix w wire wire");    // automatic substeps: runs
  EXPECT_EQ(error_of("run 1"), "");
  EXPECT_GT(fix_value("w", 5), 1.0);
}

// A substep count far beyond what stability needs is a mistake (a dt_sp meant for another
// timestep): warned above 10 times the need, refused above 10^6 per step (a step that never
// ends); dt_sp 0 is not "automatic"; contacts with contacts_per_node 0 would leave the
// contacts out of the automatic step.
// A grain (the rounded cube) resting on a wire held still (all its nodes anchored but the
// end one, outside the grain's reach) with the column's contact law at the column's grain
// step: k_t dt = 7.5 > 2 gamma_t = 2. Kicked along the wire, its sticking contacts ring and
// must die away, on any rank count (the wire's two legs cross the ranks' boundaries, so the
// grain is a ghost where most of its contacts are computed), the wire carrying its weight.
class KickedGrainTest : public WireTest {
 protected:
  struct Kicked {
    double weight = 0.0, kick = 0.0, highest = 0.0, last = 0.0;    // the wire's force on it; its kinetic energies
  };
  // The cube of mass m_cube kicked at 0.002 along the wire, then 400 steps; `springs`: fix
  // wire's grain_springs.
  Kicked kick(double m_cube, const std::string &springs)
  {
    // two legs of four elements at y = -0.2 and 0.2 joined at x = 0.8, the cube's face (0.8
    // wide) lying across the two middle elements of each: 8 stretch ends, each stiffer than
    // k_n alone would be (several elements under one face make the normal direction too
    // stiff for the grain step: that limit is another matter)
    const double l = 0.4, r_w = 0.05, m_node = 0.005;
    std::vector<Point> atoms;
    for (int k = 0; k <= 4; k++) atoms.push_back({-0.8 + k * l, -0.2, r_w, m_node});
    for (int k = 0; k <= 4; k++) atoms.push_back({0.8 - k * l, 0.2, r_w, m_node});
    const int nodes = (int) atoms.size();
    atoms.push_back({0.0, 0.0, 2.0 * r_w + 0.4, m_cube, 2, 3});    // half size 0.3, rounding 0.1
    scene(atoms, nodes, true, 5000.0, l, 0.01);
    commands({"pair_style nscd", "pair_coeff * * 0.5", "special_bonds lj 0 0 0", "timestep 0.005",
              "group cube type 2", "group end id 1", "fix g cube gravity 1.0 vector 0 0 -1",
              "fix w end wire radius " + num(r_w) + " k_n 2000 gamma_n 2 k_t 1500 gamma_t 1 mu_s 1 grain_springs " +
                  springs,
              "fix solver cube nscd tolerance 1e-9 max_sweeps 500"});
    run("run 400");
    Kicked out;
    out.weight = fix_value("w", 9);    // the wire's force on the grains, z
    run("velocity cube set 0.002 0 0");
    out.kick = kinetic_energy(nodes + 1, nodes + 1);
    for (int k = 0; k < 8; k++) {
      run("run 50");
      out.highest = std::max(out.highest, kinetic_energy(nodes + 1, nodes + 1));
    }
    out.last = kinetic_energy(nodes + 1, nodes + 1);
    std::printf("[ grain kicked on a held wire ] cube of mass %g, %s springs: wire carries %.10g; kinetic energy "
                "%.3g at the kick, highest %.3g, %.3g after 400 steps\n",
                m_cube, springs.c_str(), out.weight, out.kick, out.highest, out.last);
    return out;
  }
};

// The cube is heavier than the column's grains (2 against 0.3-0.5) so that its
// sliding-rocking mode stays within the explicit coupling's reach with the default carried
// springs, h^2 K / m_eff below about 2 (doc/Howto_nscd_wire_model.rst). Before the springs
// took the grain's motion that its velocity at the step's start did not carry
// (lib/wire/contact_model.h), the grain rang on at the friction limit.
TEST_F(KickedGrainTest, GrainKickedOnAHeldWireComesToRestAtTheColumnsStep)
{
  for (const std::string springs : {"carried", "held"}) {
    restart_instance();
    const Kicked k = kick(2.0, springs);
    // what is left is the cube rocking on the normal springs, which only their dashpots damp
    // (2 % of the kick after the 400 steps with carried springs, measured)
    EXPECT_NEAR(k.weight / 2.0, 1.0, 1e-3) << springs;
    EXPECT_LT(k.highest, k.kick) << springs;
    EXPECT_LT(k.last, 0.1 * k.kick) << springs;
  }
}

// A cube of the column's grains' mass (0.3) makes the mode too stiff for carried springs:
// its energy grew to three times the kick's and was 0.76 of it after 400 steps (measured).
// Held springs, whose limit is twice as high, bring it to rest (5e-8 of the kick on 1 rank; at 0.2
// both grew first, at 0.12 both rang on: the normal springs' own limit).
TEST_F(KickedGrainTest, LightGrainKickedOnAHeldWireComesToRestWithHeldSprings)
{
  const double m_cube = 0.3;
  const Kicked carried = kick(m_cube, "carried");
  restart_instance();
  const Kicked held = kick(m_cube, "held");
  EXPECT_NEAR(held.weight / m_cube, 1.0, 1e-3);
  EXPECT_LT(held.highest, held.kick);
  EXPECT_LT(held.last, 1e-3 * held.kick);
  EXPECT_GT(carried.highest, carried.kick);    // the reason for held springs here
}

TEST_F(WireTest, AbsurdSubstepsAreRefusedAndExcessiveOnesWarned)
{
  scene(straight_chain(11, 0.1, 0.01), 11, true, 1e4, 0.1, 1.0);
  run("group wire id 2:11");
  run("fix w wire wire substeps stable");
  run("run 0");
  const int needed = (int) fix_value("w", 5);    // the fewest stable
  run("unfix w");
  run("fix w wire wire substeps 1000000000");
  const std::string absurd = error_of("run 1");
  EXPECT_NE(absurd.find("substeps 1000000000 asks for 1e+09 wire substeps per step, more than 1000000"), std::string::npos) << absurd;
  EXPECT_NE(absurd.find(fmt::format("needs {} (substeps stable)", needed)), std::string::npos) << absurd;
  run("unfix w");
  run("fix w wire wire dt_sp 1e-15");
  EXPECT_NE(error_of("run 1").find("more than"), std::string::npos);
  run("unfix w");
  const std::string zero = error_of("fix w wire wire dt_sp 0");
  EXPECT_NE(zero.find("dt_sp 0 must be > 0"), std::string::npos) << zero;
  EXPECT_NE(zero.find("substeps auto"), std::string::npos) << zero;
  const std::string uncounted = error_of("fix w wire wire radius 0.02 k_n 100 contacts_per_node 0");
  EXPECT_NE(uncounted.find("contacts_per_node 0"), std::string::npos) << uncounted;
  run("fix w wire wire radius 0.02 contacts_per_node 0");    // no contacts (k_n 0): nothing to count
  run("unfix w");
  // 20 times the need: runs, with a warning naming the ratio
  run(fmt::format("fix w wire wire substeps {}", 20 * needed));
  const std::string log = scratch("excessive.log");
  run("log " + log);
  run("run 1");
  run("log none");
  MPI_Barrier(MPI_COMM_WORLD);
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(fmt::format("asks for {} wire substeps per step, 20 times the {}", 20 * needed, needed)),
            std::string::npos) << text;
  EXPECT_EQ(fix_value("w", 5), 20.0 * needed);
}

TEST_F(WireTest, BadOptionsAndPartnersAreNamedErrors)
{
  scene(straight_chain(3, 0.1, 0.01), 3, true, 1e2, 0.1, 1.0);
  run("group wire id 1:3");
  EXPECT_NE(error_of("fix w wire wire k_n -1").find("k_n"), std::string::npos);
  EXPECT_NE(error_of("fix w wire wire k_n 1 mu_s 0.2 mu_d 0.5").find("mu"), std::string::npos);
  const std::string bogus = error_of("fix w wire wire radius 0.02 bogus 1");
  EXPECT_NE(bogus.find("unknown keyword 'bogus'"), std::string::npos) << bogus;
  EXPECT_NE(bogus.find("keywords are listed in doc/fix_wire.rst, Syntax"), std::string::npos) << bogus;
  // grain_friction TYPES MU_S MU_D: three values, types in range, 0 <= mu_d <= mu_s
  const std::string short_list = error_of("fix w wire wire k_n 1 radius 0.02 grain_friction 1 0.3");
  EXPECT_NE(short_list.find("grain_friction needs three values"), std::string::npos) << short_list;
  EXPECT_NE(error_of("fix w wire wire k_n 1 radius 0.02 grain_friction 1 0.2 0.5").find("mu_d 0.5"), std::string::npos);
  EXPECT_NE(error_of("fix w wire wire k_n 1 radius 0.02 grain_friction 1 -1 0").find("mu_s -1"), std::string::npos);
  const std::string type = error_of("fix w wire wire k_n 1 radius 0.02 grain_friction 7 0.3 0.2");
  EXPECT_NE(type.find("7"), std::string::npos) << type;
  // grain_springs: carried or held
  const std::string springs = error_of("fix w wire wire k_n 1 radius 0.02 grain_springs still");
  EXPECT_NE(springs.find("grain_springs still is neither carried (the default) nor held"), std::string::npos)
      << springs;
  // a keyword where a value belongs names both and where the keywords are listed
  const std::string early = error_of("fix w wire wire radius k_n 100");
  EXPECT_NE(early.find("keyword 'radius' needs a value"), std::string::npos) << early;
  EXPECT_NE(early.find("'k_n'"), std::string::npos) << early;
  EXPECT_NE(early.find("doc/fix_wire.rst, Syntax"), std::string::npos) << early;
  const std::string last = error_of("fix w wire wire radius 0.02 k_n");
  EXPECT_NE(last.find("keyword 'k_n' needs a value"), std::string::npos) << last;
  EXPECT_NE(error_of("fix w wire wire k_n 100").find("need a wire radius > 0"), std::string::npos);
  run("bond_style harmonic");
  run("bond_coeff 1 1 0.1");
  run("fix w wire wire");
  EXPECT_NE(error_of("run 1").find("bond_style wire"), std::string::npos);
}

// fix wire integrates the nodes on its own subcycle in post_force: under respa it would be
// skipped and under minimize the nodes would not move; both are refused by name.
TEST_F(WireTest, RespaAndMinimizeAreRefusedByName)
{
  scene(straight_chain(3, 0.1, 0.01), 3, true, 1e2, 0.1, 1.0);
  commands({"group wire id 1:3", "fix w wire wire radius 0.02"});
  const std::string minimize = error_of("minimize 0 0 10 10");
  EXPECT_NE(minimize.find("fix wire cannot take part in 'minimize'"), std::string::npos) << minimize;
  run("run_style respa 2 2");
  const std::string respa = error_of("run 1");
  EXPECT_NE(respa.find("fix wire does not work with 'run_style respa'"), std::string::npos) << respa;
  EXPECT_NE(respa.find("run_style verlet"), std::string::npos) << respa;
  run("run_style verlet");
  run("run 1");    // and the ordinary integrator still runs
  EXPECT_EQ(lmp->update->ntimestep, 1);
}

// ---------------------------------------------------------------- capstan

class CapstanTest : public WireTest {
 protected:
  static constexpr double kBall = 0.5, kWireRadius = 0.02, kLoad = 1.0;
  static constexpr int kArc = 24, kHang = 6;    // elements on the half turn, on each side
  int last = 0;                                 // atom ID of the heavy end

  // A string (no bending) laid over the top of a fixed ball (radius 0.5, atom `last` + 1):
  // a half turn of kArc elements whose middles touch the ball, then kHang elements hanging
  // straight down on each side, so the wrap angle is phi = pi. Only the two end nodes are
  // loaded (fix addforce, down): the light end by kLoad, the heavy end by `ratio` kLoad.
  void wire_over_ball(double mu_s, double mu_d)
  {
    const double half = M_PI / kArc / 2.0, rho = (kBall + kWireRadius) / std::cos(half);
    const double l = 2.0 * rho * std::sin(half);
    std::vector<Point> atoms;
    for (int j = kHang; j >= 1; j--) atoms.push_back({-rho, 0.0, -j * l, 0.005});
    for (int k = 0; k <= kArc; k++) {
      const double theta = M_PI - 2.0 * half * k;
      atoms.push_back({rho * std::cos(theta), 0.0, rho * std::sin(theta), 0.005});
    }
    for (int j = 1; j <= kHang; j++) atoms.push_back({rho, 0.0, -j * l, 0.005});
    last = (int) atoms.size();
    atoms.push_back({0.0, 0.0, 0.0, 1.0, 2, 2});
    const std::string data = scratch("capstan.data");
    write_data(data, atoms, last, false);
    load_scene(data, 1000.0, l, 0.0, " string yes");
    commands({"group wire id 1:" + std::to_string(last), "group light id 1",
              "group heavy id " + std::to_string(last), "variable f1 equal 0",
              "variable f2 equal 0", "fix pull1 light addforce 0 0 v_f1",
              "fix pull2 heavy addforce 0 0 v_f2",
              "fix w wire wire radius " + num(kWireRadius) + " k_n 1000 gamma_n 0.2 k_t 1000 "
              "gamma_t 0.1 mu_s " + num(mu_s) + " mu_d " + num(mu_d) + " damp 0.002"});
  }

  // Loads both ends to kLoad (0.2 time units), then the heavy end on to ratio * kLoad over
  // 2 time units; returns how far the heavy end sinks over the next `hold` time units.
  double sink_under_ratio(double ratio, double hold)
  {
    const std::string F = num(-kLoad), R = num(-ratio * kLoad);
    commands({"variable f1 equal ramp(0," + F + ")", "variable f2 equal ramp(0," + F + ")",
              "run 200", "variable f1 equal " + F, "variable f2 equal ramp(" + F + "," + R + ")",
              "run 2000", "variable f2 equal " + R});
    const double z0 = position(last)[2];
    run("run " + std::to_string((int) std::lround(hold / 0.001)));
    return z0 - position(last)[2];
  }
};

TEST_F(CapstanTest, WireOverAFixedGrainHoldsBelowExpMuPhiAndSlipsAbove)
{
  // Capstan: a string over a fixed ball with wrap phi = pi holds while T_heavy / T_light <
  // exp(mu phi). Bracket: at 0.9 exp(mu phi) the heavy end stays (it sinks by the elastic
  // creep only, < 1e-3, over 1 time unit), at 1.1 exp(mu phi) it slides off (> 0.05).
  const double mu = 0.3, capstan = std::exp(mu * M_PI);
  wire_over_ball(mu, mu);
  const double held = sink_under_ratio(0.9 * capstan, 1.0);
  restart_instance();
  wire_over_ball(mu, mu);
  const double slid = sink_under_ratio(1.1 * capstan, 1.0);
  std::printf("[ capstan ] exp(mu phi) = %.4f: sinks %.3g at 0.9x, %.3g at 1.1x\n", capstan, held, slid);
  EXPECT_LT(std::fabs(held), 1e-3);
  EXPECT_GT(slid, 0.05);
}

// ---------------------------------------------------------------- crossing wires

class CrossingWiresTest : public WireTest {
 protected:
  static constexpr double kRadius = 0.05, kNormal = 1.0, kN = 1e4, kMass = 0.01;
  static constexpr double kMuS = 0.5, kMuD = 0.3;

  // Element A: atoms 1, 2 along x, held (not in the group). Element B: atoms 3, 4 along y,
  // crossing A at its middle and just touching it, pressed down by kNormal and pulled along
  // x by the variable fx (both split evenly over its two nodes).
  // x0 moves the crossing along x (with periodic x, x0 = 5 puts it on the box's boundary).
  void crossing(const std::string &friction = "mu_s " + num(kMuS) + " mu_d " + num(kMuD), double x0 = 0.0)
  {
    const std::vector<Point> atoms = {{x0 - 0.5, 0, 0, kMass}, {x0 + 0.5, 0, 0, kMass},
                                      {x0, -0.5, 2 * kRadius, kMass}, {x0, 0.5, 2 * kRadius, kMass}};
    const std::string data = scratch("crossing.data");
    write_topology(data, atoms, {{1, 2}, {3, 4}}, {});
    load_scene(data, 100.0, 1.0, 0.0);
    commands({"group wire id 3 4", "variable fx equal 0",
              "fix press wire addforce v_fx 0 " + num(-kNormal / 2),
              "fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) + " gamma_n 1 k_t 1e4 "
              "gamma_t 1 " + friction});
  }
  // Mean of B's two nodes along axis d.
  double b_position(int d) { return 0.5 * (position(3)[d] + position(4)[d]); }
  void pull(double total) { run("variable fx equal " + num(total / 2)); }
  // Atoms 1-5 joined by `bonds`, only node 4 free and pressed down by kNormal onto element
  // 1-2 below it: its overlap after 300 steps.
  double node_4_pressed(const std::vector<Point> &atoms, const std::vector<std::array<int, 2>> &bonds,
                        double r0, const std::string &string_option)
  {
    const std::string data = scratch("node_4.data");
    write_topology(data, atoms, bonds, {});
    load_scene(data, 100.0, r0, 0.0, string_option);
    commands({"group wire id 4", "fix press wire addforce 0 0 " + num(-kNormal),
              "fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) + " gamma_n 1 k_t 1e4 gamma_t 1 mu_s 0.5",
              "run 300"});
    return 2 * kRadius - position(4)[2];
  }
  double moved_across_balance(bool rebuild_every_step);
};

TEST_F(CrossingWiresTest, PressedWireStaysAtTheSpringOverlapSticksUntilMuSAndSlidesAtMuD)
{
  crossing();
  run("run 300");
  // at rest under f_n: overlap = f_n / k_n (the dashpot carries nothing), within 0.1 %
  const double overlap = 2 * kRadius - b_position(2);
  EXPECT_NEAR(overlap / (kNormal / kN), 1.0, 1e-3);

  // pull sideways, increasing by 0.001 f_n every 0.02 time units, until B moves
  // (sticking it moves by the tangential spring only, < mu_s f_n / k_t = 5e-5)
  run("variable fx equal ramp(0," + num(0.2 * kNormal) + ")");    // to 0.4 f_n, slowly
  run("run 400");
  double onset = 0.0;
  for (double F = 0.4; F < 0.7 && onset == 0.0; F += 0.001) {
    pull(F * kNormal);
    run("run 20");
    if (b_position(0) > 1e-3) onset = F;
  }
  // the load that broke the contact was applied in the last chunk: onset within one
  // increment of mu_s, and the one before it held
  std::printf("[ crossing ] slip at F / f_n = %.4f (mu_s %.2f), overlap %.6g (f_n/k_n %.4g)\n",
              onset, kMuS, overlap, kNormal / kN);
  EXPECT_NEAR(onset, kMuS, 1.5e-3);

  // now pull by 0.4 f_n, between mu_d and mu_s: B keeps sliding, and its acceleration
  // gives the friction force: m a = F - f_t, f_t = mu_d f_n within 0.1 %
  const double F = 0.4 * kNormal, T = 0.05, m = 2 * kMass;
  pull(F);
  run("run 20");
  double x[3], deepest = 0.0;
  for (double &xi : x) {
    xi = b_position(0);
    for (int k = 0; k < 10; k++) {
      run("run 5");
      deepest = std::max(deepest, 2 * kRadius - b_position(2));
    }
  }
  const double a = (x[2] - 2 * x[1] + x[0]) / (T * T), friction = F - m * a;
  std::printf("[ crossing ] sliding: a %.4g, friction / f_n = %.6f (mu_d %.2f), deepest overlap %.6g\n",
              a, friction / kNormal, kMuD, deepest);
  EXPECT_GT(x[2] - x[1], x[1] - x[0]);    // still sliding, faster and faster
  EXPECT_NEAR(friction / (kMuD * kNormal), 1.0, 1e-3);
  EXPECT_LT(deepest, 1.001 * kNormal / kN);    // no interpenetration beyond the spring's
}

// Wire-wire friction of its own (mu_ww_s 0.2, mu_ww_d 0.1) below the wire-grain one (0.5,
// 0.3): B holds under 0.15 f_n, and under 0.25 f_n (which the wire-grain friction would
// hold) it slides with the friction force mu_ww_d f_n.
TEST_F(CrossingWiresTest, WireWireFrictionIsItsOwnAndSetsTheSlidingThreshold)
{
  crossing("mu_s 0.5 mu_d 0.3 mu_ww_s 0.2 mu_ww_d 0.1");
  run("run 300");
  run("variable fx equal ramp(0," + num(0.075 * kNormal) + ")");    // to 0.15 f_n, slowly
  run("run 300");
  const double held = b_position(0);
  run("run 200");
  EXPECT_LT(std::abs(held), 0.15 * kNormal / 1e4 * 1.01);    // the tangential spring's stretch only
  EXPECT_NEAR(b_position(0), held, 1e-6);    // (free, it would move by F t^2 / 2m = 0.15)
  const double F = 0.25 * kNormal, T = 0.05, m = 2 * kMass;
  pull(F);
  run("run 20");
  double x[3];
  for (double &xi : x) {
    xi = b_position(0);
    run("run 50");
  }
  const double a = (x[2] - 2 * x[1] + x[0]) / (T * T), friction = F - m * a;
  std::printf("[ crossing, mu_ww ] held at %.3g under 0.15 f_n; sliding under 0.25 f_n: friction / f_n = %.6f "
              "(mu_ww_d 0.1)\n", held, friction / kNormal);
  EXPECT_GT(x[2] - x[1], x[1] - x[0]);    // sliding, faster and faster
  EXPECT_NEAR(friction / (0.1 * kNormal), 1.0, 1e-3);
  EXPECT_NE(error_of("fix w wire wire radius 0.05 k_n 1e4 mu_ww_s 0.1 mu_ww_d 0.2").find("mu_ww_d = 0.2 exceeds"),
            std::string::npos);
}

// compute wire/contacts on a wire-wire contact: one row, element 1-2 against the element
// whose first node is 3, the normal from B down to A, fn = the press, and fix wire's count.
TEST_F(CrossingWiresTest, WireContactsComputeReportsTheCrossingOnce)
{
  crossing();
  run("compute wc all wire/contacts");
  run("run 300");
  const std::vector<std::vector<double>> rows = local_rows("wc");
  ASSERT_EQ(rows.size(), 1u);
  const std::vector<double> &r = rows[0];
  EXPECT_EQ(fix_value("w", 3), 1.0);
  EXPECT_EQ(r[0], 1.0);
  EXPECT_EQ(r[1], 2.0);
  EXPECT_EQ(r[2], 3.0);
  EXPECT_EQ(r[3], 2.0);    // wire-wire
  EXPECT_NEAR(r[9], -1.0, 1e-9);
  EXPECT_NEAR(r[10], kNormal, 1e-3 * kNormal);    // (still settling: 2e-4 after 300 steps)
  EXPECT_NEAR(r[14], kNormal / kN, 1e-3 * kNormal / kN);
}

// mu_s alone means mu_d = mu_s: after a slip, a pull below mu_s f_n lets the wire stick
// again (with mu_d left at 0 it would slide on without friction).
// The friction history of a sticking contact follows its computing node to another rank:
// B, pressed onto A and pulled sideways by 0.3 f_n (below mu_s), is held by the tangential
// spring alone (stretched by 0.3 f_n / k_t = 3e-5). Moving the cut (balance) hands node 1,
// the first node of the lower element and so the contact's owner, to another rank. With the
// history handed over B does not move; without it the spring restarts from zero and B
// slides back by about 3e-5 before it sticks again.
// B sticks under a pull of 0.3 f_n; then `balance` moves the cut so that node 1 (which
// owns the contact) changes rank, and the run goes on. With `rebuild_every_step` the first
// run rebuilds its lists on its last step and the second never: the neighbour build of the
// second run's setup keeps the old time stamp, and the hand-over must happen all the same.
// Returns how far B moved over the second run (it must stay: sticking).
double CrossingWiresTest::moved_across_balance(bool rebuild_every_step)
{
  crossing();
  pull(0.3 * kNormal);
  if (rebuild_every_step) run("neigh_modify every 1 delay 0 check no");
  run("run 400");
  const double before = b_position(0);
  auto owner_of_node_1 = [&]() {
    const int i = lmp->atom->map(1);
    int mine = (i >= 0 && i < lmp->atom->nlocal) ? rank() : -1, all;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return all;
  };
  const int owner = owner_of_node_1();
  // the cut through x = 0 (or y: 2 and 4 ranks are split 2 x 1 or 2 x 2) moves to 2 % of the box
  if (ranks() > 1) run(std::string("balance 1.0 ") + (lmp->comm->procgrid[0] == 2 ? "x" : "y") + " 0.02");
  if (rebuild_every_step) run("neigh_modify every 1000 delay 0 check no");
  run("run 50");
  std::printf("[ crossing ] node 1 owned by rank %d, then %d; B moved by %.3g while sticking\n",
              owner, owner_of_node_1(), b_position(0) - before);
  if (ranks() > 1) {
    EXPECT_NE(owner_of_node_1(), owner);    // the contact changed rank
  }
  return b_position(0) - before;
}

TEST_F(CrossingWiresTest, StickingHistoryFollowsTheContactToAnotherRank)
{
  EXPECT_NEAR(moved_across_balance(false), 0.0, 1e-9);
}

// The same crossing on the boundary of a periodic box (A's nodes at x = 4.5 and -4.5, B on
// x = +-5): one contact, computed once, at the same overlap, and it sticks under 0.3 f_n
// (moved 3e-5 = 0.3 f_n / k_t, the same as at x = 0 in a closed box).
TEST_F(CrossingWiresTest, AcrossAPeriodicBoundaryTheContactIsFoundOnceAndSticks)
{
  boundary = "p f f";
  crossing("mu_s " + num(kMuS) + " mu_d " + num(kMuD), 5.0);
  run("run 300");
  const double overlap = 2 * kRadius - b_position(2);
  EXPECT_NEAR(overlap / (kNormal / kN), 1.0, 1e-3);
  EXPECT_EQ(fix_value("w", 3), 1.0);    // wire-wire contacts, summed over the ranks
  auto x3 = [&]() { return std::fmod(position(3)[0] + 10.0, 10.0); };    // B's node, unwrapped
  const double before = x3();
  run("variable fx equal ramp(0," + num(0.15 * kNormal) + ")");    // to 0.3 f_n in all, slowly
  run("run 300");
  pull(0.3 * kNormal);
  run("run 100");
  std::printf("[ crossing, periodic ] overlap %.6g (f_n/k_n %.4g), contacts %g, B moved by %.3g under 0.3 f_n\n",
              overlap, kNormal / kN, fix_value("w", 3), x3() - before);
  // sticking: the tangential spring only, 0.3 f_n / k_t = 3e-5 (without friction: ~ 0.7)
  EXPECT_NEAR(x3() - before, 0.3 * kNormal / 1e4, 1e-5);
}

// fix wire hands its memories to the atoms in its pre_exchange, by where they were at the
// last step: a fix that moves atoms between ranks in its own pre_exchange (fix balance)
// must come after it, and is refused by name before it.
TEST_F(CrossingWiresTest, FixBalanceBeforeFixWireIsRefused)
{
  crossing();
  commands({"unfix w", "fix lb all balance 100 1.0 shift x 10 1.0",
            "fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) + " mu_s 0.5"});
  const std::string message = error_of("run 1");
  EXPECT_NE(message.find("fix wire w must be defined before fix balance lb"), std::string::npos) << message;
  commands({"unfix lb", "fix lb all balance 100 1.0 shift x 10 1.0", "run 1"});    // after it: fine
}

TEST_F(CrossingWiresTest, HistoryIsHandedOverWhenTheLastStepRebuiltTheLists)
{
  EXPECT_NEAR(moved_across_balance(true), 0.0, 1e-9);
}

TEST_F(CrossingWiresTest, GhostCutoffBelowTheContactReachIsANamedErrorAcrossRanks)
{
  // elements of length 1, r_w = 0.05, skin 0.3: a contact reaches 2 + 0.1 + 0.3 = 2.4 from
  // its owner's node; pair_style zero 1.0 + skin gives a ghost cutoff of only 1.3
  crossing();
  run("comm_modify cutoff 0.0");
  const std::string message = error_of("run 0");
  if (ranks() == 1) {
    EXPECT_EQ(message, "");    // one rank, no periodic boundary: nothing needs ghosts
  } else {
    EXPECT_NE(message.find("ghost cutoff 1.3 "), std::string::npos) << message;
    EXPECT_NE(message.find("comm_modify cutoff 2.4'"), std::string::npos) << message;
  }
}

// Only atoms within the ghost cutoff (neighbour skin 0.3 beyond the reach of a contact) are
// there to be found. Element B falling at 600 (0.6 per step) from 0.4 above A closes by
// more than the skin in a step (and passes through A between two substeps); fix wire
// counts such steps (output 13) and warns once, naming a skin that would cover the
// motion. A slow run counts none.
TEST_F(CrossingWiresTest, MotionBeyondTheSkinWithinAStepIsCountedAndWarned)
{
  crossing();
  const std::string log = scratch("too_fast.log");
  commands({"set atom 3*4 z 0.5", "velocity wire set 0 0 -600", "log " + log, "run 2", "log none"});
  EXPECT_LT(b_position(2), -0.5);    // through A without a contact
  EXPECT_EQ(fix_value("w", 12), 2.0);
  if (rank() == 0) {
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("fix wire: step 1: a node moved 0.59"), std::string::npos) << text;
    EXPECT_NE(text.find(": over the skin 0.3; lower the timestep"), std::string::npos) << text;
    EXPECT_NE(text.find("or use neighbor 2.3"), std::string::npos) << text;    // 2 x (0.6 + 0.6)
    EXPECT_EQ(text.find("fix wire: step 2:"), std::string::npos) << "warned twice";
  }
  commands({"velocity wire set 0 0 0", "run 10"});
  EXPECT_EQ(fix_value("w", 12), 0.0);
}

// A wire's node pressed onto another wire (element A along x, held): both elements meeting
// at the node touch A with the node's sphere, each its own contact (the paper's model), so
// the node sinks by f_n / (2 k_n).
TEST_F(CrossingWiresTest, ContactAtANodeIsMadeByEachElementMeetingThere)
{
  // B's elements 3-4, 4-5 at their rest length 0.5 across A
  const double overlap = node_4_pressed({{-0.5, 0, 0, kMass}, {0.5, 0, 0, kMass}, {0, -0.5, 2 * kRadius, kMass},
                                         {0, 0, 2 * kRadius, kMass}, {0, 0.5, 2 * kRadius, kMass}},
                                        {{1, 2}, {3, 4}, {4, 5}}, 0.5, "");
  std::printf("[ node on wire ] overlap %.6g (f_n/2k_n %.4g), contacts %g\n", overlap, kNormal / (2 * kN),
              fix_value("w", 3));
  EXPECT_NEAR(overlap / (kNormal / (2 * kN)), 1.0, 1e-3);
  EXPECT_EQ(fix_value("w", 3), 2.0);    // elements 3-4 and 4-5 each touch A at node 4
}

// A hairpin: the wire 1-2-3-4-5 folds back so that node 4 presses on its own element 1-2.
// Element 3-4 is joined to 1-2 through 2-3 and makes no contact with it; 4-5 alone touches
// it with node 4's sphere (sinks by f_n / k_n). Slack string elements put no force on node 4.
TEST_F(CrossingWiresTest, ContactAtANodeIsMadeOnlyByElementsNotJoinedToThePartner)
{
  const double overlap = node_4_pressed({{-0.5, 0, 0, kMass}, {0.5, 0, 0, kMass}, {0.5, 0, 0.5, kMass},
                                         {0, 0, 2 * kRadius, kMass}, {0, 0.5, 2 * kRadius, kMass}},
                                        chain_bonds(1, 5, false), 1.0, " string yes");
  std::printf("[ hairpin ] overlap %.6g (f_n/k_n %.4g), contacts %g\n", overlap, kNormal / kN, fix_value("w", 3));
  EXPECT_NEAR(overlap / (kNormal / kN), 1.0, 1e-3);
  EXPECT_EQ(fix_value("w", 3), 1.0);
}

TEST_F(CrossingWiresTest, StaticCoefficientAloneAlsoActsWhileSliding)
{
  crossing("mu_s " + num(kMuS));
  run("run 300");
  pull(0.6 * kNormal);    // above mu_s f_n: B slips
  run("run 40");
  const double slipped = b_position(0);
  EXPECT_GT(slipped, 1e-3);
  pull(0.4 * kNormal);    // below: friction 0.5 f_n brakes it within a few steps
  run("run 200");
  const double before = b_position(0);
  run("run 200");
  EXPECT_NEAR(b_position(0), before, 1e-5);    // stuck again (no friction: moves ~0.8)
}

// ---------------------------------------------------------------- wire loop on grains

class WireLoopTest : public WireTest {
 protected:
  static constexpr int kNodes = 72;
  static constexpr double kNodeMass = 0.002, kBallMass = 0.5, kWireRadius = 0.02;

  // Four balls (radius 0.5, atoms kNodes+1..kNodes+4) touching each other on a frictional
  // floor (fix nscd/wall), and a closed wire loop of kNodes nodes (bonds and angles) laid
  // around them at mid-height, its rest length 1 % short so its tension grips the balls.
  void loop_around_balls()
  {
    const double rho = 0.5 + kWireRadius + 0.0025, perimeter = 4.0 + 2.0 * M_PI * rho;
    const double l = perimeter / kNodes;
    std::vector<Point> atoms;
    for (int k = 0; k < kNodes; k++) atoms.push_back(loop_point(k * l, rho));
    const double c[4][2] = {{0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}, {-0.5, -0.5}};
    for (const auto &xy : c) atoms.push_back({xy[0], xy[1], 0.5, kBallMass, 2, 2});
    const std::string data = scratch("loop.data");
    write_topology(data, atoms, chain_bonds(1, kNodes, true), ring_joints(kNodes));
    load_scene(data, 20.0, 0.99 * l, 1e-3);
    commands({"pair_style nscd", "pair_coeff * * 0.5", "special_bonds lj 0 0 0",
              "group wire id 1:" + std::to_string(kNodes), "group balls type 2",
              "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5",
              "fix g all gravity 1.0 vector 0 0 -1",
              "fix w wire wire radius " + num(kWireRadius) + " k_n 100 gamma_n 0.05 k_t 80 "
              "gamma_t 0.02 mu_s 0.5 mu_d 0.4 damp 0.01",
              "fix solver balls nscd tolerance 1e-9 max_sweeps 500"});
  }
  // The point at arc length s along the convex hull of four circles of radius rho centred
  // at (+-h, +-h), at height 0.5, counter-clockwise from (h + rho, -h); a node of mass m.
  static Point loop_point(double s, double rho, double h = 0.5, double m = kNodeMass)
  {
    const double c[4][2] = {{h, h}, {-h, h}, {-h, -h}, {h, -h}};
    const double quarter = 0.5 * M_PI * rho, side_length = 2.0 * h;
    for (int side = 0; side < 4; side++) {
      const double start[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};    // outward normal
      const double along[4][2] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};    // direction of travel
      const double *n = start[side], *t = along[side], *o = c[(side + 3) % 4];
      if (s <= side_length) return {o[0] + rho * n[0] + s * t[0], o[1] + rho * n[1] + s * t[1], 0.5, m};
      s -= side_length;
      if (s <= quarter) {
        const double phi = std::atan2(n[1], n[0]) + s / rho;
        return {c[side][0] + rho * std::cos(phi), c[side][1] + rho * std::sin(phi), 0.5, m};
      }
      s -= quarter;
    }
    return {h + rho, -h, 0.5, m};
  }
  using WireTest::kinetic_energy;
  double kinetic_energy(bool wire_nodes)
  {
    return wire_nodes ? WireTest::kinetic_energy(1, kNodes) : WireTest::kinetic_energy(kNodes + 1, MAXTAGINT);
  }
};

TEST_F(WireLoopTest, LoopAroundGrainsComesToRestAndTheFloorCarriesEverything)
{
  loop_around_balls();
  run("run 6000");
  // time averages over 1000 more steps
  const int samples = 100;
  double floor_z = 0.0, on_grains[3] = {0, 0, 0}, lowest = INFINITY;
  for (int k = 0; k < samples; k++) {
    run("run 10");
    floor_z += fix_value("floor", 2) / samples;
    for (int d = 0; d < 3; d++) on_grains[d] += fix_value("w", 7 + d) / samples;
  }
  for (int k = 1; k <= kNodes; k++) lowest = std::min(lowest, position(k)[2]);
  const double wire = kNodes * kNodeMass, total = 4 * kBallMass + wire;
  std::printf("[ wire loop ] floor %.10g (weight %.10g), wire on grains %.3g %.3g %.10g (wire weight %.8g)\n",
              floor_z, total, on_grains[0], on_grains[1], on_grains[2], wire);
  std::printf("[ wire loop ] kinetic energy: wire %.3g, balls %.3g; lowest node z %.6g, contacts %g\n",
              kinetic_energy(true), kinetic_energy(false), lowest, fix_value("w", 4));
  EXPECT_NEAR(floor_z / -total, 1.0, 1e-6);          // the floor carries balls + wire
  EXPECT_NEAR(on_grains[2] / -wire, 1.0, 1e-6);      // the grains carry the wire
  EXPECT_NEAR(on_grains[0], 0.0, 1e-6);
  EXPECT_NEAR(on_grains[1], 0.0, 1e-6);
  EXPECT_LT(kinetic_energy(true), 1e-10);
  EXPECT_LT(kinetic_energy(false), 1e-10);
  EXPECT_GT(lowest, 0.45);    // the loop stayed up, gripping the balls
}

// ---------------------------------------------------------------- a wire-bound stack across ranks

// A pyramid of 14 balls (radius 0.5, mass 0.5: 3 x 3, then 4 in the pockets, then 1) on a
// frictionless floor, held together only by a closed wire loop around the base (rest
// length 1 % short). Without the loop the base slides apart. On 2 and 4 ranks the loop,
// the base and the pyramid's contacts cross rank boundaries.
class WireBoundPyramidTest : public WireLoopTest {
 protected:
  static constexpr int kLoopNodes = 96;
  static constexpr double kBall = 0.5;

  void pyramid(bool with_loop)
  {
    const double rho = 0.5 + kWireRadius + 0.0025, perimeter = 8.0 + 2.0 * M_PI * rho;
    const double l = perimeter / kLoopNodes, rise = std::sqrt(0.5);
    std::vector<Point> atoms;
    for (int k = 0; k < kLoopNodes; k++) atoms.push_back(loop_point(k * l, rho, 1.0));
    for (int x = -1; x <= 1; x++)
      for (int y = -1; y <= 1; y++) atoms.push_back({(double) x, (double) y, 0.5, kBall, 2, 2});
    for (double x : {-0.5, 0.5})
      for (double y : {-0.5, 0.5}) atoms.push_back({x, y, 0.5 + rise, kBall, 2, 2});
    atoms.push_back({0.0, 0.0, 0.5 + 2.0 * rise, kBall, 2, 2});
    const std::string data = scratch("pyramid.data");
    write_topology(data, atoms, chain_bonds(1, kLoopNodes, true), ring_joints(kLoopNodes));
    // a stiff loop: 1 % short gives a tension of 2, four times the thrust of the upper balls
    load_scene(data, 200.0, 0.99 * l, 1e-3);
    commands({"pair_style nscd", "pair_coeff * * 0.5", "special_bonds lj 0 0 0",
              "group wire id 1:" + std::to_string(kLoopNodes), "group balls type 2",
              "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0",
              "fix g all gravity 1.0 vector 0 0 -1"});
    if (with_loop)
      run("fix w wire wire radius " + num(kWireRadius) + " k_n 100 gamma_n 0.05 k_t 80 "
          "gamma_t 0.02 mu_s 0.5 mu_d 0.4 damp 0.05");
    else
      run("delete_atoms group wire bond yes");
    run("fix solver balls nscd tolerance 1e-9 max_sweeps 1000");
  }
  double top_height() { return position(kLoopNodes + 14)[2]; }
  // The floor's and the wire's vertical loads on the balls, averaged over 50 samples 10 steps
  // apart (the loop still trembles).
  void sample_loads(double &floor_z, double &on_grains)
  {
    const int samples = 50;
    floor_z = on_grains = 0.0;
    for (int k = 0; k < samples; k++) {
      run("run 10");
      floor_z += fix_value("floor", 2) / samples;
      on_grains += fix_value("w", 9) / samples;
    }
  }
  // How many ranks own at least one loop node.
  int ranks_holding_the_loop()
  {
    int mine = 0, all = 0;
    for (int i = 0; i < lmp->atom->nlocal; i++) mine |= lmp->atom->tag[i] <= kLoopNodes;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    return all;
  }
};

TEST_F(WireBoundPyramidTest, LoopHoldsThePyramidAtItsClosedFormHeightOnAnyRankCount)
{
  pyramid(true);
  run("run 1000");
  double floor_z, on_grains;
  sample_loads(floor_z, on_grains);
  const double wire = kLoopNodes * kNodeMass, total = 14 * kBall + wire;
  const double height = 0.5 + 2.0 * std::sqrt(0.5);    // balls touching: top centre height
  std::printf("[ wire-bound pyramid, %d ranks, loop on %d ] floor %.10g (weight %.10g), top %.10g "
              "(closed form %.10g), wire on balls %.10g (wire weight %.6g), kinetic energy %.3g, "
              "atoms %lld, sweeps %g\n",
              ranks(), ranks_holding_the_loop(), floor_z, total, top_height(), height, on_grains,
              wire, kinetic_energy(1, MAXTAGINT), (long long) lmp->atom->natoms, fix_value("solver", 0));
  EXPECT_EQ(lmp->atom->natoms, kLoopNodes + 14);    // no atom lost
  EXPECT_EQ(ranks_holding_the_loop(), ranks());      // the loop crosses every rank boundary
  EXPECT_NEAR(floor_z / -total, 1.0, 1e-6);          // the floor carries balls + wire
  EXPECT_NEAR(on_grains / -wire, 1.0, 1e-6);         // the balls carry the wire
  // the balls stay in touch: the loop's tension (2) exceeds the upper balls' thrust, so
  // it does not stretch (measured: equal to 10 digits on 1, 2 and 4 ranks)
  EXPECT_NEAR(top_height(), height, 1e-6);
  EXPECT_LT(kinetic_energy(1, MAXTAGINT), 1e-10);
}

// The same pyramid with comm_style tiled and `fix balance rcb` every 100 steps (grains,
// loop nodes, their contacts and friction histories change rank during the run): the same
// closed-form forces and height to the same tolerances.
TEST_F(WireBoundPyramidTest, LoopHoldsThePyramidUnderRcbBalance)
{
  commands({"comm_style tiled"});
  pyramid(true);
  commands({"balance 1.0 rcb", "fix lb all balance 100 1.0 rcb", "run 1000"});
  double floor_z, on_grains;
  sample_loads(floor_z, on_grains);
  const double wire = kLoopNodes * kNodeMass, total = 14 * kBall + wire;
  const double height = 0.5 + 2.0 * std::sqrt(0.5), top = top_height();    // collective
  const int holding = ranks_holding_the_loop();
  if (rank() == 0)
    std::printf("[ wire-bound pyramid, rcb, %d ranks, loop on %d ] floor %.10g (weight %.10g), top %.10g "
                "(closed form %.10g)\n",
                ranks(), holding, floor_z, total, top, height);
  EXPECT_EQ(lmp->atom->natoms, kLoopNodes + 14);
  EXPECT_EQ(holding, ranks());    // rcb cuts the loop too
  EXPECT_NEAR(floor_z / -total, 1.0, 1e-6);
  EXPECT_NEAR(on_grains / -wire, 1.0, 1e-6);
  EXPECT_NEAR(top, height, 1e-6);
  EXPECT_LT(kinetic_energy(1, MAXTAGINT), 1e-10);
}

TEST_F(WireBoundPyramidTest, WithoutTheLoopTheBaseSlidesApart)
{
  // the control: the same pyramid without its wire collapses on the frictionless floor
  pyramid(false);
  run("run 1200");
  EXPECT_LT(top_height(), 0.5 + 2.0 * std::sqrt(0.5) - 0.1);    // measured: 0.13 lower
}

// ---------------------------------------------------------------- the wire on walls and the plate

// A straight wire of kNodes nodes (mass kMass, radius kRadius) along x, from x = -1 to 1,
// lying on a floor (fix nscd/wall, friction kMu), with bonds and joints; a ball far away
// (atom kNodes + 1, no gravity) gives fix nscd its grain group. Gravity acts on the wire
// only, along (sin theta, 0, -cos theta) relative to the floor.
class WireOnBoundaryTest : public WireTest {
 protected:
  static constexpr int kNodes = 9;
  static constexpr double kMass = 0.01, kRadius = 0.05, kN = 1000.0, kMu = 0.5, kDamp = 0.02;

  void wire_on_floor(bool floor = true, double y = 0.0, double z = kRadius, bool slab = false)
  {
    std::vector<Point> atoms = straight_chain(kNodes, 0.25, kMass, -1.0, z);
    for (Point &p : atoms) p.y = y;
    atoms.push_back({3.0, 0.0, 0.5, 0.5, 2, 2});
    // instead of the floor, a fixed grain whose top face is at z = 0 (atom kNodes + 2)
    if (slab) atoms.push_back({0.0, 0.0, -0.5, 10.0, 1, 4});
    scene(atoms, kNodes, true, 100.0, 0.25, 0.01);
    commands({"pair_style nscd", "pair_coeff * * 0.5", "special_bonds lj 0 0 0",
              "group wire id 1:" + std::to_string(kNodes), "group balls type 2"});
    if (floor) commands({"fix floor all nscd/wall plane 0 0 0 0 0 1 friction " + num(kMu)});
  }
  // Gravity along (v_gx, v_gy, v_gz): variables, so that a test can tilt it (a fix gravity
  // defined after fix wire would act too late for the subcycle).
  void wire_and_solver(const std::string &gravity = "0 0 -1", const std::string &extra = "")
  {
    std::istringstream g(gravity);
    std::string gx, gy, gz;
    g >> gx >> gy >> gz;
    commands({"variable gx equal " + gx, "variable gy equal " + gy, "variable gz equal " + gz,
              "fix g wire gravity 1.0 vector v_gx v_gy v_gz",
              "fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) +
                  " gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.9 damp " + num(kDamp) + extra,
              "fix solver balls nscd tolerance 1e-9 max_sweeps 500"});
  }
  void tilt(double theta)
  {
    commands({"variable gx equal " + num(std::sin(theta)), "variable gz equal " + num(-std::cos(theta))});
  }
  double mean_node(int d)
  {
    double sum = 0.0;
    for (int k = 1; k <= kNodes; k++) sum += position(k)[d] / kNodes;
    return sum;
  }
  double mean_velocity_x()
  {
    double mine = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (lmp->atom->tag[i] <= kNodes) mine += lmp->atom->v[i][0] / kNodes;
    return summed(mine);
  }
  // The wire resting flat is tilted to tan(theta) = 0.9 mu, where friction must hold it,
  // then to 1.1 mu, where it must slide with dv/dt = A - k v, A = g (sin - mu cos) and the
  // nodes' damping k = C / m. What it measured; `support_x` is the support's reaction along x.
  struct Slope {
    double moved_held, support_x, weight_along, gained, expected;
  };
  Slope tilt_to_slip(double mu, const std::function<double()> &support_x)
  {
    Slope out{};
    run("run 1000");
    const double held = std::atan(0.9 * mu), slides = std::atan(1.1 * mu);
    tilt(held);
    run("run 2000");
    out.moved_held = mean_node(0);
    out.support_x = support_x();
    out.weight_along = kNodes * kMass * std::sin(held);
    tilt(slides);
    run("run 300");
    const double v0 = mean_velocity_x(), T = 0.5, A = std::sin(slides) - mu * std::cos(slides), k = kDamp / kMass;
    run("run 500");
    out.gained = mean_velocity_x() - v0;
    out.expected = (A / k - v0) * (1.0 - std::exp(-k * T));
    return out;
  }
  // tilt_to_slip, printed under `label` and checked: held (moved by the tangential springs'
  // transient only, 2.7e-5 on the floor), the support taking the weight along the slope,
  // sliding with the closed form's gain in velocity.
  void expect_held_then_slides(const std::string &label, double mu, const std::function<double()> &support_x)
  {
    const Slope s = tilt_to_slip(mu, support_x);
    std::printf("[ %s ] held at 0.9 mu: moved %.3g, support along x %.10g (weight along the slope %.10g); "
                "sliding at 1.1 mu: gains %.6g in velocity (closed form %.6g)\n",
                label.c_str(), s.moved_held, s.support_x, s.weight_along, s.gained, s.expected);
    EXPECT_LT(std::abs(s.moved_held), 1e-4);
    EXPECT_NEAR(s.support_x / s.weight_along, 1.0, 1e-6);
    EXPECT_NEAR(s.gained / s.expected, 1.0, 1e-2);
  }
};

// At rest each node sinks into the floor by its own weight over k_n, and the floor carries
// the wire's weight (reported by the wall); every node is one contact.
TEST_F(WireOnBoundaryTest, WireRestsOnTheFloorAtTheSpringOverlapAndTheFloorCarriesIt)
{
  wire_on_floor();
  wire_and_solver();
  run("run 3000");
  const double weight = kNodes * kMass;
  std::printf("[ wire on floor ] floor %.12g (weight %.12g), node z %.10g (closed form %.10g), contacts %g\n",
              -fix_value("floor", 2), weight, position(5)[2], kRadius - kMass / kN, fix_value("w", 11));
  EXPECT_NEAR(fix_value("floor", 2) / -weight, 1.0, 1e-6);    // the wire's force on the floor
  EXPECT_NEAR(fix_value("floor", 0), 0.0, 1e-9);
  for (int k = 1; k <= kNodes; k++) EXPECT_NEAR(position(k)[2], kRadius - kMass / kN, 1e-3 * kMass / kN) << "node " << k;
  EXPECT_EQ(fix_value("w", 11), kNodes);    // wire-boundary contacts
  EXPECT_EQ(fix_value("w", 4), 0.0);        // no wire-grain contact: the ball is far away
  EXPECT_LT(kinetic_energy(1, kNodes), 1e-14);
}

// A ghost cutoff above a quarter of a periodic box puts two images of one node on a rank
// (on 4 ranks, 2 x 2: the ranks beside the wire see it across both their y faces, those
// along it across both x faces). Near the edge of the ghost region an element's other node
// may be there only in the image a box length away; an element to that image lay along the
// wire and pushed it up (nodes settled 0.04-0.06 above a floor for r_w = 0.02). The wire
// must rest as on one rank: each node at r_w - m g / k_n, the floor carrying the weight, no
// sideways drift.
TEST_F(WireOnBoundaryTest, WireRestsOnTheFloorWhenARankHoldsTwoImagesOfItsNodes)
{
  boundary = "p p f";
  const int n = 33;    // x from -4 to 4 in a box of +-5, ghost cutoff 3 > 10 / 4
  std::vector<Point> atoms = straight_chain(n, 0.25, kMass, -4.0, kRadius);
  for (Point &p : atoms) p.y = -2.5;
  scene(atoms, n, true, 100.0, 0.25, 0.01);
  commands({"pair_style nscd", "pair_coeff * * 0.5", "special_bonds lj 0 0 0", "group wire id 1:" + std::to_string(n),
            "group balls empty", "fix floor all nscd/wall plane 0 0 0 0 0 1 friction " + num(kMu)});
  wire_and_solver();
  run("run 200");    // (the faulty element copies had thrown nodes off the floor by then)
  for (int k = 1; k <= n; k++) ASSERT_LT(position(k)[2], 1.01 * kRadius) << "node " << k << " after 200 steps";
  run("run 2800");
  const double rest = kRadius - kMass / kN;
  double lowest = INFINITY, highest = -INFINITY, mean_x = 0.0, mean_y = 0.0;
  for (int k = 1; k <= n; k++) {
    const std::vector<double> x = position(k);
    lowest = std::min(lowest, x[2]), highest = std::max(highest, x[2]);
    mean_x += x[0] / n, mean_y += x[1] / n;
  }
  std::printf("[ wire on floor, two images ] %d ranks: node z %.10g .. %.10g (closed form %.10g), floor %.10g "
              "(weight %.10g), mean x %.3g y %.6g\n", ranks(), lowest, highest, rest, -fix_value("floor", 2),
              n * kMass, mean_x, mean_y);
  EXPECT_NEAR(lowest, rest, 1e-2 * kMass / kN);
  EXPECT_NEAR(highest, rest, 1e-2 * kMass / kN);
  EXPECT_NEAR(fix_value("floor", 2) / -(n * kMass), 1.0, 1e-6);
  EXPECT_NEAR(mean_x, 0.0, 1e-9);    // no net sideways force: the start is symmetric about x = 0
  EXPECT_NEAR(mean_y, -2.5, 1e-9);
  EXPECT_EQ(fix_value("w", 11), n);    // wire-boundary contacts
  EXPECT_EQ(fix_value("w", 3), 0.0);   // wire-wire: none along a straight wire
  EXPECT_LT(kinetic_energy(1, n), 1e-14);
}

// compute wire/contacts: at rest on the floor each node is one row (kind 3, the floor as
// -1), carrying its weight along the floor's normal, at the overlap m g / k_n, sticking;
// as many rows as fix wire counts contacts, each once over the ranks.
TEST_F(WireOnBoundaryTest, WireContactsComputeGivesEachNodeOnTheFloorItsWeight)
{
  wire_on_floor();
  wire_and_solver();
  run("compute wc all wire/contacts");
  EXPECT_TRUE(local_rows("wc").empty());    // before any step
  run("run 3000");
  const std::vector<std::vector<double>> rows = local_rows("wc");
  ASSERT_EQ((int) rows.size(), kNodes);
  EXPECT_EQ(fix_value("w", 11), (double) rows.size());
  double total = 0.0;
  for (int k = 0; k < kNodes; k++) {
    const std::vector<double> &r = rows[k];
    EXPECT_EQ(r[0], k + 1.0);    // the node (rows sorted)
    EXPECT_EQ(r[1], 0.0);
    EXPECT_EQ(r[2], -1.0);       // the first boundary fix
    EXPECT_EQ(r[3], 3.0);        // wire-boundary
    EXPECT_NEAR(r[4], position(k + 1)[0], 1e-12);
    EXPECT_NEAR(r[6], -0.5 * kMass / kN, 1e-9);    // midway between node sphere and floor
    EXPECT_NEAR(r[9], 1.0, 1e-12);                 // normal from the floor to the wire
    EXPECT_NEAR(r[10], kMass, 1e-6 * kMass) << "node " << k + 1;
    EXPECT_NEAR(std::hypot(r[11], r[12], r[13]), 0.0, 1e-9 * kMass);
    EXPECT_NEAR(r[14], kMass / kN, 1e-3 * kMass / kN);
    EXPECT_EQ(r[15], 0.0);    // sticking
    total += r[10];
  }
  EXPECT_NEAR(total, -fix_value("floor", 2), 1e-9 * total);    // as the floor reports it
}

// Elements lying on a grain's face: every row is a wire-grain contact with that grain, two
// ends per element, and the rows' forces on the wire, fn n + f_t, sum to minus the force
// fix wire hands to the grains (both averaged over the substeps), which is the wire's weight.
TEST_F(WireOnBoundaryTest, WireContactsComputeSumsToTheForceOnTheGrain)
{
  wire_on_floor(false, 0.0, kRadius, true);    // on the top face of a fixed slab, atom kNodes + 2
  wire_and_solver();
  run("compute wc all wire/contacts");
  run("run 3000");
  const std::vector<std::vector<double>> rows = local_rows("wc");
  ASSERT_FALSE(rows.empty());
  double sum[3] = {0.0, 0.0, 0.0};
  for (const std::vector<double> &r : rows) {
    EXPECT_EQ(r[2], kNodes + 2.0);    // the slab
    EXPECT_EQ(r[3], 1.0);             // wire-grain
    EXPECT_EQ(r[1], r[0] + 1.0);      // an element's two nodes
    EXPECT_NEAR(r[9], 1.0, 1e-9);     // normal up, out of the face
    for (int d = 0; d < 3; d++) sum[d] += r[10] * r[7 + d] + r[11 + d];
  }
  std::printf("[ wire contacts on a face ] %zu rows, sum of forces on the wire %.12g %.12g %.12g, fix wire on "
              "grains %.12g, weight %.12g\n", rows.size(), sum[0], sum[1], sum[2], fix_value("w", 9), kNodes * kMass);
  EXPECT_EQ(rows.size() % 2, 0u);    // two stretch ends per element on the face
  EXPECT_GE(fix_value("w", 4) * 2, (double) rows.size());    // fix wire counts elements
  for (int d = 0; d < 3; d++) EXPECT_NEAR(sum[d], -fix_value("w", 7 + d), 1e-12) << "axis " << d;
  EXPECT_NEAR(sum[2], kNodes * kMass, 1e-6 * kNodes * kMass);
}

// The floor's friction (mu of fix nscd/wall, static = dynamic for the wire) holds the wire
// on a slope below tan(theta) = mu, with the floor taking the wire's weight along the slope;
// above it the wire slides with acceleration g (sin theta - mu cos theta).
TEST_F(WireOnBoundaryTest, FloorFrictionHoldsTheWireBelowTheSlopeOfMuAndItSlidesAbove)
{
  wire_on_floor();
  wire_and_solver();
  expect_held_then_slides("wire on slope", kMu, [&] { return fix_value("floor", 0); });
}

// The same wire on the flat top face of a grain: every element touches the face with its two
// end spheres, each its own contact, so a node inside the wire is held by two contacts and
// sinks by m g / (2 k_n), an end node by m g / k_n (on the floor every node is one contact).
// The wire comes to rest and the grain carries its weight. With one contact point per
// element (the middle of the touching stretch, or the lower end once it tilts) the wire
// kept rocking (kinetic energy 5e-9) and the grain's reaction was off by 0.3 %.
TEST_F(WireOnBoundaryTest, WireRestsOnAGrainFaceHeldAtEachElementsEnds)
{
  wire_on_floor(false, 0.0, kRadius, true);
  wire_and_solver();
  run("run 3000");
  const double weight = kNodes * kMass;
  auto sunk = [&](int node) { return kRadius - kMass / ((node == 1 || node == kNodes ? 1 : 2) * kN); };
  std::printf("[ wire on a grain face ] force on grains z %.12g (weight %.12g), end node z %.10g "
              "(closed form %.10g), middle node z %.10g (closed form %.10g), kinetic energy %.3g\n",
              fix_value("w", 9), weight, position(1)[2], sunk(1), position(5)[2], sunk(5), kinetic_energy(1, kNodes));
  EXPECT_NEAR(fix_value("w", 9) / -weight, 1.0, 1e-6);    // handed to the grain
  EXPECT_NEAR(force_on(kNodes + 2)[2] / -weight, 1.0, 1e-6);
  EXPECT_NEAR(fix_value("w", 7), 0.0, 1e-9);
  // (the joints' bending springs, 1e-2, shift this by ~1e-9)
  for (int k = 1; k <= kNodes; k++) EXPECT_NEAR(position(k)[2], sunk(k), 1e-3 * kMass / kN) << "node " << k;
  EXPECT_EQ(fix_value("w", 4), kNodes - 1);    // every element touches the face
  EXPECT_LT(kinetic_energy(1, kNodes), 1e-14);
}

// Friction on a grain face (fix wire's mu_s = mu_d = 0.9 here): held below the slope of mu,
// sliding above it as on the floor, the grain taking the weight along the slope.
TEST_F(WireOnBoundaryTest, GrainFaceFrictionHoldsTheWireBelowTheSlopeOfMuAndItSlidesAbove)
{
  wire_on_floor(false, 0.0, kRadius, true);
  wire_and_solver();
  expect_held_then_slides("wire on a grain slope", 0.9, [&] { return fix_value("w", 7); });
}

// grain_friction gives the grains of a type their own wire-grain friction: the slab (type 1)
// at 0.4 holds the wire below the slope of 0.4 and lets it slide above it, where fix wire's
// mu_s 0.9 would hold it.
TEST_F(WireOnBoundaryTest, GrainFrictionOfATypeSetsItsSlope)
{
  wire_on_floor(false, 0.0, kRadius, true);
  wire_and_solver("0 0 -1", " grain_friction 1 0.4 0.4");
  expect_held_then_slides("wire on a grain slope, grain_friction 0.4", 0.4, [&] { return fix_value("w", 7); });
}

// A loading plate (fix nscd/plate, weight W) falls onto the wire lying on the floor and
// rests where each node's springs carry W / n from above and W / n + m g from below.
TEST_F(WireOnBoundaryTest, PlateRestsOnTheWireAtTheClosedFormHeight)
{
  const double W = 1.0;
  wire_on_floor();
  commands({"fix plate wire nscd/plate " + num(2 * kRadius) + " mass " + num(W) + " gravity 1"});
  wire_and_solver();
  // The plate's bounce on the wire's springs decays by e every ~440 steps: at step 9000 (1 rank)
  // the reaction is within 7e-10 of W, the floor's within 7e-10 of W plus the wire, the plate
  // 1.4e-6 of the tolerance from its height and moving at 5e-12 (8000: 8e-9; 12000 before).
  run("run 9000");
  const double from_plate = W / kNodes, weight = kNodes * kMass;
  const double z = 2 * kRadius - (from_plate + kMass) / kN - from_plate / kN;
  std::printf("[ plate on wire ] plate z %.12g (closed form %.12g), reaction %.10g (W %g), floor %.10g\n",
              fix_value("plate", 0), z, fix_value("plate", 2), W, fix_value("floor", 2));
  EXPECT_NEAR(fix_value("plate", 0), z, 1e-3 * from_plate / kN);
  EXPECT_NEAR(fix_value("plate", 2) / W, 1.0, 1e-6);             // grains + wire under the plate
  EXPECT_NEAR(fix_value("floor", 2) / -(W + weight), 1.0, 1e-6);
  EXPECT_LT(std::abs(fix_value("plate", 1)), 1e-7);
}

// A wire parallel to the axis of a cylinder wall, pushed sideways against it by gravity along x:
// each node sinks into the wall by m g / k_n and the wall takes the weight.
TEST_F(WireOnBoundaryTest, CylinderWallHoldsTheWireAgainstSidewaysGravity)
{
  wire_on_floor(false, kRadius, 0.0);    // touching the wall at +y
  commands({"fix silo wire nscd/wall cylinder 0 0 0 1 0 0 " + num(2 * kRadius)});
  wire_and_solver("0 1 0");
  run("run 3000");
  const double weight = kNodes * kMass;
  std::printf("[ wire in cylinder ] wall %.10g (weight %.10g), node y %.10g (closed form %.10g)\n",
              fix_value("silo", 1), weight, position(5)[1], kRadius + kMass / kN);
  EXPECT_NEAR(fix_value("silo", 1) / weight, 1.0, 1e-6);
  for (int k = 1; k <= kNodes; k++) EXPECT_NEAR(position(k)[1], kRadius + kMass / kN, 1e-3 * kMass / kN) << "node " << k;
}

TEST_F(WireOnBoundaryTest, NodeBehindAWallIsANamedError)
{
  wire_on_floor();
  commands({"fix high wire nscd/wall plane 0 0 " + num(2 * kRadius) + " 0 0 1"});
  wire_and_solver();
  const std::string message = error_of("run 0");
  EXPECT_NE(message.find("atom ID 1 is outside the wall"), std::string::npos) << message;
}

// The papers' wire (examples/column: k_elo 5000 on elements of 0.2, nodes of 0.005, k_n
// 2000, gamma_n 2; no node damping) lying on a frictional floor with a ball of mass 0.5
// resting on it, at the NSCD step 0.005 and the fewest substeps fix wire takes as stable
// (substeps stable: 83, against 247 before the rule of 2026-11; substeps auto takes 233,
// the accurate step). Unstable substeps would blow the wire up within a few hundred steps;
// stable ones bring everything to rest with the floor carrying it all.
TEST_F(WireOnBoundaryTest, PapersWireUnderABallAtRestStaysStableAtTheChosenSubsteps)
{
  const int nodes = 11;
  const double l = 0.2, m = 0.005, r_w = 0.05, ball = 0.5;
  std::vector<Point> atoms = straight_chain(nodes, l, m, -1.0, r_w);
  atoms.push_back({0.0, 0.0, 2.0 * r_w + 0.5, ball, 2, 2});
  scene(atoms, nodes, true, 5000.0, l, 0.01);
  commands({"pair_style nscd", "pair_coeff * * 0.5", "special_bonds lj 0 0 0", "timestep 0.005",
            "group wire id 1:" + std::to_string(nodes), "group balls type 2",
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction 0.5", "fix g all gravity 1.0 vector 0 0 -1",
            "fix w wire wire radius " + num(r_w) + " k_n 2000 gamma_n 2 k_t 1500 gamma_t 1 mu_s 0.5",
            "fix solver balls nscd tolerance 1e-9 max_sweeps 500"});
  run("run 0");
  EXPECT_EQ(fix_value("w", 5), 233.0);    // substeps auto: w_max dt_SP <= 0.1
  run("unfix w");
  run("fix w wire wire radius " + num(r_w) + " k_n 2000 gamma_n 2 k_t 1500 gamma_t 1 mu_s 0.5 substeps stable");
  double highest = 0.0;    // kinetic energy over the second half
  for (int k = 0; k < 8; k++) {
    run("run 500");
    if (k >= 4) highest = std::max(highest, kinetic_energy(1, MAXTAGINT));
  }
  const double weight = nodes * m + ball;
  std::printf("[ papers' wire under a ball ] %g substeps; floor %.10g (weight %.10g), kinetic energy %.3g, "
              "ball z %.6g\n", fix_value("w", 5), -fix_value("floor", 2), weight, kinetic_energy(1, MAXTAGINT),
              position(nodes + 1)[2]);
  EXPECT_EQ(fix_value("w", 5), 83.0);
  EXPECT_NEAR(fix_value("floor", 2) / -weight, 1.0, 1e-6);
  // A slow rocking of the ball on the undamped wire stays (~1e-8 at 83 and at 247 substeps);
  // an unstable subcycle would grow by orders of magnitude.
  EXPECT_LT(highest, 1e-6);
  EXPECT_GT(position(nodes + 1)[2], r_w + 0.5);    // the ball lies on the wire, not on the floor
  EXPECT_LT(position(nodes + 1)[2], 2.0 * r_w + 0.5);
}

// Option inertia S: the nodes move as if S times heavier while their weight is unchanged.
// A free wire falls at g / S (closed form z0 - g t^2 / (2 S)), the substep count falls by
// sqrt(S), and a wire at rest on the floor still presses on it with its true weight (its
// dashpots scaled by sqrt(S), it lands as the unscaled wire does instead of bouncing).
TEST_F(WireOnBoundaryTest, InertiaScalesTheDynamicsNotTheWeight)
{
  wire_on_floor(true, 0.0, kRadius + 0.01);    // 0.01 above the floor: falls freely first
  commands({"fix g wire gravity 1.0 vector 0 0 -1",
            "fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) + " gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.9",
            "fix solver balls nscd tolerance 1e-9 max_sweeps 500"});
  run("run 0");
  const double plain_substeps = fix_value("w", 5), plain_stable = fix_value("w", 10);
  run("unfix w");
  run("fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) + " gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.9 inertia 16");
  const double t = 0.5, S = 16.0;    // 500 steps of 0.001: falls 0.0078, touches nothing
  run("run 500");
  std::printf("[ inertia ] substeps %g (without: %g); node 5 fell %.10g (closed form %.10g)\n", fix_value("w", 5),
              plain_substeps, kRadius + 0.01 - position(5)[2], t * t / (2.0 * S));
  EXPECT_NEAR((kRadius + 0.01 - position(5)[2]) / (t * t / (2.0 * S)), 1.0, 0.01);    // (the Gear start lags ~dt)
  EXPECT_EQ(fix_value("w", 5), std::ceil(plain_substeps / 4.0 - 1e-9));
  EXPECT_NEAR(fix_value("w", 10) / plain_stable, 4.0, 1e-9);    // every rate of the wire / sqrt(S)
  // down onto the floor (dashpots scaled: it does not bounce away), at rest there: on 1 rank the
  // floor carries the weight to 8.5e-11 at step 8000 and to round-off (2e-16) from 10000 on
  // (20000 before)
  run("run 10000");
  const double weight = kNodes * kMass;
  EXPECT_NEAR(fix_value("floor", 2) / -weight, 1.0, 1e-6);
  EXPECT_NEAR(position(5)[2], kRadius - kMass / kN, 1e-3 * kMass / kN);
  EXPECT_NE(error_of("fix w2 wire wire inertia 0.5").find("inertia 0.5 must be >= 1"), std::string::npos);
}

// ---- communication between ranks, counted (doc/scaling.md, "Counted") ----

// fix wire counts what its exchanges carry between ranks as the receiving rank gets it. A
// straight wire at rest along x across the cut at x = 0, in the upper half of the box (y =
// 0.25), in a closed box: every ghost node comes from another rank, and in each substep it
// gets its position and velocity (6 doubles) and hands back its force (3): 72 bytes per ghost
// node, all ranks' ghost nodes counted by hand from their atoms. The messages go straight
// from the owners to the holders of copies and back (nscd_copy_exchange.h): on 2 ranks (2 x 1)
// each rank receives its ghosts in one message and sends their forces back in one, 4 in all;
// on 4 ranks (2 x 2) the two upper ranks exchange with each other as on 2 and each empty rank
// below receives from both: 12 (LAMMPS' swaps relayed the other upper rank's nodes through the
// one above, 8 messages in two rounds). On 1 rank no ghost, nothing.
TEST_F(WireTest, CommunicationBetweenRanksIsCountedAsByHand)
{
  std::vector<Point> nodes = straight_chain(21, 0.2, 0.01, -2.0);
  for (Point &p : nodes) p.y = 0.25;
  scene(nodes, 21, true, 100.0, 0.2, 0.05);
  commands({"fix w all wire k_n 0", "thermo_style custom step", "thermo 1000", "run 10"});
  const auto *fix = dynamic_cast<FixWire *>(lmp->modify->get_fix_by_id("w"));
  const std::vector<NSCD_NS::NSCDCommCount::Tally> all = fix->comm_count().summed(MPI_COMM_WORLD);
  const double ghosts = summed(lmp->atom->nghost), substeps = (double) fix->substeps();
  // by hand: per substep each rank receives one message from every other rank owning some of
  // its ghost nodes (their positions and velocities) and one from every other rank holding
  // copies of its nodes (their forces), i.e. twice the (holder, other owner) pairs
  std::vector<int> owner_mine((size_t) lmp->atom->natoms + 1, -1), owner((size_t) lmp->atom->natoms + 1);
  for (int i = 0; i < lmp->atom->nlocal; i++) owner_mine[lmp->atom->tag[i]] = rank();
  MPI_Allreduce(owner_mine.data(), owner.data(), (int) owner.size(), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  std::vector<int> sources;
  for (int i = lmp->atom->nlocal; i < lmp->atom->nlocal + lmp->atom->nghost; i++)
    if (owner[lmp->atom->tag[i]] != rank()) sources.push_back(owner[lmp->atom->tag[i]]);
  std::sort(sources.begin(), sources.end());
  const double pairs = summed((double) (std::unique(sources.begin(), sources.end()) - sources.begin()));
  const double messages = 2.0 * pairs;
  if (ranks() == 2) {
    EXPECT_EQ(messages, 4.0);    // as LAMMPS' comm sent them before (doc/wire_speed.md, "Speed")
  }
  if (rank() == 0)
    std::printf("[ INFO     ] %d ranks: %g ghost nodes, %g substeps: %g messages, %g bytes in the substeps\n",
                ranks(), ghosts, substeps, all[FixWire::COMM_SUBSTEP].messages, all[FixWire::COMM_SUBSTEP].bytes);
  EXPECT_GT(substeps, 10.0);
  if (ranks() > 1) {
    EXPECT_GE(ghosts, 10.0);    // 3.0 of ghost cutoff: the nodes within 3.0 of a cut
  }
  EXPECT_EQ(all[FixWire::COMM_SUBSTEP].bytes, 72.0 * ghosts * substeps);
  EXPECT_EQ(all[FixWire::COMM_SUBSTEP].messages, messages * substeps);
}

// The same scene on all ranks of this run and on rank 0 alone (its own communicator, as
// NSCDTest.RestartWrittenOnOneRankContinuesOnAll does): a wire of kNodes nodes lying across
// the rank cuts (x = 0; y = 0 on 4 ranks) on a floor with friction, pressed from above by a
// slab (a grain held by fix move) that drags it along x at speed 1 over 400 steps: wire-grain
// and wire-floor contacts with friction memories on both sides of the cuts, nodes changing
// rank and the neighbour lists rebuilt during the run. The states and the reactions on the
// slab and the floor must agree to round-off (the forces on a node are summed in another order
// when its copies lie on several ranks); a copy's force lost or counted twice, or a copy at
// the wrong periodic image, moves the wire by far more.
class WireAcrossRanksTest : public WireOnBoundaryTest {
 protected:
  // The deck's atoms, shifted by `offset` along x and wrapped into the box of +-5.
  std::vector<Point> drag_atoms(double offset) const
  {
    auto wrap = [](double x) { return x >= 5.0 ? x - 10.0 : x < -5.0 ? x + 10.0 : x; };
    std::vector<Point> atoms = straight_chain(kNodes, 0.25, kMass, -1.0, kRadius - kMass / kN);
    for (Point &p : atoms) p.y = 0.15 * p.x + 0.05, p.x = wrap(p.x + offset);
    atoms.push_back({3.0, 3.0, 0.5, 0.5, 2, 2});                                     // a ball, far away
    atoms.push_back({wrap(offset + 0.1), 0.0, 2.0 * kRadius + 0.5 - 0.001, 10.0, 1, 4});    // the slab, on the wire
    return atoms;
  }
  std::vector<std::string> drag_deck(const std::string &data, const std::string &shapes) const
  {
    return {"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array", "boundary " + boundary,
            "processors * * 1", "shapes read " + shapes, "read_data " + data, "pair_style nscd", "pair_coeff * * 0.5",
            "special_bonds lj 0 0 0", "bond_style wire", "bond_coeff 1 100 0.25", "angle_style wire",
            "angle_coeff 1 0.01", "neighbor 0.3 bin", "neigh_modify every 1 delay 0 check yes",
            "comm_modify cutoff 3.0", "timestep 0.001", "group wire id 1:" + std::to_string(kNodes),
            "group balls type 2", "group slab id " + std::to_string(kNodes + 2),
            "fix floor all nscd/wall plane 0 0 0 0 0 1 friction " + num(kMu),
            "fix g wire gravity 1.0 vector 0.3 0.2 -1",
            "fix w wire wire radius " + num(kRadius) + " k_n " + num(kN) +
                " gamma_n 0.5 k_t 800 gamma_t 0.2 mu_s 0.9 mu_d 0.7 damp " + num(kDamp),
            "fix solver balls nscd tolerance 1e-9 max_sweeps 500", "run 100",
            "fix drag slab move linear 1.0 0.0 0.0", "run 400"};
  }
  // x, v of every atom, the wire's force on the slab (its f: fix move leaves it), the total
  // on grains (f_w[8-10]), the floor's force, the neighbour builds of the last run (with its
  // setup's), the memories migrated and the closed wire-grain and wire-floor contacts.
  std::vector<double> drag_outcome(MPI_Comm world)
  {
    const int atoms = kNodes + 2;
    std::vector<double> mine(6 * atoms + 3, 0.0), all(mine.size());
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      const int k = (int) lmp->atom->tag[i] - 1;
      for (int d = 0; d < 3; d++) mine[6 * k + d] = lmp->atom->x[i][d], mine[6 * k + 3 + d] = lmp->atom->v[i][d];
      if (k == atoms - 1)
        for (int d = 0; d < 3; d++) mine[6 * atoms + d] = lmp->atom->f[i][d];
    }
    MPI_Allreduce(mine.data(), all.data(), (int) mine.size(), MPI_DOUBLE, MPI_SUM, world);
    for (int d = 0; d < 3; d++) all.push_back(fix_value("w", 7 + d));
    for (int d = 0; d < 3; d++) all.push_back(fix_value("floor", d));
    const auto *fix = dynamic_cast<FixWire *>(lmp->modify->get_fix_by_id("w"));
    double migrated = fix->memories_migrated(), total = 0.0;
    MPI_Allreduce(&migrated, &total, 1, MPI_DOUBLE, MPI_SUM, world);
    all.push_back((double) lmp->neighbor->ncalls);
    all.push_back(total);
    all.push_back(fix_value("w", 4));    // closed wire-grain contacts
    all.push_back(fix_value("w", 11));   // closed wire-boundary contacts
    return all;
  }
  // Runs the deck on all ranks and on rank 0 alone and compares; `tolerance` on positions,
  // velocities and forces, relative to the largest of each.
  void expect_as_on_one_rank(double offset, double tolerance)
  {
    const std::string data = scratch("drag.data"), shapes = scratch("shapes");
    write_data(data, drag_atoms(offset), kNodes, true);
    if (rank() == 0) std::ofstream(shapes) << kShapes;
    MPI_Barrier(MPI_COMM_WORLD);
    commands(drag_deck(data, shapes));
    const std::vector<double> here = drag_outcome(MPI_COMM_WORLD);
    std::vector<double> alone_outcome(here.size(), 0.0);
    on_first_ranks(1, [&](MPI_Comm alone) {
      commands(drag_deck(data, shapes));
      alone_outcome = drag_outcome(alone);
    });
    MPI_Bcast(alone_outcome.data(), (int) alone_outcome.size(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    const int atoms = kNodes + 2, n = (int) here.size();
    double scale[3] = {0.0, 0.0, 0.0}, worst[3] = {0.0, 0.0, 0.0};    // positions, velocities, forces
    auto part = [&](int k) { return k < 6 * atoms ? (k % 6) / 3 : 2; };
    for (int k = 0; k < n - 4; k++) scale[part(k)] = std::max(scale[part(k)], std::fabs(alone_outcome[k]));
    for (int k = 0; k < n - 4; k++)
      worst[part(k)] = std::max(worst[part(k)], std::fabs(here[k] - alone_outcome[k]) / scale[part(k)]);
    if (rank() == 0)
      std::printf("[ INFO     ] %d ranks against 1: largest difference relative to the largest value: x %.3g, v %.3g, "
                  "forces %.3g (slab %.6g %.6g %.6g, floor %.6g %.6g %.6g; %g neighbour builds, %g memories "
                  "migrated, %g wire-grain and %g wire-floor contacts)\n", ranks(), worst[0], worst[1], worst[2],
                  here[6 * atoms], here[6 * atoms + 1], here[6 * atoms + 2], here[6 * atoms + 6],
                  here[6 * atoms + 7], here[6 * atoms + 8], here[n - 4], here[n - 3], here[n - 2], here[n - 1]);
    for (int k = 0; k < 3; k++) EXPECT_LE(worst[k], tolerance) << "part " << k << " (x, v, forces)";
    EXPECT_GE(here[n - 4], 2.0);    // the drag run's setup and a rebuild during it (at least)
    EXPECT_GE(here[n - 2], 8.0);    // the slab presses on every element
    EXPECT_EQ(here[n - 1], kNodes);
    // the slab drags the wire over the floor, which takes mu times its normal force along x
    EXPECT_NEAR(here[6 * atoms + 6] / -here[6 * atoms + 8], kMu, 1e-3 * kMu);
    if (ranks() > 1) {
      EXPECT_GT(here[n - 3], 0.0);    // memories moved with nodes changing rank
    }
  }
};

TEST_F(WireAcrossRanksTest, DraggedWireFollowsTheOneRankTrajectoryToRoundOff) { expect_as_on_one_rank(0.0, 1e-9); }

// The same across the periodic boundary x = +-5 (a rank boundary on 2 and 4 ranks too; the
// ghost cutoff 3 above a quarter of the box: two images of a node on one rank).
TEST_F(WireAcrossRanksTest, DraggedWireAcrossAPeriodicBoundaryFollowsTheOneRankTrajectory)
{
  boundary = "p p f";
  expect_as_on_one_rank(5.0, 1e-9);
}
