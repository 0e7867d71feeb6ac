// RapidCheck properties of the surface mesh (paper §2.1 steps 1-2) over random admissible
// box-union domains (tests/support/surface_fixtures.hpp):
//   - init_surface passes audit_surface, needs no step 2 split (the Lemma of
//     surface/init.hpp), and each rectangular facet's triangulation is exactly the SoS
//     Delaunay triangulation of its vertices under incircle3_sos: for up to 24 vertices
//     by enumerating every triple (brute force, O(n^4)); above, every triangle's circle is
//     SoS-empty of the facet's vertices (so each is a Delaunay triangle) and there are as
//     many as a triangulation of n points with b on the rectangle's boundary has,
//     2n - b - 2 (so none is missing); RC_CLASSIFY reports how often each oracle ran;
//   - any sequence of splits and circumcenter insertions on the unrefined mesh keeps the
//     structural invariants, and a rejected insertion changes nothing.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "geom/predicates.hpp"
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
  int brute = 0, counted = 0;  // facets per oracle, reported by RC_CLASSIFY
  for (std::uint32_t f = 0; f < m.facets.size(); ++f) {
    if (m.facets[f].boundary.size() != 4) continue;  // rectangles: convex
    std::vector<std::uint32_t> ids;
    for (const std::uint32_t t : m.facet_subfacets(f))
      for (const std::uint32_t v : m.subfacet(t).v) ids.push_back(v);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    const auto triples = facet_triples(m, f);
    if (ids.size() <= 24) {
      ++brute;
      RC_ASSERT(triples == brute_sos_delaunay(m.points(), ids));
      continue;
    }
    ++counted;
    const std::vector<Point>& pts = m.points();
    for (const auto& t : triples)
      for (const std::uint32_t d : ids)
        if (d != t[0] && d != t[1] && d != t[2])
          RC_ASSERT(incircle3_sos(pts[t[0]], pts[t[1]], pts[t[2]], pts[d]) == Sign::Negative);
    // The facet is an axis-aligned rectangle (box unions): a vertex is on its boundary
    // exactly when one of its two in-plane coordinates is extreme.
    int normal = 0;
    for (int k = 0; k < 3; ++k)
      if (std::all_of(ids.begin(), ids.end(),
                      [&](std::uint32_t v) { return pts[v][k] == pts[ids[0]][k]; }))
        normal = k;
    std::size_t on_boundary = 0;
    for (const std::uint32_t v : ids) {
      bool extreme = false;
      for (int k = 0; k < 3; ++k) {
        if (k == normal) continue;
        const auto [lo, hi] = std::minmax_element(
            ids.begin(), ids.end(),
            [&](std::uint32_t a, std::uint32_t b) { return pts[a][k] < pts[b][k]; });
        extreme = extreme || pts[v][k] == pts[*lo][k] || pts[v][k] == pts[*hi][k];
      }
      on_boundary += extreme ? 1 : 0;
    }
    RC_ASSERT(triples.size() == 2 * ids.size() - on_boundary - 2);
  }
  RC_CLASSIFY(counted > 0, "a facet of more than 24 vertices (empty circles and count)");
  RC_CLASSIFY(brute > 0, "a facet of at most 24 vertices (brute force)");
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
