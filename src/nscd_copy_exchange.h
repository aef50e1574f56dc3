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
  // of (a count to every rank, then one list to each owner, 1 double per item: an item with
  // several copies here travels once, its copies' values summed on the way back). `counts`:
  // those lists are counted there as `kind` (the MPI_Alltoall is not).
  void plan(const std::vector<Origin> &origins, MPI_Comm world, NSCDCommCount &counts, int kind);

  // Forward: each copy's values set to its owner's item's, with the shift added to the first
  // field (a position). `fields`: arrays of 3 doubles per item, this rank's own items first
  // (numbered as the indices of the plan's Origins) and its copies from `first_copy` on.
  // Returns the doubles packed (copies on this rank too).
  double forward(const std::vector<double *> &fields, int first_copy, NSCDCommCount &counts, int kind);
  // Reverse: each copy's 3 values added to its owner's item (a force). Returns the doubles packed.
  double reverse(double *field, int first_copy, NSCDCommCount &counts, int kind);

  // The same exchanges for items kept elsewhere than in arrays of 3 doubles: `width` values
  // per item. Forward: `pack(item, out)` writes an owned item's values, `take(copy, in)` sets
  // copy `copy` (0 .. copies-1, the plan's order) to them. Reverse: `pack(copy, out)` writes a
  // copy's values, `add(item, in)` adds them to the owned item (periodic images on this rank
  // first, then the other ranks' copies in rank order). No shift is added: `shift(copy)` is
  // there for a caller whose values need it. Both return the doubles packed.
  template <class Pack, class Take>
  double forward_values(int width, Pack pack, Take take, NSCDCommCount &counts, int kind);
  template <class Pack, class Add>
  double reverse_values(int width, Pack pack, Add add, NSCDCommCount &counts, int kind);
  const double *shift(int copy) const { return origins_[copy].shift.data(); }

  // Bytes held: the plan and the message buffers, at capacity.
  std::size_t memory_bytes() const;

 private:
  // Another rank and the items of the messages with it, in their order: for a rank holding
  // copies of ours (`holders`) our items it holds, for a rank owning copies held here
  // (`owners`) those copies, grouped by the owner's item: the copies of the k-th item sent are
  // items[first[k]] .. items[first[k+1]-1] (several where an item has periodic images here).
  struct Peer {
    int rank;
    std::vector<int> items, first;
    std::vector<double> buffer;
    // the items a message with this peer carries values for
    std::size_t sent() const { return first.empty() ? items.size() : first.size() - 1; }
  };
  std::vector<Peer> owners, holders;       // ranks owning copies held here; ranks holding copies of ours
  std::vector<std::array<int, 2>> self;    // (owned index, copy index) of images on this rank
  std::vector<Origin> origins_;
  std::vector<MPI_Request> requests;
  std::vector<double> scratch;    // one item's values, for an image on this rank
  MPI_Comm world_;
  static constexpr int FORWARD_TAG = 24601, REVERSE_TAG = 24602, PLAN_TAG = 24603;

  // Receives `width` doubles per item from each peer into its buffer, sends each of `to`'s
  // buffers, waits for all, and counts what arrived.
  void swap_buffers(std::vector<Peer> &from, std::vector<Peer> &to, int width, int tag, NSCDCommCount &counts,
                    int kind);
};

template <class Pack, class Take>
double NSCDCopyExchange::forward_values(int width, Pack pack, Take take, NSCDCommCount &counts, int kind)
{
  double packed = 0.0;
  for (Peer &h : holders) {
    h.buffer.resize((size_t) width * h.items.size());
    double *b = h.buffer.data();
    for (int i : h.items) pack(i, b), b += width;
    packed += (double) h.buffer.size();
  }
  swap_buffers(owners, holders, width, FORWARD_TAG, counts, kind);
  scratch.resize(width);
  for (const std::array<int, 2> &s : self) {
    pack(s[0], scratch.data());
    take(s[1], scratch.data());
  }
  packed += (double) width * self.size();
  for (const Peer &o : owners)
    for (size_t k = 0; k + 1 < o.first.size(); k++)
      for (int c = o.first[k]; c < o.first[k + 1]; c++)
        take(o.items[c], &o.buffer[(size_t) width * k]);
  return packed;
}

template <class Pack, class Add>
double NSCDCopyExchange::reverse_values(int width, Pack pack, Add add, NSCDCommCount &counts, int kind)
{
  double packed = 0.0;
  scratch.resize(width);
  for (Peer &o : owners) {    // one sum of its copies' values per item
    o.buffer.resize((size_t) width * o.sent());
    double *b = o.buffer.data();
    for (size_t k = 0; k + 1 < o.first.size(); k++, b += width) {
      pack(o.items[o.first[k]], b);
      for (int c = o.first[k] + 1; c < o.first[k + 1]; c++) {
        pack(o.items[c], scratch.data());
        for (int v = 0; v < width; v++) b[v] += scratch[v];
      }
    }
    packed += (double) width * o.items.size();
  }
  swap_buffers(holders, owners, width, REVERSE_TAG, counts, kind);
  for (const std::array<int, 2> &s : self) {
    pack(s[1], scratch.data());
    add(s[0], scratch.data());
  }
  packed += (double) width * self.size();
  for (const Peer &h : holders)
    for (size_t k = 0; k < h.items.size(); k++) add(h.items[k], &h.buffer[(size_t) width * k]);
  return packed;
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
