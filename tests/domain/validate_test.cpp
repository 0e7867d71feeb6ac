// Validation and structure of polyhedral domains (paper §1.1): every malformed-input class
// gets its own diagnostic naming the right source line, and valid inputs get the related
// components and orientation the later stages rely on.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include <cmath>

#include "domain/cells.hpp"
#include "domain/distance.hpp"
#include "domain/exact.hpp"
#include "domain/validate.hpp"
#include "geom/predicates.hpp"
#include "io/mesh_io.hpp"
#include "support/outside_fixtures.hpp"
#include "support/plc_fixtures.hpp"

namespace pdr::domain::test {
using namespace pdr::test;
namespace {

::testing::AssertionResult Fails(const Plc& plc, std::size_t line, const std::string& invariant,
                                 const PlcOptions& opt = {}) {
  const std::string e = error_of(plc, opt);
  const std::string where = "test.poly:" + std::to_string(line) + ": " + invariant;
  if (e.rfind(where, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "expected '" << where << "...', got '" << e << "'";
}

TEST(PlcValidate, AcceptsBoxAndBuildsRelatedComponents) {
  const PlcDomain dom = build_domain(box({0, 0, 0}, {1, 1, 1}));
  EXPECT_EQ(dom.vertex_count(), 8u);
  EXPECT_EQ(dom.segments.size(), 12u);
  EXPECT_EQ(dom.face_count(), 6u);
  EXPECT_EQ(dom.shells, 1u);
  EXPECT_TRUE(dom.tolerance_facets.empty());
  for (const DomainSegment& s : dom.segments) {
    EXPECT_LT(s.a, s.b);
    EXPECT_EQ(s.sides.size(), 2u);
    EXPECT_EQ(s.facets.size(), 2u);
  }
  for (std::uint32_t v = 0; v < 8; ++v) {
    EXPECT_EQ(dom.vertex_segments[v].size(), 3u);
    EXPECT_EQ(dom.vertex_facets[v].size(), 3u);
  }
  for (const DomainFacet& f : dom.facets) {
    EXPECT_TRUE(f.is_face);
    EXPECT_TRUE(f.plane.exact);
    EXPECT_EQ(f.tris.size(), 2u);
    EXPECT_EQ(f.segments.size(), 4u);
    // The defining triple spans the facet's plane exactly.
    const auto& t = f.plane.triple;
    for (std::uint32_t v : f.vertices)
      EXPECT_EQ(orient3d(dom.plc.points[t[0]], dom.plc.points[t[1]], dom.plc.points[t[2]],
                         dom.plc.points[v]),
                Sign::Zero);
  }
}

// inward = +1 iff the triangle's normal points into the domain; check against a point that
// is known to be inside (or outside) near each triangle: the centroid of the body.
void expect_inward_towards(const PlcDomain& dom, std::size_t first_facet, std::size_t end_facet,
                           const Point& centre, int expected) {
  for (std::size_t f = first_facet; f < end_facet; ++f)
    for (const FacetTri& t : dom.facets[f].tris) {
      const Sign s = orient3d(dom.plc.points[t.v[0]], dom.plc.points[t.v[1]],
                              dom.plc.points[t.v[2]], centre);
      EXPECT_EQ(to_int(s) * t.inward, expected) << "facet " << f;
    }
}

TEST(PlcValidate, OrientsBoundaryTowardsTheDomain) {
  const PlcDomain cube = build_domain(box({0, 0, 0}, {1, 1, 1}));
  expect_inward_towards(cube, 0, 6, {0.5, 0.5, 0.5}, +1);
  for (const DomainSegment& s : cube.segments) {
    ASSERT_EQ(s.sides.size(), 2u);
    EXPECT_EQ(s.sides[0].inside_after + s.sides[1].inside_after, 0);
  }
  const PlcDomain cic = build_domain(read_data("cube-in-cube.poly"));
  EXPECT_EQ(cic.shells, 2u);
  expect_inward_towards(cic, 0, 6, {5, 5, 5}, +1);   // outer walls face inwards
  expect_inward_towards(cic, 6, 12, {5, 5, 5}, -1);  // the void's walls face away from it
}

TEST(PlcValidate, RejectsDuplicateVertex) {
  Plc p = box({0, 0, 0}, {1, 1, 1});
  p.points.push_back(p.points[3]);
  relabel(p);
  EXPECT_TRUE(Fails(p, kPointLine + 8, "distinct vertices"));
}

TEST(PlcValidate, RejectsIndexOutOfRange) {
  Plc p = box({0, 0, 0}, {1, 1, 1});
  p.facets[2].polygons[0][1] = 99;
  EXPECT_TRUE(Fails(p, kFacetLine + 2, "index in range"));
}

TEST(PlcValidate, RejectsDegeneratePolygons) {
  Plc repeated = box({0, 0, 0}, {1, 1, 1});
  repeated.facets[1].polygons[0] = {4, 5, 5, 6, 7};
  EXPECT_TRUE(Fails(repeated, kFacetLine + 1, "non-degenerate polygon"));

  Plc twice = box({0, 0, 0}, {1, 1, 1});
  twice.facets[1].polygons[0] = {4, 5, 6, 4, 7};
  EXPECT_TRUE(Fails(twice, kFacetLine + 1, "simple polygon"));

  Plc flat = box({0, 0, 0}, {1, 1, 1});
  flat.points.push_back({0.5, 0, 0});
  PlcFacet sliver;
  sliver.polygons = {{0, 8, 1}};
  flat.facets.push_back(sliver);
  relabel(flat);
  EXPECT_TRUE(Fails(flat, kFacetLine + 6, "non-degenerate polygon"));

  Plc two = box({0, 0, 0}, {1, 1, 1});
  two.facets[3].polygons[0] = {1, 1};
  EXPECT_TRUE(Fails(two, kFacetLine + 3, "non-degenerate polygon"));
}

TEST(PlcValidate, RejectsSelfIntersectingFacet) {
  Plc p = box({0, 0, 0}, {1, 1, 1});
  p.facets[1].polygons[0] = {4, 5, 7, 6};  // a bow tie
  EXPECT_TRUE(Fails(p, kFacetLine + 1, "simple facet polygons"));
}

TEST(PlcValidate, PlanarityToleranceClassifiesImpreciseFacets) {
  Plc near = box({0, 0, 0}, {1, 1, 1});
  // Three facets become non-planar by about 1e-13; the coordinates keep 17 significant
  // digits, so no coarser precision is inferred from them (io/precision.hpp).
  for (double& c : near.points[6]) c += 1.2345678901234567e-13;
  const PlcDomain dom = build_domain(near);
  ASSERT_EQ(dom.tolerance_facets.size(), 3u);
  for (std::uint32_t f : dom.tolerance_facets) {
    EXPECT_FALSE(dom.facets[f].plane.exact);
    EXPECT_GT(dom.facets[f].plane.max_deviation, 0.0);
    EXPECT_LT(dom.facets[f].plane.max_deviation, 1e-12);
  }
  Plc far = box({0, 0, 0}, {1, 1, 1});
  far.points[6][2] += 1e-3;
  EXPECT_TRUE(Fails(far, kFacetLine + 1, "planar facet"));
  // The same input passes with a looser tolerance, and is rejected with a stricter one.
  EXPECT_EQ(error_of(far, PlcOptions{1e-2}), "");
  EXPECT_TRUE(Fails(near, kFacetLine + 1, "planar facet", PlcOptions{1e-15}));
}

// The box with each side given as two triangular facets, rotated so that the two triangles of
// a side are coplanar only within rounding.
Plc rotated_triangle_box() {
  const Plc b = box({0, 0, 0}, {1, 1, 1});
  Plc p = b;
  p.facets.clear();
  for (const PlcFacet& f : b.facets) {
    const auto& q = f.polygons[0];
    for (const std::vector<std::uint32_t>& tri :
         {std::vector<std::uint32_t>{q[0], q[1], q[2]}, std::vector<std::uint32_t>{q[0], q[2], q[3]}}) {
      PlcFacet t = f;
      t.polygons = {tri};
      p.facets.push_back(t);
    }
  }
  const double c = std::cos(0.7), d = std::sin(0.7), e = std::cos(1.1), g = std::sin(1.1);
  for (Point& x : p.points) {
    const Point y{c * x[0] - d * x[1], d * x[0] + c * x[1], x[2]};
    x = {y[0], e * y[1] - g * y[2], g * y[1] + e * y[2]};
  }
  return p;
}

// A box whose sides are polygons with k - 1 extra vertices on each edge (a surface mesher's
// side, merged into one facet), rotated: the vertices along an edge are collinear only to
// a few ulps. The facets meet only along their common edges, so the domain is valid; a
// facet triangulation that joined three vertices of an edge in a sliver crossed the next
// facet by ulps (a Gmsh surface of a rotated box was refused so).
Plc rotated_subdivided_box(std::uint32_t k, const std::array<double, 4>& q, const Point& size) {
  Plc p;
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> index;  // grid point -> vertex
  const auto vertex = [&](std::array<std::uint32_t, 3> g) {
    const auto [it, fresh] = index.try_emplace(g, static_cast<std::uint32_t>(p.points.size()));
    if (fresh) {
      const Point x{size[0] * g[0] / k, size[1] * g[1] / k, size[2] * g[2] / k};
      // Rotation by the unit quaternion (w, x, y, z).
      const double w = q[0], a = q[1], b = q[2], c = q[3];
      const double r[3][3] = {{1 - 2 * (b * b + c * c), 2 * (a * b - c * w), 2 * (a * c + b * w)},
                              {2 * (a * b + c * w), 1 - 2 * (a * a + c * c), 2 * (b * c - a * w)},
                              {2 * (a * c - b * w), 2 * (b * c + a * w), 1 - 2 * (a * a + b * b)}};
      Point y{};
      for (int i = 0; i < 3; ++i) y[i] = r[i][0] * x[0] + r[i][1] * x[1] + r[i][2] * x[2];
      p.points.push_back(y);
      p.point_lines.push_back(kPointLine + p.points.size());
    }
    return it->second;
  };
  // Each side: the boundary of the k x k grid on the face normal to `axis` at `at`.
  for (int axis = 0; axis < 3; ++axis)
    for (const std::uint32_t at : {0u, k}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<std::array<std::uint32_t, 2>> ring;
      for (std::uint32_t i = 0; i < k; ++i) ring.push_back({i, 0});
      for (std::uint32_t i = 0; i < k; ++i) ring.push_back({k, i});
      for (std::uint32_t i = k; i > 0; --i) ring.push_back({i, k});
      for (std::uint32_t i = k; i > 0; --i) ring.push_back({0, i});
      PlcFacet f;
      f.line = kFacetLine + p.facets.size();
      std::vector<std::uint32_t> poly;
      for (const auto& [s, t] : ring) {
        std::array<std::uint32_t, 3> g{};
        g[static_cast<std::size_t>(axis)] = at;
        g[static_cast<std::size_t>(u)] = s;
        g[static_cast<std::size_t>(v)] = t;
        poly.push_back(vertex(g));
      }
      f.polygons.push_back(std::move(poly));
      p.facets.push_back(std::move(f));
    }
  return p;
}

TEST(PlcValidate, RotatedBoxesWithSubdividedSidesAreValid) {
  std::mt19937_64 rng(20261126);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<std::uint32_t> subdivisions(2, 9);
  std::uniform_real_distribution<double> side(0.3, 3);
  for (int n = 0; n < 60; ++n) {
    std::array<double, 4> q{normal(rng), normal(rng), normal(rng), normal(rng)};
    const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= len;
    const std::uint32_t k = subdivisions(rng);
    const Point size{side(rng), side(rng), side(rng)};
    const Plc p = rotated_subdivided_box(k, q, size);
    EXPECT_EQ(error_of(p), "") << "case " << n << ": k = " << k;
  }
}

TEST(PlcValidate, FacetsCoplanarWithinToleranceAreOneGroup) {
  const Plc p = rotated_triangle_box();
  const PlcDomain dom = build_domain(p);
  ASSERT_EQ(dom.face_count(), 12u);
  std::size_t inexact = 0;
  for (std::size_t f = 0; f < 12; f += 2) {
    const DomainFacet &a = dom.facets[f], &b = dom.facets[f + 1];
    // One group per side, named by its first facet; each triangle keeps its own (exact)
    // plane, so its new vertices round onto its own plane.
    EXPECT_EQ(a.plane_group, f);
    EXPECT_EQ(b.plane_group, f);
    EXPECT_TRUE(a.plane.exact);
    EXPECT_TRUE(b.plane.exact);
    const auto& ta = p.facets[f].polygons[0];
    const auto& tb = p.facets[f + 1].polygons[0];  // (q0, q2, q3) after (q0, q1, q2)
    EXPECT_EQ(std::set(a.plane.triple.begin(), a.plane.triple.end()), std::set(ta.begin(), ta.end()));
    EXPECT_EQ(std::set(b.plane.triple.begin(), b.plane.triple.end()), std::set(tb.begin(), tb.end()));
    EXPECT_EQ(a.tris.size(), 1u);
    const auto& x = p.points;
    inexact += orient3d(x[ta[0]], x[ta[1]], x[ta[2]], x[tb[2]]) != Sign::Zero;
  }
  EXPECT_GE(inexact, 3u);  // sides where the grouping is not exact coplanarity
  EXPECT_EQ(dom.segments.size(), 18u);  // the diagonals stay segments
  // With no tolerance each triangle keeps its own (exact) plane.
  const PlcDomain alone = build_domain(p, PlcOptions{0.0});
  for (std::size_t f = 0; f < 12; ++f) EXPECT_EQ(alone.facets[f].plane_group, f);
  // A side folded along its diagonal by far more than the tolerance is two planes.
  Plc folded = p;
  for (double& x : folded.points[6]) x += 1e-4;
  const PlcDomain two = build_domain(folded);
  std::size_t groups = 0;
  for (std::size_t f = 0; f < 12; ++f) groups += two.facets[f].plane_group == f;
  EXPECT_EQ(groups, 6u + 3u);
}

TEST(PlcValidate, RejectsCrossingFacets) {
  const Plc p = merge(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}));
  const std::string e = error_of(p);
  EXPECT_NE(e.find("non-crossing components"), std::string::npos) << e;
}

TEST(PlcValidate, RejectsVertexInsideAnotherFacet) {
  // A small box glued onto the face x = 2 of a larger one, without splitting that face.
  const Plc p = merge(box({0, 0, 0}, {2, 2, 2}), box({2, 0.5, 0.5}, {3, 1.5, 1.5}));
  const std::string e = error_of(p);
  EXPECT_NE(e.find("non-crossing components"), std::string::npos) << e;
  EXPECT_NE(e.find("lies on facet"), std::string::npos) << e;
}

TEST(PlcValidate, RejectsOpenBoundary) {
  Plc p = box({0, 0, 0}, {1, 1, 1});
  p.facets.erase(p.facets.begin() + 1);  // no top
  relabel(p);
  const std::string e = error_of(p);
  EXPECT_NE(e.find("closed boundary"), std::string::npos) << e;
  EXPECT_NE(e.find("only one facet side"), std::string::npos) << e;
}

TEST(PlcValidate, AcceptsVertexInsideAnotherFacetsEdge) {
  // The top of the box [0,2]x[0,1]x[0,1] is split at x = 1 into two facets; the walls
  // y = 0 and y = 1 keep their 4-vertex polygons, whose top edges hold the new vertices.
  Plc p = box({0, 0, 0}, {2, 1, 1});
  p.points.push_back({1, 0, 1});  // 8
  p.points.push_back({1, 1, 1});  // 9
  p.facets[1].polygons = {{4, 8, 9, 7}};
  PlcFacet right;
  right.polygons = {{8, 5, 6, 9}};
  p.facets.push_back(right);
  relabel(p);
  const PlcDomain dom = build_domain(p);
  EXPECT_EQ(dom.vertex_count(), 10u);
  EXPECT_EQ(dom.segments.size(), 15u);  // 12 edges, two of them split, plus the split line
  for (const DomainSegment& s : dom.segments) EXPECT_EQ(s.sides.size(), 2u);
}

// The same box turned and printed with 7 or 9 digits, as another tool would write it: the
// new vertices then lie within the coordinates' rounding of the walls' top edges, a hair
// inside or outside them, and the edges are split there as the input means (exactly, the
// wall's polygon would cross the split line, or leave the vertex off every edge).
TEST(PlcValidate, AcceptsVertexWithinRoundingOfAnotherFacetsEdge) {
  Plc p = box({0, 0, 0}, {2, 1, 1});
  p.points.push_back({1, 0, 1});
  p.points.push_back({1, 1, 1});
  p.facets[1].polygons = {{4, 8, 9, 7}};
  PlcFacet right;
  right.polygons = {{8, 5, 6, 9}};
  p.facets.push_back(right);
  relabel(p);
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> angle(0, 6.283185307179586);
  int off_edge = 0;
  for (int n = 0; n < 40; ++n) {
    const int digits = n % 2 == 0 ? 7 : 9;
    const Plc q = printed(rotated(p, angle(rng), angle(rng), angle(rng)), digits);
    for (std::uint32_t v : {8u, 9u}) {
      const Point& a = q.points[v == 8 ? 4 : 7];
      const Point& b = q.points[v == 8 ? 5 : 6];
      off_edge += !collinear(a, b, q.points[v]);
    }
    std::string error;
    try {
      const PlcDomain dom = build_domain(q);
      EXPECT_EQ(dom.segments.size(), 15u) << "case " << n;
      for (const DomainSegment& s : dom.segments) EXPECT_EQ(s.sides.size(), 2u) << "case " << n;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << n << " (" << digits << " digits): " << e.what();
    }
  }
  EXPECT_GT(off_edge, 40);  // rounding moved most of the vertices off their edges
}

// A vertex within the rounding of two edges (a point of a facet 3.2e-6 from its 60-degree
// corner, printed with 7 digits: 2u = 1.7e-6 from both edges' lines) is near where they
// meet, not on either: it splits neither and stays a vertex of the facet, as given (it was
// inserted into both, and the facet's polygon said to touch itself).
TEST(PlcValidate, AVertexWithinRoundingOfTwoEdgesSplitsNeither) {
  Plc p;
  p.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8660254, 0}, {0.3, 0.3, 1}, {2.771281e-06, 1.6e-06, 0}};
  for (const std::vector<std::vector<std::uint32_t>>& polys :
       std::vector<std::vector<std::vector<std::uint32_t>>>{
           {{0, 1, 2}, {4}}, {{0, 1, 3}}, {{1, 2, 3}}, {{2, 0, 3}}}) {
    PlcFacet f;
    f.polygons = polys;
    p.facets.push_back(f);
  }
  relabel(p);
  const PlcDomain dom = build_domain(p);
  EXPECT_EQ(dom.segments.size(), 6u);
}

TEST(PlcValidate, AcceptsCollinearOverlappingEdges) {
  // The box [0,3]x[0,1]x[0,1] with its top split at x = 2 and its front wall (y = 0) split
  // at x = 1: the top-left facet's front edge (x in [0,2]) and the front-right wall's top
  // edge (x in [1,3]) overlap on [1,2]; splitting at vertices makes them share that piece.
  Plc p = box({0, 0, 0}, {3, 1, 1});
  p.points.push_back({2, 0, 1});  // 8
  p.points.push_back({2, 1, 1});  // 9
  p.points.push_back({1, 0, 0});  // 10
  p.points.push_back({1, 0, 1});  // 11
  p.facets[1].polygons = {{4, 8, 9, 7}};
  p.facets[2].polygons = {{0, 10, 11, 4}};
  PlcFacet top_right, front_right;
  top_right.polygons = {{8, 5, 6, 9}};
  front_right.polygons = {{10, 1, 5, 11}};
  p.facets.push_back(top_right);
  p.facets.push_back(front_right);
  relabel(p);
  const PlcDomain dom = build_domain(p);
  for (const DomainSegment& s : dom.segments) EXPECT_EQ(s.sides.size(), 2u);
  EXPECT_TRUE(dom.find_segment(11, 8).has_value());  // the shared piece [1,2]
  EXPECT_FALSE(dom.find_segment(4, 8).has_value());  // split at 11
  EXPECT_FALSE(dom.find_segment(11, 5).has_value());  // split at 8
}

TEST(PlcValidate, AcceptsFacetHolesAndTunnels) {
  // A frame: the box [0,3]x[0,3]x[0,1] with a square tunnel [1,2]^2 along z.
  std::vector<Point> pts{{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}, {0, 0, 1}, {3, 0, 1},
                         {3, 3, 1}, {0, 3, 1}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0},
                         {1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {1, 2, 1}};
  Plc p = make_plc(pts, {{{0, 1, 2, 3}, {8, 9, 10, 11}}, {{4, 5, 6, 7}, {12, 13, 14, 15}},
                         {{0, 1, 5, 4}}, {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}},
                         {{8, 9, 13, 12}}, {{9, 10, 14, 13}}, {{10, 11, 15, 14}},
                         {{11, 8, 12, 15}}});
  p.facets[0].holes = {{1.5, 1.5, 0}};
  p.facets[1].holes = {{1.5, 1.5, 1}};
  const PlcDomain dom = build_domain(p);
  EXPECT_EQ(dom.shells, 1u);
  EXPECT_EQ(dom.facets[0].tris.size(), 8u);  // an annulus of 8 vertices
  expect_inward_towards(dom, 2, 6, {1.5, 1.5, 0.5}, +1);
  expect_inward_towards(dom, 6, 10, {1.5, 1.5, 0.5}, -1);

  // Without the facet holes the caps cover the tunnel: each tunnel edge on a cap is then
  // inside the cap (2 sides) and on a tunnel wall (1 side), and the tunnel walls split the
  // box into two cells. Read from a surface file (walls: no 2-manifold), every bounded
  // cell is a region, as TetGen reads it, and the walls are internal.
  Plc covered = p;
  covered.facets[0].holes.clear();
  covered.facets[1].holes.clear();
  const PlcDomain c = build_domain(covered);
  EXPECT_TRUE(c.surface_walls || covered.enclosure == Enclosure::HolePoints);
  EXPECT_EQ(c.cells, 2u);
  EXPECT_EQ(c.cell_inside, (std::vector<std::uint8_t>{1, 1}));
  for (std::size_t f = 6; f < 10; ++f) EXPECT_FALSE(c.facets[f].separates) << f;
}

TEST(PlcValidate, RejectsBadFacetHoles) {
  Plc off = box({0, 0, 0}, {3, 3, 1});
  off.facets[1].holes = {{1.5, 1.5, 1.25}};
  EXPECT_TRUE(Fails(off, kFacetLine + 1, "facet hole in plane"));
  Plc outside = box({0, 0, 0}, {3, 3, 1});
  outside.facets[1].holes = {{4, 4, 1}};
  EXPECT_TRUE(Fails(outside, kFacetLine + 1, "facet hole inside facet"));
  Plc on_edge = box({0, 0, 0}, {3, 3, 1});
  on_edge.facets[1].holes = {{3, 1, 1}};
  EXPECT_TRUE(Fails(on_edge, kFacetLine + 1, "facet hole off edges"));
}

// Hole points on a grid through the cube-in-cube's walls, edges, corners and triangle
// diagonals: the one perturbed axis ray from each (domain/orient.cpp) runs along facet
// planes and through edges and vertices all the time, and must still classify every
// point as the box arithmetic does: in the void (accepted), in the solid or outside
// (refused, each with its reason), or on a facet (refused).
TEST(PlcValidate, HolePointsOnSymmetricGridsAreClassifiedExactly) {
  const double grid[] = {-1, 0, 2, 4, 5, 6, 8, 10, 11};
  const auto within = [](double x, double lo, double hi) { return lo <= x && x <= hi; };
  int cases = 0;
  for (const double x : grid)
    for (const double y : grid)
      for (const double z : grid) {
        const Point h{x, y, z};
        Plc cic = merge(box({0, 0, 0}, {10, 10, 10}), box({4, 4, 4}, {6, 6, 6}));
        cic.holes = {h};
        relabel(cic);
        const std::string e = error_of(cic);
        const bool in_outer = within(x, 0, 10) && within(y, 0, 10) && within(z, 0, 10);
        const bool in_void = within(x, 4, 6) && within(y, 4, 6) && within(z, 4, 6);
        const bool on_outer = in_outer && (x == 0 || x == 10 || y == 0 || y == 10 || z == 0 || z == 10);
        const bool on_void = in_void && (x == 4 || x == 6 || y == 4 || y == 6 || z == 4 || z == 6);
        std::ostringstream at;
        at << "(" << x << ", " << y << ", " << z << "): " << e;
        ++cases;
        if (on_outer || on_void)
          EXPECT_NE(e.find("volume hole off facets"), std::string::npos) << at.str();
        else if (in_void)
          EXPECT_EQ(e, "") << at.str();
        else if (in_outer)
          EXPECT_NE(e.find("inside the domain"), std::string::npos) << at.str();
        else
          EXPECT_NE(e.find("outside the domain's closed boundary"), std::string::npos) << at.str();
      }
  EXPECT_EQ(cases, 729);
}

TEST(PlcValidate, RejectsBadVolumeHoles) {
  Plc outside = box({0, 0, 0}, {1, 1, 1});
  outside.holes = {{5, 5, 5}};
  relabel(outside);
  EXPECT_TRUE(Fails(outside, kHoleLine, "volume hole in a void"));
  EXPECT_NE(error_of(outside).find("outside the domain's closed boundary"), std::string::npos);

  Plc inside = box({0, 0, 0}, {1, 1, 1});
  inside.holes = {{0.5, 0.5, 0.5}};
  relabel(inside);
  EXPECT_TRUE(Fails(inside, kHoleLine, "volume hole in a void"));
  EXPECT_NE(error_of(inside).find("inside the domain"), std::string::npos);

  Plc on = box({0, 0, 0}, {1, 1, 1});
  on.holes = {{0.5, 0.25, 1}};
  relabel(on);
  EXPECT_TRUE(Fails(on, kHoleLine, "volume hole off facets"));

  // A hole point in the void of the cube-in-cube, where ray casting along every axis hits
  // the void's walls on a triangle diagonal: the perturbed ray decides it.
  Plc cic = merge(box({0, 0, 0}, {10, 10, 10}), box({4, 4, 4}, {6, 6, 6}));
  cic.holes = {{5, 5, 5}};
  relabel(cic);
  EXPECT_EQ(error_of(cic), "");
}

TEST(PlcValidate, StandaloneSegmentsAndIsolatedVertices) {
  Plc p = box({0, 0, 0}, {4, 4, 4});
  p.points.push_back({1, 1, 1});
  p.points.push_back({3, 3, 3});
  p.points.push_back({2, 1, 3});
  PlcFacet seg;
  seg.polygons = {{8, 9}, {10}};
  p.facets.push_back(seg);
  relabel(p);
  const PlcDomain dom = build_domain(p);
  EXPECT_EQ(dom.vertex_count(), 11u);
  EXPECT_EQ(dom.segments.size(), 13u);
  EXPECT_EQ(dom.face_count(), 6u);

  Plc pierce = p;
  pierce.points[9] = {3, 3, 5};  // the segment leaves through the top
  EXPECT_NE(error_of(pierce).find("non-crossing components"), std::string::npos);
}

TEST(PlcValidate, NodesListedInNoFacetAreIsolatedVertices) {
  // TetGen inserts every node of a .poly: one that no facet lists is a component like a
  // 1-vertex polygon, so it counts for d and is refused where it lies on a facet unlisted.
  Plc p = box({0, 0, 0}, {4, 4, 4});
  const double d_box = feature_size(build_domain(p)).d;
  p.points.push_back({1, 1, 1});  // 8: in no facet, 1 from three facets
  relabel(p);
  const PlcDomain dom = build_domain(p);
  EXPECT_EQ(dom.vertex_count(), 9u);
  const FeatureSize fs = feature_size(dom);
  EXPECT_LT(fs.d, d_box);
  EXPECT_DOUBLE_EQ(fs.min_distance, 1.0);
  EXPECT_TRUE(fs.first_kind == ComponentKind::Vertex || fs.second_kind == ComponentKind::Vertex);
  EXPECT_EQ(feature_size_brute(dom).min_distance, fs.min_distance);

  for (const Point& on : {Point{2, 2, 4}, Point{2, 0, 4}, Point{0, 0, 4}}) {
    Plc q = box({0, 0, 0}, {4, 4, 4});
    q.points.push_back(on);
    relabel(q);
    const std::string e = error_of(q);
    if (on == Point{0, 0, 4}) {  // a duplicate of vertex 4
      EXPECT_NE(e, "");
      continue;
    }
    EXPECT_NE(e.find("the isolated vertex 8"), std::string::npos) << e;
    EXPECT_NE(e.find("lies on facet"), std::string::npos) << e;
  }
}

TEST(PlcValidate, RegionPointsLieInsideTheDomain) {
  // Before, one outside passed validation and the mesher's own check failed
  // (conformity.volume: empty_regions), exit 1.
  const auto with_region = [](Plc p, const Point& at) {
    PlcRegion r;
    r.point = at;
    r.attribute = 3;
    p.regions.push_back(r);
    return p;
  };
  Plc b = box({0, 0, 0}, {4, 4, 4});
  relabel(b);
  EXPECT_EQ(error_of(with_region(b, {1, 1, 1})), "");
  EXPECT_NE(error_of(with_region(b, {5, 1, 1})).find("lies outside the domain"), std::string::npos);
  EXPECT_NE(error_of(with_region(b, {1, 1, 4})).find("region point 1 lies on facet"),
            std::string::npos)
      << error_of(with_region(b, {1, 1, 4}));
  Plc cic = merge(box({0, 0, 0}, {10, 10, 10}), box({4, 4, 4}, {6, 6, 6}));
  cic.holes.push_back({5, 5, 5});
  relabel(cic);
  EXPECT_EQ(error_of(with_region(cic, {1, 1, 1})), "");
  EXPECT_NE(error_of(with_region(cic, {5, 5, 5.5})).find("lies outside the domain"),
            std::string::npos);  // in the void
}

// TetGen's reading of a .poly (Enclosure::HolePoints): every bounded cell is in Ω unless a
// volume hole point lies in it, so a shell between two regions is internal (both sides in
// Ω, its facets not separating); by parity the same shells alternate solid and void.
TEST(PlcValidate, NestedShellsAreRegionsUnlessAHolePointEmptiesThem) {
  Plc nest = merge(merge(box({0, 0, 0}, {10, 10, 10}), box({2, 2, 2}, {8, 8, 8})),
                   box({4, 4, 4}, {6, 6, 6}));
  relabel(nest);
  const auto separates = [](const PlcDomain& d) {
    std::vector<int> out;
    for (int s = 0; s < 3; ++s) out.push_back(d.facets[6 * s].separates);
    return out;
  };
  // The cell inside box s: the side of its facet 6s that box s - 1's facet does not touch.
  const auto inside = [](const PlcDomain& d) {
    std::vector<int> out;
    for (int s = 0; s < 3; ++s) {
      const std::array<int, 2> mine = d.facets[6 * s].cells;
      const std::array<int, 2> around = s > 0 ? d.facets[6 * (s - 1)].cells : std::array<int, 2>{-1, -1};
      const int c = (mine[0] == around[0] || mine[0] == around[1]) ? mine[1] : mine[0];
      out.push_back(c >= 0 ? d.cell_inside[c] : -1);
    }
    return out;
  };
  PlcDomain parity = build_domain(nest);
  EXPECT_EQ(parity.cells, 3u);
  EXPECT_EQ(inside(parity), (std::vector<int>{1, 0, 1}));
  EXPECT_EQ(separates(parity), (std::vector<int>{1, 1, 1}));

  nest.enclosure = Enclosure::HolePoints;
  PlcDomain cells = build_domain(nest);
  EXPECT_EQ(inside(cells), (std::vector<int>{1, 1, 1}));
  EXPECT_EQ(separates(cells), (std::vector<int>{1, 0, 0}));
  for (const DomainSegment& s : cells.segments)
    for (const HalfFacet& h : s.sides)
      if (!cells.facets[h.facet].separates) {
        EXPECT_EQ(h.inside_after, 1);
      }

  Plc mid = nest;
  mid.holes.push_back({3, 3, 3});  // the middle region is a void: all three separate
  const PlcDomain m = build_domain(mid);
  EXPECT_EQ(inside(m), (std::vector<int>{1, 0, 1}));
  EXPECT_EQ(separates(m), (std::vector<int>{1, 1, 1}));
  PlcRegion r;
  r.point = {5, 5, 5};  // in the innermost box: a region, inside Ω
  mid.regions.push_back(r);
  EXPECT_EQ(error_of(mid), "");
  mid.regions[0].point = {3, 3, 3};  // in the void
  EXPECT_NE(error_of(mid).find("lies outside the domain"), std::string::npos);

  Plc on_face = nest;
  on_face.holes.push_back({6, 5, 5});  // on the innermost box: named, not a far surface
  EXPECT_NE(error_of(on_face).find("volume hole point 1 lies on facet 15"), std::string::npos)
      << error_of(on_face);

  // Two boxes sharing an edge elsewhere (four facet sides around it) change nothing: each
  // box is a region, and the nested boxes are regions as before.
  Plc pair = merge(box({20, 0, 0}, {21, 1, 1}), box({21, 1, 0}, {22, 2, 1}));
  // The second box's corners (21, 1, 0) and (21, 1, 1) are the first's 2 and 6.
  for (PlcFacet& f : pair.facets)
    for (auto& poly : f.polygons)
      for (auto& v : poly) v = v == 8 ? 2 : (v == 12 ? 6 : v);
  Plc touching = merge(nest, pair);  // points 32 and 36 are left unused: isolated vertices
  touching.points[32] = {30, 0, 0};
  touching.points[36] = {30, 0, 1};
  touching.enclosure = Enclosure::HolePoints;
  relabel(touching);
  const PlcDomain t = build_domain(touching);
  EXPECT_EQ(t.cells, 5u);
  EXPECT_EQ(inside(t), (std::vector<int>{1, 1, 1}));
  EXPECT_EQ(separates(t), (std::vector<int>{1, 0, 0}));
  for (std::size_t f = 18; f < 30; ++f) EXPECT_TRUE(t.facets[f].separates) << f;

  // The outermost region a void: the outer box's surface bounds no region and is dropped
  // (TetGen drops it too), with its segments; the two inner boxes stay.
  Plc outer = nest;
  outer.holes.push_back({1, 1, 1});
  const PlcDomain o = build_domain(outer);
  ASSERT_EQ(o.dropped.size(), 6u);
  for (std::uint32_t f = 0; f < 6; ++f) {
    EXPECT_EQ(o.dropped[f].facet, f);
    EXPECT_EQ(o.dropped[f].tris.size(), 2u);
    EXPECT_TRUE(o.facets[f].tris.empty());
  }
  EXPECT_EQ(o.dropped_segments.size(), 12u);
  EXPECT_EQ(o.segments.size(), 24u);
  for (const DomainSegment& s : o.segments) {
    EXPECT_EQ(s.sides.size(), 2u);
    for (const HalfFacet& h : s.sides) EXPECT_GE(h.facet, 6u);
  }
  for (std::uint32_t v = 0; v < 8; ++v) EXPECT_TRUE(o.vertex_facets[v].empty() && o.vertex_segments[v].empty());
  EXPECT_EQ(inside(o), (std::vector<int>{0, 1, 1}));
  // Every region a void: the domain is empty, refused.
  outer.holes.push_back({3, 3, 3});
  outer.holes.push_back({5, 5, 5});
  EXPECT_NE(error_of(outer).find("every region is a void"), std::string::npos) << error_of(outer);
}

// Facet walls splitting a region: three facet sides around a segment where a wall meets
// the outer surface. Each cube of walled_box is a cell of its own; a wall between two
// regions is internal, a wall next to a void separates.
TEST(PlcValidate, FacetWallsSplitARegionIntoCells) {
  const Plc three = walled_box(3);
  const PlcDomain d = build_domain(three);
  EXPECT_EQ(d.cells, 3u);
  EXPECT_EQ(d.shells, 1u);
  for (std::uint32_t f = 0; f < d.facets.size(); ++f)
    EXPECT_EQ(d.facets[f].separates, f != 1 && f != 2) << f;
  std::size_t joints = 0;
  for (const DomainSegment& s : d.segments) {
    int inside = 0;
    for (const HalfFacet& h : s.sides) inside += h.inside_after > 0;
    EXPECT_EQ(inside + 1, static_cast<int>(s.sides.size())) << s.a << "-" << s.b;
    joints += s.sides.size() == 3;
  }
  EXPECT_EQ(joints, 8u);  // the two walls' edges

  // A void cube next to a wall: inside a larger box, so that its outer facets too have the
  // domain on one side. Facets 0-5 are the larger box, 6-8 the squares at x = 0, 1, 2.
  Plc nested = merge(box({-1, -1, -1}, {3, 2, 2}), walled_box(2));
  nested.enclosure = Enclosure::HolePoints;
  nested.holes.push_back({1.5, 0.5, 0.5});  // the second cube is a void
  relabel(nested);
  const PlcDomain m = build_domain(nested);
  EXPECT_EQ(m.cells, 3u);
  for (std::uint32_t f = 0; f < m.facets.size(); ++f)
    EXPECT_EQ(m.facets[f].separates, f != 6 && (f < 9 || f > 12)) << f;  // the first cube's
  std::size_t inside = 0;
  for (const std::uint8_t x : m.cell_inside) inside += x;
  EXPECT_EQ(inside, 2u);
  // In walled_box itself a void middle cube leaves its outer facets with no domain on
  // either side: they are dropped (its bottom, facet 8 among them), the walls separate.
  Plc middle = three;
  middle.holes.push_back({1.5, 0.5, 0.5});
  relabel(middle);
  const PlcDomain v = build_domain(middle);
  std::vector<std::uint32_t> gone;
  for (const PlcDomain::Dropped& x : v.dropped) gone.push_back(x.facet);
  EXPECT_NE(std::find(gone.begin(), gone.end(), 8u), gone.end());
  EXPECT_EQ(gone.size(), 4u);
  EXPECT_TRUE(v.facets[1].separates && v.facets[2].separates);
  EXPECT_EQ(v.dropped_segments.size(), 4u);  // its edges along x; the others are the walls'
  // A standalone segment inside the first cube stays; a second box with a face missing,
  // open, is refused though it bounds no region either.
  Plc rod = middle;
  rod.points.push_back({0.2, 0.5, 0.5});
  rod.points.push_back({0.8, 0.5, 0.5});
  PlcFacet seg;
  seg.polygons = {{static_cast<std::uint32_t>(rod.points.size() - 2), static_cast<std::uint32_t>(rod.points.size() - 1)}};
  rod.facets.push_back(seg);
  relabel(rod);
  EXPECT_TRUE(build_domain(rod).find_segment(static_cast<std::uint32_t>(rod.points.size() - 2),
                                             static_cast<std::uint32_t>(rod.points.size() - 1)));
  // Isolated vertices: one in the void cube, one outside, one in a region; the first two
  // are outside Ω (a mesher may leave them out, as TetGen does).
  Plc lone = middle;
  for (const Point& p : {Point{1.5, 0.5, 0.5}, Point{9, 9, 9}, Point{0.5, 0.5, 0.5}}) lone.points.push_back(p);
  relabel(lone);
  const auto n = static_cast<std::uint32_t>(middle.points.size());
  EXPECT_EQ(build_domain(lone).outside_vertices, (std::vector<std::uint32_t>{n, n + 1}));
  Plc open = merge(middle, box({5, 0, 0}, {6, 1, 1}));
  open.facets.pop_back();
  relabel(open);
  EXPECT_NE(error_of(open).find("closed boundary:"), std::string::npos) << error_of(open);

  Plc region = three;
  PlcRegion r;
  r.point = {2.5, 0.5, 0.5};
  region.regions.push_back(r);
  EXPECT_EQ(error_of(region), "");
  Plc on_wall = three;
  on_wall.holes.push_back({2, 0.5, 0.5});
  relabel(on_wall);
  EXPECT_NE(error_of(on_wall).find("lies on facet 2"), std::string::npos) << error_of(on_wall);

  // Read from a surface file (parity), walls (edges of three or more faces) make every
  // bounded cell a region, as TetGen reads a surface, the walls internal; nested in a
  // larger box, the two cubes and the space around them are three regions; no hole point
  // can be given there.
  Plc parity = three;
  parity.enclosure = Enclosure::Parity;
  const PlcDomain p = build_domain(parity);
  EXPECT_TRUE(p.surface_walls);
  EXPECT_EQ(p.plc.enclosure, Enclosure::HolePoints);
  EXPECT_EQ(p.cell_inside, (std::vector<std::uint8_t>{1, 1, 1}));
  for (std::uint32_t f = 0; f < p.facets.size(); ++f) EXPECT_EQ(p.facets[f].separates, f != 1 && f != 2) << f;
  Plc boxed = nested;
  boxed.enclosure = Enclosure::Parity;
  boxed.holes.clear();
  const PlcDomain b = build_domain(boxed);
  EXPECT_EQ(b.cell_inside, (std::vector<std::uint8_t>{1, 1, 1}));
  for (std::uint32_t f = 0; f < b.facets.size(); ++f) EXPECT_EQ(b.facets[f].separates, f < 6) << f;
  // A 2-manifold surface (no walls), parity still reads a shell inside another as a void.
  Plc hollow = merge(box({-2, -2, -2}, {4, 3, 3}), box({-1, -1, -1}, {3, 2, 2}));
  hollow.enclosure = Enclosure::Parity;
  relabel(hollow);
  const PlcDomain h = build_domain(hollow);
  EXPECT_FALSE(h.surface_walls);
  EXPECT_EQ(h.cell_inside, (std::vector<std::uint8_t>{1, 0}));
}

// Regional volume bounds: a region record's volume bounds the cell its point lies in (the
// smallest where two share a cell); a tet is located by its centroid, exactly.
TEST(PlcCells, RegionVolumesBoundTheTetsOfTheirCell) {
  Plc plc = walled_box(3);
  EXPECT_EQ(RegionVolumes::of(build_domain(plc)), nullptr);
  for (const auto& [x, v] : {std::pair{0.5, 0.1}, std::pair{0.25, 0.05}, std::pair{2.5, -1.0}}) {
    PlcRegion r;
    r.point = {x, 0.5, 0.5};
    r.max_volume = v;
    plc.regions.push_back(r);
  }
  const auto rv = RegionVolumes::of(build_domain(plc));
  ASSERT_NE(rv, nullptr);
  EXPECT_EQ(rv->smallest(), 0.05);
  // A tet with a face on the wall x = 1 and its apex on either side of it.
  const Point a{1, 0.2, 0.2}, b{1, 0.8, 0.2}, c{1, 0.5, 0.8};
  EXPECT_EQ(rv->bound(a, b, c, {0.9, 0.5, 0.5}), 0.05);
  EXPECT_EQ(rv->bound(a, b, c, {1.1, 0.5, 0.5}), 0.0);  // the middle cube: no bound
  EXPECT_EQ(rv->bound({2.1, 0.1, 0.1}, {2.9, 0.1, 0.1}, {2.5, 0.9, 0.1}, {2.5, 0.5, 0.9}), 0.0);
}

// Walls meeting facets inside them, facets of two cells, and 2-complexes enclosing no
// volume (the review's counterexamples, tests/regress/outside-walls-*.poly).
TEST(PlcCells, WallsInsideFacetsFacetsOfTwoCellsAndEmptyComplexes) {
  const auto regress = [](const std::string& name) {
    return io::read_domain(std::string(PDR_SOURCE_DIR) + "/tests/regress/" + name);
  };
  // A wall's foot inside a face: two cells, not one.
  const Plc foot = regress("outside-walls-foot-inside-facets.poly");
  EXPECT_EQ(build_domain(foot).cells, 2u);

  // One facet of two polygons, under a void and under a region: split into two parts, the
  // first separating (Ω below, the void above) and the second internal.
  const Plc two = regress("outside-walls-facet-of-two-cells.poly");
  const PlcDomain d = build_domain(two);
  ASSERT_EQ(d.facets.size(), two.facets.size() + 1);
  const DomainFacet& added = d.facets.back();
  ASSERT_GE(added.part_of, 0);
  const DomainFacet& first = d.facets[static_cast<std::size_t>(added.part_of)];
  EXPECT_NE(first.separates, added.separates);
  EXPECT_EQ(d.plc.facets.back().marker, two.facets[static_cast<std::size_t>(added.part_of)].marker);
  for (const DomainSegment& s : d.segments)
    for (const HalfFacet& h : s.sides) EXPECT_LT(h.tri, d.facets[h.facet].tris.size());

  // Bing's house inside a box: one cell; its facets internal, the box's separate.
  const Plc house = regress("outside-walls-bings-house-in-box.poly");
  const PlcDomain b = build_domain(house);
  EXPECT_EQ(b.cells, 1u);
  std::size_t internal = 0;
  for (const DomainFacet& f : b.facets) internal += !f.separates;
  EXPECT_EQ(internal, b.facets.size() - 6);
  // Alone it encloses no volume: refused.
  Plc alone = house;
  alone.facets.resize(alone.facets.size() - 6);
  EXPECT_NE(error_of(alone).find("the facets enclose no volume"), std::string::npos) << error_of(alone);
}

TEST(PlcValidate, RejectsSegmentsInsideAFacetWithoutBeingItsEdges) {
  // A standalone segment along the diagonal of the top of a box: it lies in the top facet
  // whether or not the facet's triangulation happens to use that diagonal.
  for (int diagonal = 0; diagonal < 2; ++diagonal) {
    Plc p = box({0, 0, 0}, {2, 2, 2});
    PlcFacet seg;
    seg.polygons = {{diagonal ? 4u : 5u, diagonal ? 6u : 7u}};
    p.facets.push_back(seg);
    relabel(p);
    EXPECT_NE(error_of(p).find("non-crossing components"), std::string::npos) << error_of(p);
  }
  // A fin through the top facet along that diagonal (listed as an edge of the fin only).
  for (int diagonal = 0; diagonal < 2; ++diagonal) {
    Plc p = box({0, 0, 0}, {2, 2, 2});
    const std::uint32_t a = diagonal ? 4u : 5u, b = diagonal ? 6u : 7u;
    const Point pa = p.points[a], pb = p.points[b];
    p.points.push_back({pa[0], pa[1], 1});  // 8
    p.points.push_back({pb[0], pb[1], 1});  // 9
    p.points.push_back({pb[0], pb[1], 3});  // 10
    p.points.push_back({pa[0], pa[1], 3});  // 11
    PlcFacet fin;
    fin.polygons = {{8, 9, b, 10, 11, a}, {a, b}};
    p.facets.push_back(fin);
    relabel(p);
    EXPECT_NE(error_of(p).find("non-crossing components"), std::string::npos) << error_of(p);
  }
}

TEST(PlcValidate, DataFilesAreValid) {
  for (const char* name : {"box.poly", "l-prism.poly", "wedge60.poly", "tee.poly",
                           "tee-admissible.poly", "cube-in-cube.poly"}) {
    const Plc p = read_data(name);
    EXPECT_EQ(error_of(p), "") << name;
  }
}

}  // namespace
}  // namespace pdr::domain::test
