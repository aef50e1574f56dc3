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

/* Gathering plain records (trivially copyable structs) of all ranks, in rank order: restart
   blocks written by rank 0 and per-contact state handed over between ranks. */
#ifndef LMP_NSCD_GATHER_H
#define LMP_NSCD_GATHER_H

#include <mpi.h>

#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

// Every rank's `mine`, concatenated in rank order: on every rank (to_all_ranks) or on rank 0
// only (the others get an empty vector). Collective over `world`.
template <class Record>
std::vector<Record> gather_records(const std::vector<Record> &mine, MPI_Comm world, bool to_all_ranks)
{
  static_assert(std::is_trivially_copyable<Record>::value, "records travel as bytes");
  int nprocs = 1, me = 0;
  MPI_Comm_size(world, &nprocs);
  MPI_Comm_rank(world, &me);
  const int bytes = (int) (mine.size() * sizeof(Record));
  std::vector<int> counts(nprocs, 0), offsets(nprocs, 0);
  if (to_all_ranks) MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  else MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  for (int r = 1; r < nprocs; r++) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<Record> all;
  if (to_all_ranks || me == 0) all.resize(((size_t) offsets.back() + counts.back()) / sizeof(Record));
  if (to_all_ranks)
    MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, world);
  else
    MPI_Gatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, world);
  return all;
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
