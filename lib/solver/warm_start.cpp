#include "solver/warm_start.h"

#include <algorithm>
#include <tuple>

namespace nscd {
namespace {

bool key_less(const ContactKey &a, const ContactKey &b)
{
  return std::tie(a.tag_i, a.tag_j, a.feature) < std::tie(b.tag_i, b.tag_j, b.feature);
}

bool key_equal(const ContactKey &a, const ContactKey &b)
{
  return a.tag_i == b.tag_i && a.tag_j == b.tag_j && a.feature == b.feature;
}

// Swaps the tags into increasing order; returns -1 when the impulse must change sign.
double canonicalise(ContactKey &key)
{
  if (key.tag_i <= key.tag_j) return 1.0;
  std::swap(key.tag_i, key.tag_j);
  return -1.0;
}

}    // namespace

void WarmStartCache::store(const std::vector<Contact> &contacts)
{
  entries_.resize(contacts.size());
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    Entry &entry = entries_[c];
    entry.key = contacts[c].key;
    entry.impulse = canonicalise(entry.key) * contacts[c].impulse;
  }
  std::sort(entries_.begin(), entries_.end(),
            [](const Entry &a, const Entry &b) { return key_less(a.key, b.key); });
}

long WarmStartCache::apply(std::vector<Contact> &contacts) const
{
  long found = 0;
  for (Contact &contact : contacts) {
    ContactKey key = contact.key;
    const double sign = canonicalise(key);
    const auto it = std::lower_bound(
        entries_.begin(), entries_.end(), key,
        [](const Entry &entry, const ContactKey &k) { return key_less(entry.key, k); });
    if (it != entries_.end() && key_equal(it->key, key)) {
      contact.impulse = sign * it->impulse;
      ++found;
    } else {
      contact.impulse.setZero();
    }
  }
  return found;
}

}    // namespace nscd
