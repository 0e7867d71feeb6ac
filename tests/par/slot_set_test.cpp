// SlotSet (par/slot_set.hpp) against std::set: random insertions, look-ups and clears,
// runs of neighbouring slots that make its table grow, and many epochs.
#include "par/slot_set.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>
#include <vector>

namespace pdr::par {
namespace {

RC_GTEST_PROP(SlotSet, BehavesAsASetClearedAtOnce, ()) {
  SlotSet s;
  std::set<TetId> ref;
  const int ops = *rc::gen::inRange(1, 600);
  const TetId range = *rc::gen::element<TetId>(8, 300, 70000, 4000000000u);
  for (int i = 0; i < ops; ++i) {
    const TetId t = *rc::gen::inRange<TetId>(0, range);
    const int op = *rc::gen::inRange(0, 40);
    if (op == 0) {
      s.clear();
      ref.clear();
    } else if (op < 16) {
      s.insert(t);
      ref.insert(t);
    } else if (op == 16) {  // a run of neighbouring slots, as a cavity's: the table grows
      const TetId n = *rc::gen::inRange<TetId>(1, 200);
      std::vector<TetId> run;
      for (TetId k = 0; k < n && t + k < range; ++k) run.push_back(t + k);
      s.insert(run.begin(), run.end());
      ref.insert(run.begin(), run.end());
    }
    RC_ASSERT(s.contains(t) == (ref.count(t) != 0));
    RC_ASSERT(s.size() == ref.size());
  }
  for (TetId t = 0; t < range && t < 1000; ++t) RC_ASSERT(s.contains(t) == (ref.count(t) != 0));
  for (const TetId t : ref) RC_ASSERT(s.contains(t));
}

// The epoch counter wraps after 2^32 - 1 clears: entries written in the first epochs
// must not count as members of the same-numbered epochs after the wrap.
TEST(SlotSet, ClearsAcrossTheEpochWrap) {
  SlotSet s;
  s.insert(3);  // epoch 1
  s.clear();
  s.insert(70);  // epoch 2
  s.clear_to_epoch_for_tests(0xFFFFFFFFu);
  s.insert(5);
  EXPECT_TRUE(s.contains(5));
  EXPECT_FALSE(s.contains(3));
  EXPECT_FALSE(s.contains(70));
  for (std::uint32_t epoch = 1; epoch <= 3; ++epoch) {
    s.clear();  // the first wraps: epoch 1 again, then 2, 3
    EXPECT_EQ(s.size(), 0u);
    s.insert(9);  // a member, so look-ups probe the table
    EXPECT_TRUE(s.contains(9));
    for (const TetId t : {3u, 5u, 70u}) EXPECT_FALSE(s.contains(t)) << t << " in epoch " << epoch;
    s.insert(3);
    EXPECT_EQ(s.size(), 2u);
  }
}

TEST(SlotSet, ARangeAndSlotsBeyondItsSize) {
  SlotSet s;
  const TetId a[] = {5, 1, 4000000, 7};
  s.insert(std::begin(a), std::end(a));
  for (const TetId t : a) EXPECT_TRUE(s.contains(t));
  EXPECT_FALSE(s.contains(2));
  EXPECT_FALSE(s.contains(4000001));
  EXPECT_FALSE(s.contains(kNoTet));
  s.clear();
  for (const TetId t : a) EXPECT_FALSE(s.contains(t));
  s.insert(1);
  EXPECT_TRUE(s.contains(1));
  EXPECT_FALSE(s.contains(5));
}

}  // namespace
}  // namespace pdr::par
