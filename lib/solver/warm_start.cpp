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

#include "solver/warm_start.h"

#include "math/capacity_bytes.h"

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

ImpulseRecord record_of(const ContactKey &key, const Vec3 &impulse)
{
  ImpulseRecord r;
  r.tag_i = key.tag_i;
  r.tag_j = key.tag_j;
  r.feature = key.feature;
  for (int d = 0; d < 3; d++) r.impulse[d] = impulse[d];
  return r;
}

}    // namespace

ImpulseRecord record_of(const Contact &contact)
{
  return record_of(contact.key, contact.impulse);
}

ImpulseRecord reversed(const ImpulseRecord &record)
{
  ImpulseRecord r = record;
  std::swap(r.tag_i, r.tag_j);
  for (double &p : r.impulse) p = -p;
  return r;
}

void WarmStartCache::add(ContactKey key, const Vec3 &impulse, std::size_t at)
{
  const double sign = canonicalise(key);
  entries_[at] = {key, sign * impulse};
}

void WarmStartCache::sort_entries()
{
  std::sort(entries_.begin(), entries_.end(),
            [](const Entry &a, const Entry &b) { return key_less(a.key, b.key); });
}

void WarmStartCache::store(const std::vector<Contact> &contacts)
{
  entries_.resize(contacts.size());
  for (std::size_t c = 0; c < contacts.size(); ++c) add(contacts[c].key, contacts[c].impulse, c);
  sort_entries();
}

void WarmStartCache::store(const std::vector<ImpulseRecord> &records)
{
  entries_.resize(records.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    const ImpulseRecord &r = records[k];
    add({r.tag_i, r.tag_j, r.feature}, Vec3(r.impulse[0], r.impulse[1], r.impulse[2]), k);
  }
  sort_entries();
  // A contact kept by both of its atoms comes twice when one rank holds both: keep one.
  entries_.erase(std::unique(entries_.begin(), entries_.end(),
                             [](const Entry &a, const Entry &b) { return key_equal(a.key, b.key); }),
                 entries_.end());
}

long WarmStartCache::find(const Contact &contact, double &sign) const
{
  ContactKey key = contact.key;
  sign = canonicalise(key);
  const auto it = std::lower_bound(
      entries_.begin(), entries_.end(), key,
      [](const Entry &entry, const ContactKey &k) { return key_less(entry.key, k); });
  if (it == entries_.end() || !key_equal(it->key, key)) return -1;
  return (long) (it - entries_.begin());
}

long WarmStartCache::apply(std::vector<Contact> &contacts) const
{
  long found = 0;
  for (Contact &contact : contacts) {
    double sign;
    const long e = find(contact, sign);
    if (e >= 0) {
      contact.impulse = sign * entries_[e].impulse;
      ++found;
    } else {
      contact.impulse.setZero();
    }
  }
  return found;
}

std::vector<ImpulseRecord> WarmStartCache::records() const
{
  std::vector<ImpulseRecord> out;
  out.reserve(entries_.size());
  for (const Entry &e : entries_) out.push_back(record_of(e.key, e.impulse));
  return out;
}

void WarmStartCache::release()
{
  std::vector<Entry>().swap(entries_);
}

std::size_t WarmStartCache::memory_bytes() const
{
  return capacity_bytes(entries_);
}

}    // namespace nscd
