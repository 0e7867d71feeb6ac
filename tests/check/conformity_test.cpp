// conformity.* and encroachment.* against a domain; FacetRegion; tolerance classification.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "check/facet_region.hpp"
#include "check_test_util.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

using Ids = std::set<std::string>;

TEST(Conformity, KuhnGridConformsToItsBox) {
  const Report r = run(kuhn_grid(3), box_domain(3));
  EXPECT_TRUE(r.ok()) << to_text(r);
  for (const char* id : {"conformity.vertices", "conformity.segments", "conformity.facets",
                         "conformity.volume", "encroachment.subsegments", "encroachment.subfacets"})
    EXPECT_EQ(result(r, id).status, Status::Pass) << id;
  EXPECT_EQ(count(r, "conformity.segments", "subsegments"), 12u * 3);
  EXPECT_EQ(count(r, "conformity.facets", "subfacets"), 6u * 9 * 2);
  EXPECT_EQ(count(r, "conformity.facets", "tolerance_vertices"), 0u);
  // The fourth corner of each boundary square lies on its triangles' equatorial spheres.
  EXPECT_GT(count(r, "encroachment.subfacets", "on_sphere"), 0u);
}

TEST(Conformity, MissingInputVertexFailsOnlyVertices) {
  Plc d = box_domain(3);
  d.points.push_back({1.5, 1.5, 1.5});
  const Report r = run(kuhn_grid(3), d);
  EXPECT_EQ(failed(r), Ids{"conformity.vertices"}) << to_text(r);
  EXPECT_EQ(result(r, "conformity.vertices").findings.at(0).id, 8u);
}

TEST(Conformity, DeletedBoundaryTetFailsFacetsAndVolume) {
  MeshData m = kuhn_grid(3);
  m.tets.erase(m.tets.begin() + 4 * 6);  // cube (1,1,0): its tet on the bottom facet
  const Report r = run(m, box_domain(3));
  EXPECT_EQ(failed(r), (Ids{"conformity.facets", "conformity.volume"})) << to_text(r);
  EXPECT_EQ(result(r, "conformity.facets").findings.at(0).id, 0u);  // the bottom facet
}

TEST(Conformity, DeletedInteriorTetFailsVolume) {
  MeshData m = kuhn_grid(3);
  m.tets.erase(m.tets.begin() + 13 * 6 + 1);
  const Report r = run(m, box_domain(3));
  EXPECT_EQ(failed(r), Ids{"conformity.volume"}) << to_text(r);
  EXPECT_EQ(count(r, "conformity.volume", "boundary_faces_off_facets"), 4u);
}

TEST(Conformity, HoleAndRegionPointsAreLocated) {
  Plc d = box_domain(2);
  d.holes.push_back({1.25, 0.5, 0.75});
  d.regions.push_back({{5, 5, 5}, 1.0, -1, 0});
  d.regions.push_back({{0.5, 0.5, 0.5}, 2.0, -1, 0});
  const Report r = run(kuhn_grid(2), d);
  EXPECT_EQ(failed(r), Ids{"conformity.volume"});
  EXPECT_EQ(count(r, "conformity.volume", "filled_holes"), 1u);
  EXPECT_EQ(count(r, "conformity.volume", "empty_regions"), 1u);
}

TEST(Conformity, InternalFacetIsCoveredByInteriorFaces) {
  Plc d = box_domain(3);
  for (int k = 0; k < 4; ++k) d.points.push_back({k % 2 * 3.0, k / 2 * 3.0, 1.0});
  PlcFacet f;
  f.polygons.push_back({8, 9, 11, 10});
  d.facets.push_back(f);
  const Report r = run(kuhn_grid(3), d);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(count(r, "conformity.facets", "subfacets"), 6u * 9 * 2 + 9 * 2);
}

// Pieces the domain analysis dropped (bounding no region, as TetGen drops them) are not
// asked of the mesh, and a mesher may leave out the vertices only they hold; a mesh that
// covers a dropped piece has boundary faces in no facet.
TEST(Conformity, DroppedPiecesAreNotRequired) {
  Plc d = box_domain(3);
  const std::uint32_t n = static_cast<std::uint32_t>(d.points.size());
  for (int k = 0; k < 4; ++k) d.points.push_back({10.0, k % 2 * 1.0, k / 2 * 1.0});
  PlcFacet far;
  far.polygons.push_back({n, n + 1, n + 3, n + 2});
  d.facets.push_back(far);
  const std::uint32_t facet = static_cast<std::uint32_t>(d.facets.size() - 1);
  EXPECT_EQ(failed(run(kuhn_grid(3), d)), Ids{"conformity.vertices"});
  Options o;
  o.dropped_tris = {{facet, {n, n + 1, n + 3}}, {facet, {n, n + 3, n + 2}}};
  o.dropped_segments = {{n, n + 1}, {n + 1, n + 3}, {n + 3, n + 2}, {n + 2, n}};
  o.dropped_vertices = {n, n + 1, n + 2, n + 3};
  const Report r = run(kuhn_grid(3), d, o);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(result(r, "conformity.segments").status, Status::Pass) << to_text(r);
  EXPECT_EQ(result(r, "conformity.facets").status, Status::Pass) << to_text(r);

  // The bottom facet's triangle (0,0)-(3,0)-(0,3) dropped: the mesh's faces there are in
  // no facet.
  Options half;
  Plc b = box_domain(3);
  const PlcFacet& bottom = b.facets[0];
  ASSERT_EQ(bottom.polygons.at(0).size(), 4u);
  const auto& q = bottom.polygons[0];
  half.dropped_tris = {{0, {q[0], q[1], q[2]}}};
  const Report h = run(kuhn_grid(3), b, half);
  EXPECT_EQ(failed(h), Ids{"conformity.volume"}) << to_text(h);
  EXPECT_EQ(result(h, "conformity.facets").status, Status::Pass) << to_text(h);
}

TEST(Encroachment, VertexNearASubsegmentFails) {
  MeshData m = kuhn_grid(3);
  m.points[grid_id(3, 1, 1, 1)] = {0.3, 0.3, 0.3};  // 70% along the edge to the corner
  const Report r = run(m, box_domain(3));
  EXPECT_TRUE(failed(r).count("encroachment.subsegments")) << to_text(r);
  EXPECT_EQ(result(r, "validity.orientation").status, Status::Pass);
  const Finding& f = result(r, "encroachment.subsegments").findings.at(0);
  EXPECT_EQ(f.vertices.back(), grid_id(3, 1, 1, 1));
}

TEST(Encroachment, VertexNearASubfacetFailsSubfacetsOnly) {
  MeshData m = kuhn_grid(4);
  m.points[grid_id(4, 2, 2, 1)] = {1.6, 1.6, 0.6};  // 40% along the edge to (1,1,0)
  const Report r = run(m, box_domain(4));
  EXPECT_TRUE(failed(r).count("encroachment.subfacets")) << to_text(r);
  EXPECT_EQ(result(r, "encroachment.subsegments").status, Status::Pass);
  EXPECT_EQ(result(r, "validity.orientation").status, Status::Pass);
  for (const char* id : {"conformity.segments", "conformity.facets", "conformity.volume"})
    EXPECT_EQ(result(r, id).status, Status::Pass) << id;
}

// Rotating a grid rounds its coordinates: vertices on tilted facets and segments are no
// longer exactly coplanar or collinear. The relative tolerance classifies them; areas and
// orders stay exact.
Point rotate(const Point& p) {
  const double c = std::cos(0.3), s = std::sin(0.3), c2 = std::cos(0.7), s2 = std::sin(0.7);
  const Point q = {c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]};
  return {q[0], c2 * q[1] - s2 * q[2], s2 * q[1] + c2 * q[2]};
}

TEST(Conformity, ToleranceClassifiesRoundedVertices) {
  MeshData m = kuhn_grid(2);
  for (Point& p : m.points) p = rotate(p);
  Plc d = box_domain(2);
  for (Point& p : d.points) p = rotate(p);
  const Report r = run(m, d);
  for (const char* id : {"conformity.vertices", "conformity.segments", "conformity.facets", "conformity.volume"})
    EXPECT_EQ(result(r, id).status, Status::Pass) << id << "\n" << to_text(r);
  EXPECT_GT(count(r, "conformity.segments", "tolerance_vertices"), 0u);
  EXPECT_GT(count(r, "conformity.facets", "tolerance_vertices"), 0u);
  Options exact_only;
  exact_only.relative_tolerance = 0;
  const Report e = run(m, d, exact_only);
  EXPECT_EQ(result(e, "conformity.segments").status, Status::Fail);
  EXPECT_EQ(result(e, "conformity.volume").status, Status::Fail);
  EXPECT_NE(result(e, "conformity.facets").status, Status::Pass);
}

// A pyramid over a base of two triangle facets, ABC and ACD, D raised 1e-10 above ABC's
// plane (a quad's triangles a hair from coplanar, folded up along AC), meshed with the
// sliver ABCD inside and two tets on it to the apex E. The sliver's upper faces ABD and BCD
// have every corner within tolerance of ABC's plane and their centroids inside ABC, but D
// lies outside ABC: they are not in the facet, and the facet is covered once (they were
// counted, and the facet covered more than once). Without the sliver nothing covers the
// base (nor segment AC), and ABD and BCD do not pass for it.
TEST(Conformity, SliverAcrossANearlyFlatFoldIsNotInTheFacet) {
  const auto pyramid = [] {
    Plc d;
    d.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.2, 1, 1e-10}, {0.5, 0.5, 1}};
    for (const std::vector<std::uint32_t>& f :
         std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}) {
      PlcFacet g;
      g.polygons.push_back(f);
      d.facets.push_back(g);
    }
    MeshData m;
    m.points = d.points;
    m.tets = {{0, 1, 2, 3}, {0, 1, 3, 4}, {1, 2, 3, 4}};
    return std::pair{m, d};
  };
  const auto [m, d] = pyramid();
  const Report r = run(m, d);
  for (const CheckResult& c : r.checks)
    if (c.id.rfind("validity.", 0) == 0) {
      EXPECT_NE(c.status, Status::Fail) << c.id << "\n" << to_text(r);
    }
  for (const char* id : {"conformity.vertices", "conformity.segments", "conformity.facets", "conformity.volume"})
    EXPECT_EQ(result(r, id).status, Status::Pass) << id << "\n" << to_text(r);
  EXPECT_GT(count(r, "conformity.facets", "tolerance_vertices"), 0u);
  MeshData open = m;
  open.tets.erase(open.tets.begin());
  const Ids without = failed(run(open, d));
  EXPECT_TRUE(without.contains("conformity.facets") && without.contains("conformity.volume"));
}

// A domain whose facets are one polygon each.
Plc domain_of(std::vector<Point> points,
              const std::vector<std::vector<std::uint32_t>>& facets) {
  Plc d;
  d.points = std::move(points);
  for (const auto& f : facets) {
    PlcFacet g;
    g.polygons.push_back(f);
    d.facets.push_back(g);
  }
  return d;
}

// The tets, each positively oriented (two vertices swapped where the exact orient3d says
// negative).
std::vector<Tet> positive(const std::vector<Point>& p, std::vector<Tet> tets) {
  for (Tet& t : tets)
    if (exact::orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) == Sign::Negative)
      std::swap(t[0], t[1]);
  return tets;
}

void expect_valid_and_conforming(const Report& r) {
  for (const char* id : {"validity.orientation", "validity.overlap", "conformity.vertices",
                         "conformity.segments", "conformity.facets", "conformity.volume"})
    EXPECT_EQ(result(r, id).status, Status::Pass) << id << "\n" << to_text(r);
}

// A pyramid over a square base given as one facet ABCD, D raised 1e-10 (coplanar only
// within the tolerance), meshed with a flat tet ABCQ on the base: Q lies 1e-11 above
// ABC's plane, so all four corners are within the tolerance of the facet and so are the
// flat tet's upper faces ABQ, BCQ and CAQ, between it and the tets to the apex. Those
// are faces of a stack in the facet's slab, not subfacets: the facet is covered once, by
// the boundary faces ABC and ACD (they were counted too, and the facet covered about
// twice, as pdr's own meshes of a scanned model with 6-digit coordinates were reported).
// (The mesh is no Delaunay one: only conformity is asked of it.)
TEST(Conformity, FacesOfAFlatTetOnAToleranceFacetAreNotSubfacets) {
  const Plc d = domain_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-10}, {0.5, 0.5, 1}},
                          {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  MeshData m;
  m.points = d.points;
  m.points.push_back({0.6, 0.3, 1e-11});  // Q is the mesh's, not the domain's
  m.tets = positive(m.points,
                    {{0, 1, 2, 5}, {0, 1, 5, 4}, {1, 2, 5, 4}, {2, 0, 5, 4}, {0, 2, 3, 4}});
  const Report r = run(m, d);
  expect_valid_and_conforming(r);
  EXPECT_EQ(count(r, "conformity.facets", "subfacets"), 2u + 4u);
  EXPECT_GT(count(r, "conformity.facets", "tolerance_vertices"), 0u);
}

// The same flat tet on the base of two pyramids glued base to base (apexes E above and F
// below; no hole point, so both are regions and the base lies between them, as TetGen
// reads a .poly). Every face on the base is now held by two tets: ABC and ACD between the
// flat tet or the upper tet and the lower pyramid's, ABQ, BCQ and CAQ between the flat tet
// and the upper ones. Either layer covers the base once; the faces on the flat tet's
// lower side count (its outward normal there points down the chart's axis), its upper
// ones not (they were counted too: the base covered about twice).
TEST(Conformity, AFlatTetOnAToleranceFacetBetweenTwoRegionsCoversItOnce) {
  const Plc d = domain_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-10}, {0.5, 0.5, 1},
                           {0.5, 0.5, -1}},
                          {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 1, 5},
                           {1, 2, 5}, {2, 3, 5}, {3, 0, 5}});
  MeshData m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-10}, {0.5, 0.5, 1}, {0.6, 0.3, 1e-11},
              {0.5, 0.5, -1}};
  m.tets = positive(m.points, {{0, 1, 2, 5}, {0, 1, 5, 4}, {1, 2, 5, 4}, {2, 0, 5, 4},
                               {0, 2, 3, 4}, {0, 1, 2, 6}, {0, 2, 3, 6}});
  const Report r = run(m, d);
  expect_valid_and_conforming(r);
  EXPECT_EQ(count(r, "conformity.facets", "subfacets"), 2u + 8u);
  EXPECT_GT(count(r, "conformity.facets", "tolerance_vertices"), 0u);
  // A mesh that lists its faces says which layer is the facet's: here the upper one (ABQ,
  // BCQ, CAQ with ACD), which then covers the base once.
  MeshData listed = m;
  listed.faces = {{0, 1, 5}, {1, 2, 5}, {2, 0, 5}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4},
                  {3, 0, 4}, {0, 1, 6}, {1, 2, 6}, {2, 3, 6}, {3, 0, 6}};
  const Report l = run(listed, d);
  for (const char* id : {"conformity.facets", "conformity.volume"})
    EXPECT_EQ(result(l, id).status, Status::Pass) << id << "\n" << to_text(l);
  EXPECT_EQ(count(l, "conformity.facets", "subfacets"), 4u + 8u);
}

TEST(FacetRegion, NestedPolygonWithHoleIsARing) {
  const std::vector<P2> outer = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<P2> inner = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  const FacetRegion ring({outer, inner}, {{2, 2}});
  ASSERT_TRUE(ring.supported());
  EXPECT_EQ(ring.area2(), 24);
  EXPECT_EQ(ring.locate(Q2::at({2, 2})), Where::Outside);
  EXPECT_EQ(ring.locate(Q2::at({0.5, 2})), Where::Inside);
  EXPECT_EQ(ring.locate(Q2::at({1, 2})), Where::Boundary);
  EXPECT_EQ(ring.locate(Q2::at({5, 2})), Where::Outside);
  EXPECT_EQ(ring.locate(Q2::centroid({0, 0}, {1, 0}, {0, 1})), Where::Inside);
  const FacetRegion full({outer, inner}, {});
  EXPECT_EQ(full.area2(), 32);
  EXPECT_EQ(full.locate(Q2::at({2, 2})), Where::Inside);
  const FacetRegion crossing({outer, {{3, 3}, {5, 3}, {5, 5}, {3, 5}}}, {});
  EXPECT_FALSE(crossing.supported());
}

TEST(FacetRegion, NonConvexPolygon) {
  const std::vector<P2> ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const FacetRegion r({ell}, {});
  EXPECT_EQ(r.area2(), 6);
  EXPECT_EQ(r.locate(Q2::at({1.5, 1.5})), Where::Outside);
  EXPECT_EQ(r.locate(Q2::centroid({1, 1}, {2, 1}, {1, 2})), Where::Outside);
  EXPECT_EQ(r.locate(Q2::centroid({0, 0}, {1, 0}, {0, 1})), Where::Inside);
}

// The slab index decides q as the scan of every edge does.
void slabs_agree(const PolygonSlabs& slabs, const std::vector<P2>& poly, const Q2& q) {
  RC_ASSERT(slabs.locate(poly, q) == locate_in_polygon(poly, q));
}

// ... at vertex i, at the midpoint of its edge to i + 1, and at the centroid of i, j, l.
void slabs_agree_at(const PolygonSlabs& slabs, const std::vector<P2>& poly, std::size_t i,
                    std::size_t j, std::size_t l) {
  const std::size_t n = poly.size();
  slabs_agree(slabs, poly, Q2::at(poly[i]));
  slabs_agree(slabs, poly, {{poly[i][0], poly[(i + 1) % n][0], 0}, {poly[i][1], poly[(i + 1) % n][1], 0}, 2});
  slabs_agree(slabs, poly, Q2::centroid(poly[i], poly[j], poly[l]));
}

// The slab index visits only the edges of the query's slab and must decide as the scan of
// every edge does: star polygons of up to 2,000 vertices (many at one y, horizontal edges,
// vertices repeated along chains as on a meshed facet), queried at vertices, edge
// midpoints, triangle centroids and random points.
RC_GTEST_PROP(FacetRegion, SlabsLocateAsTheFullScan, ()) {
  const int n = *rc::gen::inRange(3, 2000);
  const int levels = *rc::gen::inRange(1, 64);  // few distinct y values: many ties
  std::vector<P2> poly;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    const double r = 1 + *rc::gen::inRange(0, 1000) / 1000.0;
    const double y = std::round(r * std::sin(a) * levels) / levels;
    poly.push_back({r * std::cos(a), y});
  }
  const PolygonSlabs slabs(poly);
  for (int k = 0; k < 200; ++k) {
    const auto i = *rc::gen::inRange(0, n), j = *rc::gen::inRange(0, n), l = *rc::gen::inRange(0, n);
    slabs_agree_at(slabs, poly, i, j, l);
    slabs_agree(slabs, poly, Q2::at({*rc::gen::inRange(-2100, 2100) / 1000.0, *rc::gen::inRange(-2100, 2100) / 1000.0}));
  }
}

// Combs (long vertical teeth: every edge spans many slabs, so the slabs widen
// until the listings stay linear) and axis-aligned dyadic polygons (vertices and edge
// midpoints exactly on slab boundaries: the query's interval meets two slabs), queried
// on a dyadic lattice, at vertices, edge midpoints and centroids.
RC_GTEST_PROP(FacetRegion, SlabsLocateAsTheFullScanOnCombs, ()) {
  const int teeth = *rc::gen::inRange(1, 120);
  const double h = std::ldexp(1.0, *rc::gen::inRange(0, 10));  // tooth height
  std::vector<P2> poly = {{0, 0}, {2.0 * teeth, 0}};
  for (int k = teeth - 1; k >= 0; --k) {  // along the top, right to left: up and down each tooth
    poly.push_back({2.0 * k + 2, 1});
    poly.push_back({2.0 * k + 1.5, h});
    poly.push_back({2.0 * k + 1, h});
    poly.push_back({2.0 * k + 1, 1});
  }
  const std::size_t n = poly.size();
  const PolygonSlabs slabs(poly);
  RC_ASSERT(slabs.listings() <= 8 * n);
  for (int k = 0; k < 100; ++k) {
    const auto i = *rc::gen::inRange<std::size_t>(0, n), j = *rc::gen::inRange<std::size_t>(0, n),
               l = *rc::gen::inRange<std::size_t>(0, n);
    slabs_agree_at(slabs, poly, i, j, l);
    slabs_agree(slabs, poly, Q2::at({*rc::gen::inRange(-8, 16 * teeth + 8) / 8.0, *rc::gen::inRange(-8, 8 * int(h) + 16) / 8.0}));
  }
}

// A facet refined toward a sharp corner (a repair cascade toward a thin notch's tip: 8
// vertices per octave from 1 down to 2^-50 on both sides of a wedge of 1 to 10 degrees,
// turned by a random angle): the slabs hold a few vertices each however they crowd, so a
// query near the tip visits a few edges, not the whole chain, and decides as the full scan.
RC_GTEST_PROP(FacetRegion, SlabsStayFewEdgesOnGradedChains, ()) {
  const double wedge = *rc::gen::inRange(1, 11) * M_PI / 180;
  const double turn = *rc::gen::inRange(0, 3600) * M_PI / 1800;
  const int octaves = *rc::gen::inRange(10, 51);
  auto at = [&](double r, double a) { return P2{r * std::cos(turn + a), r * std::sin(turn + a)}; };
  std::vector<P2> poly = {at(0, 0)};
  for (int k = 8 * octaves; k >= 0; --k) poly.push_back(at(std::exp2(-k / 8.0), 0));
  for (int k = 0; k <= 8 * octaves; ++k) poly.push_back(at(std::exp2(-k / 8.0), wedge));
  const std::size_t n = poly.size();
  const PolygonSlabs slabs(poly);
  RC_ASSERT(slabs.listings() <= 8 * n);
  RC_ASSERT(slabs.busiest() <= 16);
  for (int k = 0; k < 100; ++k) {
    const auto i = *rc::gen::inRange<std::size_t>(0, n), j = *rc::gen::inRange<std::size_t>(0, n),
               l = *rc::gen::inRange<std::size_t>(0, n);
    slabs_agree_at(slabs, poly, i, j, l);
    slabs_agree(slabs, poly, Q2::centroid(poly[i], poly[(i + 1) % n], poly[(i + n - 1) % n]));
  }
}

}  // namespace
}  // namespace pdr::check::test
