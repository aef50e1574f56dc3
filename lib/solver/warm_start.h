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

// Warm start of the Gauss-Seidel from the previous step's impulses, matched by contact key.
#pragma once

#include "solver/contact_problem.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace nscd {

// One stored impulse as plain data, so it can be sent as bytes (MPI) and written to files:
// the impulse on the body named by tag_i, world frame.
struct ImpulseRecord {
  std::int64_t tag_i = 0;
  std::int64_t tag_j = 0;
  std::uint64_t feature = 0;
  double impulse[3] = {0.0, 0.0, 0.0};
};

ImpulseRecord record_of(const Contact &contact);
// The same record seen from its other body (tags swapped, impulse on that body): a contact
// kept with each of its two atoms is stored once from each side. The feature code is kept:
// it names the feature pair whichever body comes first (see WarmStartCache).
ImpulseRecord reversed(const ImpulseRecord &record);

// Remembers the solved impulses of one step and hands them to the next step's contacts.
// Keys are canonicalised so the body order does not matter: a key stored as (a, b, f)
// with impulse P on a is found again as (b, a, f) with impulse -P. The feature code f must
// therefore name the touching feature pair independently of the body order.
// Storage is one sorted vector reused between steps (lookup by binary search), so after the
// first steps neither store() nor apply() allocates.
class WarmStartCache {
 public:
  // Call after the solve (after ContactProblem::finish()).
  void store(const std::vector<Contact> &contacts);
  // The same from plain records (those kept with the atoms, a restart file); a key given
  // twice (a contact seen from both of its bodies) is kept once.
  void store(const std::vector<ImpulseRecord> &records);

  // Sets every contact's impulse to its stored value, or zero for a new contact.
  // Returns how many contacts were found.
  long apply(std::vector<Contact> &contacts) const;
  // Empties the cache and gives its memory back (the impulses now live elsewhere).
  void release();

  std::size_t size() const { return entries_.size(); }
  // The stored entries as records (canonical: tag_i <= tag_j).
  std::vector<ImpulseRecord> records() const;
  // Bytes held on the heap (the stored entries, at capacity).
  std::size_t memory_bytes() const;

 private:
  struct Entry {
    ContactKey key;    // canonical: tag_i <= tag_j
    Vec3 impulse;      // on the body named by key.tag_i
  };
  std::vector<Entry> entries_;

  void add(ContactKey key, const Vec3 &impulse, std::size_t at);
  void sort_entries();
  // Index of the entry of this contact's key, or -1; sign tells how the impulse turns.
  long find(const Contact &contact, double &sign) const;
};

}    // namespace nscd
