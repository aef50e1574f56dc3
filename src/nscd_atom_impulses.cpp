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

/* Warm-start impulses kept with the atoms (nscd_atom_impulses.h). */

#include "nscd_atom_impulses.h"

#include "math/capacity_bytes.h"

#include <algorithm>
#include <cstring>

namespace LAMMPS_NS {

int NSCDAtomImpulses::pack(int i, double *buf) const
{
  const std::vector<nscd::ImpulseRecord> &list = lists[i];
  buf[0] = (double) list.size();
  if (!list.empty()) std::memcpy(buf + 1, list.data(), list.size() * sizeof(nscd::ImpulseRecord));
  return values_for(list.size());
}

int NSCDAtomImpulses::pack_last(int i, int most, double *buf)
{
  std::vector<nscd::ImpulseRecord> &list = lists[i];
  const std::size_t count = std::min(list.size(), (std::size_t) most);
  buf[0] = (double) count;
  if (count) std::memcpy(buf + 1, list.data() + list.size() - count, count * sizeof(nscd::ImpulseRecord));
  list.resize(list.size() - count);
  if (list.empty()) clear(i);
  return values_for(count);
}

int NSCDAtomImpulses::unpack_append(int i, const double *buf)
{
  const auto count = (std::size_t) buf[0];
  std::vector<nscd::ImpulseRecord> &list = lists[i];
  const std::size_t before = list.size();
  list.resize(before + count);
  if (count) std::memcpy(list.data() + before, buf + 1, count * sizeof(nscd::ImpulseRecord));
  return values_for(count);
}

std::size_t NSCDAtomImpulses::count(int first, int n) const
{
  std::size_t total = 0;
  for (int i = first; i < first + n; i++) total += lists[i].size();
  return total;
}

std::size_t NSCDAtomImpulses::longest(int first, int n) const
{
  std::size_t most = 0;
  for (int i = first; i < first + n; i++) most = std::max(most, lists[i].size());
  return most;
}

std::size_t NSCDAtomImpulses::memory_bytes() const
{
  std::size_t bytes = nscd::capacity_bytes(lists);
  for (const auto &list : lists) bytes += nscd::capacity_bytes(list);
  return bytes;
}

}    // namespace LAMMPS_NS
