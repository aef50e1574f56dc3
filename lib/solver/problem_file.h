/* -*- c++ -*- ----------------------------------------------------------
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

// One time step's contact problem as a text file: the bodies and contacts fix nscd hands to
// the solver (before prepare(): start-of-step velocities, external impulses, warm-start
// impulses) with the step's dt and theta, so a hard step of a LAMMPS run can be solved
// again, alone, with other solver options (benchmarks/solver/replay_problem.cpp,
// doc/Howto_nscd_solver.rst "Replaying a step"). Doubles are written with 17 significant
// digits, so a read problem is the written one bit for bit.
#pragma once

#include "solver/contact_problem.h"

#include <iosfwd>

namespace nscd {

struct ProblemFile {
  ContactProblem problem;
  double dt = 0.0;
  double theta = 1.0;
};

void write_problem(std::ostream &out, const ContactProblem &problem, double dt, double theta);

// Throws SolverError naming the first field that could not be read (a truncated or damaged
// file is refused, never half-read).
ProblemFile read_problem(std::istream &in);

}    // namespace nscd
