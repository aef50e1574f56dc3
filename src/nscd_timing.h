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

/* A style's own timing of a run, split into parts a user can act on, reported after the run
   per rank (min, average and max over the ranks, and the average's share of the loop time),
   in the layout of LAMMPS' "MPI task timing breakdown". Used by fix nscd and fix wire. */
#ifndef LMP_NSCD_TIMING_H
#define LMP_NSCD_TIMING_H

#include <mpi.h>

#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

class NSCDPartTimes {
 public:
  explicit NSCDPartTimes(std::vector<std::string> names);

  void clear();
  // Seconds of part `part` so far (add to it).
  double &operator[](int part) { return seconds[part]; }
  double operator[](int part) const { return seconds[part]; }
  double total() const;

  // Collective over `world`. The table, one row per part and a row "total": min, avg, max
  // seconds over the ranks, %varavg (spread of the ranks about the average, as LAMMPS'),
  // and the average as % of loop_seconds. Every rank gets the text; print it on rank 0.
  std::string table(MPI_Comm world, const std::string &title, double loop_seconds) const;

 private:
  std::vector<std::string> names;
  std::vector<double> seconds;
};

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
