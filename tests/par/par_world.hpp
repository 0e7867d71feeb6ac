// A world of submeshes for the parallel layer's tests: a refined cube-in-cube cut into
// METIS parts (par/submesh.hpp), channels that deliver migrations and relink notices in a
// seeded random order, FIFO per pair (as MPI), random migrations, and the check that the
// submeshes together still hold the original mesh (M1-M3 of par/submesh.hpp).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <map>
#include <random>
#include <string>
#include <variant>

#include "mesh/tables.hpp"
#include "par/par_meshes.hpp"
#include "par/partition.hpp"
#include "par/submesh.hpp"

namespace pdr::par::test {

// A tet as its sorted global ids and the parity of the sort (orientation).
using TetKey = std::array<Gid, 4>;
inline std::pair<TetKey, bool> canonical(std::array<Gid, 4> v) {
  bool odd = false;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j + 1 < 4 - i; ++j)
      if (v[static_cast<std::size_t>(j)] > v[static_cast<std::size_t>(j + 1)]) {
        std::swap(v[static_cast<std::size_t>(j)], v[static_cast<std::size_t>(j + 1)]);
        odd = !odd;
      }
  return {v, odd};
}

struct Held {
  bool odd = false;
  std::uint8_t inside = 0;
  int copies = 0;
};

inline std::map<TetKey, Held> original_tets(const refine::VolumeMesh& vm) {
  std::map<TetKey, Held> out;
  const TetStore& s = vm.dt.store();
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t)) continue;
    std::array<Gid, 4> g{};
    for (int i = 0; i < 4; ++i) {
      const VertexId v = s.vertex(t, i);
      g[static_cast<std::size_t>(i)] = v == kGhostVertex ? kGhostGid : v;
    }
    const auto [k, odd] = canonical(g);
    out[k] = {odd, vm.inside[t], 0};
  }
  return out;
}

using Message = std::variant<Migration, Relink>;

struct World {
  std::vector<Submesh> subs;
  std::map<std::pair<ActorId, ActorId>, std::deque<Message>> channels;  // (from, to)
  std::mt19937_64 rng;
  std::size_t migrated = 0, relinks = 0, forwards = 0;

  void send(ActorId from, ActorId to, Message m) { channels[{from, to}].push_back(std::move(m)); }

  // One random face-connected set of real tets of a random submesh, to another one.
  void migrate_some() {
    const ActorId a = static_cast<ActorId>(rng() % subs.size());
    Submesh& s = subs[a];
    if (s.real_tets() == 0) return;
    const TetStore& st = s.store();
    TetId seed = kNoTet;
    while (seed == kNoTet) {
      const TetId t = static_cast<TetId>(rng() % st.slots());
      if (st.is_alive(t) && !st.is_proxy(t)) seed = t;
    }
    const std::size_t want = 1 + rng() % 40;
    std::vector<TetId> ball{seed};
    for (std::size_t i = 0; i < ball.size() && ball.size() < want; ++i)
      for (int f = 0; f < 4 && ball.size() < want; ++f) {
        const TetId u = st.neighbour(ball[i], f);
        if (!st.is_proxy(u) && std::find(ball.begin(), ball.end(), u) == ball.end())
          ball.push_back(u);
      }
    ActorId b = static_cast<ActorId>(rng() % (subs.size() - 1));
    if (b >= a) ++b;
    std::vector<Relink> notes;
    Migration m = s.take(ball, b, notes);
    migrated += ball.size();
    send(a, b, std::move(m));
    for (Relink& r : notes) send(a, r.recipient, std::move(r));
  }

  // Delivers the head of a random non-empty channel; false when none has anything.
  bool deliver_one() {
    std::vector<std::pair<ActorId, ActorId>> ready;
    for (const auto& [k, q] : channels)
      if (!q.empty()) ready.push_back(k);
    if (ready.empty()) return false;
    const auto key = ready[rng() % ready.size()];
    Message m = std::move(channels[key].front());
    channels[key].pop_front();
    const ActorId to = key.second;
    if (auto* mig = std::get_if<Migration>(&m)) {
      subs[to].give(*mig);
    } else {
      Relink r = std::get<Relink>(m);
      ++relinks;
      if (!subs[to].relink(r)) {
        ++forwards;
        send(to, r.recipient, r);
      }
    }
    return true;
  }
};

inline World cut(std::uint32_t parts, std::uint64_t seed) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  const Partition p = partition_tets(vm.dt.store(), vm.inside, parts, seed);
  World w;
  w.rng.seed(seed);
  // Odd seeds: M_o's ids through the dense vectors, even ones through the hash maps.
  for (ActorId k = 0; k < parts; ++k)
    w.subs.push_back(Submesh::extract(k, vm.dt.store(), vm.dt.points(), vm.inside, p, {},
                                      /*dense=*/seed % 2 == 1));
  return w;
}

// M1 and M3 at quiescence; M2 for every submesh.
inline void expect_same_mesh(const World& w, const std::string& what) {
  std::map<TetKey, Held> tets = original_tets(test::cube_in_cube());
  // Per face of a held tet: the submeshes holding a tet with it, and those tets' ids.
  struct OnFace {
    ActorId holder;
    Gid tet;
  };
  std::map<FaceKey, std::vector<OnFace>> holders;
  for (const Submesh& s : w.subs) {
    const auto problems = s.check();
    ASSERT_TRUE(problems.empty()) << what << ": submesh " << s.id() << ": " << problems.front();
    const TetStore& st = s.store();
    for (TetId t = 0; t < st.slots(); ++t) {
      if (!st.is_alive(t) || st.is_proxy(t)) continue;
      std::array<Gid, 4> g{};
      for (int i = 0; i < 4; ++i) g[static_cast<std::size_t>(i)] = s.gid(st.vertex(t, i));
      const auto [k, odd] = canonical(g);
      const auto it = tets.find(k);
      ASSERT_NE(it, tets.end()) << what << ": submesh " << s.id() << " holds a tet not in the mesh";
      EXPECT_EQ(it->second.odd, odd) << what << ": orientation flipped";
      EXPECT_EQ(it->second.inside, s.inside(t) ? 1 : 0) << what << ": inside flag changed";
      ++it->second.copies;
      for (int f = 0; f < 4; ++f) {
        const auto& fv = tables::kFaceVertex[f];
        holders[face_key(g[static_cast<std::size_t>(fv[0])], g[static_cast<std::size_t>(fv[1])],
                         g[static_cast<std::size_t>(fv[2])])]
            .push_back({s.id(), s.tet_gid(t)});
      }
    }
  }
  for (const auto& [k, h] : tets) ASSERT_EQ(h.copies, 1) << what << ": a tet held " << h.copies << " times";
  for (const Submesh& s : w.subs) {
    const TetStore& st = s.store();
    for (TetId t = 0; t < st.slots(); ++t) {
      if (!st.is_alive(t) || !st.is_proxy(t)) continue;
      const FaceKey k = face_key(s.gid(st.vertex(t, 0)), s.gid(st.vertex(t, 1)), s.gid(st.vertex(t, 2)));
      const auto& h = holders[k];
      ASSERT_EQ(h.size(), 2u) << what << ": a proxy's face is not a face of two tets";
      const OnFace& other = h[0].holder == s.id() ? h[1] : h[0];
      EXPECT_NE(other.holder, s.id()) << what << ": a proxy between two tets of one submesh";
      EXPECT_EQ(s.proxy_side(t).claim.holder, other.holder)
          << what << ": a proxy of submesh " << s.id() << " names " << s.proxy_side(t).claim.holder
          << ", not the holder";
      // The tet it names is the one across its face (submesh.hpp M3), which give() relies
      // on to find the proxy from that tet.
      EXPECT_EQ(s.proxy_side(t).tet, other.tet)
          << what << ": a proxy of submesh " << s.id() << " names tet " << s.proxy_side(t).tet
          << ", not the tet across";
    }
  }
}

}  // namespace pdr::par::test
