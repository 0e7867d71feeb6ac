// TetStore (mesh/tet_store.hpp): accessors, the free list, and check_topology() catching
// each kind of broken adjacency.
#include <gtest/gtest.h>

#include <string>

#include "mesh/tables.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {
namespace {

bool mentions(const std::vector<std::string>& v, const std::string& name) {
  for (const auto& s : v)
    if (s.rfind(name, 0) == 0) return true;
  return false;
}

// One tet (0,1,2,3) and its four ghost tets, wired by hand: the smallest valid store.
TetStore five_tets() {
  TetStore s;
  const TetId t = s.create(0, 1, 2, 3);
  TetId g[4];
  for (int f = 0; f < 4; ++f) {
    const auto& fv = tables::kFaceVertex[f];
    g[f] = s.create(s.vertex(t, fv[0]), s.vertex(t, fv[1]), s.vertex(t, fv[2]), kGhostVertex);
    s.link(half_face(t, f), half_face(g[f], 3));
  }
  for (int f = 0; f < 4; ++f)
    for (int j = 0; j < 3; ++j) {
      if (s.opposite(g[f], j) != kNoHalfFace) continue;
      const VertexId x = s.vertex(g[f], (j + 1) % 3), y = s.vertex(g[f], (j + 2) % 3);
      for (int h = 0; h < 4; ++h)
        for (int k = 0; k < 3 && h != f; ++k)
          if (s.vertex(g[h], (k + 1) % 3) == y && s.vertex(g[h], (k + 2) % 3) == x)
            s.link(half_face(g[f], j), half_face(g[h], k));
    }
  return s;
}

TEST(HalfFace, EncodesTetAndFace) {
  for (TetId t : {0u, 1u, 12345u, 0x3FFFFFFEu})
    for (int f = 0; f < 4; ++f) {
      EXPECT_EQ(tet_of(half_face(t, f)), t);
      EXPECT_EQ(face_of(half_face(t, f)), f);
    }
}

// The last slot a store may hold: its record offset computed without wrap-around (8 t
// wraps 32 bits from t = 2^29), its half-faces distinct from kNoHalfFace, its id from
// kNoTet. Nothing is allocated.
TEST(TetStore, LargestSlotIndexesWithoutWrapAround) {
  const TetId last = static_cast<TetId>(kMaxTetSlots - 1);
  EXPECT_EQ(last, 0x3FFFFFFEu);
  EXPECT_EQ(TetStore::record_offset(last), std::size_t{8} * 0x3FFFFFFEu);
  EXPECT_GT(TetStore::record_offset(last), std::size_t{0xFFFFFFFFu});  // beyond 32 bits
  EXPECT_EQ(TetStore::record_offset(TetId{1} << 29), std::size_t{1} << 32);
  EXPECT_NE(last, kNoTet);
  for (int f = 0; f < 4; ++f) {
    EXPECT_NE(half_face(last, f), kNoHalfFace);
    EXPECT_EQ(tet_of(half_face(last, f)), last);
  }
}

// A store at its slot limit throws CapacityError instead of handing out a wrapped id; a
// freed slot can still be reused.
TEST(TetStore, RefusesToGrowBeyondItsLimit) {
  TetStore s(3);
  for (VertexId v = 0; v < 3; ++v) s.create(v, v + 1, v + 2, v + 3);
  EXPECT_THROW(s.create(7, 8, 9, 10), CapacityError);
  s.destroy(1);
  EXPECT_EQ(s.create(7, 8, 9, 10), 1u);
  EXPECT_EQ(s.slots(), 3u);
}

TEST(TetStore, SmallestClosedStoreIsValid) {
  const TetStore s = five_tets();
  EXPECT_EQ(s.live(), 5u);
  EXPECT_TRUE(s.check_topology().empty()) << s.check_topology().front();
  EXPECT_FALSE(s.is_ghost(0));
  for (TetId g = 1; g < 5; ++g) EXPECT_TRUE(s.is_ghost(g));
  for (int f = 0; f < 4; ++f) {
    EXPECT_EQ(s.neighbour(s.neighbour(0, f), s.back_face(0, f)), 0u);
  }
}

TEST(TetStore, FreeListReusesLastFreedFirst) {
  TetStore s;
  const TetId a = s.create(0, 1, 2, 3), b = s.create(4, 5, 6, 7), c = s.create(8, 9, 10, 11);
  s.destroy(a);
  s.destroy(c);
  EXPECT_FALSE(s.is_alive(a));
  EXPECT_TRUE(s.is_alive(b));
  EXPECT_EQ(s.live(), 1u);
  EXPECT_EQ(s.create(0, 1, 2, 3), c);
  EXPECT_EQ(s.create(0, 1, 2, 3), a);
  EXPECT_EQ(s.create(0, 1, 2, 3), 3u);  // free list empty: a fresh slot
  EXPECT_EQ(s.slots(), 4u);
}

TEST(TetStore, CheckFindsAsymmetricAdjacency) {
  TetStore s = five_tets();
  s.set_opposite(half_face(0, 0), half_face(2, 3));  // 2's face 3 points elsewhere
  EXPECT_TRUE(mentions(s.check_topology(), "adjacency-symmetric"));
}

TEST(TetStore, CheckFindsWrongSharedFace) {
  TetStore s = five_tets();
  // Swap two ghost tets' links to the finite tet: symmetric, but the faces differ.
  const HalfFace a = s.opposite(0, 0), b = s.opposite(0, 1);
  s.link(half_face(0, 0), b);
  s.link(half_face(0, 1), a);
  EXPECT_TRUE(mentions(s.check_topology(), "shared-face-opposite-orientation"));
}

TEST(TetStore, CheckFindsDeadNeighbourAndMisplacedGhost) {
  TetStore s = five_tets();
  s.destroy(4);
  EXPECT_TRUE(mentions(s.check_topology(), "adjacency-live"));
  TetStore t = five_tets();
  t.set_vertices(1, kGhostVertex, t.vertex(1, 1), t.vertex(1, 2), t.vertex(1, 0));
  EXPECT_TRUE(mentions(t.check_topology(), "ghost-in-slot-3"));
}

TEST(TetStore, CheckFindsRepeatedVertexAndMissingNeighbour) {
  TetStore s = five_tets();
  s.create(7, 7, 8, 9);
  const auto v = s.check_topology();
  EXPECT_TRUE(mentions(v, "tet-vertices-distinct"));
  EXPECT_TRUE(mentions(v, "adjacency-defined"));
}

}  // namespace
}  // namespace pdr
