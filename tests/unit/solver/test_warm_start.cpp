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

#include <gtest/gtest.h>

using namespace nscd;

namespace {
Contact keyed(std::int64_t tag_i, std::int64_t tag_j, std::uint64_t feature, const Vec3 &impulse)
{
  Contact contact;
  contact.key = {tag_i, tag_j, feature};
  contact.impulse = impulse;
  return contact;
}
}    // namespace

TEST(WarmStartCache, FindsImpulsesByKeyWhateverTheBodyOrder)
{
  WarmStartCache cache;
  cache.store({keyed(4, 9, 1, Vec3(1.0, 2.0, 3.0)), keyed(9, 2, 0, Vec3(-1.0, 0.5, 0.0)),
               keyed(4, 9, 2, Vec3(7.0, 0.0, 0.0))});
  std::vector<Contact> next = {keyed(9, 4, 1, Vec3::Constant(99.0)),    // swapped bodies
                               keyed(2, 9, 0, Vec3::Zero()),            // swapped bodies
                               keyed(4, 9, 2, Vec3::Zero()),            // same order
                               keyed(4, 9, 3, Vec3::Constant(5.0))};    // new feature
  EXPECT_EQ(cache.apply(next), 3);
  EXPECT_EQ(next[0].impulse, Vec3(-1.0, -2.0, -3.0));
  EXPECT_EQ(next[1].impulse, Vec3(1.0, -0.5, 0.0));
  EXPECT_EQ(next[2].impulse, Vec3(7.0, 0.0, 0.0));
  EXPECT_EQ(next[3].impulse, Vec3::Zero());
}

// Each contact kept with both of its atoms (fix nscd under domain decomposition): a rank
// that holds either atom's records finds every contact of that atom with the impulse a
// single cache gives, whichever body comes first in the new contact.
TEST(WarmStartCache, RecordsSeenFromEitherBodyGiveTheSameImpulses)
{
  const std::int64_t wall = -77;
  const std::vector<Contact> solved = {keyed(1, 3, 4, Vec3(0.5, -0.2, 0.1)),
                                       keyed(1, wall, 9, Vec3(2.0, 0.0, -0.3)),
                                       keyed(2, 3, 0, Vec3(1.0, 1.0, 1.0))};
  WarmStartCache single;
  single.store(solved);
  std::vector<Contact> next = {keyed(3, 1, 4, Vec3::Zero()), keyed(1, wall, 9, Vec3::Zero()),
                               keyed(2, 3, 0, Vec3::Zero())};
  std::vector<Contact> expected = next;
  EXPECT_EQ(single.apply(expected), 3);

  // the records atom 3 keeps: both of its contacts seen from its side
  const ImpulseRecord seen_by_3[] = {reversed(record_of(solved[0])), reversed(record_of(solved[2]))};
  EXPECT_EQ(seen_by_3[0].tag_i, 3);
  EXPECT_EQ(seen_by_3[0].tag_j, 1);
  EXPECT_EQ(seen_by_3[0].feature, 4u);
  EXPECT_EQ(Vec3(seen_by_3[0].impulse[0], seen_by_3[0].impulse[1], seen_by_3[0].impulse[2]), Vec3(-0.5, 0.2, -0.1));
  const ImpulseRecord twice = reversed(reversed(record_of(solved[1])));
  EXPECT_EQ(twice.tag_i, 1);
  EXPECT_EQ(twice.tag_j, wall);
  EXPECT_EQ(Vec3(twice.impulse[0], twice.impulse[1], twice.impulse[2]), Vec3(2.0, 0.0, -0.3));

  WarmStartCache kept;    // atom 3's records and atom 1's (the 1-3 contact then comes twice)
  kept.store(std::vector<ImpulseRecord>{seen_by_3[0], seen_by_3[1], record_of(solved[1]), record_of(solved[0])});
  EXPECT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept.apply(next), 3);
  for (std::size_t c = 0; c < next.size(); ++c) EXPECT_EQ(next[c].impulse, expected[c].impulse) << "contact " << c;

  kept.release();
  EXPECT_EQ(kept.size(), 0u);
  EXPECT_EQ(kept.memory_bytes(), 0u);
}
