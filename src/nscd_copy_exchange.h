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

/* An exchange of copies of a few kinds of atom (fix wire: the wire nodes) straight between the
   ranks that own them and the ranks that hold them as ghosts: one message per pair of ranks
   and direction, holding those copies only. LAMMPS' comm->forward_comm / reverse_comm of a
   fix walk its swaps (6 on a brick, each rank in turn, ghosts of ghosts relayed) over every
   ghost atom, grains too, and send a message per swap that has any ghost atom, wire node or
   not; fix wire exchanged its nodes that way twice per wire substep (doc/wire_speed.md, "Speed").

   The plan is made after each neighbour build from where each copy comes from (its owner
   rank and the item's index there, which the caller learns with one LAMMPS forward_comm),
   and the shift of its periodic image, which stays with the copy. Owned items and copies are
   numbered by the caller (fix wire: its node index; the copies after the owned ones). A copy
   held on its own owner's rank (a periodic image) is filled without a message. */
#ifndef LMP_NSCD_COPY_EXCHANGE_H
#define LMP_NSCD_COPY_EXCHANGE_H

#include "nscd_comm_count.h"

#include <mpi.h>

#include <array>
#include <cstddef>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

class NSCDCopyExchange {
 public:
  NSCDCopyExchange() : world_(MPI_COMM_NULL) {}

  // Where copy c (0 .. copies-1) comes from: the owner's rank, the item's index there and the
  // periodic shift of this image (added to the first 3 values of a forward exchange).
  struct Origin {
    int rank, index;
    std::array<double, 3> shift;
  };

  // Collective over `world`: each rank tells the owners which of their items it holds copies
  // of (a count to every rank, then one list to each owner, 1 double per copy). `counts`:
  // those lists are counted there as `kind` (the MPI_Alltoall is not).
  void plan(const std::vector<Origin> &origins, MPI_Comm world, NSCDCommCount &counts, int kind);

  // Forward: each copy's values set to its owner's item's, with the shift added to the first
  // field (a position). `fields`: arrays of 3 doubles per item, this rank's own items first
  // (numbered as the indices of the plan's Origins) and its copies from `first_copy` on.
  // Returns the doubles packed (copies on this rank too).
  double forward(const std::vector<double *> &fields, int first_copy, NSCDCommCount &counts, int kind);
  // Reverse: each copy's 3 values added to its owner's item (a force). Returns the doubles packed.
  double reverse(double *field, int first_copy, NSCDCommCount &counts, int kind);

  // Bytes held: the plan and the message buffers, at capacity.
  std::size_t memory_bytes() const;

 private:
  // Another rank and the items of the messages with it, in their order: for a rank holding
  // copies of ours (`holders`) our items it holds, for a rank owning copies held here
  // (`owners`) those copies.
  struct Peer {
    int rank;
    std::vector<int> items;
    std::vector<double> buffer;
  };
  std::vector<Peer> owners, holders;       // ranks owning copies held here; ranks holding copies of ours
  std::vector<std::array<int, 2>> self;    // (owned index, copy index) of images on this rank
  std::vector<Origin> origins_;
  std::vector<MPI_Request> requests;
  MPI_Comm world_;
  static constexpr int FORWARD_TAG = 24601, REVERSE_TAG = 24602, PLAN_TAG = 24603;

  // Receives `width` doubles per item from each peer into its buffer, sends each of `to`'s
  // buffers, waits for all, and counts what arrived.
  void swap_buffers(std::vector<Peer> &from, std::vector<Peer> &to, int width, int tag, NSCDCommCount &counts,
                    int kind);
};

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
