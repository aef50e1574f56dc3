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

// main() of our `lmp`. LAMMPS is built with LAMMPS_EXCEPTIONS (so tests can check error
// messages); LAMMPS' own main() then aborts on an error of one rank without flushing the
// screen and log files, and the message is lost whenever output goes to a file or pipe.
// This main flushes every open stream first; otherwise it runs LAMMPS as usual.
#include "exceptions.h"
#include "input.h"
#include "lammps.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

using LAMMPS_NS::LAMMPS;

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  try {
    auto *lammps = new LAMMPS(argc, argv, MPI_COMM_WORLD);
    lammps->input->file();
    delete lammps;
  } catch (LAMMPS_NS::LAMMPSAbortException &) {
    std::fflush(nullptr);    // the message is in the screen/log buffers of the failing rank
    MPI_Abort(MPI_COMM_WORLD, 1);    // (its universe accessor differs between versions)
  } catch (LAMMPS_NS::LAMMPSException &) {
    std::fflush(nullptr);
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Finalize();
    std::exit(1);
  } catch (std::exception &e) {    // a bug: nothing in the package should let one escape
    std::fflush(nullptr);
    std::fprintf(stderr, "lmp: unexpected error: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  return 0;
}
