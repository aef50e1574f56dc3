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

TEST(WarmStartCache, ReportsMissedContactsAndUnusedEntries)
{
  WarmStartCache cache;
  cache.store({keyed(4, 9, 1, Vec3(1.0, 2.0, 3.0)), keyed(9, 2, 0, Vec3(-1.0, 0.5, 0.0)),
               keyed(4, 9, 2, Vec3(7.0, 0.0, 0.0))});
  std::vector<Contact> next = {keyed(5, 6, 0, Vec3::Constant(3.0)),     // new
                               keyed(9, 4, 1, Vec3::Zero()),             // found, swapped
                               keyed(4, 9, 7, Vec3::Constant(3.0))};     // new feature
  WarmStartLeftovers leftovers;
  EXPECT_EQ(cache.apply(next, &leftovers), 1);
  EXPECT_EQ(leftovers.missed, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(next[0].impulse, Vec3::Zero());    // a miss still starts cold unless handed over
  ASSERT_EQ(leftovers.unused.size(), 2u);      // canonical order: tag_i <= tag_j, sorted
  const ImpulseRecord &a = leftovers.unused[0], &b = leftovers.unused[1];
  EXPECT_EQ(a.tag_i, 2);
  EXPECT_EQ(a.tag_j, 9);
  EXPECT_EQ(a.feature, 0u);
  EXPECT_EQ(Vec3(a.impulse[0], a.impulse[1], a.impulse[2]), Vec3(1.0, -0.5, 0.0));
  EXPECT_EQ(b.tag_i, 4);
  EXPECT_EQ(b.feature, 2u);
  EXPECT_EQ(Vec3(b.impulse[0], b.impulse[1], b.impulse[2]), Vec3(7.0, 0.0, 0.0));

  // a second apply starts the report afresh
  std::vector<Contact> all_found = {keyed(2, 9, 0, Vec3::Zero())};
  EXPECT_EQ(cache.apply(all_found, &leftovers), 1);
  EXPECT_TRUE(leftovers.missed.empty());
  EXPECT_EQ(leftovers.unused.size(), 2u);
}

TEST(WarmStartCache, AppliesRecordsOnlyToTheListedContacts)
{
  WarmStartCache from_records;
  from_records.store(std::vector<ImpulseRecord>{record_of(keyed(4, 9, 1, Vec3(1.0, 2.0, 3.0))),
                                                record_of(keyed(8, 3, 5, Vec3(0.0, 1.0, 0.0)))});
  std::vector<Contact> next = {keyed(9, 4, 1, Vec3::Constant(2.0)),     // listed, swapped
                               keyed(3, 8, 5, Vec3::Constant(2.0)),     // not listed
                               keyed(1, 2, 0, Vec3::Constant(2.0))};    // listed, not held
  EXPECT_EQ(from_records.apply_to(next, {0, 2}), 1);
  EXPECT_EQ(next[0].impulse, Vec3(-1.0, -2.0, -3.0));
  EXPECT_EQ(next[1].impulse, Vec3::Constant(2.0));
  EXPECT_EQ(next[2].impulse, Vec3::Constant(2.0));
}

// Two ranks: a grain-grain and a boundary contact (negative tag) solved on rank A move to
// rank B. B misses them, A leaves them unused, and B finds them among A's leftovers with
// the impulses a single cache would have given.
TEST(WarmStartCache, HandsImpulsesOverBetweenTwoRanksCaches)
{
  const std::int64_t wall = -77;
  const std::vector<Contact> solved_on_a = {keyed(3, 1, 4, Vec3(0.5, -0.2, 0.1)),
                                            keyed(1, wall, 9, Vec3(2.0, 0.0, -0.3)),
                                            keyed(2, 1, 0, Vec3(1.0, 1.0, 1.0))};
  const std::vector<Contact> solved_on_b = {keyed(5, 6, 2, Vec3(4.0, 0.0, 0.0))};
  WarmStartCache rank_a, rank_b, single;
  rank_a.store(solved_on_a);
  rank_b.store(solved_on_b);
  single.store({solved_on_a[0], solved_on_a[1], solved_on_a[2], solved_on_b[0]});

  std::vector<Contact> now_on_a = {keyed(1, 2, 0, Vec3::Zero())};
  std::vector<Contact> now_on_b = {keyed(6, 5, 2, Vec3::Zero()), keyed(1, 3, 4, Vec3::Zero()),
                                   keyed(wall, 1, 9, Vec3::Zero())};
  std::vector<Contact> expected = now_on_b;
  EXPECT_EQ(single.apply(expected), 3);

  WarmStartLeftovers left_a, left_b;
  EXPECT_EQ(rank_a.apply(now_on_a, &left_a), 1);
  EXPECT_EQ(rank_b.apply(now_on_b, &left_b), 1);
  EXPECT_TRUE(left_a.missed.empty());
  EXPECT_EQ(left_b.missed, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(left_a.unused.size(), 2u);
  EXPECT_TRUE(left_b.unused.empty());

  WarmStartCache handed_over;    // what an all-gather of every rank's unused entries gives B
  handed_over.store(left_a.unused);
  EXPECT_EQ(handed_over.apply_to(now_on_b, left_b.missed), 2);
  for (std::size_t c = 0; c < now_on_b.size(); ++c)
    EXPECT_EQ(now_on_b[c].impulse, expected[c].impulse) << "contact " << c;
}
