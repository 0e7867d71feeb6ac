// Encroached subsegments and subfacets among a set of tets; see refine/guard.hpp.
#include "refine/guard.hpp"

#include "geom/encroach.hpp"
#include "mesh/tables.hpp"

namespace pdr::refine {

void find_encroached(const VolumeMesh& m, std::span<const TetId> tets, EncroachedLists& out) {
  const TetStore& s = m.dt.store();
  for (const TetId t : tets) {
    if (!s.is_alive(t) || s.is_ghost(t)) continue;
    const VertexId* v = s.vertices(t);
    for (int e = 0; e < 6; ++e) {
      const int i = tables::kEdgeVertex[e][0], j = tables::kEdgeVertex[e][1];
      const auto sub = m.subsegment(v[i], v[j]);
      if (!sub) continue;
      const Point &a = m.dt.point(v[i]), &b = m.dt.point(v[j]);
      for (int k = 0; k < 4; ++k) {
        if (k == i || k == j || in_diametral_ball(a, b, m.dt.point(v[k])) != Sign::Positive)
          continue;
        const Subsegment& x = m.surf.subsegment(*sub);
        out.subsegments.push_back({*sub, {x.v[0], x.v[1], 0}, v[k], t});
        break;
      }
    }
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (!sf) continue;
      const auto& fv = tables::kFaceVertex[f];
      if (in_equatorial_ball(m.dt.point(v[fv[0]]), m.dt.point(v[fv[1]]), m.dt.point(v[fv[2]]),
                             m.dt.point(v[f])) != Sign::Positive)
        continue;
      out.subfacets.push_back({*sf, m.surf.subfacet(*sf).v, v[f], t});
    }
  }
}

bool still_subsegment(const SurfaceMesh& s, const Encroached& e) {
  const Subsegment& x = s.subsegment(e.id);
  return x.v[0] == e.v[0] && x.v[1] == e.v[1];
}

bool still_subfacet(const SurfaceMesh& s, const Encroached& e) {
  if (e.id >= s.subfacets().size()) return false;
  const Subfacet& x = s.subfacet(e.id);
  return x.alive && x.v == e.v;
}

}  // namespace pdr::refine
