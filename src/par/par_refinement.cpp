// The parallel phase on one rank and the absorption of its points; see
// par/par_refinement.hpp.
#include "par/par_refinement.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <optional>

#include "delaunay/spatial_sort.hpp"
#include "par/actor_mux.hpp"
#include "par/idle.hpp"

namespace pdr::par {

RankResult refine_part(const refine::VolumeMesh& m0, const Partition& part, Transport& t,
                       const refine::TetBounds& bounds, std::uint64_t seed) {
  using Clock = std::chrono::steady_clock;
  RefinementRules rules(m0, bounds);
  // One actor per submesh of this rank: with N == P the rank's transport itself, else the
  // ports of a mux (par/actor_mux.hpp).
  const int n = static_cast<int>(part.parts);
  std::optional<ActorMux> mux;
  if (n != t.size()) mux.emplace(t, n);
  std::vector<Transport*> ports;
  std::vector<std::unique_ptr<InsertionActor>> actors;
  for (int k = t.rank(); k < n; k += t.size()) {
    Transport& port = mux ? mux->port(k) : t;
    ports.push_back(&port);
    actors.push_back(std::make_unique<InsertionActor>(
        port,
        Submesh::extract(static_cast<ActorId>(k), m0.dt.store(), m0.dt.points(), m0.inside,
                         part, rules.vertex_tags()),
        seed, &rules));
  }
  RankResult out;
  RankFigures& f = out.figures;
  for (const auto& a : actors) f.start_tets += a->submesh().real_tets();
  const auto start = Clock::now();
  for (const auto& a : actors) a->add_wanted_tets();
  IdlePolicy idle;
  Clock::duration busy{};
  std::vector<std::uint8_t> done(actors.size(), 0);
  for (std::size_t left = actors.size(); left > 0;) {
    bool worked = false, waiting = false;
    for (std::size_t i = 0; i < actors.size(); ++i) {
      if (done[i]) continue;
      InsertionActor& a = *actors[i];
      const auto before = Clock::now();
      const bool finished = a.step();
      if (a.worked()) busy += Clock::now() - before;
      worked = worked || a.worked();
      waiting = waiting || a.waiting();
      if (finished) done[i] = 1, --left;
    }
    if (left > 0) idle.after_iteration(worked, waiting);
  }
  f.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  f.busy_seconds = std::chrono::duration<double>(busy).count();
  for (const auto& a : actors) {
    f.steps += a->stats();
    f.final_tets += a->submesh().real_tets();
    out.points.insert(out.points.end(), a->committed_points().begin(),
                      a->committed_points().end());
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
  return out;
}

std::size_t absorb(refine::VolumeMesh& m, std::span<const Point> points) {
  if (points.empty()) return 0;
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  Point lo = points[0], hi = points[0];
  for (const Point& p : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  hilbert_sort(order, points, lo, hi);
  Cavity c;
  std::vector<TetId> star;
  std::size_t added = 0;
  TetId hint = m.dt.last_tet();
  for (const std::uint32_t i : order) {
    const Location loc = m.dt.locate(points[i], hint);
    if (loc.kind == Location::Kind::OnVertex) continue;
    m.dt.build_cavity(points[i], loc.tet, c);
    commit_point(m, c, refine::kNone, star);
    hint = m.dt.last_tet();
    ++added;
  }
  return added;
}

}  // namespace pdr::par
