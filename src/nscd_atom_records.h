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

/* Contact state kept with the atoms, as LAMMPS' fix neigh/history keeps pair granular's
   shear history: per atom, a list of records (fix nscd: warm-start impulses,
   nscd::ImpulseRecord; fix wire: friction memories, nscd::wire::StoredContact). Each fix
   decides which atom keeps which record; the lists travel with their atoms (exchange,
   restart files, reverse communication) as doubles: {count, count x the record's bytes}.
   Plain C++; the fixes do the LAMMPS side. */

#ifndef LMP_NSCD_ATOM_RECORDS_H
#define LMP_NSCD_ATOM_RECORDS_H

#include "math/capacity_bytes.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

template <class Record> class NSCDAtomRecords {
  static_assert(std::is_trivially_copyable<Record>::value && sizeof(Record) % sizeof(double) == 0,
                "a record travels as whole doubles");

 public:
  static constexpr int VALUES_PER_RECORD = (int) (sizeof(Record) / sizeof(double));

  void grow(int nmax) { lists.resize(nmax); }
  void copy(int from, int to)
  {
    if (from != to) lists[to] = lists[from];
  }
  // Empties the atom's list and gives its memory back.
  void clear(int i) { std::vector<Record>().swap(lists[i]); }
  void add(int i, const Record &record) { lists[i].push_back(record); }
  const std::vector<Record> &of(int i) const { return lists[i]; }
  void set(int i, std::vector<Record> records) { lists[i] = std::move(records); }

  // Doubles that pack() writes for atom i, and for an atom of `count` records.
  int values(int i) const { return values_for(lists[i].size()); }
  static int values_for(std::size_t count) { return 1 + VALUES_PER_RECORD * (int) count; }
  int pack(int i, double *buf) const
  {
    const std::vector<Record> &list = lists[i];
    buf[0] = (double) list.size();
    if (!list.empty()) std::memcpy(buf + 1, list.data(), list.size() * sizeof(Record));
    return values_for(list.size());
  }
  // Packs at most `most` of atom i's last records in the same layout and removes them.
  int pack_last(int i, int most, double *buf)
  {
    std::vector<Record> &list = lists[i];
    const std::size_t count = std::min(list.size(), (std::size_t) most);
    buf[0] = (double) count;
    if (count) std::memcpy(buf + 1, list.data() + list.size() - count, count * sizeof(Record));
    list.resize(list.size() - count);
    if (list.empty()) clear(i);
    return values_for(count);
  }
  // Appends the records packed at buf to atom i's list; returns the doubles read.
  int unpack_append(int i, const double *buf)
  {
    const auto count = (std::size_t) buf[0];
    std::vector<Record> &list = lists[i];
    const std::size_t before = list.size();
    list.resize(before + count);
    // Bytes into constructed records: valid for a trivially copyable Record (asserted above);
    // through void * because GCC's -Wclass-memaccess asks for a trivial one.
    if (count) std::memcpy(static_cast<void *>(list.data() + before), buf + 1, count * sizeof(Record));
    return values_for(count);
  }
  // Moves the lists of atoms first .. first + n - 1 to the end of `out`, emptying them.
  void move_all(int first, int n, std::vector<Record> &out)
  {
    out.reserve(out.size() + count(first, n));
    for (int i = first; i < first + n; i++) {
      out.insert(out.end(), lists[i].begin(), lists[i].end());
      clear(i);
    }
  }

  // Records held by the atoms first .. first + n - 1, and the longest of their lists.
  std::size_t count(int first, int n) const
  {
    std::size_t total = 0;
    for (int i = first; i < first + n; i++) total += lists[i].size();
    return total;
  }
  std::size_t longest(int first, int n) const
  {
    std::size_t most = 0;
    for (int i = first; i < first + n; i++) most = std::max(most, lists[i].size());
    return most;
  }
  // Bytes on the heap (the lists at capacity and the table of lists).
  std::size_t memory_bytes() const
  {
    std::size_t bytes = nscd::capacity_bytes(lists);
    for (const auto &list : lists) bytes += nscd::capacity_bytes(list);
    return bytes;
  }

 private:
  std::vector<std::vector<Record>> lists;
};

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
