// The distributed cavity search (par/cavity_search.hpp) against the sequential kernel: a
// refined cube-in-cube cut into METIS parts and stirred by random migrations; for the
// circumcenters of random inside tets (the points refinement inserts) and random points
// in the domain's box, the root alternates root_cavity() and fetches (fetch_set, migrated
// with take/give, relink notices delivered) until the cavity is local. The cavity found is
// then exactly the one CavityBuilder builds on the whole mesh, its ring holds no proxy,
// every submesh stays valid and together they still hold the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "delaunay/cavity.hpp"
#include "delaunay/delaunay.hpp"
#include "delaunay/walk.hpp"
#include "geom/construct.hpp"
#include "par/cavity_search.hpp"
#include "par/par_world.hpp"
#include "par/point_tets.hpp"

namespace pdr::par {
namespace {

using test::World;

// Delivers every message in flight (relink notices may forward further).
void drain(World& w) {
  while (w.deliver_one()) {
  }
}

std::size_t in_flight(const World& w) {
  std::size_t n = 0;
  for (const auto& [k, q] : w.channels) n += q.size();
  return n;
}

struct SearchStats {
  std::size_t rounds = 0, fetched = 0, redirects = 0, waits = 0;
};

// The search for p from tet `hint` of submesh `root`; the complete cavity at the end.
Cavity search(World& w, ActorId root, const Point& p, TetId hint, SearchStats& st) {
  CavitySearch cs;
  for (int rounds = 1;; ++rounds) {
    // The walk goes on from where it got to: the tet a walk fetch stopped at, if any.
    RootCavity rc = cs.root_cavity(w.subs[root], p, hint);
    EXPECT_NE(rc.kind, RootCavity::Kind::OnVertex);
    if (rc.kind != RootCavity::Kind::Remote) return rc.cavity;
    ++st.rounds;
    if (rounds > 200) {
      ADD_FAILURE() << "the search did not end in 200 rounds";
      return {};
    }
    std::map<ActorId, std::vector<Side>> todo = std::move(rc.fetch);
    while (!todo.empty()) {
      auto node = todo.extract(todo.begin());
      const ActorId at = node.key();
      const std::vector<Side> sides = std::move(node.mapped());
      if (at == root || sides.empty()) {
        // A proxy of the root names the root: that tet is on its way here.
        ++st.waits;
        if (!w.deliver_one()) {
          ADD_FAILURE() << "the root waits for a tet nothing brings";
          return {};
        }
        break;  // look again
      }
      std::vector<Gid> ask;
      for (const Side& x : sides) ask.push_back(x.tet);
      const std::vector<TetId> tets = CavitySearch().fetch_set(w.subs[at], p, ask, rc.walk).tets;
      bool waited = false;
      for (const Side& x : sides) {
        if (w.subs[at].find_tet(x.tet) != kNoTet) continue;
        if (const auto next = w.subs[at].moved(x.tet, x.claim.epoch)) {
          if (next->holder == kDeleted) {
            ADD_FAILURE() << "a proxy of the root names tet " << x.tet << ", deleted at " << at;
            return {};
          }
          ++st.redirects;  // it moved on: follow the record of where it went
          todo[next->holder].push_back({x.tet, *next});
        } else {
          ++st.waits;  // it is on its way to `at`
          if (!waited && !w.deliver_one()) {
            ADD_FAILURE() << "submesh " << at << " waits for tet " << x.tet << " that nothing brings";
            return {};
          }
          waited = true;
          todo[at].push_back(x);
        }
      }
      std::vector<Relink> notes;
      st.fetched += tets.size();
      if (!tets.empty()) {
        const std::vector<TetId> ids = w.subs[root].give(w.subs[at].take(tets, root, notes));
        if (rc.walk) hint = ids.front();
      }
      for (Relink& r : notes) w.send(at, r.recipient, std::move(r));
      if (rc.walk && !tets.empty()) break;  // a walk goes on from its new hint
    }
  }
}

std::set<Gid> global_cavity(const Point& p, TetId hint) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  WalkRng rng;
  const Location loc = locate(vm.dt.store(), vm.dt.points(), p, hint, rng);
  Cavity c;
  CavityBuilder().build(vm.dt.store(), vm.dt.points(), p, loc.tet, c);
  return {c.conflict.begin(), c.conflict.end()};
}

TEST(CavitySearch, FindsTheSequentialCavityAcrossSubmeshes) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  const TetStore& g = vm.dt.store();
  std::vector<TetId> inside;
  for (TetId t = 0; t < g.slots(); ++t)
    if (g.is_alive(t) && !g.is_ghost(t) && vm.is_inside(t)) inside.push_back(t);
  SearchStats st;
  std::size_t distributed = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    World w = test::cut(2 + static_cast<std::uint32_t>(seed % 6), seed);
    for (int k = 0; k < 60; ++k) {
      for (int m = 0; m < 5; ++m) w.migrate_some();
      // A few messages stay in flight: stale claims and tets on their way.
      const std::size_t keep = w.rng() % 64;
      while (in_flight(w) > keep) w.deliver_one();
      // The root: the submesh holding tau (its hint); tau is not in flight.
      TetId tau = kNoTet, hint = kNoTet;
      ActorId root = 0;
      while (hint == kNoTet) {
        tau = inside[w.rng() % inside.size()];
        for (const Submesh& s : w.subs)
          if (const TetId t = s.find_tet(tau); t != kNoTet) root = s.id(), hint = t;
      }
      const VertexId* v = g.vertices(tau);
      Point p = construct::circumcenter(vm.dt.point(v[0]), vm.dt.point(v[1]), vm.dt.point(v[2]),
                                        vm.dt.point(v[3]));
      if (k % 3 == 2)  // a random point of the box instead
        for (int i = 0; i < 3; ++i) p[i] = 10.0 * static_cast<double>(w.rng() % 1000003) / 1000003.0;
      const std::size_t before = st.rounds;
      const Cavity c = search(w, root, p, hint, st);
      distributed += st.rounds > before;
      ASSERT_FALSE(c.conflict.empty()) << "seed " << seed << " point " << k;
      const Submesh& r = w.subs[root];
      std::set<Gid> got;
      for (const TetId t : c.conflict) got.insert(r.tet_gid(t));
      for (const TetId t : c.ring) ASSERT_FALSE(r.store().is_proxy(t)) << "a proxy in the ring";
      EXPECT_EQ(got, global_cavity(p, tau)) << "seed " << seed << " point " << k;
    }
    drain(w);
    test::expect_same_mesh(w, "seed " + std::to_string(seed));
  }
  EXPECT_GT(distributed, 100u);  // most searches crossed submeshes
  EXPECT_GT(st.redirects, 0u);   // some followed a moved tet
  EXPECT_GT(st.waits, 0u);       // some waited for one on its way
  std::printf("%zu distributed searches, %zu rounds, %zu tets fetched, %zu redirects, %zu waits\n",
              distributed, st.rounds, st.fetched, st.redirects, st.waits);
}

// Distributed Bowyer-Watson: random points inserted at random submeshes, each through a
// distributed search and a local commit (Submesh::insert), with migrations and messages
// in flight between them. The symbolic perturbation makes the Delaunay tetrahedralization
// of a point set unique, so the submeshes together must hold exactly the tets the
// sequential kernel makes from the same points.
TEST(CavitySearch, DistributedInsertionGivesTheSequentialDelaunayMesh) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    World w = test::cut(2 + static_cast<std::uint32_t>(seed % 4) * 2, seed);
    Delaunay reference = vm.dt;
    SearchStats st;
    for (int k = 0; k < 400; ++k) {
      for (int m = 0; m < 2; ++m) w.migrate_some();
      const std::size_t keep = w.rng() % 32;
      while (in_flight(w) > keep) w.deliver_one();
      Point p;
      for (int i = 0; i < 3; ++i) p[i] = 10.0 * static_cast<double>(w.rng() % 1000003) / 1000003.0;
      ActorId root = static_cast<ActorId>(w.rng() % w.subs.size());
      while (w.subs[root].real_tets() == 0) root = (root + 1) % static_cast<ActorId>(w.subs.size());
      const TetStore& rs = w.subs[root].store();
      TetId hint = 0;
      while (!rs.is_alive(hint) || rs.is_proxy(hint)) ++hint;
      const Cavity c = search(w, root, p, hint, st);
      ASSERT_FALSE(c.conflict.empty()) << "seed " << seed << " point " << k;
      w.subs[root].insert(c, 0);
      ASSERT_EQ(reference.insert(p).outcome, Outcome::Inserted);
      if (k % 50 == 0) {
        const auto problems = w.subs[root].check();
        ASSERT_TRUE(problems.empty()) << problems.front();
      }
    }
    drain(w);
    std::vector<test::PointTet> got, want;
    std::size_t ghosts_got = 0, ghosts_want = 0;
    for (const Submesh& s : w.subs) {
      ASSERT_TRUE(s.check().empty()) << s.check().front();
      EXPECT_EQ(s.waiting_relinks(), 0u);
      const TetStore& ts = s.store();
      for (TetId t = 0; t < ts.slots(); ++t) ghosts_got += ts.is_alive(t) && ts.is_ghost(t);
      test::add_finite_tets(ts, s.points(), got);
    }
    const TetStore& rs = reference.store();
    for (TetId t = 0; t < rs.slots(); ++t) ghosts_want += rs.is_alive(t) && rs.is_ghost(t);
    test::add_finite_tets(rs, reference.points(), want);
    got = test::sorted(std::move(got));
    want = test::sorted(std::move(want));
    EXPECT_EQ(ghosts_got, ghosts_want) << "seed " << seed;
    EXPECT_EQ(got.size(), want.size()) << "seed " << seed;
    EXPECT_TRUE(got == want) << "seed " << seed << ": the distributed mesh is not the Delaunay mesh";
    std::printf("seed %llu: %zu tets, %zu search rounds, %zu tets fetched, %zu redirects, %zu waits\n",
                static_cast<unsigned long long>(seed), got.size(), st.rounds, st.fetched,
                st.redirects, st.waits);
  }
}

}  // namespace
}  // namespace pdr::par
