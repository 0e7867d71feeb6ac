// FlatHashMap (par/flat_hash_map.hpp) against std::map: random insertions, look-ups and
// erasures, with a hash that puts many keys in the same home slot so that probe runs
// wrap around the table and erase() must shift entries back (H1, H2).
#include "par/flat_hash_map.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <map>

namespace pdr::par {
namespace {

// 8 homes at the end of the table, whatever its size: long runs that wrap around, and
// shifts across the table's end.
struct Crowded {
  std::size_t operator()(std::uint64_t k) const { return ~std::size_t{0} - static_cast<std::size_t>(k % 8) * 3; }
};

RC_GTEST_PROP(FlatHashMap, BehavesAsAMap, ()) {
  FlatHashMap<std::uint64_t, int, Crowded> m;
  std::map<std::uint64_t, int> ref;
  const int ops = *rc::gen::inRange(1, 400);
  for (int i = 0; i < ops; ++i) {
    const std::uint64_t k = *rc::gen::inRange<std::uint64_t>(0, 60);
    switch (*rc::gen::inRange(0, 3)) {
      case 0: {
        const int v = *rc::gen::arbitrary<int>();
        m[k] = v;
        ref[k] = v;
        break;
      }
      case 1:
        RC_ASSERT(m.erase(k) == (ref.erase(k) == 1));
        break;
      default:
        break;
    }
    RC_ASSERT(m.size() == ref.size());
    for (std::uint64_t q = 0; q < 60; ++q) {
      const int* got = m.find(q);
      const auto it = ref.find(q);
      RC_ASSERT((got != nullptr) == (it != ref.end()));
      if (got) RC_ASSERT(*got == it->second);
    }
  }
}

TEST(FlatHashMap, MovedFromIsEmptyAndUsable) {
  FlatHashMap<std::uint64_t, int, Crowded> a;
  for (std::uint64_t k = 0; k < 40; ++k) a[k] = static_cast<int>(k);
  FlatHashMap<std::uint64_t, int, Crowded> b = std::move(a);
  EXPECT_EQ(b.size(), 40u);
  EXPECT_EQ(*b.find(7), 7);
  EXPECT_EQ(a.size(), 0u);  // NOLINT(bugprone-use-after-move): the contract under test
  EXPECT_EQ(a.find(7), nullptr);
  EXPECT_FALSE(a.erase(7));
  a[3] = 9;
  EXPECT_EQ(*a.find(3), 9);
  b = std::move(a);
  EXPECT_EQ(b.size(), 1u);
  EXPECT_EQ(a.find(3), nullptr);
}

}  // namespace
}  // namespace pdr::par
