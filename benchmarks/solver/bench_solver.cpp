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

// Micro-benchmarks of the contact solver. Each prints its accuracy beside its speed:
//   build/benchmarks/solver/bench_solver
#include "solver/contact_problem.h"
#include "solver/local_coulomb.h"
#include "solver/rigid_motion.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

using namespace nscd;

namespace {

struct LocalProblem {
  Mat3 W, W_inverse;
  Vec3 u_free;
  double mu;
};

// Random SPD blocks and free velocities; `regime` keeps those the solver puts in it.
std::vector<LocalProblem> local_problems(ContactRegime regime, std::size_t count)
{
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<LocalProblem> problems;
  while (problems.size() < count) {
    Mat3 L;
    for (int k = 0; k < 9; ++k) L.data()[k] = uniform(random);
    LocalProblem p;
    p.W = L * L.transpose() + 0.2 * Mat3::Identity();
    p.W_inverse = p.W.inverse();
    p.u_free = Vec3(uniform(random), uniform(random), uniform(random));
    p.mu = 0.1 + std::abs(uniform(random));
    if (solve_local_coulomb(p.W, p.W_inverse, p.u_free, p.mu).regime == regime)
      problems.push_back(p);
  }
  return problems;
}

void local_solve(benchmark::State &state, ContactRegime regime)
{
  const std::vector<LocalProblem> problems = local_problems(regime, 1024);
  std::size_t k = 0;
  double worst = 0.0;
  for (auto _ : state) {
    const LocalProblem &p = problems[k++ % problems.size()];
    const LocalSolution s = solve_local_coulomb(p.W, p.W_inverse, p.u_free, p.mu);
    benchmark::DoNotOptimize(s);
  }
  for (const LocalProblem &p : problems) {
    const Vec3 P = solve_local_coulomb(p.W, p.W_inverse, p.u_free, p.mu).impulse;
    worst = std::max(worst, coulomb_residual(p.W, p.u_free, p.mu, P, p.W(0, 0)) / p.u_free.norm());
  }
  state.counters["worst_rel_residual"] = worst;
}
void BM_LocalSolveStick(benchmark::State &state) { local_solve(state, ContactRegime::stick); }
void BM_LocalSolveSlip(benchmark::State &state) { local_solve(state, ContactRegime::slip); }
BENCHMARK(BM_LocalSolveStick);
BENCHMARK(BM_LocalSolveSlip);

// A column of `levels` cubes (mass 1, half size 0.5) on a floor, four corner contacts per
// interface, friction mu, all at rest and touching: one cold-start solve.
ContactProblem box_column(int levels, double mu, double dt)
{
  ContactProblem problem;
  const Vec3 moments = Vec3::Constant(1.0 / 6.0);
  for (int level = 0; level < levels; ++level) {
    SolverBody body;
    body.position = Vec3(0.0, 0.0, 0.5 + level);
    body.inv_mass = 1.0;
    body.inv_inertia = world_inverse_inertia(moments, Quat::Identity());
    body.external_impulse = Vec3(0.0, 0.0, -9.81 * dt);
    problem.bodies.push_back(body);
    for (const double sx : {-0.5, 0.5})
      for (const double sy : {-0.5, 0.5}) {
        Contact contact;
        contact.body_i = level;
        contact.body_j = level == 0 ? kEnvironment : level - 1;
        contact.point = Vec3(sx, sy, level);
        contact.friction = mu;
        problem.contacts.push_back(contact);
      }
  }
  return problem;
}

// Args: levels, -log10(tolerance), 100 mu.
void BM_ColumnColdSolve(benchmark::State &state)
{
  const int levels = static_cast<int>(state.range(0));
  SolverOptions options;
  options.dt = 1e-3;
  options.tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  options.max_sweeps = 1000000;
  const double mu = 0.01 * static_cast<double>(state.range(2));
  const ContactProblem original = box_column(levels, mu, options.dt);
  ContactProblem problem;
  SolveReport report;
  for (auto _ : state) {
    problem = original;    // copies outside the solver; the solve itself does not allocate
    report = solve(problem, options);
  }
  // Accuracy: relative error of the floor reaction against the column weight.
  double floor = 0.0;
  for (const Contact &contact : problem.contacts)
    if (contact.body_j == kEnvironment) floor += contact.impulse.z();
  const double weight = levels * 9.81 * options.dt;
  state.counters["sweeps"] = report.sweeps;
  state.counters["residual"] = report.residual;
  state.counters["floor_rel_err"] = std::abs(floor - weight) / weight;
  state.counters["max_overlap"] = report.terms.max_interpenetration;
  state.counters["ns_per_contact_sweep"] = benchmark::Counter(
      static_cast<double>(report.sweeps) * static_cast<double>(problem.contacts.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ColumnColdSolve)
    ->ArgsProduct({{4}, {2, 4, 6, 8, 10}, {0, 50}})
    ->Unit(benchmark::kMillisecond);

// A pile of 384 spheres (radius 0.5, mass 1) in face-centred cubic order, 8 x 8 x 12 lattice
// sites with i + j + k even, spacing 1/sqrt(2): every touching pair (distance 1) is a
// contact, plus the floor and the four side walls; friction mu, gravity, at rest. Lattice
// positions are jittered by +-1e-3 so normals are not axis-aligned. ~2000 contacts, the size
// of the piles the LAMMPS runs solve.
ContactProblem sphere_pile(double mu, double dt)
{
  constexpr int nx = 8, ny = 8, nz = 12;
  const double spacing = 1.0 / std::sqrt(2.0), radius = 0.5;
  const double moment = 0.4 * radius * radius;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  ContactProblem problem;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if ((i + j + k) % 2 != 0) continue;
        SolverBody body;
        body.position = Vec3(i * spacing + jitter(random), j * spacing + jitter(random),
                             radius + k * spacing + jitter(random));
        body.inv_mass = 1.0;
        body.inv_inertia = (1.0 / moment) * Mat3::Identity();
        body.external_impulse = Vec3(0.0, 0.0, -9.81 * dt);
        problem.bodies.push_back(body);
      }
  const double low = -radius, high_x = (nx - 1) * spacing + radius, high_y = (ny - 1) * spacing + radius;
  const int n = static_cast<int>(problem.bodies.size());
  auto add = [&](int a, int b, const Vec3 &point, const Vec3 &normal, double gap) {
    Contact contact;
    contact.body_i = a;
    contact.body_j = b;
    contact.point = point;
    contact.normal = normal;
    contact.gap = gap;
    contact.friction = mu;
    problem.contacts.push_back(contact);
  };
  for (int a = 0; a < n; ++a) {
    const Vec3 x = problem.bodies[a].position;
    for (int b = 0; b < a; ++b) {
      const Vec3 d = x - problem.bodies[b].position;
      const double distance = d.norm();
      if (distance < 2.0 * radius + 0.05)
        add(a, b, x - radius * d / distance, d / distance, distance - 2.0 * radius);
    }
    const Vec3 walls[5] = {Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
    const double gaps[5] = {x.z() - radius, x.x() - radius - low, high_x - x.x() - radius,
                            x.y() - radius - low, high_y - x.y() - radius};
    for (int w = 0; w < 5; ++w)
      if (gaps[w] < 0.05) add(a, kEnvironment, x - radius * walls[w], walls[w], gaps[w]);
  }
  return problem;
}

// Cost of one sweep and of one residual evaluation on the pile (mu = 0.5), mid-solve.
void BM_PileSweep(benchmark::State &state)
{
  SolverOptions options;
  options.dt = 1e-3;
  ContactProblem problem = sphere_pile(0.5, options.dt);
  problem.prepare(options);
  for (int k = 0; k < 20; ++k) problem.sweep();
  for (auto _ : state) problem.sweep();
  state.counters["contacts"] = static_cast<double>(problem.contacts.size());
  state.counters["ns_per_contact"] = benchmark::Counter(
      static_cast<double>(problem.contacts.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PileSweep)->Unit(benchmark::kMicrosecond);

void BM_PileResidual(benchmark::State &state)
{
  SolverOptions options;
  options.dt = 1e-3;
  ContactProblem problem = sphere_pile(0.5, options.dt);
  problem.prepare(options);
  for (int k = 0; k < 20; ++k) problem.sweep();
  for (auto _ : state) benchmark::DoNotOptimize(problem.residual_terms());
  state.counters["ns_per_contact"] = benchmark::Counter(
      static_cast<double>(problem.contacts.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PileResidual)->Unit(benchmark::kMicrosecond);

// One step of the pile to tolerance 1e-4, warm-started from the converged impulses of a
// step with 20 % weaker gravity (a load change, ~ the sweeps of a step in a LAMMPS run).
// Args: check_every.
void BM_PileWarmSolve(benchmark::State &state)
{
  SolverOptions options;
  options.dt = 1e-3;
  options.tolerance = 1e-4;
  options.max_sweeps = 100000;
  options.check_every = static_cast<int>(state.range(0));
  ContactProblem original = sphere_pile(0.5, options.dt);
  {
    ContactProblem lighter = original;
    for (SolverBody &body : lighter.bodies) body.external_impulse *= 0.8;
    SolverOptions tight = options;
    tight.tolerance = 1e-8;
    tight.check_every = 1;
    solve(lighter, tight);
    for (std::size_t c = 0; c < original.contacts.size(); ++c)
      original.contacts[c].impulse = lighter.contacts[c].impulse;
  }
  ContactProblem problem;
  SolveReport report;
  for (auto _ : state) {
    problem = original;
    report = solve(problem, options);
  }
  state.counters["sweeps"] = report.sweeps;
  state.counters["residual"] = report.residual;
  state.counters["contacts"] = static_cast<double>(problem.contacts.size());
}
BENCHMARK(BM_PileWarmSolve)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);

}    // namespace

BENCHMARK_MAIN();
