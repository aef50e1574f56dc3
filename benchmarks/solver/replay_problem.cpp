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

// Solves a contact problem written by fix nscd's write_problem again, alone, with other
// solver options: sweeps, residual and time (best of --repeat), and with --where the
// residual at every check split by height (grain-grain | boundary contacts), to see where
// a hard step's error sits. doc/Howto_nscd_solver.rst, "Replaying a step".
//
//   replay_problem FILE [--method gs|nesterov|nncg|anderson] [--tolerance T] [--check N]
//                  [--max-sweeps N] [--skip yes|no] [--slip-guess yes|no] [--coarse C] [--relaxation W] [--memory M]
//                  [--order as_given|shuffled|forward_backward] [--repeat N] [--where BINS]
//                  [--worst N]
// Defaults are fix nscd's (nesterov, 1e-4, 4, 1000, skip no, no coarse).
#include "solver/problem_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace nscd;

namespace {

[[noreturn]] void usage(const std::string &why)
{
  std::fprintf(stderr, "replay_problem: %s\nusage: replay_problem FILE [--method gs|nesterov|nncg|anderson] "
               "[--tolerance T] [--check N] [--max-sweeps N] [--skip yes|no] [--slip-guess yes|no] [--coarse C] [--relaxation W] [--memory M] "
               "[--order as_given|shuffled|forward_backward] [--repeat N] [--where BINS] [--worst N]\n", why.c_str());
  std::exit(2);
}

// The residual of every check, its error split into height bins (grain-grain | boundary).
void print_where(const ProblemFile &file, const SolverOptions &options, int bins)
{
  ContactProblem problem = file.problem;
  problem.prepare(options);
  double z_low = INFINITY, z_high = -INFINITY;
  for (const Contact &c : problem.contacts) z_low = std::min(z_low, c.point.z()), z_high = std::max(z_high, c.point.z());
  const double width = (z_high - z_low) / bins + 1e-300;
  std::printf("residual at each check; its error by height bin of %.3g from z = %.3g (grain-grain|boundary)\n",
              width, z_low);
  int check = 0;
  std::vector<double> error, scale;
  SolverCommunication communication;
  communication.sum = [&](double *values, int n) {
    if (n != ResidualTerms::kSummed) return;    // only the residual terms' sum at a check
    problem.contact_residuals(error, scale);
    double scale_squared = 0.0;
    for (double s : scale) scale_squared += s * s;
    std::vector<double> grains(bins), boundaries(bins);
    for (std::size_t c = 0; c < error.size(); ++c) {
      const int bin = std::min(bins - 1, (int) ((problem.contacts[c].point.z() - z_low) / width));
      (problem.contacts[c].body_j == kEnvironment ? boundaries : grains)[bin] += error[c] * error[c];
    }
    std::printf("%5d %.3e |", options.check_every * check++, std::sqrt(values[0] / values[1]));
    for (int b = 0; b < bins; ++b)
      std::printf(" %.0e|%.0e", std::sqrt(grains[b] / scale_squared), std::sqrt(boundaries[b] / scale_squared));
    std::printf("\n");
  };
  iterate(problem, options, communication);
}

// The n contacts with the largest residual at the end of the solve, and how much of the
// squared error they hold: whether a stalled step's error is a few contacts or spread.
void print_worst(const ContactProblem &problem, int n)
{
  std::vector<double> error, scale;
  problem.contact_residuals(error, scale);
  double error_squared = 0.0, scale_squared = 0.0;
  for (std::size_t c = 0; c < error.size(); ++c) error_squared += error[c] * error[c], scale_squared += scale[c] * scale[c];
  std::vector<std::size_t> order(error.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  n = std::min<int>(n, (int) order.size());
  std::partial_sort(order.begin(), order.begin() + n, order.end(),
                    [&](std::size_t a, std::size_t b) { return error[a] > error[b]; });
  static const char *regimes[] = {"open", "sticking", "sliding"};
  std::printf("the %d contacts with the largest residual (share of the squared error; %zu contacts):\n", n,
              order.size());
  double held = 0.0;
  for (int k = 0; k < n; ++k) {
    const Contact &c = problem.contacts[order[k]];
    const double share = error[order[k]] * error[order[k]] / (error_squared + 1e-300);
    held += share;
    std::printf("  contact %zu: bodies %d %d, z %.3f, gap %.2e, mu %.2f, %s, |P| %.3e, share %.3f (sum %.3f)\n",
                order[k], c.body_i, c.body_j, c.point.z(), c.gap, c.friction,
                regimes[std::min<int>(2, (int) c.regime)], c.impulse.norm(), share, held);
  }
  std::printf("  relative residual of the rest: %.3e\n",
              std::sqrt(std::max(0.0, error_squared * (1 - held)) / (scale_squared + 1e-300)));
}

// FNV-1a over the bits of every contact's impulse and every body's velocities after the
// solve: equal digests mean the same answer to the last bit (a change meant to keep the
// arithmetic, e.g. compiler flags, is checked with it; one that changes round-off is not).
std::uint64_t digest(const ContactProblem &problem)
{
  std::uint64_t hash = 1469598103934665603ull;
  const auto add = [&hash](const Vec3 &x) {
    unsigned char bytes[sizeof(double) * 3];
    const double values[3] = {x[0], x[1], x[2]};
    std::memcpy(bytes, values, sizeof bytes);
    for (const unsigned char b : bytes) hash = (hash ^ b) * 1099511628211ull;
  };
  for (const Contact &contact : problem.contacts) add(contact.impulse);
  for (const SolverBody &body : problem.bodies) {
    add(body.velocity);
    add(body.angular_velocity);
  }
  return hash;
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc < 2) usage("no file");
  SolverOptions options;
  options.acceleration = Acceleration::nesterov;
  options.tolerance = 1e-4;
  options.check_every = 4;
  options.max_sweeps = 1000;
  int repeat = 5, where = 0, worst = 0;
  for (int k = 2; k < argc; k += 2) {
    const std::string key = argv[k];
    if (k + 1 >= argc) usage(key + " needs a value");
    const std::string value = argv[k + 1];
    if (key == "--method") {
      if (value == "gs") options.acceleration = Acceleration::none;
      else if (value == "nesterov") options.acceleration = Acceleration::nesterov;
      else if (value == "nncg") options.acceleration = Acceleration::nncg;
      else if (value == "anderson") options.acceleration = Acceleration::anderson;
      else usage("unknown method " + value);
    } else if (key == "--tolerance") options.tolerance = std::atof(value.c_str());
    else if (key == "--check") options.check_every = std::atoi(value.c_str());
    else if (key == "--max-sweeps") options.max_sweeps = std::atoi(value.c_str());
    else if (key == "--skip") options.skip_separating = value == "yes";
    else if (key == "--slip-guess") options.slip_guess = value == "yes";
    else if (key == "--coarse") options.coarse_cell = std::atof(value.c_str());
    else if (key == "--relaxation") options.relaxation = std::atof(value.c_str());
    else if (key == "--memory") options.anderson_memory = std::atoi(value.c_str());
    else if (key == "--order") {
      if (value == "as_given") options.order = SweepOrder::as_given;
      else if (value == "shuffled") options.order = SweepOrder::shuffled;
      else if (value == "forward_backward") options.order = SweepOrder::forward_backward;
      else usage("unknown order " + value);
    }
    else if (key == "--repeat") repeat = std::max(1, std::atoi(value.c_str()));
    else if (key == "--where") where = std::max(1, std::atoi(value.c_str()));
    else if (key == "--worst") worst = std::max(1, std::atoi(value.c_str()));
    else usage("unknown option " + key);
  }
  std::ifstream in(argv[1]);
  if (!in) usage(std::string("cannot open ") + argv[1]);
  ProblemFile file;
  try {
    file = read_problem(in);
    options.dt = file.dt;
    options.theta = file.theta;
    options.validate();
  } catch (const SolverError &e) {
    usage(e.what());
  }
  SolveReport report;
  double best = INFINITY;
  ContactProblem problem;
  for (int k = 0; k < repeat; ++k) {
    problem = file.problem;
    const auto start = std::chrono::steady_clock::now();
    report = solve(problem, options);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  long active = report.terms.active;
  std::printf("%s: %zu bodies, %zu contacts (%ld active at the end: %ld sticking, %ld sliding): %d sweeps, "
              "residual %.6e%s, %.2f ms (best of %d)\n", argv[1], file.problem.bodies.size(),
              file.problem.contacts.size(), active, report.terms.sticking, report.terms.sliding,
              report.sweeps, report.residual, report.converged ? "" : " (not converged)", 1e3 * best, repeat);
  std::printf("digest of the impulses and velocities at the end: %016llx\n",
              static_cast<unsigned long long>(digest(problem)));
  if (where) print_where(file, options, where);
  if (worst) print_worst(problem, worst);
  return 0;
}
