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

/* The copies grouped by owner (other ranks, in rank order; within a rank in copy order), a
   count to every rank (MPI_Alltoall), then each holder's list of wanted indices to the owner,
   which sends those items in that order from then on. */
void NSCDCopyExchange::plan(const std::vector<Origin> &origins, MPI_Comm world, NSCDCommCount &counts, int kind)
{
  world_ = world;
  origins_ = origins;
  int me = 0, nprocs = 1;
  MPI_Comm_rank(world, &me);
  MPI_Comm_size(world, &nprocs);
  std::map<int, Peer> by_owner;
  self.clear();
  for (int c = 0; c < (int) origins.size(); c++) {
    const Origin &o = origins[c];
    if (o.rank == me) self.push_back({o.index, c});
    else by_owner[o.rank].items.push_back(c);
  }
  owners.clear();
  std::vector<int> wanted(nprocs, 0), asked(nprocs, 0);
  for (auto &entry : by_owner) {
    entry.second.rank = entry.first;
    wanted[entry.first] = (int) entry.second.items.size();
    owners.push_back(std::move(entry.second));
  }
  MPI_Alltoall(wanted.data(), 1, MPI_INT, asked.data(), 1, MPI_INT, world);
  holders.clear();
  for (int r = 0; r < nprocs; r++)
    if (asked[r] > 0 && r != me) holders.push_back({r, std::vector<int>(asked[r]), {}});

  // the owners' indices of the wanted copies, as doubles (counted like the other messages)
  requests.assign(owners.size() + holders.size(), MPI_REQUEST_NULL);
  for (size_t p = 0; p < holders.size(); p++) {
    holders[p].buffer.resize(holders[p].items.size());
    MPI_Irecv(holders[p].buffer.data(), (int) holders[p].buffer.size(), MPI_DOUBLE, holders[p].rank, PLAN_TAG, world,
              &requests[p]);
  }
  for (size_t p = 0; p < owners.size(); p++) {
    owners[p].buffer.clear();
    for (int c : owners[p].items) owners[p].buffer.push_back(origins[c].index);
    MPI_Isend(owners[p].buffer.data(), (int) owners[p].buffer.size(), MPI_DOUBLE, owners[p].rank, PLAN_TAG, world,
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
    f.buffer.resize((size_t) width * f.items.size());
    MPI_Irecv(f.buffer.data(), (int) f.buffer.size(), MPI_DOUBLE, f.rank, tag, world_, &requests[p]);
  }
  for (size_t p = 0; p < to.size(); p++)
    MPI_Isend(to[p].buffer.data(), (int) to[p].buffer.size(), MPI_DOUBLE, to[p].rank, tag, world_,
              &requests[from.size() + p]);
  MPI_Waitall((int) requests.size(), requests.data(), MPI_STATUSES_IGNORE);
  for (const Peer &f : from) counts.received(kind, (int) f.items.size(), (int) f.buffer.size());
}

/* Each field: 3 doubles per item, the owned items first and the copies from `first_copy` on.
   (Plain loops over 3 doubles: this runs twice per wire substep.) */
double NSCDCopyExchange::forward(const std::vector<double *> &fields, int first_copy, NSCDCommCount &counts, int kind)
{
  const int nf = (int) fields.size(), width = 3 * nf;
  double *const *field = fields.data();
  double packed = 0.0;
  for (Peer &h : holders) {
    h.buffer.resize((size_t) width * h.items.size());
    double *b = h.buffer.data();
    for (int i : h.items)
      for (int f = 0; f < nf; f++, b += 3) std::copy(field[f] + 3 * (size_t) i, field[f] + 3 * (size_t) i + 3, b);
    packed += (double) h.buffer.size();
  }
  swap_buffers(owners, holders, width, FORWARD_TAG, counts, kind);
  // a copy is its owner's item, the first field (a position) at the copy's periodic image;
  // `value(f)`: the item's 3 values of field f
  auto place = [&](int c, auto value) {
    const double *shift = origins_[c].shift.data(), *x = value(0);
    double *copy = field[0] + 3 * ((size_t) first_copy + c);
    for (int d = 0; d < 3; d++) copy[d] = x[d] + shift[d];
    for (int f = 1; f < nf; f++) std::copy(value(f), value(f) + 3, field[f] + 3 * ((size_t) first_copy + c));
  };
  for (const std::array<int, 2> &s : self) place(s[1], [&](int f) { return field[f] + 3 * (size_t) s[0]; });
  packed += (double) width * self.size();
  for (const Peer &o : owners)
    for (size_t k = 0; k < o.items.size(); k++) {
      const double *b = &o.buffer[(size_t) width * k];
      place(o.items[k], [&](int f) { return b + 3 * f; });
    }
  return packed;
}

double NSCDCopyExchange::reverse(double *field, int first_copy, NSCDCommCount &counts, int kind)
{
  const double *copies = field + 3 * (size_t) first_copy;
  double packed = 0.0;
  for (Peer &o : owners) {
    o.buffer.resize(3 * o.items.size());
    double *b = o.buffer.data();
    for (int c : o.items) b = std::copy(copies + 3 * (size_t) c, copies + 3 * (size_t) c + 3, b);
    packed += (double) o.buffer.size();
  }
  swap_buffers(holders, owners, 3, REVERSE_TAG, counts, kind);
  auto add = [&](const double *value, int i) {
    for (int d = 0; d < 3; d++) field[3 * (size_t) i + d] += value[d];
  };
  for (const std::array<int, 2> &s : self) add(copies + 3 * (size_t) s[1], s[0]);
  packed += 3.0 * self.size();
  for (const Peer &h : holders)
    for (size_t k = 0; k < h.items.size(); k++) add(&h.buffer[3 * k], h.items[k]);
  return packed;
}

std::size_t NSCDCopyExchange::memory_bytes() const
{
  std::size_t bytes = nscd::capacity_bytes(self) + nscd::capacity_bytes(origins_) + nscd::capacity_bytes(requests) +
      nscd::capacity_bytes(owners) + nscd::capacity_bytes(holders);
  for (const std::vector<Peer> *peers : {&owners, &holders})
    for (const Peer &p : *peers) bytes += nscd::capacity_bytes(p.items) + nscd::capacity_bytes(p.buffer);
  return bytes;
}
