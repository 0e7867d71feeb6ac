// GrowingArray (mesh/growing_array.hpp) against std::vector: random sequences of its
// operations, with elements whose default value is not zero bytes and sizes that cross
// from malloc'd buffers to mappings grown by mremap, then copies and moves of the result.
#include "mesh/growing_array.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pdr {
namespace {

// 1 KiB with a non-zero default: 2,048 of them fill the 2 MiB from which buffers are
// mappings.
struct Big {
  std::uint64_t tag = 0xC0FFEEull;
  std::array<std::uint32_t, 254> pad{};
  bool operator==(const Big&) const = default;
};
static_assert(sizeof(Big) == 1024);

Big big(std::uint64_t v) {
  Big b;
  b.tag = v;
  b.pad[253] = static_cast<std::uint32_t>(v * 7);
  return b;
}

template <class T>
void expect_same(const GrowingArray<T>& a, const std::vector<T>& v) {
  RC_ASSERT(a.size() == v.size());
  RC_ASSERT(a.capacity() >= a.size());
  RC_ASSERT(a.empty() == v.empty());
  for (std::size_t i = 0; i < v.size(); ++i) RC_ASSERT(a[i] == v[i]);
  RC_ASSERT(static_cast<std::size_t>(a.end() - a.begin()) == v.size());
}

RC_GTEST_PROP(GrowingArray, BehavesAsAVector, ()) {
  GrowingArray<Big> a;
  std::vector<Big> v;
  const int ops = *rc::gen::inRange(1, 60);
  for (int i = 0; i < ops; ++i) {
    const std::size_t n = *rc::gen::inRange<std::size_t>(0, 6000);
    const auto x = *rc::gen::arbitrary<std::uint64_t>();
    switch (*rc::gen::inRange(0, 9)) {
      case 0:
      case 1: {
        const int k = *rc::gen::inRange(1, 700);
        for (int j = 0; j < k; ++j) {
          a.push_back(big(x + static_cast<std::uint64_t>(j)));
          v.push_back(big(x + static_cast<std::uint64_t>(j)));
        }
        break;
      }
      case 2:
        a.resize(n);
        v.resize(n);
        break;
      case 3:
        a.resize(n, big(x));
        v.resize(n, big(x));
        break;
      case 4:
        a.reserve(n);
        v.reserve(n);
        RC_ASSERT(a.capacity() >= n);
        break;
      case 5: {
        const std::size_t k = v.empty() ? 0 : n % (v.size() + 1);
        a.erase(a.begin(), a.begin() + k);
        v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k));
        break;
      }
      case 6:
        a.assign(n % 3000, big(x));
        v.assign(n % 3000, big(x));
        break;
      case 7:
        if (!v.empty()) {  // an element pushed onto its own array as it grows
          a.push_back(a.back());
          v.push_back(v.back());
        }
        break;
      default:
        a.clear();
        v.clear();
        break;
    }
    expect_same(a, v);
  }
  GrowingArray<Big> copy(a);
  expect_same(copy, v);
  GrowingArray<Big> moved(std::move(copy));
  expect_same(moved, v);
  RC_ASSERT(copy.empty());
  GrowingArray<Big> assigned;
  assigned.push_back(big(1));
  assigned = moved;
  expect_same(assigned, v);
  assigned = GrowingArray<Big>(3, big(5));
  expect_same(assigned, std::vector<Big>(3, big(5)));
}

TEST(GrowingArray, KeepsItsContentsAcrossManyGrowths) {
  GrowingArray<std::uint32_t> a;
  for (std::uint32_t i = 0; i < 20'000'000; ++i) a.push_back(i * 2654435761u);
  for (std::uint32_t i = 0; i < 20'000'000; i += 9973) ASSERT_EQ(a[i], i * 2654435761u);
  ASSERT_EQ(a.size(), 20'000'000u);
  // A buffer this large is a mapping at a 2 MiB boundary (huge pages can back all of it).
  if (growing_array_detail::kCanMap) {
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % (std::uintptr_t{1} << 21), 0u);
  }
  a.resize(5);
  EXPECT_EQ(a[4], 4u * 2654435761u);
  EXPECT_THROW((void)a.at(5), std::out_of_range);
}

TEST(GrowingArray, ValueInitializesWhatResizeAdds) {
  struct Marked {
    std::uint32_t v = 7;
  };
  GrowingArray<Marked> a;
  a.resize(3'000'000);  // a mapping: fresh pages are zero, the elements must not be
  EXPECT_EQ(a[0].v, 7u);
  EXPECT_EQ(a[2'999'999].v, 7u);
  a[5].v = 1;
  a.resize(2);
  a.resize(10);  // what comes back is new
  EXPECT_EQ(a[5].v, 7u);
}

}  // namespace
}  // namespace pdr
