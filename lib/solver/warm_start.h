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

// What one apply() could not match: under domain decomposition the missed contacts may
// find their impulses among the entries another rank left unused.
struct WarmStartLeftovers {
  std::vector<std::size_t> missed;       // indices of the contacts that found no entry
  std::vector<ImpulseRecord> unused;     // entries that no contact asked for
};

// Remembers the solved impulses of one step and hands them to the next step's contacts.
// Keys are canonicalised so the body order does not matter: a key stored as (a, b, f)
// with impulse P on a is found again as (b, a, f) with impulse -P. The feature code f must
// therefore name the touching feature pair independently of the body order.
// Storage is one sorted vector reused between steps (lookup by binary search), so after the
// first steps neither store() nor apply() without leftovers allocates.
class WarmStartCache {
 public:
  // Call after the solve (after ContactProblem::finish()).
  void store(const std::vector<Contact> &contacts);
  // The same from plain records (a restart file, another rank's leftovers).
  void store(const std::vector<ImpulseRecord> &records);

  // Sets every contact's impulse to its stored value, or zero for a new contact.
  // Returns how many contacts were found. With leftovers, also says which contacts were
  // not found and which entries were not used.
  long apply(std::vector<Contact> &contacts, WarmStartLeftovers *leftovers = nullptr) const;

  // Sets the impulse of each contact listed in `which` that this cache holds and leaves the
  // others as they are. Returns how many were found.
  long apply_to(std::vector<Contact> &contacts, const std::vector<std::size_t> &which) const;

  std::size_t size() const { return entries_.size(); }
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
