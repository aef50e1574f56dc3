// Warm start of the Gauss-Seidel from the previous step's impulses, matched by contact key.
#pragma once

#include "solver/contact_problem.h"

#include <vector>

namespace nscd {

// Remembers the solved impulses of one step and hands them to the next step's contacts.
// Keys are canonicalised so the body order does not matter: a key stored as (a, b, f)
// with impulse P on a is found again as (b, a, f) with impulse -P. The feature code f must
// therefore name the touching feature pair independently of the body order.
// Storage is one sorted vector reused between steps (lookup by binary search), so after the
// first steps neither call allocates.
class WarmStartCache {
 public:
  // Call after the solve (after ContactProblem::finish()).
  void store(const std::vector<Contact> &contacts);

  // Sets every contact's impulse to its stored value, or zero for a new contact.
  // Returns how many contacts were found.
  long apply(std::vector<Contact> &contacts) const;

  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    ContactKey key;    // canonical: tag_i <= tag_j
    Vec3 impulse;      // on the body named by key.tag_i
  };
  std::vector<Entry> entries_;
};

}    // namespace nscd
