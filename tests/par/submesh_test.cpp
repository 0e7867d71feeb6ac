// Submeshes and migration (par/submesh.hpp): a refined cube-in-cube cut into METIS parts,
// then random face-connected sets of tets migrated between random submeshes, with the
// migrations and relink notices delivered in a seeded random order (FIFO per pair, as
// MPI). Throughout and at the end: every submesh's store is valid (M2); once everything is
// delivered, the submeshes hold exactly the original tets, each once, with orientation
// and inside flag (M1), and every proxy names the submesh that holds its other side (M3);
// every edge and face of a tet held has the label of the surface mesh D (M4).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "par/par_world.hpp"
#include "par/refinement_rules.hpp"

namespace pdr::par {
namespace {

using test::cut;
using test::expect_same_mesh;
using test::World;

TEST(Submesh, ExtractedPartsAreTheMesh) {
  for (const std::uint32_t parts : {1u, 2u, 5u, 12u}) expect_same_mesh(cut(parts, 3), std::to_string(parts) + " parts");
}

TEST(Submesh, RandomMigrationsKeepTheMesh) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    World w = cut(2 + static_cast<std::uint32_t>(seed % 5), seed);
    for (int step = 0; step < 600; ++step) {
      if (w.rng() % 3 == 0 || !w.deliver_one()) w.migrate_some();
      if (step % 97 == 0)
        for (const Submesh& s : w.subs) {
          const auto problems = s.check();
          ASSERT_TRUE(problems.empty()) << "seed " << seed << " step " << step << ": " << problems.front();
        }
    }
    while (w.deliver_one()) {
    }
    EXPECT_GT(w.migrated, 1000u);
    EXPECT_GT(w.relinks, 0u);
    EXPECT_GT(w.forwards, 0u);
    for (const Submesh& s : w.subs)
      EXPECT_EQ(s.waiting_relinks(), 0u) << "seed " << seed << ": a notice waits for a tet that never came";
    expect_same_mesh(w, "seed " + std::to_string(seed));
  }
}

// A proxy's side is asked of proxies only: a real tet's, or a slot's that no proxy
// holds, is a logic error, not an empty side.
TEST(Submesh, OnlyAProxyHasASide) {
  World w = cut(2, 1);
  const Submesh& s = w.subs[0];
  const TetStore& st = s.store();
  TetId proxy = kNoTet, real = kNoTet;
  for (TetId t = 0; t < st.slots(); ++t) {
    if (!st.is_alive(t)) continue;
    (st.is_proxy(t) ? proxy : real) = t;
  }
  ASSERT_NE(proxy, kNoTet);
  ASSERT_NE(real, kNoTet);
  EXPECT_NE(s.proxy_side(proxy).tet, kNoGid);
  EXPECT_THROW((void)s.proxy_side(real), std::logic_error);
  EXPECT_THROW((void)s.proxy_side(static_cast<TetId>(st.slots())), std::logic_error);
}

// M4: the submeshes labelled with D's subsegments and subfacets (as the parallel phase
// does), then random migrations. Each submesh starts with the labels of the vertices it
// holds, so a tet that reaches a submesh that lacked its vertices is labelled only by what
// travelled with it.
TEST(Submesh, LabelsTravelWithTheTets) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  const RefinementRules rules(vm, refine::TetBounds{2.0, std::nullopt, 1.0});
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    World w = cut(2 + static_cast<std::uint32_t>(seed % 4), seed);
    for (Submesh& s : w.subs) rules.label(s);
    std::vector<std::size_t> before;
    for (const Submesh& s : w.subs) before.push_back(s.labels());
    for (int step = 0; step < 600; ++step)
      if (w.rng() % 3 == 0 || !w.deliver_one()) w.migrate_some();
    while (w.deliver_one()) {
    }
    std::size_t edges = 0, faces = 0, gained = 0;
    for (const Submesh& s : w.subs) {
      gained += s.labels() - before[s.id()];
      const TetStore& st = s.store();
      for (TetId t = 0; t < st.slots(); ++t) {
        if (!st.is_alive(t) || st.is_proxy(t)) continue;
        const VertexId* v = st.vertices(t);
        const auto g = [&](int i) { return static_cast<VertexId>(s.gid(v[i])); };
        for (const auto& e : tables::kEdgeVertex) {
          if (v[e[0]] == kGhostVertex || v[e[1]] == kGhostVertex) continue;
          const refine::MaybeId d = vm.subsegment(g(e[0]), g(e[1]));
          const std::uint32_t want = d ? vm.surf.subsegment(*d).segment : kNoLabel;
          ASSERT_EQ(s.edge_label(v[e[0]], v[e[1]]), want)
              << "seed " << seed << ": submesh " << s.id() << ", edge " << g(e[0]) << "-" << g(e[1]);
          edges += d.has_value();
        }
        for (const auto& f : tables::kFaceVertex) {
          if (v[f[0]] == kGhostVertex || v[f[1]] == kGhostVertex || v[f[2]] == kGhostVertex)
            continue;
          const refine::MaybeId d = vm.subfacet(g(f[0]), g(f[1]), g(f[2]));
          const std::uint32_t want = d ? vm.surf.subfacet(*d).facet : kNoLabel;
          ASSERT_EQ(s.face_label(v[f[0]], v[f[1]], v[f[2]]), want)
              << "seed " << seed << ": submesh " << s.id() << ", face " << g(f[0]) << "-"
              << g(f[1]) << "-" << g(f[2]);
          faces += d.has_value();
        }
      }
    }
    // Not vacuous: elements of D checked, and labels that came with migrated tets.
    EXPECT_GT(edges, 100u) << "seed " << seed;
    EXPECT_GT(faces, 100u) << "seed " << seed;
    EXPECT_GT(gained, 10u) << "seed " << seed;
  }
}

// A tet goes from submesh 1 to 0 and back to 1, the way back still in flight. A search
// that holds the claim "at 0, epoch 1" follows 0's record to 1, where the only record is
// the older hand-over to 0: the chain must stop there (the tet is on its way to 1), not
// go back to 0 and round again.
TEST(Submesh, ForwardingRecordsNeverCircle) {
  World w = cut(3, 5);
  const TetStore& st = w.subs[1].store();
  TetId t = 0;
  while (!st.is_alive(t) || st.is_proxy(t)) ++t;
  const Gid g = w.subs[1].tet_gid(t);
  std::vector<Relink> notes;
  const TetId t0 = w.subs[0].give(w.subs[1].take(std::vector<TetId>{t}, 0, notes)).front();
  const Migration back = w.subs[0].take(std::vector<TetId>{t0}, 1, notes);  // in flight
  Claim c{0, 1};
  int hops = 0;
  while (const auto next = w.subs[c.holder].moved(g, c.epoch)) {
    c = *next;
    ASSERT_LT(++hops, 5) << "the forwarding records of tet " << g << " go round";
  }
  EXPECT_EQ(c.holder, 1u);
  EXPECT_EQ(c.epoch, 2u);
  EXPECT_EQ(w.subs[1].find_tet(g), kNoTet);
  w.subs[1].give(back);
  EXPECT_NE(w.subs[1].find_tet(g), kNoTet);
  EXPECT_FALSE(w.subs[1].moved(g, 0).has_value());  // back home: its record says nothing
}

// A face's key names it in any vertex order: its ids sorted, and equal keys only for the
// same three ids.
TEST(Submesh, FaceKeyIsTheSortedIds) {
  std::array<Gid, 3> ids{7, 1ull << 41, 3};
  std::sort(ids.begin(), ids.end());
  const FaceKey sorted{ids};
  do {
    const FaceKey k = face_key(ids[0], ids[1], ids[2]);
    EXPECT_EQ(k.v, sorted.v);
    EXPECT_TRUE(k == sorted);
  } while (std::next_permutation(ids.begin(), ids.end()));
  EXPECT_FALSE(face_key(7, 3, 8) == sorted);
  EXPECT_FALSE(face_key(1ull << 41, 3, 3) == sorted);
  EXPECT_FALSE((FaceKey{{3, 7, 1ull << 42}} == sorted));
}

}  // namespace
}  // namespace pdr::par
