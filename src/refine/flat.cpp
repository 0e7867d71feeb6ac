// Subfacets a tet asks to refine (issue #3); see refine/flat.hpp.
#include "refine/flat.hpp"

#include "geom/construct.hpp"
#include "geom/encroach.hpp"

namespace pdr::refine {

namespace {

// Rule 2 when `encroached`, rule 1 when `flat`.
std::optional<std::uint32_t> pick(const VolumeMesh& m, TetId t, bool flat, bool encroached) {
  const TetStore& s = m.dt.store();
  std::optional<std::uint32_t> best;
  double best_r2 = -1;
  for (int f = 0; f < 4; ++f) {
    const auto sf = m.face_subfacet(t, f);
    if (!sf) continue;
    const VertexId apex = s.vertex(t, f);
    if (apex == kGhostVertex) continue;
    const Subfacet& x = m.surf.subfacet(*sf);
    const Point &a = m.surf.point(x.v[0]), &b = m.surf.point(x.v[1]), &c = m.surf.point(x.v[2]);
    const std::uint32_t v = apex < m.d2s.size() ? m.d2s[apex] : kNone;
    bool hit = false;
    const std::uint32_t plane = m.surf.facets[x.facet].plane_group;
    if (flat && v != kNone)
      for (const std::uint32_t y : m.surf.vertex_subfacets(v))
        hit = hit || (m.surf.subfacet(y).alive &&
                      m.surf.facets[m.surf.subfacet(y).facet].plane_group == plane);
    hit = hit || (encroached && in_equatorial_ball(a, b, c, m.dt.point(apex)) == Sign::Positive);
    if (!hit) continue;
    const double r2 = construct::triangle_circumradius2(a, b, c);  // a choice only
    if (r2 > best_r2) best_r2 = r2, best = *sf;
  }
  return best;
}

}  // namespace

std::optional<std::uint32_t> subfacet_to_refine(const VolumeMesh& m, TetId t) {
  return pick(m, t, true, true);
}

std::optional<std::uint32_t> encroached_subfacet_face(const VolumeMesh& m, TetId t) {
  return pick(m, t, false, true);
}

std::optional<std::uint32_t> flat_subfacet_face(const VolumeMesh& m, TetId t) {
  return pick(m, t, true, false);
}

}  // namespace pdr::refine
