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

// A LAMMPS instance per test, driven by deck lines; errors are exceptions
// (LAMMPS is built with LAMMPS_EXCEPTIONS). Works on any number of MPI ranks.
#pragma once

#include "atom.h"
#include "exceptions.h"
#include "input.h"
#include "lammps.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

// The rank of `world` owning the atom of this ID in `lmp` (-1 if none), on every rank of it.
inline int owner_of(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::tagint tag, MPI_Comm world)
{
  const int i = lmp->atom->map(tag);
  int me = 0, mine = -1, owner = -1;
  MPI_Comm_rank(world, &me);
  if (i >= 0 && i < lmp->atom->nlocal) mine = me;
  MPI_Allreduce(&mine, &owner, 1, MPI_INT, MPI_MAX, world);
  return owner;
}

// A shape library of a unit cube (shape 1), a rounded cube (2) and a ball (3, one vertex),
// all of isotropic inertia and size 1.
inline constexpr const char *kIsotropicShapes = R"(shape cube
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
shape ball
radius 0.5
vertices 1
0 0 0
end
)";

class LammpsTest : public ::testing::Test {
 protected:
  LAMMPS_NS::LAMMPS *lmp = nullptr;

  void SetUp() override { start(); }
  void TearDown() override { stop(); }

  static LAMMPS_NS::LAMMPS *quiet_instance(MPI_Comm comm)
  {
    const char *argv[] = {"lmp", "-log", "none", "-echo", "none", "-screen", "none", "-nocite"};
    return new LAMMPS_NS::LAMMPS(8, const_cast<char **>(argv), comm);
  }
  void start() { lmp = quiet_instance(MPI_COMM_WORLD); }

  // Runs body(comm) on ranks 0 .. size-1 alone, `lmp` a fresh instance on their own
  // communicator `comm` (the fixture's helpers drive it); the other ranks skip it. The
  // world's instance is back afterwards.
  template <class Body> void on_first_ranks(int size, Body body)
  {
    MPI_Comm part;
    MPI_Comm_split(MPI_COMM_WORLD, rank() < size ? 0 : MPI_UNDEFINED, 0, &part);
    if (rank() >= size) return;
    LAMMPS_NS::LAMMPS *world_instance = lmp;
    lmp = quiet_instance(part);
    body(part);
    delete lmp;
    lmp = world_instance;
    MPI_Comm_free(&part);
  }
  void stop()
  {
    delete lmp;
    lmp = nullptr;
  }
  void restart_instance()
  {
    stop();
    start();
  }

  void run(const std::string &line) { lmp->input->one(line); }
  void commands(const std::vector<std::string> &lines)
  {
    for (auto &line : lines) run(line);
  }

  // The message of the LAMMPS error a command raises ("" if it raises none).
  std::string error_of(const std::string &line)
  {
    try {
      run(line);
    } catch (LAMMPS_NS::LAMMPSException &e) {
      return e.what();
    }
    return "";
  }

  // What `compute reduce` needs after its inputs to read local data (a compute's rows):
  // LAMMPS 29 Aug 2024 and newer ask for "inputs local", older ones refuse the keyword.
  std::string reduce_local() const { return lmp->num_ver >= 20240829 ? " inputs local" : ""; }

  // A number written with all its digits (std::to_string keeps only 6 decimals).
  static std::string num(double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", value);
    return text;
  }

  int rank() const
  {
    int me = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &me);
    return me;
  }
  int ranks() const
  {
    int n = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
  }

  // Row `tag` of a per-atom 3-vector (x, v, ...) of whichever rank owns the atom, on every rank.
  std::array<double, 3> vector_of(LAMMPS_NS::tagint tag, double **per_atom)
  {
    double mine[3] = {0.0, 0.0, 0.0}, all[3];
    const int i = lmp->atom->map(tag);
    if (i >= 0 && i < lmp->atom->nlocal)
      for (int k = 0; k < 3; k++) mine[k] = per_atom[i][k];
    MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return {all[0], all[1], all[2]};
  }
  std::array<double, 3> velocity_of(LAMMPS_NS::tagint tag) { return vector_of(tag, lmp->atom->v); }
  std::array<double, 3> position_of(LAMMPS_NS::tagint tag) { return vector_of(tag, lmp->atom->x); }

  // Path of a scratch file unique to this test (and shared by all ranks).
  std::string scratch(const std::string &name) const
  {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::string(NSCD_TEST_SCRATCH) + "/" + info->test_suite_name() + "." + info->name() +
        "." + std::to_string(ranks()) + "." + name;
  }
};
