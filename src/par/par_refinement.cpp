// The parallel phase on one rank; see par/par_refinement.hpp.
#include "par/par_refinement.hpp"

#include <chrono>
#include <memory>
#include <optional>

#include "par/actor_mux.hpp"
#include "par/assembly.hpp"
#include "par/idle.hpp"

namespace pdr::par {

refine::QualityRange submesh_quality(const Submesh& s) {
  refine::QualityRange q;
  const TetStore& st = s.store();
  const auto pts = s.points();
  for (TetId t = 0; t < st.slots(); ++t) {
    if (t + 8 < st.slots())  // a later tet's points, scattered, requested meanwhile
      for (int k = 0; k < 4; ++k)
        if (const VertexId w = st.vertex(t + 8, k); w < pts.size()) __builtin_prefetch(&pts[w]);
    if (!st.is_alive(t) || st.is_proxy(t) || st.is_ghost(t) || !s.inside(t)) continue;
    const VertexId* v = st.vertices(t);
    q.add(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]);
  }
  return q;
}

RankResult refine_part(const refine::VolumeMesh& m0, const Partition& part, Transport& t,
                       const refine::TetBounds& bounds, std::uint64_t seed, bool surface_steps,
                       std::uint64_t points) {
  using Clock = std::chrono::steady_clock;
  RefinementRules rules(m0, bounds, surface_steps);
  rules.set_point_budget(points);
  // One actor per submesh of this rank: with N == P the rank's transport itself, else the
  // ports of a mux (par/actor_mux.hpp).
  const int n = static_cast<int>(part.parts);
  std::optional<ActorMux> mux;
  if (n != t.size()) mux.emplace(t, n);
  std::vector<Transport*> ports;
  std::vector<std::unique_ptr<InsertionActor>> actors;
  // Few submeshes here: each finds M_o's tets and vertices through vectors as long as M_o
  // (Submesh::extract), at most four times M_o's ids, which this rank holds anyway.
  constexpr int kDenseSubmeshes = 4;
  const bool dense = (n + t.size() - 1) / t.size() <= kDenseSubmeshes;
  for (int k = t.rank(); k < n; k += t.size()) {
    Transport& port = mux ? mux->port(k) : t;
    ports.push_back(&port);
    Submesh sub = Submesh::extract(static_cast<ActorId>(k), m0.dt.store(), m0.dt.points(),
                                   m0.inside, part, rules.vertex_tags(), dense);
    rules.label(sub);
    actors.push_back(std::make_unique<InsertionActor>(port, std::move(sub), seed, &rules));
  }
  RankResult out;
  RankFigures& f = out.figures;
  for (const auto& a : actors) f.start_tets += a->submesh().real_tets();
  const auto start = Clock::now();
  for (const auto& a : actors) a->add_wanted_tets();
  IdlePolicy idle;
  Clock::duration busy{};
  std::vector<std::uint8_t> done(actors.size(), 0);
  // The clock readings chain: each step starts at the previous one's last reading (two
  // readings a step, InsertionActor::step), and a fresh one is taken only after an
  // iteration that did nothing (the idle policy may have slept).
  auto now = Clock::now();
  for (std::size_t left = actors.size(); left > 0;) {
    bool worked = false, waiting = false;
    for (std::size_t i = 0; i < actors.size(); ++i) {
      if (done[i]) continue;
      InsertionActor& a = *actors[i];
      const auto before = now;
      const bool finished = a.step(now);
      if (a.worked()) busy += now - before;
      worked = worked || a.worked();
      waiting = waiting || a.waiting();
      if (finished) done[i] = 1, --left;
    }
    if (left > 0 && !worked) {
      idle.after_iteration(false, waiting);
      now = Clock::now();
    } else if (left > 0) {
      idle.after_iteration(true, waiting);
    }
  }
  f.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  f.busy_seconds = std::chrono::duration<double>(busy).count();
  for (const auto& a : actors) {
    f.steps += a->stats();
    f.final_tets += a->submesh().real_tets();
    out.points.insert(out.points.end(), a->committed_points().begin(),
                      a->committed_points().end());
    out.made.push_back(a->committed_points().size());
    out.submeshes.push_back(a->release_submesh());
  }
  f.deferred = rules.deferred();
  for (const Transport* p : ports) {
    f.messages_sent += p->sent();
    f.messages_received += p->received();
    f.bytes_sent += p->bytes_sent();
  }
  f.empty_polls = idle.empty_iterations();
  f.sleeps = idle.sleeps();
  f.points = out.points.size();
  out.surface_steps = rules.surface_steps();
  return out;
}

Bytes pieces_of(std::span<const Submesh> submeshes) {
  WireWriter w;
  for (const Submesh& s : submeshes) put_piece(w, piece_of(s));
  return w.take();
}

refine::QualityRange quality_of(std::span<const Submesh> submeshes) {
  refine::QualityRange q;
  for (const Submesh& s : submeshes) q.merge(submesh_quality(s));
  return q;
}

}  // namespace pdr::par
