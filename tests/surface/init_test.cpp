// Mesh initialization, paper §2.1 steps 1 and 2 (surface/init.hpp): the data/ domains
// initialize and pass audit_surface; a cocircular grid facet gets exactly the SoS Delaunay
// triangulation of incircle3_sos; tilted facets keep every exact structural invariant;
// inadmissible domains terminate; the guard fires with a message naming the facet.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

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

// A box 8 x 5 x 5 with a cubical void of side 1/8: d is set by the void, so the uniform
// mesh of §2.1 covers the outer box at the void's scale; the graded one sizes each facet and
// segment by its own distance to unrelated components (surface/init.hpp), keeps every
// exact invariant of audit_surface (sizes per element, encroachment included), and is far
// smaller.
TEST(SurfaceInit, GradedOnASmallFeature) {
  Plc plc = merge(box({0, 0, 0}, {8, 5, 5}), box({1, 1, 1}, {1.125, 1.125, 1.125}));
  plc.holes.push_back({1.0625, 1.0625, 1.0625});
  relabel(plc);
  const DomainAnalysis a = analyze(plc);
  ASSERT_TRUE(a.report.admissible);
  const SurfaceInit graded = init_surface(a);  // auto
  const SurfaceInit uniform = init_surface(a, {0, SurfaceSizing::Uniform});
  EXPECT_TRUE(graded.stats.graded);
  EXPECT_FALSE(uniform.stats.graded);
  EXPECT_GT(graded.stats.uniform_estimate, kGradedGain * graded.stats.graded_estimate);
  const SurfaceAudit audit = audit_surface(graded.mesh);
  EXPECT_TRUE(audit.ok()) << describe(audit);
  EXPECT_TRUE(audit_surface(uniform.mesh).ok());
  EXPECT_LT(10 * graded.mesh.vertex_count(), uniform.mesh.vertex_count());
  // Every size is at least d. The outer box's facets are sized by their distance to the
  // void (1 for the three walls at x, y, z = 0; 3.875 and 6.875 for the others), the
  // void's by their opposite faces (1/8 apart, sharing no vertex: unrelated), which set d.
  const SurfaceMesh& m = graded.mesh;
  EXPECT_NEAR(m.d, 0.125 / std::sqrt(2.0), 1e-12);
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) EXPECT_GE(m.segment_size(s), m.d);
  std::multiset<long> outer;
  for (std::uint32_t f = 0; f < 6; ++f) outer.insert(std::lround(m.facet_size(f) * std::sqrt(2.0) * 1000));
  EXPECT_EQ(outer, (std::multiset<long>{1000, 1000, 1000, 3875, 3875, 6875}));
  for (std::uint32_t f = 6; f < 12; ++f) EXPECT_NEAR(m.facet_size(f), m.d, 1e-15);
  // Step 2 needs no split (the per-facet argument of surface/init.hpp).
  EXPECT_EQ(graded.stats.encroachment_splits, 0u);
  // On a uniform domain auto keeps the paper's mesh.
  EXPECT_FALSE(init_surface(analyze(read_data("cube-in-cube.poly"))).stats.graded);
  // Forced graded on a cube of side 6 with a unit void 2 from its walls (a property test's
  // find): an outer edge is 2 sqrt(2) from the void, its faces only 2, so the edge must be
  // refined for its faces' d, not its own, or step 2's circumcenters encroach it.
  Plc cube = merge(box({0, 0, 0}, {6, 6, 6}), box({2, 2, 2}, {3, 3, 3}));
  cube.holes.push_back({2.5, 2.5, 2.5});
  relabel(cube);
  const SurfaceInit forced = init_surface(analyze(cube), {0, SurfaceSizing::Graded});
  EXPECT_TRUE(forced.stats.graded);
  EXPECT_EQ(forced.stats.encroachment_splits, 0u);
  EXPECT_TRUE(audit_surface(forced.mesh).ok()) << describe(audit_surface(forced.mesh));
}

// Graded by position, not by facet: a void of side 1/2 just 0.01 inside the wall x = 0 of
// a 10-cube makes only the patch of that wall facing it fine. Sized by facet, the whole
// wall (area 100) would be refined for the gap: about 100 / (0.01 / sqrt 2)^2 = 2 million
// vertices; by position a few thousand. Every element meets its size at its position
// (audit_surface), and step 2 splits nothing (surface/init.hpp's argument).
TEST(SurfaceInit, GradedByPositionNotByFacet) {
  Plc plc = merge(box({0, 0, 0}, {10, 10, 10}), box({0.01, 4.75, 4.75}, {0.51, 5.25, 5.25}));
  plc.holes.push_back({0.26, 5, 5});
  relabel(plc);
  const SurfaceInit g = init_surface(analyze(plc));
  EXPECT_TRUE(g.stats.graded);
  EXPECT_LT(g.mesh.vertex_count(), 50000u);
  EXPECT_GT(g.mesh.vertex_count(), 1000u);  // the patch is refined for the gap
  EXPECT_EQ(g.stats.encroachment_splits, 0u);
  const SurfaceAudit audit = audit_surface(g.mesh);
  EXPECT_TRUE(audit.ok()) << describe(audit);
}

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
  // Step 1 cannot complete (it makes 24 vertices), yet the estimate's lower bound (about
  // 8) does not stop it before: the message names a segment.
  o.max_vertices = 20;
  try {
    (void)init_of(plc, o);
    FAIL() << "the guard did not fire";
  } catch (const SurfaceCapError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("surface.cap: segment ", 0), 0u) << e.what();
  }
}

// A mesh that cannot fit under the cap is not started: a 10 x 10 x 0.001 plate (d is the
// thickness over sqrt(2), so about 4e8 vertices) stops before any refinement.
TEST(SurfaceInit, ThinPlateStopsBeforeRefinement) {
  SurfaceOptions o;
  o.max_vertices = 1000000;
  try {
    (void)init_of(box({0, 0, 0}, {10, 10, 0.001}), o);
    FAIL() << "the guard did not fire";
  } catch (const SurfaceCapError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("surface.cap: before refinement: ", 0), 0u) << e.what();
  }
}

// What the early stop relies on: the finished meshes hold more than the estimate's lower
// bound (kEstimateOverLeast), uniform and graded, with room to spare.
TEST(SurfaceInit, FinishedMeshesHoldMoreThanTheEstimatesLowerBound) {
  std::vector<Plc> plcs;
  for (const char* name : {"box.poly", "cube-in-cube.poly", "l-prism.poly", "tee.poly",
                           "tee-paper.poly", "wedge60.poly"})
    plcs.push_back(read_data(name));
  plcs.push_back(box({0, 0, 0}, {100, 1, 1}));
  plcs.push_back(merge(box({0, 0, 0}, {8, 5, 5}), box({1, 1, 1}, {1.125, 1.125, 1.125})));
  for (const Plc& plc : plcs)
    for (const SurfaceSizing sizing : {SurfaceSizing::Uniform, SurfaceSizing::Graded}) {
      SurfaceOptions o;
      o.sizing = sizing;
      const SurfaceInit init = init_of(plc, o);
      const double estimate =
          init.stats.graded ? init.stats.graded_estimate : init.stats.uniform_estimate;
      const auto n = static_cast<double>(init.mesh.vertex_count());
      EXPECT_GT(n, 2 * estimate / kEstimateOverLeast) << plc.source << " graded " << init.stats.graded;
    }
}

}  // namespace
}  // namespace pdr::surface::test
