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

// A step's contact problem written to text and read back is the same problem: solving the
// read one gives the written one's impulses and velocities bit for bit; damaged files are
// refused naming what could not be read.
#include "solver/problem_file.h"
#include "solver_scenes.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace nscd;
using namespace nscd::test;

TEST(ProblemFile, ReadBackProblemSolvesToTheSameImpulsesBitForBit)
{
  ContactProblem problem = brick_pyramid(4, 0.5, 1e-3);
  problem.bodies[3].inv_mass_axes = Vec3(0.0, 0.0, 1.0);    // fields that are rarely set
  problem.bodies[3].share = 2.0;
  problem.contacts[1].restitution = 0.3;
  problem.contacts[2].wall_velocity = Vec3(0.1, -0.2, 0.0);
  problem.contacts[2].impulse = Vec3(1e-3, 2e-4, -3e-5);
  problem.contacts[2].key = {-7, 123456789012345, 18446744073709551615ull};
  std::stringstream text;
  write_problem(text, problem, 1e-3, 0.75);
  const ProblemFile file = read_problem(text);
  EXPECT_EQ(file.dt, 1e-3);
  EXPECT_EQ(file.theta, 0.75);
  ASSERT_EQ(file.problem.bodies.size(), problem.bodies.size());
  ASSERT_EQ(file.problem.contacts.size(), problem.contacts.size());
  EXPECT_EQ(file.problem.contacts[2].key.tag_i, -7);
  EXPECT_EQ(file.problem.contacts[2].key.tag_j, 123456789012345);
  EXPECT_EQ(file.problem.contacts[2].key.feature, 18446744073709551615ull);
  EXPECT_EQ(file.problem.bodies[3].share, 2.0);

  SolverOptions options;
  options.dt = 1e-3;
  options.theta = 0.75;
  options.tolerance = 1e-8;
  options.max_sweeps = 5000;
  ContactProblem original = problem, replayed = file.problem;
  const SolveReport a = solve(original, options), b = solve(replayed, options);
  EXPECT_EQ(a.sweeps, b.sweeps);
  EXPECT_EQ(a.residual, b.residual);
  for (std::size_t c = 0; c < original.contacts.size(); ++c)
    EXPECT_EQ(original.contacts[c].impulse, replayed.contacts[c].impulse) << c;
  for (std::size_t k = 0; k < original.bodies.size(); ++k) {
    EXPECT_EQ(original.bodies[k].velocity, replayed.bodies[k].velocity) << k;
    EXPECT_EQ(original.bodies[k].angular_velocity, replayed.bodies[k].angular_velocity) << k;
  }
}

TEST(ProblemFile, DamagedFilesAreRefusedNamingWhatIsMissing)
{
  const ContactProblem problem = brick_pyramid(3, 0.5, 1e-3);
  std::stringstream text;
  write_problem(text, problem, 1e-3, 1.0);
  const std::string whole = text.str();
  const auto error_of = [](const std::string &content) {
    std::istringstream in(content);
    try {
      read_problem(in);
    } catch (const SolverError &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error_of(whole), "");
  const std::string truncated = error_of(whole.substr(0, whole.size() - 40));
  EXPECT_NE(truncated.find("of contact " + std::to_string(problem.contacts.size() - 1)), std::string::npos) << truncated;
  EXPECT_NE(error_of("something else 1\n").find("not a contact problem"), std::string::npos);
  EXPECT_NE(error_of("nscd-contact-problem 9\n").find("version 9"), std::string::npos);
  std::string garbled = whole;
  garbled.replace(whole.find('\n', whole.find('\n') + 1) + 3, 4, "x!y#");
  EXPECT_NE(error_of(garbled).find("of body 0"), std::string::npos) << error_of(garbled);
}
