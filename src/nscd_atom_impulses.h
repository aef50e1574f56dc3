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

/* The warm-start impulses kept with the atoms (fix nscd): per atom, the records of its
   contacts seen from it (nscd::ImpulseRecord with tag_i = the atom's ID). A contact between
   two grains is kept by both of its atoms, a boundary contact by its grain, so the rank that
   solves a contact after the atoms moved owns at least one atom that holds its record. The
   lists travel with their atoms (exchange, restart files) as doubles: {count, count x 6
   values}. Plain C++ over lib/solver; fix nscd does the LAMMPS side. */

#ifndef LMP_NSCD_ATOM_IMPULSES_H
#define LMP_NSCD_ATOM_IMPULSES_H

#include "nscd_restart_blocks.h"

#include "solver/warm_start.h"

#include <cstddef>
#include <vector>

namespace LAMMPS_NS {

class NSCDAtomImpulses {
 public:
  static constexpr int kValuesPerRecord = nscd_restart::kValuesPerImpulseRecord;

  void grow(int nmax) { lists.resize(nmax); }
  void copy(int from, int to)
  {
    if (from != to) lists[to] = lists[from];
  }
  // Empties the atom's list and gives its memory back.
  void clear(int i) { std::vector<nscd::ImpulseRecord>().swap(lists[i]); }
  void add(int i, const nscd::ImpulseRecord &record) { lists[i].push_back(record); }
  const std::vector<nscd::ImpulseRecord> &of(int i) const { return lists[i]; }
  void set(int i, std::vector<nscd::ImpulseRecord> records) { lists[i] = std::move(records); }

  // Doubles that pack() writes for atom i, and for an atom of `count` records.
  int values(int i) const { return values_for(lists[i].size()); }
  static int values_for(std::size_t count) { return 1 + kValuesPerRecord * (int) count; }
  int pack(int i, double *buf) const;
  // Packs at most `most` of atom i's last records in the same layout and removes them.
  int pack_last(int i, int most, double *buf);
  // Appends the records packed at buf to atom i's list; returns the doubles read.
  int unpack_append(int i, const double *buf);

  // Records held by the atoms first .. first + n - 1, and the longest of their lists.
  std::size_t count(int first, int n) const;
  std::size_t longest(int first, int n) const;
  // Bytes on the heap (the lists at capacity and the table of lists).
  std::size_t memory_bytes() const;

 private:
  std::vector<std::vector<nscd::ImpulseRecord>> lists;
};

}    // namespace LAMMPS_NS

#endif
