// Flat tets on a facet (issue #3); see surface_flat.hpp.
#include "refine/surface_flat.hpp"

#include "geom/construct.hpp"

namespace pdr::refine {

std::optional<std::uint32_t> flat_on_facet(const VolumeMesh& m, TetId t) {
  const TetStore& s = m.dt.store();
  std::optional<std::uint32_t> best;
  double best_r2 = -1;
  for (int f = 0; f < 4; ++f) {
    const auto sf = m.face_subfacet(t, f);
    if (!sf) continue;
    const VertexId apex = s.vertex(t, f);
    const std::uint32_t v = apex < m.d2s.size() ? m.d2s[apex] : kNone;
    if (v == kNone) continue;
    const std::uint32_t facet = m.surf.subfacet(*sf).facet;
    bool on = false;
    for (const std::uint32_t x : m.surf.vertex_subfacets(v))
      on = on || (m.surf.subfacet(x).alive && m.surf.subfacet(x).facet == facet);
    if (!on) continue;
    const Subfacet& x = m.surf.subfacet(*sf);
    const double r2 = construct::triangle_circumradius2(  // a choice only
        m.surf.point(x.v[0]), m.surf.point(x.v[1]), m.surf.point(x.v[2]));
    if (r2 > best_r2) best_r2 = r2, best = *sf;
  }
  return best;
}

}  // namespace pdr::refine
