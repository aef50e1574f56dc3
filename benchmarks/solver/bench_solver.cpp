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

}    // namespace

BENCHMARK_MAIN();
