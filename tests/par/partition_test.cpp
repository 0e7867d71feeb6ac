// The element-wise METIS partition of M_o (par/partition.hpp) on a refined cube-in-cube:
// every finite tet in exactly one part, every part non-empty, face-connected and balanced
// by weight, ghost tets with their finite neighbour, the interface faces counted exactly,
// and the same partition for the same seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>

#include "par/par_meshes.hpp"
#include "par/partition.hpp"
#include "par/submesh.hpp"

namespace pdr::par {
namespace {

const refine::VolumeMesh& mesh() { return test::cube_in_cube(); }

// The finite tets of part k, reached from one of them across faces within the part.
std::size_t reachable_in_part(const TetStore& s, const Partition& p, std::uint32_t k) {
  std::vector<TetId> stack;
  std::vector<std::uint8_t> seen(s.slots(), 0);
  for (TetId t = 0; t < s.slots() && stack.empty(); ++t)
    if (s.is_alive(t) && !s.is_ghost(t) && p.part[t] == k) stack.push_back(t), seen[t] = 1;
  std::size_t n = 0;
  while (!stack.empty()) {
    const TetId t = stack.back();
    stack.pop_back();
    ++n;
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (!s.is_ghost(u) && p.part[u] == k && !seen[u]) seen[u] = 1, stack.push_back(u);
    }
  }
  return n;
}

TEST(Partition, EveryTetInOneConnectedBalancedPart) {
  const refine::VolumeMesh& vm = mesh();
  const TetStore& s = vm.dt.store();
  std::size_t finite = 0;
  for (TetId t = 0; t < s.slots(); ++t) finite += s.is_alive(t) && !s.is_ghost(t);
  ASSERT_GT(finite, 3000u);
  for (const std::uint32_t parts : {1u, 2u, 3u, 8u, 16u}) {
    const Partition p = partition_tets(s, vm.inside, parts, 42);
    ASSERT_EQ(p.parts, parts);
    std::vector<std::uint64_t> count(parts, 0), weight(parts, 0);
    std::uint64_t cut = 0;
    for (TetId t = 0; t < s.slots(); ++t) {
      if (!s.is_alive(t)) {
        EXPECT_EQ(p.part[t], kNoPart);
        continue;
      }
      ASSERT_LT(p.part[t], parts) << "tet " << t;
      if (s.is_ghost(t)) {
        EXPECT_EQ(p.part[t], p.part[s.neighbour(t, 3)]) << "ghost tet " << t;
        continue;
      }
      ++count[p.part[t]];
      weight[p.part[t]] += vm.is_inside(t) ? kInsideWeight : 1;
      for (int f = 0; f < 4; ++f) {
        const TetId u = s.neighbour(t, f);
        if (!s.is_ghost(u) && p.part[u] != p.part[t]) ++cut;
      }
    }
    EXPECT_EQ(count, p.tets) << parts << " parts";
    EXPECT_EQ(weight, p.weight) << parts << " parts";
    EXPECT_EQ(std::accumulate(count.begin(), count.end(), std::uint64_t{0}), finite);
    EXPECT_EQ(cut, 2 * p.interface_faces) << parts << " parts";
    if (parts == 1) {
      EXPECT_EQ(p.interface_faces, 0u);
    }
    const std::uint64_t total = std::accumulate(weight.begin(), weight.end(), std::uint64_t{0});
    for (std::uint32_t k = 0; k < parts; ++k) {
      EXPECT_GT(count[k], 0u) << "part " << k << " of " << parts << " is empty";
      EXPECT_EQ(reachable_in_part(s, p, k), count[k]) << "part " << k << " of " << parts
                                                      << " is not face-connected";
      EXPECT_LE(static_cast<double>(weight[k]), 1.1 * static_cast<double>(total) / parts)
          << "part " << k << " of " << parts;
    }
  }
}

TEST(Partition, ASeedNamesOnePartition) {
  const TetStore& s = mesh().dt.store();
  EXPECT_EQ(partition_tets(s, mesh().inside, 6, 7).part, partition_tets(s, mesh().inside, 6, 7).part);
}

TEST(Partition, MorePartsThanTetsIsRefused) {
  const TetStore& s = mesh().dt.store();
  EXPECT_THROW(partition_tets(s, mesh().inside, 0, 1), std::invalid_argument);
  EXPECT_THROW(partition_tets(s, mesh().inside, static_cast<std::uint32_t>(s.slots()) + 1, 1),
               std::invalid_argument);
}

// Near one part per tet, METIS may leave parts empty: that is refused with a clear
// error, never returned.
TEST(Partition, EmptyPartsAreRefused) {
  const refine::VolumeMesh vm = test::refined("cube-in-cube.poly", 50.0);
  const TetStore& s = vm.dt.store();
  std::uint32_t finite = 0;
  for (TetId t = 0; t < s.slots(); ++t) finite += s.is_alive(t) && !s.is_ghost(t);
  int refused = 0;
  for (std::uint32_t parts = finite / 4; parts <= finite; parts += std::max(1u, finite / 8)) {
    try {
      const Partition p = partition_tets(s, vm.inside, parts, 1);
      for (std::uint32_t k = 0; k < parts; ++k) EXPECT_GT(p.tets[k], 0u) << parts << " parts";
    } catch (const std::invalid_argument& e) {
      ++refused;
      EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(refused, 0);
}

// A submesh's store (proxies on its interface faces) partitions too: proxies get no part.
TEST(Partition, ProxiesAreLeftOut) {
  const refine::VolumeMesh& vm = mesh();
  const Partition whole = partition_tets(vm.dt.store(), vm.inside, 6, 3);
  const Submesh sub = Submesh::extract(2, vm.dt.store(), vm.dt.points(), vm.inside, whole);
  const TetStore& s = sub.store();
  ASSERT_GT(sub.proxies(), 0u);
  const Partition p = partition_tets(s, {}, 3, 3);
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t)) continue;
    if (s.is_proxy(t))
      EXPECT_EQ(p.part[t], kNoPart);
    else
      EXPECT_LT(p.part[t], 3u);
  }
}

}  // namespace
}  // namespace pdr::par
