// Fig. 2's encroachment tests on a cavity's closure; see refine/closure.hpp.
#include "refine/closure.hpp"

#include <algorithm>
#include <array>

#include "geom/encroach.hpp"
#include "mesh/tables.hpp"

namespace pdr::refine {

std::optional<std::uint32_t> closure_encroached_subsegment(const VolumeMesh& m,
                                                           ClosureTets tets, const Point& p) {
  const TetStore& s = m.dt.store();
  auto scan = [&](TetId t) -> std::optional<std::uint32_t> {
    if (s.is_ghost(t)) return std::nullopt;
    const VertexId* v = s.vertices(t);
    for (const auto& e : tables::kEdgeVertex) {
      const auto sub = m.subsegment(v[e[0]], v[e[1]]);
      if (sub && in_diametral_ball(m.dt.point(v[e[0]]), m.dt.point(v[e[1]]), p) !=
                     Sign::Negative)
        return sub;
    }
    return std::nullopt;
  };
  for (const auto& list : tets)
    for (const TetId t : list)
      if (auto r = scan(t)) return r;
  return std::nullopt;
}

bool larger_subfacet(std::array<Point, 3> a, std::array<Point, 3> b) {
  const Sign s = compare_circumradius(a[0], a[1], a[2], b[0], b[1], b[2]);
  if (s != Sign::Zero) return s == Sign::Positive;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a < b;
}

std::optional<std::uint32_t> closure_encroached_subfacet(const VolumeMesh& m,
                                                         ClosureTets tets, const Point& p) {
  std::optional<std::uint32_t> best;
  std::array<Point, 3> best_v{};
  auto scan = [&](TetId t) {
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (!sf || sf == best) continue;
      const Subfacet& x = m.surf.subfacet(*sf);
      const std::array<Point, 3> v{m.surf.point(x.v[0]), m.surf.point(x.v[1]), m.surf.point(x.v[2])};
      if (in_equatorial_ball(v[0], v[1], v[2], p) == Sign::Negative) continue;
      if (!best || larger_subfacet(v, best_v)) best = *sf, best_v = v;
    }
  };
  for (const auto& list : tets)
    for (const TetId t : list) scan(t);
  return best;
}

void ClosureScan::stamp(const TetStore& s, std::span<const TetId> conflict) {
  if (stamp_.size() < s.slots()) stamp_.resize(s.slots(), 0);
  if (++gen_ == 0) {  // wrapped: old stamps could match
    std::fill(stamp_.begin(), stamp_.end(), 0);
    gen_ = 1;
  }
  for (const TetId t : conflict) stamp_[t] = gen_;
}

bool ClosureScan::inside_cavity(const TetStore& s, TetId t, VertexId a, VertexId b) const {
  // Edge ab of conflict tet t is on no boundary face iff every tet around it is in conflict.
  TetId prev = kNoTet, cur = t;
  do {
    const VertexId* w = s.vertices(cur);
    int other[2], n = 0;
    for (int i = 0; i < 4; ++i)
      if (w[i] != a && w[i] != b) other[n++] = i;
    TetId next = s.neighbour(cur, other[0]);
    if (next == prev) next = s.neighbour(cur, other[1]);
    prev = cur;
    cur = next;
    if (stamp_[cur] != gen_) return false;
  } while (cur != t);
  return true;
}

std::optional<ClosureScan::Hit> ClosureScan::look(const VolumeMesh& m, TetId t, const Point& p,
                                                  bool encroached, bool doomed) const {
  const TetStore& s = m.dt.store();
  if (s.is_ghost(t)) return std::nullopt;
  const VertexId* v = s.vertices(t);
  for (const auto& e : tables::kEdgeVertex) {
    const auto sub = m.subsegment(v[e[0]], v[e[1]]);
    if (!sub) continue;
    if (encroached &&
        in_diametral_ball(m.dt.point(v[e[0]]), m.dt.point(v[e[1]]), p) != Sign::Negative)
      return Hit{true, true, *sub};
    if (doomed && inside_cavity(s, t, v[e[0]], v[e[1]])) return Hit{true, false, *sub};
  }
  for (int f = 0; f < 4; ++f) {
    const auto sf = m.face_subfacet(t, f);
    if (!sf) continue;
    const Subfacet& x = m.surf.subfacet(*sf);
    if (encroached && in_equatorial_ball(m.surf.point(x.v[0]), m.surf.point(x.v[1]),
                                         m.surf.point(x.v[2]), p) != Sign::Negative)
      return Hit{false, true, *sf};
    if (doomed && stamp_[s.neighbour(t, f)] == gen_) return Hit{false, false, *sf};
  }
  return std::nullopt;
}

std::optional<ClosureScan::Hit> ClosureScan::joins(const VolumeMesh& m, TetId from, int face,
                                                   TetId u, const Point& p) const {
  if (from != kNoTet)
    if (const auto sf = m.face_subfacet(from, face)) return Hit{false, false, *sf};
  return look(m, u, p, true, false);
}

std::optional<ClosureScan::Hit> ClosureScan::first(const VolumeMesh& m, const Cavity& c,
                                                  const Point& p, bool conflict_seen) {
  stamp(m.dt.store(), c.conflict);
  for (const TetId t : c.conflict)
    if (auto h = look(m, t, p, !conflict_seen, true)) return h;
  for (const TetId t : c.ring)
    if (auto h = look(m, t, p, true, false)) return h;
  return std::nullopt;
}

}  // namespace pdr::refine
