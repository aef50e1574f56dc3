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

/* Messages and bytes that a style's forward and reverse communications (comm->forward_comm,
   comm->reverse_comm with the style as argument) carry between ranks, per kind of exchange
   the style names, counted where they arrive. LAMMPS' Comm, brick and tiled alike, hands a
   swap that stays on the rank (a periodic image, a dimension of one rank) to the style's
   unpack function in the very buffer its pack function has just filled, and a message from
   another rank in its receive buffer: an unpack from another buffer than the last pack's, for
   at least one atom, is one message. A brick swap with no atom sends none; a tiled swap's
   zero-atom messages are not counted. Used by fix nscd and fix wire (doc/scaling.md); fix
   wire's exchange of node copies in its substeps counts its own messages (received()). */
#ifndef LMP_NSCD_COMM_COUNT_H
#define LMP_NSCD_COMM_COUNT_H

#include <mpi.h>

#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

class NSCDCommCount {
 public:
  struct Tally {
    Tally() : messages(0.0), bytes(0.0), atoms(0.0) {}
    double messages;    // received from other ranks
    double bytes;       // their doubles, 8 bytes each
    double atoms;       // the atoms they were for
  };
  static_assert(sizeof(Tally) == 3 * sizeof(double), "summed() reduces a Tally as 3 doubles");

  explicit NSCDCommCount(int kinds) : tallies(kinds), last_packed(nullptr) {}

  // In pack_forward_comm and pack_reverse_comm: the buffer being filled.
  void packed(const double *buffer) { last_packed = buffer; }
  // In unpack_forward_comm and unpack_reverse_comm: `values` doubles read for `atoms` atoms
  // from `buffer`, counted as an exchange of `kind` if another rank sent them (returns whether).
  bool unpacked(int kind, int atoms, int values, const double *buffer)
  {
    if (atoms == 0 || buffer == last_packed) return false;
    received(kind, atoms, values);
    return true;
  }
  // A message from another rank of `values` doubles for `atoms` atoms, sent by the style's
  // own exchange (nscd_copy_exchange.h), not through LAMMPS' Comm.
  void received(int kind, int atoms, int values)
  {
    Tally &t = tallies[kind];
    t.messages += 1.0;
    t.bytes += 8.0 * values;
    t.atoms += atoms;
  }

  const Tally &operator[](int kind) const { return tallies[kind]; }
  void clear() { tallies.assign(tallies.size(), Tally()); }

  // Collective over `world`: each kind's tally summed over the ranks.
  std::vector<Tally> summed(MPI_Comm world) const
  {
    std::vector<Tally> all(tallies.size());
    MPI_Allreduce(tallies.data(), all.data(), 3 * (int) tallies.size(), MPI_DOUBLE, MPI_SUM, world);
    return all;
  }

 private:
  std::vector<Tally> tallies;
  const double *last_packed;
};

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
