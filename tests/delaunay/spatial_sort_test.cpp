// spatial_sort.hpp: the Hilbert index is a bijection whose consecutive cells are grid
// neighbours, and the BRIO order is a permutation, deterministic for a seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "delaunay/point_sets.hpp"
#include "delaunay/spatial_sort.hpp"

namespace pdr {
namespace {

TEST(Hilbert, ConsecutiveCellsAreNeighbours) {
  for (int bits = 1; bits <= 4; ++bits) {
    const std::uint32_t k = 1u << bits;
    std::vector<std::pair<std::uint64_t, std::array<int, 3>>> cells;
    for (std::uint32_t x = 0; x < k; ++x)
      for (std::uint32_t y = 0; y < k; ++y)
        for (std::uint32_t z = 0; z < k; ++z)
          cells.push_back({hilbert_index(x, y, z, bits), {int(x), int(y), int(z)}});
    std::sort(cells.begin(), cells.end());
    for (std::size_t i = 0; i < cells.size(); ++i) {
      ASSERT_EQ(cells[i].first, i) << "not a bijection onto 0..k^3-1, bits " << bits;
      if (i == 0) continue;
      int d = 0;
      for (int c = 0; c < 3; ++c) d += std::abs(cells[i].second[c] - cells[i - 1].second[c]);
      EXPECT_EQ(d, 1) << "cells " << i - 1 << " and " << i << " not adjacent, bits " << bits;
    }
  }
}

TEST(Brio, IsADeterministicPermutation) {
  const auto pts = testing::random_cube(5000, 9);
  std::vector<std::uint32_t> ids(pts.size());
  std::iota(ids.begin(), ids.end(), 0u);
  const auto a = brio_order(ids, pts, 42, 100);
  EXPECT_EQ(a, brio_order(ids, pts, 42, 100));
  EXPECT_NE(a, brio_order(ids, pts, 43, 100));
  auto sorted = a;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, ids);
}

}  // namespace
}  // namespace pdr
