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

// Sweeps per step of the solver methods on time-stepped scenes (a plain table, not Google
// Benchmark: every number comes from one deterministic run).
//
//   build/benchmarks/solver/solver_methods [--tol 1e-4] [--steps 50] [--scene NAME]...
//                                          [--method NAME]...
//   build/benchmarks/solver/solver_methods --settle   (pours the random pile once and
//                                                      writes benchmarks/solver/pile_324.state)
//
// Per scene and method: the first step solved cold (the same problem for every method), the
// mean and maximum sweeps of the later steps, each warm-started from the method's own
// answers of the step before (so a method's inaccuracies come back as work in the next
// steps), the mean residual reached and the solve time per step. --ramp R multiplies the
// load by 1 + R k in step k; --verbose prints every step, --trace N the residual after every
// sweep of step N.
// Error: the cold step and the last step are also solved by plain Gauss-Seidel to --ref-tol
// (default 1e-9) from the same state; "err cold"/"err last" is the largest difference of the
// end-of-step velocities over the bodies (|dv| + |dw| L, L the body's bounding size) in
// units of |g| dt, the velocity one step of gravity gives.
#include "grain_scene.h"

#include "solver/rigid_motion.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace nscd;
using namespace nscd::bench;

namespace {

bool verbose = false;
double reference_tolerance = 1e-9;
int trace_step = -1, trace_sweeps = 100;
const std::string kPileState = std::string(NSCD_SOURCE_DIR) + "/benchmarks/solver/pile_324.state";

GrainScene random_pile() { return random_grain_pour(6, 6, 9, 10.0, 0.5); }

struct Method {
  std::string name;
  std::function<void(SolverOptions &)> configure;
  int sort_by_height = 0;    // GrainScene::sort_by_height
};

std::vector<Method> all_methods()
{
  const auto with = [](Acceleration acceleration, double cell, int every = 1) {
    return [=](SolverOptions &o) {
      o.acceleration = acceleration;
      o.coarse_cell = cell;
      o.coarse_every = every;
    };
  };
  return {
      {"gs", with(Acceleration::none, 0.0)},
      {"nncg", with(Acceleration::nncg, 0.0)},
      {"nesterov", with(Acceleration::nesterov, 0.0)},
      {"gs+coarse", with(Acceleration::none, 2.0)},
      {"gs+coarse1", with(Acceleration::none, 1.0)},
      {"nesterov+coarse", with(Acceleration::nesterov, 2.0)},
      {"nesterov+coarse/4", with(Acceleration::nesterov, 2.0, 4)},
      // as fix nscd checks by default: the residual every 4 sweeps
      {"gs/check4", [](SolverOptions &o) { o.check_every = 4; }},
      {"nesterov/check4", [](SolverOptions &o) {
         o.acceleration = Acceleration::nesterov;
         o.check_every = 4;
       }},
      {"anderson/check4", [](SolverOptions &o) {
         o.acceleration = Acceleration::anderson;
         o.check_every = 4;
       }},
      {"nesterov+coarse/check4", [](SolverOptions &o) {
         o.acceleration = Acceleration::nesterov;
         o.coarse_cell = 2.0;
         o.check_every = 4;
       }},
      // sweep orders and relaxation, plain and with momentum
      {"gs-up", with(Acceleration::none, 0.0), 1},
      {"gs-down", with(Acceleration::none, 0.0), -1},
      {"gs-fb", [](SolverOptions &o) { o.order = SweepOrder::forward_backward; }},
      {"gs-shuffled", [](SolverOptions &o) { o.order = SweepOrder::shuffled; }},
      {"gs-omega0.8", [](SolverOptions &o) { o.relaxation = 0.8; }},
      {"nesterov-up", with(Acceleration::nesterov, 0.0), 1},
      {"nesterov-down", with(Acceleration::nesterov, 0.0), -1},
  };
}

// Prints the residual after every sweep of one step's solve (the loop of solve() without
// its safeguards, the coarse correction after every coarse_every sweeps), without changing
// the scene.
void trace_solve(GrainScene &scene, const SolverOptions &options)
{
  ContactProblem problem;
  scene.build(problem, options.dt);
  if (scene.warm_start) scene.cache.apply(problem.contacts);
  problem.prepare(options);
  for (int sweep = 0; sweep <= trace_sweeps; ++sweep) {
    if (sweep > 0) {
      problem.sweep();
      problem.accelerate(problem.acceleration_terms());
    }
    const ResidualTerms terms = problem.residual_terms();
    double after = 0.0;
    if (sweep > 0 && options.coarse_cell > 0.0 && sweep % options.coarse_every == 0) {
      problem.coarse_correction();
      after = problem.residual_terms().residual();
    }
    std::printf("    sweep %d residual %.3e (after coarse %.3e) active %ld sliding %ld\n", sweep,
                terms.residual(), after, terms.active, terms.sliding);
  }
}

struct SceneCase {
  std::string name;
  std::function<GrainScene()> make;
  double dt = 0.005;
};

GrainScene settled_pile()
{
  GrainScene scene = random_pile();
  if (!scene.read_state(kPileState))
    std::fprintf(stderr, "no settled pile in %s: run with --settle first\n", kPileState.c_str());
  return scene;
}

std::vector<SceneCase> all_scenes()
{
  return {
      {"tower20", [] { return box_tower(20, 0.5); }},
      {"pyramid10", [] { return box_pyramid(10, 0.5); }},
      {"column1d20", [] { return sphere_column(20, 1, 1000.0, 1.0); }},
      {"column1d40", [] { return sphere_column(40, 1, 1000.0, 1.0); }},
      {"column2d20", [] { return sphere_column(20, 3, 1000.0, 1.0); }},
      {"column2d40", [] { return sphere_column(40, 3, 1000.0, 1.0); }},
      {"column2d20mu0", [] { return sphere_column(20, 3, 1000.0, 0.0); }},
      {"column2d20m1", [] { return sphere_column(20, 3, 1.0, 1.0); }},
      {"pile", settled_pile},
      {"pile+plate", [] {
         GrainScene scene = settled_pile();
         add_plate_over_pile(scene, 10.0, 50.0);
         return scene;
       }},
  };
}

// The velocity error of `solved` (the scene after a step of some method) against plain
// Gauss-Seidel to reference_tolerance from `before` (the scene before that step), in |g| dt.
double velocity_error(GrainScene before, const GrainScene &solved, const SolverOptions &method)
{
  SolverOptions tight;
  tight.dt = method.dt;
  tight.theta = method.theta;
  tight.tolerance = reference_tolerance;
  tight.max_sweeps = 200000;
  ContactProblem problem;
  const SolveReport report = before.step(problem, tight);
  if (!report.converged)
    std::fprintf(stderr, "reference not converged: residual %.2e after %d sweeps\n",
                 report.residual, report.sweeps);
  double error = 0.0;
  for (std::size_t k = 0; k < solved.bodies.size(); ++k) {
    const SceneBody &a = solved.bodies[k], &b = before.bodies[k];
    const double size = 2.0 * solved.shapes[a.shape].bounding_radius;
    error = std::max(error, (a.velocity - b.velocity).norm() +
                                size * (a.angular_velocity - b.angular_velocity).norm());
  }
  return error / (before.gravity.norm() * method.dt);
}

struct Row {
  int cold = 0;               // step 0: the same problem for every method, no warm start
  double warm_mean = 0.0;     // steps 1..: the method's own trajectory and warm starts
  int warm_max = 0;
  double residual_mean = 0.0;
  double ms_per_step = 0.0;   // solve time
  int unconverged = 0;
  double error_cold = 0.0, error_last = 0.0;    // velocity_error()
};

Row measure(const SceneCase &scene_case, const Method &method, double tolerance, int steps,
            double ramp)
{
  SolverOptions options;
  options.dt = scene_case.dt;
  options.tolerance = tolerance;
  options.max_sweeps = 100000;
  method.configure(options);
  Row row;
  GrainScene scene = scene_case.make();
  scene.sort_by_height = method.sort_by_height;
  ContactProblem problem;
  double seconds = 0.0;
  for (int step = 0; step < steps; ++step) {
    scene.warm_start = step > 0;
    scene.load_factor = 1.0 + ramp * step;
    if (step == trace_step) trace_solve(scene, options);
    const bool compare = step == 0 || step == steps - 1;
    GrainScene before;
    if (compare) before = scene;
    const auto start = std::chrono::steady_clock::now();
    const SolveReport report = scene.step(problem, options);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.residual_mean += report.residual / steps;
    if (step == 0) row.error_cold = velocity_error(before, scene, options);
    if (step == steps - 1) row.error_last = velocity_error(before, scene, options);
    if (!report.converged) ++row.unconverged;
    if (step == 0) {
      row.cold = report.sweeps;
    } else {
      row.warm_mean += report.sweeps / (steps - 1.0);
      row.warm_max = std::max(row.warm_max, report.sweeps);
    }
    if (verbose) {
      // Internal load: the sum of normal impulses over the weight impulse of all bodies (a
      // self-equilibrated stress locked in by friction raises it without moving anything).
      double normal = 0.0, weight = 0.0;
      for (const Contact &c : problem.contacts) normal += c.impulse.dot(c.normal);
      for (const SolverBody &b : problem.bodies) weight += b.external_impulse.norm();
      std::printf("  step %d: %d sweeps, residual %.2e, contacts %zu (active %ld, sliding %ld), "
                  "kinetic energy %.3e, load ratio %.4f\n", step, report.sweeps, report.residual,
                  problem.contacts.size(), report.terms.active, report.terms.sliding,
                  scene.kinetic_energy(), normal / weight);
    }
  }
  row.ms_per_step = 1e3 * seconds / steps;
  return row;
}

void settle_pile()
{
  GrainScene scene = random_pile();
  SolverOptions options;
  options.dt = 0.005;
  options.tolerance = 1e-4;
  options.max_sweeps = 500;
  ContactProblem problem;
  for (int step = 1; step <= 6000; ++step) {
    const SolveReport report = scene.step(problem, options);
    if (step % 200 == 0) {
      std::printf("step %d: contacts %zu sweeps %d residual %.2e kinetic energy %.3e\n", step,
                  problem.contacts.size(), report.sweeps, report.residual, scene.kinetic_energy());
      std::fflush(stdout);
      if (step >= 2000 && scene.kinetic_energy() < 1e-10) break;
    }
  }
  scene.write_state(kPileState);
  std::printf("wrote %s\n", kPileState.c_str());
}

}    // namespace

int main(int argc, char **argv)
{
  double tolerance = 1e-4, ramp = 0.0;
  int steps = 50;
  std::vector<std::string> scene_names, method_names;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--verbose") {
      verbose = true;
      continue;
    }
    if (arg == "--settle") {
      settle_pile();
      return 0;
    }
    if (k + 1 >= argc) {
      std::fprintf(stderr, "option %s needs a value\n", arg.c_str());
      return 1;
    }
    const char *value = argv[++k];
    if (arg == "--tol") tolerance = std::atof(value);
    else if (arg == "--steps") steps = std::atoi(value);
    else if (arg == "--ref-tol") reference_tolerance = std::atof(value);
    else if (arg == "--ramp") ramp = std::atof(value);
    else if (arg == "--trace") trace_step = std::atoi(value);
    else if (arg == "--trace-sweeps") trace_sweeps = std::atoi(value);
    else if (arg == "--scene") scene_names.push_back(value);
    else if (arg == "--method") method_names.push_back(value);
    else {
      std::fprintf(stderr, "unknown option %s (--tol, --steps, --scene, --method, --settle)\n", arg.c_str());
      return 1;
    }
  }
  auto wanted = [](const std::vector<std::string> &names, const std::string &name) {
    return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
  };
  std::printf("tolerance %g, %d steps, load +%g per step. Sweeps: cold = step 0 without warm "
              "start; warm = steps 1.., warm-started from the method's own answers, mean (max)\n",
              tolerance, steps, ramp);
  std::printf("%-13s %-15s %7s %16s %9s %9s %6s %9s %9s\n", "scene", "method", "cold",
              "warm mean(max)", "residual", "ms/step", "unconv", "err cold", "err last");
  for (const SceneCase &scene_case : all_scenes()) {
    if (!wanted(scene_names, scene_case.name)) continue;
    for (const Method &method : all_methods()) {
      if (!wanted(method_names, method.name)) continue;
      const Row row = measure(scene_case, method, tolerance, steps, ramp);
      std::printf("%-13s %-15s %7d %9.1f(%5d) %9.2e %9.3f %6d %9.2e %9.2e\n",
                  scene_case.name.c_str(), method.name.c_str(), row.cold, row.warm_mean,
                  row.warm_max, row.residual_mean, row.ms_per_step, row.unconverged,
                  row.error_cold, row.error_last);
      std::fflush(stdout);
    }
  }
  return 0;
}
