// SlotSet (par/slot_set.hpp) against std::set: random insertions, look-ups and clears,
// over slots that make it grow, and many epochs.
#include "par/slot_set.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>

namespace pdr::par {
namespace {

RC_GTEST_PROP(SlotSet, BehavesAsASetClearedAtOnce, ()) {
  SlotSet s;
  std::set<TetId> ref;
  const int ops = *rc::gen::inRange(1, 600);
  const TetId range = *rc::gen::element<TetId>(8, 300, 70000);
  for (int i = 0; i < ops; ++i) {
    const TetId t = *rc::gen::inRange<TetId>(0, range);
    switch (*rc::gen::inRange(0, 8)) {
      case 0:
        s.clear();
        ref.clear();
        break;
      case 1:
      case 2:
      case 3:
        s.insert(t);
        ref.insert(t);
        break;
      default:
        break;
    }
    RC_ASSERT(s.contains(t) == (ref.count(t) != 0));
  }
  for (TetId t = 0; t < range && t < 1000; ++t) RC_ASSERT(s.contains(t) == (ref.count(t) != 0));
}

TEST(SlotSet, ARangeAndSlotsBeyondItsSize) {
  SlotSet s;
  const TetId a[] = {5, 1, 4000000, 7};
  s.insert(std::begin(a), std::end(a));
  for (const TetId t : a) EXPECT_TRUE(s.contains(t));
  EXPECT_FALSE(s.contains(2));
  EXPECT_FALSE(s.contains(4000001));  // past the stamps: in no epoch
  EXPECT_FALSE(s.contains(kNoTet));
  s.clear();
  for (const TetId t : a) EXPECT_FALSE(s.contains(t));
  s.insert(1);
  EXPECT_TRUE(s.contains(1));
  EXPECT_FALSE(s.contains(5));
}

}  // namespace
}  // namespace pdr::par
