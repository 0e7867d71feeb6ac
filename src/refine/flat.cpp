// Subfacets a tet asks to refine (issue #3); see refine/flat.hpp.
#include "refine/flat.hpp"

#include <cmath>
#include <sstream>

#include "geom/construct.hpp"
#include "geom/encroach.hpp"

namespace pdr::refine {

namespace {

// One scan of t's subfacet faces: the largest hit of rule 1 (when `flat`) and the largest
// hit of rule 1 or rule 2.
SubfacetPicks pick(const VolumeMesh& m, TetId t, bool flat) {
  const TetStore& s = m.dt.store();
  SubfacetPicks out;
  double flat_r2 = -1, any_r2 = -1;
  for (int f = 0; f < 4; ++f) {
    const auto sf = m.face_subfacet(t, f);
    if (!sf) continue;
    const VertexId apex = s.vertex(t, f);
    if (apex == kGhostVertex) continue;
    const Subfacet& x = m.surf.subfacet(*sf);
    const Point &a = m.surf.point(x.v[0]), &b = m.surf.point(x.v[1]), &c = m.surf.point(x.v[2]);
    const std::uint32_t v = apex < m.d2s.size() ? m.d2s[apex] : kNone;
    bool on_plane = false;
    const std::uint32_t plane = m.surf.facets[x.facet].plane_group;
    if (flat && v != kNone)
      for (const std::uint32_t y : m.surf.vertex_subfacets(v))
        on_plane = on_plane || (m.surf.subfacet(y).alive &&
                                m.surf.facets[m.surf.subfacet(y).facet].plane_group == plane);
    if (!on_plane && in_equatorial_ball(a, b, c, m.dt.point(apex)) != Sign::Positive) continue;
    const double r2 = construct::triangle_circumradius2(a, b, c);  // a choice only
    if (on_plane && r2 > flat_r2) flat_r2 = r2, out.flat = *sf;
    if (r2 > any_r2) any_r2 = r2, out.any = *sf;
  }
  return out;
}

}  // namespace

SubfacetPicks subfacets_to_refine(const VolumeMesh& m, TetId t) { return pick(m, t, true); }

std::optional<std::uint32_t> subfacet_to_refine(const VolumeMesh& m, TetId t) {
  return pick(m, t, true).any;
}

std::optional<std::uint32_t> encroached_subfacet_face(const VolumeMesh& m, TetId t) {
  return pick(m, t, false).any;
}

std::optional<std::uint32_t> flat_subfacet_face(const VolumeMesh& m, TetId t) {
  return pick(m, t, true).flat;
}

std::string within_planarity_gap(const SurfaceMesh& s, std::uint32_t f) {
  const Subfacet& x = s.subfacet(f);
  const double gap = s.facets[x.facet].gap;
  if (gap == 0) return {};
  const double r = std::sqrt(
      construct::triangle_circumradius2(s.point(x.v[0]), s.point(x.v[1]), s.point(x.v[2])));
  if (r >= gap) return {};
  std::ostringstream os;
  os.precision(6);
  os << "refine.flat: subfacet (" << x.v[0] << ", " << x.v[1] << ", " << x.v[2] << ") of "
     << s.facet_name(x.facet)
     << " under a tet with its four vertices on the facet has circumradius " << r
     << ", below the facet's planarity gap " << gap
     << " (its input vertices lie that far off its plane): the tet is the facet's own bend";
  return os.str();
}

}  // namespace pdr::refine
