// The parallel phase on one rank and the absorption of its points; see
// par/par_refinement.hpp.
#include "par/par_refinement.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "delaunay/spatial_sort.hpp"
#include "par/idle.hpp"

namespace pdr::par {

RankResult refine_part(const refine::VolumeMesh& m0, const Partition& part, Transport& t,
                       const refine::TetBounds& bounds, std::uint64_t seed) {
  using Clock = std::chrono::steady_clock;
  RefinementRules rules(m0, bounds);
  InsertionActor actor(t,
                       Submesh::extract(static_cast<ActorId>(t.rank()), m0.dt.store(),
                                        m0.dt.points(), m0.inside, part),
                       seed, &rules);
  RankResult out;
  RankFigures& f = out.figures;
  f.start_tets = actor.submesh().real_tets();
  const auto start = Clock::now();
  actor.add_wanted_tets();
  IdlePolicy idle;
  Clock::duration busy{};
  for (;;) {
    const auto before = Clock::now();
    const bool done = actor.step();
    if (actor.worked()) busy += Clock::now() - before;
    if (done) break;
    idle.after_iteration(actor.worked(), actor.waiting());
  }
  f.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  f.busy_seconds = std::chrono::duration<double>(busy).count();
  f.steps = actor.stats();
  f.deferred = rules.deferred();
  f.messages_sent = t.sent();
  f.messages_received = t.received();
  f.bytes_sent = t.bytes_sent();
  f.empty_polls = idle.empty_iterations();
  f.sleeps = idle.sleeps();
  f.final_tets = actor.submesh().real_tets();
  out.points = actor.committed_points();
  out.figures.points = out.points.size();
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
