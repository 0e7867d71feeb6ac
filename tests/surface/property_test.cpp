// RapidCheck properties of the surface mesh (paper §2.1 steps 1-2) over random admissible
// box-union domains (tests/support/surface_fixtures.hpp):
//   - init_surface passes audit_surface, needs no step 2 split (the Lemma of
//     surface/init.hpp), and each convex facet's triangulation is exactly the SoS Delaunay
//     triangulation of its vertices under incircle3_sos (brute force, small facets);
//   - any sequence of splits and circumcenter insertions on the unrefined mesh keeps the
//     structural invariants, and a rejected insertion changes nothing.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "support/surface_fixtures.hpp"
#include "surface/build.hpp"
#include "surface/insert.hpp"
#include "surface/split.hpp"

namespace pdr::surface::test {
using namespace pdr::test;
using namespace pdr::domain;
namespace {

RC_GTEST_PROP(SurfaceProperty, InitPassesAudit, ()) {
  const Plc plc = *gen_box_union();
  const DomainAnalysis a = analyze(plc);
  RC_ASSERT(a.report.admissible);
  const SurfaceInit init = init_surface(a);
  const SurfaceMesh& m = init.mesh;
  const SurfaceAudit audit = audit_surface(m, 5);
  RC_ASSERT(audit.ok());
  RC_ASSERT(init.stats.encroachment_splits == 0u);
  RC_ASSERT(audit.off_plane_edges == 0u);
  for (std::uint32_t f = 0; f < m.facets.size(); ++f) {
    if (m.facets[f].boundary.size() != 4) continue;  // rectangles: convex
    std::vector<std::uint32_t> ids;
    for (const std::uint32_t t : m.facet_subfacets(f))
      for (const std::uint32_t v : m.subfacet(t).v) ids.push_back(v);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (ids.size() > 24) continue;  // brute force is O(n^4)
    RC_ASSERT(facet_triples(m, f) == brute_sos_delaunay(m.points(), ids));
  }
}

RC_GTEST_PROP(SurfaceProperty, OperationsKeepTheStructure, ()) {
  const Plc plc = *gen_box_union();
  SurfaceMesh m = build_surface(analyze(plc).domain);
  const int steps = *rc::gen::inRange(1, 25);
  for (int k = 0; k < steps; ++k) {
    if (*rc::gen::inRange(0, 2) == 0) {
      const auto s = static_cast<std::uint32_t>(
          *rc::gen::inRange<std::size_t>(0, m.subsegments().size()));
      split_subsegment(m, s);
    } else {
      std::vector<std::uint32_t> live;
      for (std::uint32_t t = 0; t < m.subfacets().size(); ++t)
        if (m.subfacet(t).alive) live.push_back(t);
      const std::uint32_t t = live[*rc::gen::inRange<std::size_t>(0, live.size())];
      const std::size_t nv = m.vertex_count(), nt = m.live_subfacets();
      const InsertResult r = insert_circumcenter(m, t);
      if (r.outcome == InsertOutcome::Encroaches)
        for (const std::uint32_t g : r.encroached) split_subsegment(m, g);
      if (r.outcome == InsertOutcome::Rejected) {
        RC_ASSERT(m.vertex_count() == nv);
        RC_ASSERT(m.live_subfacets() == nt);
      }
    }
    SurfaceAudit audit;
    audit.max_reported = 5;
    audit_surface_structure(m, audit);
    RC_ASSERT(audit.ok());
  }
}

}  // namespace
}  // namespace pdr::surface::test
