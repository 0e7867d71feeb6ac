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

std::optional<std::uint32_t> closure_encroached_subfacet(const VolumeMesh& m,
                                                         ClosureTets tets, const Point& p) {
  std::optional<std::uint32_t> best;
  std::array<Point, 3> best_v{};
  // Whether triangle v beats the best so far: the larger circumradius, exactly; on a tie,
  // the lexicographically smaller sorted vertices (a geometric rule: the same choice for
  // every numbering of the same mesh).
  auto beats = [&](std::array<Point, 3> v) {
    const Sign s = compare_circumradius(v[0], v[1], v[2], best_v[0], best_v[1], best_v[2]);
    if (s != Sign::Zero) return s == Sign::Positive;
    std::array<Point, 3> w = best_v;
    std::sort(v.begin(), v.end());
    std::sort(w.begin(), w.end());
    return v < w;
  };
  auto scan = [&](TetId t) {
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (!sf || sf == best) continue;
      const Subfacet& x = m.surf.subfacet(*sf);
      const std::array<Point, 3> v{m.surf.point(x.v[0]), m.surf.point(x.v[1]), m.surf.point(x.v[2])};
      if (in_equatorial_ball(v[0], v[1], v[2], p) == Sign::Negative) continue;
      if (!best || beats(v)) best = *sf, best_v = v;
    }
  };
  for (const auto& list : tets)
    for (const TetId t : list) scan(t);
  return best;
}

}  // namespace pdr::refine
