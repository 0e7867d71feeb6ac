// Subfacet circumcenter insertion (paper §2.1 step 2, Fig. 2); see surface/insert.hpp.
#include "surface/insert.hpp"

#include "geom/construct.hpp"

namespace pdr::surface {

Point subfacet_circumcenter(const SurfaceMesh& m, std::uint32_t t) {
  const Subfacet& s = m.subfacet(t);
  const Point c =
      construct::triangle_circumcenter(m.point(s.v[0]), m.point(s.v[1]), m.point(s.v[2]));
  return place_on_facet(m.facets[s.facet].chart, c);
}

FacetCavity plan_circumcenter(const SurfaceMesh& m, std::uint32_t t) {
  return build_facet_cavity(m, m.subfacet(t).facet, subfacet_circumcenter(m, t), {t},
                            std::nullopt);
}

InsertResult insert_circumcenter(SurfaceMesh& m, std::uint32_t t) {
  const FacetCavity c = plan_circumcenter(m, t);
  InsertResult r;
  r.point = c.p;
  r.cavity = c.status;
  switch (c.status) {
    case CavityStatus::Ok:
      r.outcome = InsertOutcome::Inserted;
      r.vertex = m.add_vertex(c.p, {HomeKind::Facet, c.facet});
      r.subfacets = commit_facet_cavity(m, c, r.vertex);
      break;
    case CavityStatus::Encroaches:
      r.outcome = InsertOutcome::Encroaches;
      r.encroached = c.encroached;
      break;
    default:
      r.outcome = InsertOutcome::Rejected;
      break;
  }
  return r;
}

}  // namespace pdr::surface
