// Mesh initialization, paper §2.1 steps 1 and 2 (surface/init.hpp): the data/ domains
// initialize and pass audit_surface; a cocircular grid facet gets exactly the SoS Delaunay
// triangulation of incircle3_sos; tilted facets keep every exact structural invariant;
// inadmissible domains terminate; the guard fires with a message naming the facet.
#include <gtest/gtest.h>

#include <cmath>

#include "support/plc_fixtures.hpp"
#include "support/surface_fixtures.hpp"

namespace pdr::surface::test {
using namespace pdr::test;
using namespace pdr::domain;
namespace {

SurfaceInit init_of(const Plc& plc, const SurfaceOptions& o = {}) {
  return init_surface(analyze(plc), o);
}

void expect_clean(const std::string& name) {
  SCOPED_TRACE(name);
  const DomainAnalysis a = analyze(read_data(name));
  ASSERT_TRUE(a.report.admissible);
  const SurfaceInit init = init_surface(a);
  const SurfaceMesh& m = init.mesh;
  const SurfaceAudit audit = audit_surface(m);
  EXPECT_TRUE(audit.ok()) << describe(audit);
  EXPECT_EQ(m.d, a.report.feature.d);
  EXPECT_GT(init.stats.segment_splits, 0u);
  // Paper §2.1 / Lemma 1: no step 2 split is needed after step 1 (exact coplanar input).
  EXPECT_EQ(init.stats.encroachment_splits, 0u);
  EXPECT_GT(audit.coplanar_edges, 0u);
  EXPECT_EQ(audit.off_plane_edges, 0u);  // axis-parallel facets: every point exactly on them
  for (std::uint32_t f = 0; f < m.facets.size(); ++f) EXPECT_FALSE(m.facet_subfacets(f).empty());
}

TEST(SurfaceInit, Box) { expect_clean("box.poly"); }
TEST(SurfaceInit, CubeInCube) { expect_clean("cube-in-cube.poly"); }
TEST(SurfaceInit, LPrism) { expect_clean("l-prism.poly"); }
TEST(SurfaceInit, TeeAdmissible) { expect_clean("tee-admissible.poly"); }

TEST(SurfaceInit, FrameWithFacetHoles) {
  const DomainAnalysis a = analyze(frame_box());
  ASSERT_TRUE(a.report.admissible);
  const SurfaceInit init = init_surface(a);
  const SurfaceAudit audit = audit_surface(init.mesh);
  EXPECT_TRUE(audit.ok()) << describe(audit);
  // No subfacet of a cap lies in the hole.
  for (const std::uint32_t f : {0u, 1u})
    for (const std::uint32_t t : init.mesh.facet_subfacets(f)) {
      double cx = 0, cy = 0;
      for (const std::uint32_t v : init.mesh.subfacet(t).v) {
        cx += init.mesh.point(v)[0] / 3;
        cy += init.mesh.point(v)[1] / 3;
      }
      EXPECT_FALSE(cx > 1.5 && cx < 2.5 && cy > 1.5 && cy < 2.5);
    }
}

TEST(SurfaceInit, InteriorSegmentIsConformedOnBothSides) {
  const DomainAnalysis a = analyze(box_with_interior_segment());
  ASSERT_TRUE(a.report.admissible);
  const SurfaceInit init = init_surface(a);
  const SurfaceMesh& m = init.mesh;
  const SurfaceAudit audit = audit_surface(m);
  EXPECT_TRUE(audit.ok()) << describe(audit);
  const auto s = a.domain.find_segment(8, 9);
  ASSERT_TRUE(s.has_value());
  const auto chain = m.chain(*s);
  for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    EXPECT_EQ(m.subfacets_on_edge(1, chain[i], chain[i + 1]).size(), 2u);
}

TEST(SurfaceInit, BoxCountsAndHomes) {
  // box [0,3]x[0,2]x[0,1], d = 1/sqrt(2): subsegments < sqrt(2): the 3-edges in 4 pieces,
  // the 2-edges in 2, the 1-edges unsplit.
  const SurfaceInit init = init_of(read_data("box.poly"));
  const SurfaceMesh& m = init.mesh;
  std::size_t pieces = 0;
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) {
    const auto chain = m.chain(s);
    const Point &a = m.point(m.segments[s].a), &b = m.point(m.segments[s].b);
    const double len = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                 (a[2] - b[2]) * (a[2] - b[2]));
    EXPECT_EQ(chain.size() - 1, len == 3 ? 4u : (len == 2 ? 2u : 1u));
    pieces += chain.size() - 1;
    for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
      EXPECT_EQ(m.home(chain[i]).kind, HomeKind::Segment);
      EXPECT_EQ(m.home(chain[i]).id, s);
    }
  }
  EXPECT_EQ(pieces, m.subsegments().size());
  for (std::uint32_t v = 0; v < 8; ++v) EXPECT_EQ(m.home(v).kind, HomeKind::Input);
  for (std::uint32_t v = 8; v < m.vertex_count(); ++v) EXPECT_NE(m.home(v).kind, HomeKind::Input);
}

TEST(SurfaceInit, GridFacetIsTheSosDelaunayTriangulation) {
  // Every grid square is cocircular: the diagonals are decided by the symbolic
  // perturbation alone, and must be those of incircle3_sos (hence of insphere_sos).
  const int n = 4;  // a power of two: step 1 puts the boundary vertices on the grid
  const SurfaceInit init = init_of(grid_facet_box(n));
  const SurfaceMesh& m = init.mesh;
  const SurfaceAudit audit = audit_surface(m);
  EXPECT_TRUE(audit.ok()) << describe(audit);
  EXPECT_GT(audit.cocircular, 0u);
  // Facet 0 (z = 0): its vertices are the (n+1)^2 grid points, nothing else was needed.
  std::vector<std::uint32_t> ids;
  for (const std::uint32_t t : m.facet_subfacets(0))
    for (const std::uint32_t v : m.subfacet(t).v) ids.push_back(v);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  EXPECT_EQ(ids.size(), static_cast<std::size_t>((n + 1) * (n + 1)));
  EXPECT_EQ(facet_triples(m, 0), brute_sos_delaunay(m.points(), ids));
  EXPECT_EQ(m.facet_subfacets(0).size(), static_cast<std::size_t>(2 * n * n));
}

TEST(SurfaceInit, TiltedFacetsKeepTheExactStructure) {
  // Tilted walls (rotated about z) and tolerance-planar facets (tumbled): constructed
  // points are a few ulps off the facet planes, so incircle3_sos is compared only where
  // four points are exactly coplanar; every exact structural invariant must hold
  // regardless (surface/chart.hpp). Ball violations may only come from near-cocircular
  // vertices of the same facet off the subfacet's plane (the documented limitation).
  for (const Plc& plc : {rotated_box(8, 6, 1), tumbled_box(8, 6, 1), tumbled_box(16, 16, 1)}) {
    const SurfaceInit init = init_of(plc);
    const SurfaceMesh& m = init.mesh;
    SurfaceAudit structure;
    audit_surface_structure(m, structure);
    EXPECT_TRUE(structure.ok()) << describe(structure);
    EXPECT_GT(structure.off_plane_edges, 0u);
    const SurfaceAudit full = audit_surface(m);
    EXPECT_EQ(full.violation_count, full.off_plane_balls) << describe(full);
  }
}

TEST(SurfaceInit, InadmissibleDomainsTerminate) {
  for (const char* name : {"wedge60.poly", "tee.poly"}) {
    SCOPED_TRACE(name);
    const DomainAnalysis a = analyze(read_data(name));
    EXPECT_FALSE(a.report.admissible);
    try {
      const SurfaceInit init = init_surface(a);
      SurfaceAudit audit;
      audit_surface_structure(init.mesh, audit);
      EXPECT_TRUE(audit.ok()) << describe(audit);
    } catch (const SurfaceError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("surface.", 0), 0u) << e.what();
    }
  }
}

TEST(SurfaceInit, GuardNamesTheFacet) {
  const Plc plc = read_data("box.poly");
  const SurfaceInit full = init_of(plc);
  ASSERT_GT(full.stats.circumcenters, 0u);
  SurfaceOptions o;
  o.max_vertices = 8 + full.stats.segment_splits + 1;  // step 1 completes, step 2 cannot
  try {
    (void)init_of(plc, o);
    FAIL() << "the guard did not fire";
  } catch (const SurfaceCapError& e) {  // a resource limit, its own type (exit 3)
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("surface.cap: facet ", 0), 0u) << msg;
    EXPECT_NE(msg.find("box.poly:"), std::string::npos) << msg;
  }
  o.max_vertices = 9;  // step 1 cannot complete: the message names a segment
  try {
    (void)init_of(plc, o);
    FAIL() << "the guard did not fire";
  } catch (const SurfaceCapError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("surface.cap: segment ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace pdr::surface::test
