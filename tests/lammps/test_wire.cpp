// bond_style wire, angle_style wire, fix wire and compute wire/local against closed forms:
// a pulled wire, a cantilever, a hanging chain, a wire resting on a fixed grain, the
// stability-limit error and restart continuation. Units are LJ-like, g = 1.
#include "lammps_fixture.h"

#include "angle.h"
#include "bond.h"
#include "compute.h"
#include "fix.h"
#include "force.h"
#include "modify.h"

#include <cmath>
#include <fstream>
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
)";

struct Point {
  double x, y, z, mass;
  int type = 1;
  int shape = 0;
};
}    // namespace

class WireTest : public LammpsTest {
 protected:
  // A data file for `atom_style hybrid spheropolyhedron angle`: atoms in order, the first
  // `chain` of them joined into one open wire (bonds, and angles if `angles`).
  void write_data(const std::string &path, const std::vector<Point> &atoms, int chain, bool angles,
                  double box = 5.0)
  {
    if (rank() != 0) return;
    const int nbonds = chain - 1, nangles = angles ? chain - 2 : 0;
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
    if (nbonds > 0) {
      out << "\nBonds\n\n";
      for (int k = 1; k <= nbonds; k++) out << k << " 1 " << k << " " << k + 1 << "\n";
    }
    if (nangles > 0) {
      out << "\nAngles\n\n";
      for (int k = 1; k <= nangles; k++) out << k << " 1 " << k << " " << k + 1 << " " << k + 2 << "\n";
    }
  }

  // Reads the data file with the wire styles set up (no pair interactions between nodes).
  void scene(const std::vector<Point> &atoms, int chain, bool angles, double k_elo, double r0,
             double k_rot = 0.0, const std::string &string_option = "")
  {
    const std::string data = scratch("wire.data");
    write_data(data, atoms, chain, angles);
    MPI_Barrier(MPI_COMM_WORLD);
    commands({"units lj", "atom_style hybrid spheropolyhedron angle", "atom_modify map array",
              "boundary f f f"});
    if (rank() == 0) std::ofstream(scratch("shapes")) << kShapes;
    MPI_Barrier(MPI_COMM_WORLD);
    commands({"shapes read " + scratch("shapes"), "read_data " + data, "pair_style zero 1.0",
              "pair_coeff * *", "bond_style wire", "bond_coeff 1 " + num(k_elo) + " " + num(r0) + string_option,
              "angle_style wire", "angle_coeff 1 " + num(k_rot), "neighbor 0.3 bin",
              "timestep 0.001"});
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
    return lmp->modify->fix[lmp->modify->find_fix(id.c_str())]->compute_vector(index);
  }
  // Rows of compute wire/local `id` (computed now).
  std::vector<std::vector<double>> wire_rows(const std::string &id)
  {
    Compute *c = lmp->modify->compute[lmp->modify->find_compute(id.c_str())];
    c->compute_local();
    std::vector<std::vector<double>> rows;
    for (int r = 0; r < c->size_local_rows; r++)
      rows.emplace_back(c->array_local[r], c->array_local[r] + c->size_local_cols);
    return rows;
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
  EXPECT_NEAR(lmp->force->bond->energy, 0.5, 1e-12);
  // compute bond/local goes through single(): same energy and force
  Compute *c = lmp->modify->compute[lmp->modify->find_compute("bl")];
  c->compute_local();
  ASSERT_EQ(c->size_local_rows, 1);
  EXPECT_NEAR(c->array_local[0][1], 0.5, 1e-12);
  EXPECT_NEAR(std::fabs(c->array_local[0][2]), 10.0, 1e-10);
}

TEST_F(WireTest, StringBondCarriesNoCompressionAndPlainBondDoes)
{
  scene({{0, 0, 0, 1}, {0.9, 0, 0, 1}}, 2, false, 100.0, 1.0, 0.0, " string yes");
  run("run 0");
  EXPECT_EQ(force_on(1)[0], 0.0);
  EXPECT_EQ(lmp->force->bond->energy, 0.0);
  run("bond_coeff 1 100 1 string no");
  run("run 0");
  EXPECT_NEAR(force_on(1)[0], -10.0, 1e-10);    // pushed apart
  EXPECT_NEAR(lmp->force->bond->energy, 0.5, 1e-12);
  EXPECT_NE(error_of("bond_coeff 1 -1 1"), "");
  EXPECT_NE(error_of("bond_coeff 1 1 0"), "");
}

TEST_F(WireTest, AngleMomentIsKrotTimesNodeAngle)
{
  // joint bent by nu = 0.3 at node 2: energy k nu^2 / 2, end forces k nu / l perpendicular
  const double nu = 0.3, k = 2.0, l = 0.5;
  scene({{-l, 0, 0, 1}, {0, 0, 0, 1}, {l * std::cos(nu), l * std::sin(nu), 0, 1}}, 3, true, 0.0, l, k);
  commands({"compute al all angle/local theta eng", "run 0"});
  EXPECT_NEAR(lmp->force->angle->energy, 0.5 * k * nu * nu, 1e-12);
  const std::vector<double> f1 = force_on(1), f3 = force_on(3);
  EXPECT_NEAR(std::hypot(f1[0], f1[1]), k * nu / l, 1e-10);
  EXPECT_NEAR(f1[0], 0.0, 1e-12);    // perpendicular to the first element
  EXPECT_NEAR(std::hypot(f3[0], f3[1]), k * nu / l, 1e-10);
  EXPECT_LT(f1[1], 0.0);    // straightening: end 1 pushed to -y (to follow the bend of 3)
  Compute *c = lmp->modify->compute[lmp->modify->find_compute("al")];
  c->compute_local();
  EXPECT_NEAR(c->array_local[0][0], 180.0 - nu * 180.0 / M_PI, 1e-9);    // LAMMPS angle, degrees
  EXPECT_NEAR(c->array_local[0][1], 0.5 * k * nu * nu, 1e-12);           // single()
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
  const auto rows = wire_rows("el");
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
  // Tip load F: delta = F l^3 / EI * (N-1) N (2N-1) / 6 (doc/wire_model.md section 2).
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
  const auto rows = wire_rows("el");
  double lowest = INFINITY;
  for (const auto &r : rows) lowest = std::min(lowest, r[3]);
  std::printf("[ catenary ] lowest tension %.6g, H = %.6g\n", lowest, c);
  EXPECT_NEAR(lowest / c, 1.0, 1e-2);
  // at rest: kinetic energy of the nodes tiny
  double ke = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    for (int d = 0; d < 3; d++) ke += 0.5 * lmp->atom->rmass[i] * lmp->atom->v[i][d] * lmp->atom->v[i][d];
  EXPECT_LT(ke, 1e-10);
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
  // On a ball: one smooth contact point per element. (On a flat face the contact point of
  // an element jumps between its middle and its lower end as it tilts, and a 5-node wire
  // keeps chattering at ~1e-3 of its weight: see doc/fix_wire.md, restrictions.)
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

TEST_F(WireTest, BadOptionsAndPartnersAreNamedErrors)
{
  scene(straight_chain(3, 0.1, 0.01), 3, true, 1e2, 0.1, 1.0);
  run("group wire id 1:3");
  EXPECT_NE(error_of("fix w wire wire k_n -1").find("k_n"), std::string::npos);
  EXPECT_NE(error_of("fix w wire wire k_n 1 mu_s 0.2 mu_d 0.5").find("mu"), std::string::npos);
  EXPECT_NE(error_of("fix w wire wire bogus 1").find("unknown keyword"), std::string::npos);
  run("bond_style harmonic");
  run("bond_coeff 1 1 0.1");
  run("fix w wire wire");
  EXPECT_NE(error_of("run 1").find("bond_style wire"), std::string::npos);
}
