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
