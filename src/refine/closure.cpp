// Fig. 2's encroachment tests on a cavity's closure; see refine/closure.hpp.
#include "refine/closure.hpp"

#include "geom/construct.hpp"
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
  double best_r2 = -1;
  auto scan = [&](TetId t) {
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (!sf) continue;
      const Subfacet& x = m.surf.subfacet(*sf);
      const Point &a = m.surf.point(x.v[0]), &b = m.surf.point(x.v[1]),
                  &c = m.surf.point(x.v[2]);
      if (in_equatorial_ball(a, b, c, p) == Sign::Negative) continue;
      const double r2 = construct::triangle_circumradius2(a, b, c);  // choice only
      if (r2 > best_r2) best_r2 = r2, best = *sf;
    }
  };
  for (const auto& list : tets)
    for (const TetId t : list) scan(t);
  return best;
}

}  // namespace pdr::refine
