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

#include "nscd_copy_exchange.h"

#include "math/capacity_bytes.h"

#include <algorithm>
#include <map>
#include <utility>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

/* The copies grouped by owner (other ranks, in rank order) and by the owner's item (in the
   order of their first copy), a count of items to every rank (MPI_Alltoall), then each
   holder's list of wanted indices to the owner, which sends those items in that order from
   then on. */
void NSCDCopyExchange::plan(const std::vector<Origin> &origins, MPI_Comm world, NSCDCommCount &counts, int kind)
{
  world_ = world;
  origins_ = origins;
  int me = 0, nprocs = 1;
  MPI_Comm_rank(world, &me);
  MPI_Comm_size(world, &nprocs);
  std::map<int, std::vector<int>> by_owner;    // owner rank -> its copies held here
  self.clear();
  for (int c = 0; c < (int) origins.size(); c++) {
    const Origin &o = origins[c];
    if (o.rank == me) self.push_back({o.index, c});
    else by_owner[o.rank].push_back(c);
  }
  owners.clear();
  std::vector<int> wanted(nprocs, 0), asked(nprocs, 0);
  for (auto &entry : by_owner) {
    Peer peer{entry.first, {}, {}, {}};
    std::map<int, int> slot_of;    // owner's index -> its place in the message
    std::vector<std::vector<int>> slots;
    for (int c : entry.second) {
      auto placed = slot_of.emplace(origins[c].index, (int) slots.size());
      if (placed.second) slots.emplace_back();
      slots[placed.first->second].push_back(c);
    }
    for (const std::vector<int> &copies : slots) {
      peer.first.push_back((int) peer.items.size());
      peer.items.insert(peer.items.end(), copies.begin(), copies.end());
    }
    peer.first.push_back((int) peer.items.size());
    wanted[entry.first] = (int) peer.sent();
    owners.push_back(std::move(peer));
  }
  MPI_Alltoall(wanted.data(), 1, MPI_INT, asked.data(), 1, MPI_INT, world);
  holders.clear();
  for (int r = 0; r < nprocs; r++)
    if (asked[r] > 0 && r != me) holders.push_back({r, std::vector<int>(asked[r]), {}, {}});

  // the owners' indices of the wanted items, as doubles (counted like the other messages)
  requests.assign(owners.size() + holders.size(), MPI_REQUEST_NULL);
  for (size_t p = 0; p < holders.size(); p++) {
    holders[p].buffer.resize(holders[p].items.size());
    MPI_Irecv(holders[p].buffer.data(), (int) holders[p].buffer.size(), MPI_DOUBLE, holders[p].rank, PLAN_TAG, world,
              &requests[p]);
  }
  for (size_t p = 0; p < owners.size(); p++) {
    Peer &o = owners[p];
    o.buffer.clear();
    for (size_t k = 0; k < o.sent(); k++) o.buffer.push_back(origins[o.items[o.first[k]]].index);
    MPI_Isend(o.buffer.data(), (int) o.buffer.size(), MPI_DOUBLE, o.rank, PLAN_TAG, world,
              &requests[holders.size() + p]);
  }
  MPI_Waitall((int) requests.size(), requests.data(), MPI_STATUSES_IGNORE);
  for (Peer &h : holders)
    for (size_t k = 0; k < h.items.size(); k++) h.items[k] = (int) h.buffer[k];
  for (const Peer &h : holders) counts.received(kind, (int) h.items.size(), (int) h.items.size());
}

void NSCDCopyExchange::swap_buffers(std::vector<Peer> &from, std::vector<Peer> &to, int width, int tag,
                                    NSCDCommCount &counts, int kind)
{
  requests.assign(from.size() + to.size(), MPI_REQUEST_NULL);
  for (size_t p = 0; p < from.size(); p++) {
    Peer &f = from[p];
    f.buffer.resize((size_t) width * f.sent());
    MPI_Irecv(f.buffer.data(), (int) f.buffer.size(), MPI_DOUBLE, f.rank, tag, world_, &requests[p]);
  }
  for (size_t p = 0; p < to.size(); p++)
    MPI_Isend(to[p].buffer.data(), (int) to[p].buffer.size(), MPI_DOUBLE, to[p].rank, tag, world_,
              &requests[from.size() + p]);
  MPI_Waitall((int) requests.size(), requests.data(), MPI_STATUSES_IGNORE);
  for (const Peer &f : from) counts.received(kind, (int) f.sent(), (int) f.buffer.size());
}

/* Each field: 3 doubles per item, the owned items first and the copies from `first_copy` on;
   a copy is its owner's item, the first field (a position) at the copy's periodic image. */
double NSCDCopyExchange::forward(const std::vector<double *> &fields, int first_copy, NSCDCommCount &counts, int kind)
{
  const int nf = (int) fields.size();
  double *const *field = fields.data();
  auto pack = [&](int i, double *out) {
    for (int f = 0; f < nf; f++, out += 3) std::copy(field[f] + 3 * (size_t) i, field[f] + 3 * (size_t) i + 3, out);
  };
  auto take = [&](int c, const double *in) {
    const double *s = shift(c);
    double *x = field[0] + 3 * ((size_t) first_copy + c);
    for (int d = 0; d < 3; d++) x[d] = in[d] + s[d];
    for (int f = 1; f < nf; f++) std::copy(in + 3 * f, in + 3 * f + 3, field[f] + 3 * ((size_t) first_copy + c));
  };
  return forward_values(3 * nf, pack, take, counts, kind);
}

double NSCDCopyExchange::reverse(double *field, int first_copy, NSCDCommCount &counts, int kind)
{
  const double *copies = field + 3 * (size_t) first_copy;
  auto pack = [&](int c, double *out) { std::copy(copies + 3 * (size_t) c, copies + 3 * (size_t) c + 3, out); };
  auto add = [&](int i, const double *in) {
    for (int d = 0; d < 3; d++) field[3 * (size_t) i + d] += in[d];
  };
  return reverse_values(3, pack, add, counts, kind);
}

std::size_t NSCDCopyExchange::memory_bytes() const
{
  std::size_t bytes = nscd::capacity_bytes(self) + nscd::capacity_bytes(origins_) + nscd::capacity_bytes(requests) +
      nscd::capacity_bytes(scratch) +
      nscd::capacity_bytes(owners) + nscd::capacity_bytes(holders);
  for (const std::vector<Peer> *peers : {&owners, &holders})
    for (const Peer &p : *peers)
      bytes += nscd::capacity_bytes(p.items) + nscd::capacity_bytes(p.first) + nscd::capacity_bytes(p.buffer);
  return bytes;
}
