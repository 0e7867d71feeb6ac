// The unrefined surface mesh (paper §2.1); see surface_build.hpp.
#include "refine/surface_build.hpp"

namespace pdr::refine {

SurfaceMesh build_surface(const PlcDomain& dom) {
  const Plc& plc = dom.plc;
  SurfaceMesh m;
  m.source = plc.source;
  for (std::uint32_t v = 0; v < plc.points.size(); ++v)
    m.add_vertex(plc.points[v], {dom.on_boundary[v] ? HomeKind::Input : HomeKind::Unused, v});
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    const DomainSegment& S = dom.segments[s];
    m.segments.push_back({S.a, S.b, S.facets});
    m.add_subsegment(S.a, S.b, s);
  }
  m.facets.resize(dom.facets.size());
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    const DomainFacet& F = dom.facets[f];
    SurfaceFacet& sf = m.facets[f];
    sf.is_face = F.is_face;
    sf.segments = F.segments;
    sf.line = plc.facets[f].line;
    if (!F.is_face) continue;
    sf.chart = make_chart(F.plane, plc.points);
    const auto base = static_cast<std::int32_t>(m.subfacets().size());
    for (const FacetTri& T : F.tris) {
      Subfacet t;
      t.v = T.v;
      t.facet = f;
      for (int i = 0; i < 3; ++i) {
        t.nbr[i] = T.nbr[i] >= 0 ? base + T.nbr[i] : -1;
        t.constrained[i] = T.on_segment[i];
        if (T.nbr[i] >= 0) continue;
        const std::uint32_t u = T.v[(i + 1) % 3], w = T.v[(i + 2) % 3];
        const std::uint32_t s = *dom.find_segment(u, w);
        sf.boundary.push_back({s, u == dom.segments[s].a});
      }
      m.add_subfacet(t);
    }
    make_facet_delaunay(m, f);
  }
  return m;
}

}  // namespace pdr::refine
