// spatial_sort.hpp: the Hilbert index is a bijection whose consecutive cells are grid
// neighbours, the BRIO order is a permutation, deterministic for a seed, and the Hilbert
// order of tets is a permutation that puts consecutive tets near each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <random>

#include "delaunay/bulk.hpp"
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

// The summed distance between consecutive centroids: the order's locality.
double path_length(const Delaunay& dt, const std::vector<TetId>& tets) {
  const TetStore& s = dt.store();
  double total = 0;
  Point prev{};
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const VertexId* v = s.vertices(tets[i]);
    Point c{};
    for (int k = 0; k < 3; ++k)
      c[k] = (dt.point(v[0])[k] + dt.point(v[1])[k] + dt.point(v[2])[k] + dt.point(v[3])[k]) / 4;
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (c[k] - prev[k]) * (c[k] - prev[k]);
    if (i > 0) total += std::sqrt(d2);
    prev = c;
  }
  return total;
}

TEST(HilbertTetOrder, IsAPermutationThatKeepsConsecutiveTetsNear) {
  Delaunay dt(testing::random_cube(4000, 5));
  ASSERT_EQ(bulk_insert(dt, {}).status, BulkStatus::Ok);
  const TetStore& s = dt.store();
  std::vector<TetId> tets;
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t) && !s.is_ghost(t)) tets.push_back(t);
  const std::vector<std::uint32_t> order = hilbert_tet_order(s, dt.points(), tets);
  ASSERT_EQ(order.size(), tets.size());
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  std::vector<TetId> along(tets.size());
  for (std::size_t i = 0; i < order.size(); ++i) along[i] = tets[order[i]];
  // Against the same tets shuffled: along the curve a step is about one tet's size,
  // in a random order about the cube's.
  std::vector<TetId> shuffled = tets;
  std::mt19937_64 rng(7);
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  EXPECT_LT(path_length(dt, along), 0.1 * path_length(dt, shuffled))
      << path_length(dt, along) << " against " << path_length(dt, shuffled);
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
