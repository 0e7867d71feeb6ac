// The order-independence check (src/app/order_check.hpp): a Delaunay tetrahedralization
// passes whatever the rebuild's seed; the other tetrahedralization of the same five points
// (a 2-3 flip of a bipyramid) is found out, and so is one foreign tet.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "app/order_check.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/delaunay.hpp"
#include "delaunay/export.hpp"

namespace pdr::app {
namespace {

// A triangle abc in z = 0 pierced by the segment de: two tets (abcd, abce) or three
// (dea, deb, dec) fill the bipyramid; with d, e far above and below the triangle the
// two-tet one is Delaunay (e is outside abcd's sphere: center (2, 2, 1.9), R^2 = 11.61,
// |e - center|^2 = 49.61).
MeshData bipyramid(bool delaunay) {
  MeshData m;
  m.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 5}, {1, 1, -5}};
  if (delaunay)
    m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  else
    m.tets = {{3, 4, 0, 1}, {3, 4, 1, 2}, {3, 4, 2, 0}};
  return m;
}

TEST(OrderCheck, TheDelaunayBipyramidPasses) {
  const MeshData m = bipyramid(true);
  for (std::uint64_t seed : {1u, 2u, 77u}) {
    const OrderCheck r = check_order_independence(m, seed);
    EXPECT_TRUE(r.ok()) << seed;
    EXPECT_EQ(r.tets, 2u);
  }
}

TEST(OrderCheck, TheFlippedBipyramidIsFound) {
  const OrderCheck r = check_order_independence(bipyramid(false), 1);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.missing, 3u);
  ASSERT_FALSE(r.first.empty());
  EXPECT_EQ(r.first.front(), (std::array<std::uint32_t, 4>{0, 1, 3, 4}));
}

// A kernel-built Delaunay tetrahedralization of a grid with jitter passes for several
// seeds; changing one tet's vertex to a non-Delaunay quadruple is found.
TEST(OrderCheck, KernelMeshPassesAndOneForeignTetIsFound) {
  std::vector<Point> pts;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        pts.push_back({i + 0.001 * ((i * 7 + j * 3 + k) % 5), j + 0.0013 * ((i + j * 5) % 7),
                       k + 0.0007 * ((j + k * 3) % 11)});
  Delaunay dt(pts);
  BulkOptions o;
  o.renumber = false;
  ASSERT_EQ(bulk_insert(dt, o).status, BulkStatus::Ok);
  MeshData m = to_mesh_data(dt);
  for (std::uint64_t seed : {5u, 6u}) EXPECT_TRUE(check_order_independence(m, seed).ok());
  m.tets[0][0] = m.tets[0][0] == 0 ? 215u : 0u;  // far from the tet's other vertices
  EXPECT_EQ(check_order_independence(m, 5).missing, 1u);
}

}  // namespace
}  // namespace pdr::app
