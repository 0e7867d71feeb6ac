// The facet chart (surface/chart.hpp) and the surface operations (surface/split.hpp,
// surface/insert.hpp, surface/cavity.hpp; paper §2.1, Fig. 2): chart_incircle equals
// incircle3_sos on coplanar points and the GMP reference everywhere, obeys the
// permutation laws and never returns Zero on proper triangles; placement is exact on
// axis-parallel facets; splits and insertions keep every invariant of audit_surface; and
// the audit catches planted corruptions of each kind.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "geom/construct.hpp"
#include "geom/encroach.hpp"
#include "geom/predicates.hpp"
#include "support/plc_fixtures.hpp"
#include "support/surface_fixtures.hpp"
#include "surface/build.hpp"
#include "surface/encroach.hpp"
#include "surface/insert.hpp"
#include "surface/split.hpp"

namespace pdr::surface::test {
using namespace pdr::test;
using namespace pdr::domain;
namespace {

// A chart for the plane through o, o + U, o + V (as the domain analysis would make it).
FacetChart chart_of(const Point& o, const Point& p1, const Point& p2) {
  FacetPlane pl;
  pl.projection.drop = nondegenerate_drop(o, p1, p2);
  pl.projection.swap = orient2d_dropping(pl.projection.drop, o, p1, p2) == Sign::Negative;
  pl.triple = {0, 1, 2};
  pl.exact = true;  // three points
  return make_chart(pl, {o, p1, p2});
}

// The plane-centred lifted determinant of surface/chart.hpp in GMP: rows q - d for
// q = a, b, c with columns e1.(q - d), e2.(q - d), |q - t0|^2 - |d - t0|^2.
Sign raw_reference(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                   const Point& d) {
  const Point* p[3] = {&a, &b, &c};
  mpq_class x[3], y[3], w[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = y[i] = w[i] = 0;
    for (int k = 0; k < 3; ++k) {
      const mpq_class e = mpq_class((*p[i])[k]) - d[k];
      x[i] += (mpq_class(ch.t1[k]) - ch.origin[k]) * e;
      y[i] += (mpq_class(ch.t2[k]) - ch.origin[k]) * e;
      w[i] += (mpq_class((*p[i])[k]) - ch.origin[k]) * (mpq_class((*p[i])[k]) - ch.origin[k]) -
              (mpq_class(d[k]) - ch.origin[k]) * (mpq_class(d[k]) - ch.origin[k]);
    }
  }
  const mpq_class det = x[0] * (y[1] * w[2] - y[2] * w[1]) - y[0] * (x[1] * w[2] - x[2] * w[1]) +
                        w[0] * (x[1] * y[2] - x[2] * y[1]);
  return sign_of(sgn(det));
}

Point on_plane(const Point& o, const Point& U, const Point& V, int i, int j) {
  return {o[0] + i * U[0] + j * V[0], o[1] + i * U[1] + j * V[1], o[2] + i * U[2] + j * V[2]};
}

RC_GTEST_PROP(SurfaceChart, CoplanarEqualsIncircle3Sos, ()) {
  // Integer frames: every combination is exact, so the points are exactly coplanar;
  // small ranges make cocircular quadruples frequent.
  const int fr = *rc::gen::inRange(0, 3);
  static const Point Us[] = {{1, 2, 2}, {2, 3, 6}, {1, 0, 0}};
  static const Point Vs[] = {{2, 1, -2}, {3, -6, 2}, {0, 1, 1}};
  const Point o{double(*rc::gen::inRange(-5, 5)), double(*rc::gen::inRange(-5, 5)), 0.5};
  const FacetChart ch = chart_of(o, on_plane(o, Us[fr], Vs[fr], 1, 0), on_plane(o, Us[fr], Vs[fr], 0, 1));
  Point q[4];
  for (Point& p : q) p = on_plane(o, Us[fr], Vs[fr], *rc::gen::inRange(-3, 4), *rc::gen::inRange(-3, 4));
  const Sign o2 = chart_orient(ch, q[0], q[1], q[2]);
  RC_PRE(o2 != Sign::Zero);
  RC_PRE(q[3] != q[0] && q[3] != q[1] && q[3] != q[2]);
  const Sign s = chart_incircle(ch, q[0], q[1], q[2], q[3]);
  RC_ASSERT(s != Sign::Zero);
  RC_ASSERT(s * o2 == incircle3_sos(q[0], q[1], q[2], q[3]));
  RC_ASSERT(chart_incircle(ch, q[1], q[0], q[2], q[3]) == -s);
  RC_ASSERT(chart_incircle(ch, q[1], q[2], q[0], q[3]) == s);
  RC_ASSERT(chart_incircle_raw(ch, q[0], q[1], q[2], q[3]) == raw_reference(ch, q[0], q[1], q[2], q[3]));
}

RC_GTEST_PROP(SurfaceChart, OffPlaneRawEqualsGmp, ()) {
  // Points near a tilted plane, nudged by a few ulps or by random amounts.
  const double s = std::ldexp(1.0, *rc::gen::inRange(-20, 20));
  auto coord = [&] { return s * *rc::gen::inRange(-1000, 1000) / 997.0; };
  const Point o{coord(), coord(), coord()};
  const Point p1{o[0] + s, o[1] + 0.3 * s, o[2] + 0.1 * s}, p2{o[0] - 0.2 * s, o[1] + s, o[2] + 0.7 * s};
  const FacetChart ch = chart_of(o, p1, p2);
  Point q[4];
  for (Point& p : q) {
    const double i = *rc::gen::inRange(-4, 5) / 4.0, j = *rc::gen::inRange(-4, 5) / 4.0;
    p = place_on_facet(ch, {o[0] + i * (p1[0] - o[0]) + j * (p2[0] - o[0]),
                            o[1] + i * (p1[1] - o[1]) + j * (p2[1] - o[1]),
                            o[2] + i * (p1[2] - o[2]) + j * (p2[2] - o[2])});
    if (*rc::gen::inRange(0, 3) == 0) p[*rc::gen::inRange(0, 3)] = std::nextafter(p[0], 1e300);
  }
  RC_ASSERT(chart_incircle_raw(ch, q[0], q[1], q[2], q[3]) == raw_reference(ch, q[0], q[1], q[2], q[3]));
  if (chart_orient(ch, q[0], q[1], q[2]) != Sign::Zero && q[3] != q[0] && q[3] != q[1] && q[3] != q[2])
    RC_ASSERT(chart_incircle(ch, q[0], q[1], q[2], q[3]) != Sign::Zero);
}

TEST(SurfaceChart, PlacementIsExactOnAxisParallelFacets) {
  const FacetChart ch = chart_of({0, 0, 0.3}, {1, 0, 0.3}, {0, 1, 0.3});
  const Point p = place_on_facet(ch, {0.123, 4.56, 0.3000000001});
  EXPECT_EQ(p[2], 0.3);
  EXPECT_EQ(p[0], 0.123);
  const FacetChart tilted = chart_of({0.1, 0.2, 0.3}, {1.7, 0.2, 1.1}, {0.1, 2.3, 0.9});
  const Point q = place_on_facet(tilted, {0.9, 1.1, 5});
  // Within a few ulps of the plane: |orient3d determinant| / |n| tiny.
  const Point u{1.6, 0, 0.8}, v{0, 2.1, 0.6};
  const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double dist = ((q[0] - 0.1) * n[0] + (q[1] - 0.2) * n[1] + (q[2] - 0.3) * n[2]) /
                      std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  EXPECT_LT(std::fabs(dist), 1e-14);
}

// surface/chart.hpp's bound: on a facet planar only within tolerance, a point placed on
// the plane through the defining triple lies within 7 times the facet's largest deviation
// of its least-squares plane, anywhere in the facet's hull (what the check's 8T relies
// on). Star-shaped polygons of 3 to 12 corners, corners up to 1e-9 off z = 0.
RC_GTEST_PROP(SurfaceChart, PlacementStaysWithinSevenDeviationsOfTheLeastSquaresPlane, ()) {
  const int n = *rc::gen::inRange(3, 13);
  std::vector<Point> pts;
  std::vector<std::uint32_t> ids;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * 3.141592653589793 * (i + *rc::gen::inRange(0, 80) / 100.0) / n;
    const double r = 0.2 + *rc::gen::inRange(0, 181) / 100.0;
    pts.push_back({r * std::cos(t), r * std::sin(t), *rc::gen::inRange(-1000, 1001) * 1e-12});
    ids.push_back(static_cast<std::uint32_t>(i));
  }
  const PlaneFit fit = fit_facet_plane(pts, ids, {1e-6, {}});
  RC_PRE(fit.status == PlaneStatus::Ok && !fit.plane.exact);
  const FacetChart ch = make_chart(fit.plane, pts);
  for (int k = 0; k < 20; ++k) {
    // A point of the hull: a random convex combination of the corners, off the plane.
    std::vector<double> w(pts.size());
    double sum = 0;
    for (double& x : w) sum += (x = *rc::gen::inRange(0, 101));
    RC_PRE(sum > 0);
    Point q{0, 0, 1e-3};
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (int c = 0; c < 2; ++c) q[c] += w[i] / sum * pts[i][c];
    const Point p = place_on_facet(ch, q);
    RC_ASSERT(relative_deviation(fit.plane, p) <= 7 * fit.plane.max_deviation * (1 + 1e-6) + 1e-15);
  }
}

TEST(SurfaceOps, SplitUpdatesEveryFacetOfTheSegment) {
  // Unrefined or partly refined meshes are encroached (that is what §2.1 removes): only the
  // structure is audited here.
  auto structure = [](const SurfaceMesh& m) {
    SurfaceAudit a;
    audit_surface_structure(m, a);
    return a;
  };
  SurfaceMesh m = build_surface(analyze(read_data("box.poly")).domain);
  ASSERT_TRUE(structure(m).ok()) << describe(structure(m));
  const std::uint32_t s = 0;  // segment 0 is shared by two facets
  ASSERT_EQ(m.segments[m.subsegment(s).segment].facets.size(), 2u);
  const std::uint32_t before = m.subsegment(s).v[1];
  const SplitResult r = split_subsegment(m, s);
  EXPECT_EQ(m.subsegment(s).v[1], r.vertex);
  EXPECT_EQ(m.subsegment(r.new_subsegment).v[0], r.vertex);
  EXPECT_EQ(m.subsegment(r.new_subsegment).v[1], before);
  EXPECT_EQ(m.home(r.vertex).kind, HomeKind::Segment);
  EXPECT_EQ(m.vertex_subsegments(r.vertex).size(), 2u);
  std::set<std::uint32_t> facets;
  for (const std::uint32_t t : m.vertex_subfacets(r.vertex)) facets.insert(m.subfacet(t).facet);
  EXPECT_EQ(facets.size(), 2u);
  const SurfaceAudit a = structure(m);
  EXPECT_TRUE(a.ok()) << describe(a);
}

TEST(SurfaceOps, CircumcenterInsertionAndEncroachment) {
  auto structure = [](const SurfaceMesh& m) {
    SurfaceAudit a;
    audit_surface_structure(m, a);
    return a;
  };
  SurfaceMesh m = build_surface(analyze(read_data("cube-in-cube.poly")).domain);
  // Unrefined (so encroached: only the structure is audited), facet 0 is the square [0,10]^2 x {0} in two triangles; their circumcenter
  // (5,5,0) lies on the diametral sphere of all four edges: closed balls, so Fig. 2 splits
  // the four subsegments instead.
  const std::uint32_t t = m.facet_subfacets(0)[0];
  const InsertResult e = insert_circumcenter(m, t);
  ASSERT_EQ(e.outcome, InsertOutcome::Encroaches);
  EXPECT_EQ(e.point, (Point{5, 5, 0}));
  ASSERT_EQ(e.encroached.size(), 4u);
  for (const std::uint32_t g : e.encroached) {
    EXPECT_TRUE(subsegment_encroached_by(m, g, e.point));
    split_subsegment(m, g);
  }
  SurfaceAudit a = structure(m);
  EXPECT_TRUE(a.ok()) << describe(a);
  // Now the midpoints' square holds (5,5,0) in its circle and no diametral ball does.
  bool inserted = false;
  for (const std::uint32_t s : m.facet_subfacets(0)) {
    if (subfacet_circumcenter(m, s) != Point{5, 5, 0}) continue;
    const InsertResult r = insert_circumcenter(m, s);
    ASSERT_EQ(r.outcome, InsertOutcome::Inserted);
    EXPECT_EQ(m.home(r.vertex).kind, HomeKind::Facet);
    EXPECT_EQ(m.home(r.vertex).id, 0u);
    EXPECT_EQ(m.point(r.vertex), (Point{5, 5, 0}));
    inserted = true;
    break;
  }
  EXPECT_TRUE(inserted);
  a = structure(m);
  EXPECT_TRUE(a.ok()) << describe(a);
}

// Flips the edge opposite v[i] of subfacet t by hand (no Delaunay test).
void flip_by_hand(SurfaceMesh& m, std::uint32_t t, int i) {
  const Subfacet T = m.subfacet(t);
  const auto nb = static_cast<std::uint32_t>(T.nbr[i]);
  const Subfacet N = m.subfacet(nb);
  const std::uint32_t a = T.v[i], b = T.v[(i + 1) % 3], c = T.v[(i + 2) % 3];
  const int j = edge_index(N, b, c);
  const std::uint32_t d = N.v[j];
  Subfacet P = T, Q = T;
  P.v = {a, b, d};
  P.nbr = {N.nbr[(j + 1) % 3], -1, T.nbr[(i + 2) % 3]};
  P.constrained = {N.constrained[(j + 1) % 3], false, T.constrained[(i + 2) % 3]};
  Q.v = {a, d, c};
  Q.nbr = {N.nbr[(j + 2) % 3], T.nbr[(i + 1) % 3], -1};
  Q.constrained = {N.constrained[(j + 2) % 3], T.constrained[(i + 1) % 3], false};
  m.kill_subfacet(t);
  m.kill_subfacet(nb);
  const std::uint32_t p = m.add_subfacet(P), q = m.add_subfacet(Q);
  m.subfacet_mut(p).nbr[1] = static_cast<std::int32_t>(q);
  m.subfacet_mut(q).nbr[2] = static_cast<std::int32_t>(p);
  for (const std::uint32_t x : {p, q})
    for (int k = 0; k < 3; ++k) {
      const Subfacet& X = m.subfacet(x);
      if (X.nbr[k] < 0 || X.nbr[k] == static_cast<std::int32_t>(x == p ? q : p)) continue;
      Subfacet& O = m.subfacet_mut(static_cast<std::uint32_t>(X.nbr[k]));
      O.nbr[edge_index(O, X.v[(k + 1) % 3], X.v[(k + 2) % 3])] = static_cast<std::int32_t>(x);
    }
}

// Planted corruptions, one per invariant family.
TEST(SurfaceOps, CircumcenterBeyondASubsegmentSplitsIt) {
  // A triangular prism whose base has a 152-degree angle opposite the edge (0,0)-(4,0): the
  // base's circumcenter lies beyond that edge and outside its diametral ball (the apex
  // encroaches the edge: outside the theory). Ruppert's remedy, not a rejected cavity.
  SurfaceMesh m = build_surface(analyze(prism({{0, 0}, {4, 0}, {2, 0.5}}, 0, 1)).domain);
  std::optional<std::uint32_t> base;
  for (std::uint32_t t = 0; t < m.subfacets().size(); ++t) {
    const Subfacet& x = m.subfacet(t);
    if (x.alive && m.point(x.v[0])[2] == 0 && m.point(x.v[1])[2] == 0 &&
        m.point(x.v[2])[2] == 0)
      base = t;
  }
  ASSERT_TRUE(base);
  const Point p = subfacet_circumcenter(m, *base);
  ASSERT_LT(p[1], 0.0);  // beyond the edge
  ASSERT_EQ(in_diametral_ball({0, 0, 0}, {4, 0, 0}, p), Sign::Negative);
  const InsertResult r = insert_circumcenter(m, *base);
  ASSERT_EQ(r.outcome, InsertOutcome::Encroaches);
  ASSERT_EQ(r.encroached.size(), 1u);
  const Subsegment& g = m.subsegment(r.encroached[0]);
  EXPECT_EQ(m.point(g.v[0])[1] + m.point(g.v[1])[1], 0.0);  // the edge on y = 0
  EXPECT_EQ(m.point(g.v[0])[2] + m.point(g.v[1])[2], 0.0);
}

TEST(SurfaceAudit, CatchesCorruptions) {
  const DomainAnalysis an = analyze(read_data("box.poly"));
  const SurfaceMesh good = init_surface(an).mesh;
  ASSERT_TRUE(audit_surface(good).ok());
  auto first_violation = [](const SurfaceMesh& m) {
    const SurfaceAudit a = audit_surface(m);
    return a.violations.empty() ? std::string() : a.violations.front();
  };
  auto starts = [](const std::string& s, const char* p) { return s.rfind(p, 0) == 0; };
  const std::uint32_t t = good.facet_subfacets(0)[0];
  {
    SurfaceMesh m = good;
    std::swap(m.subfacet_mut(t).v[0], m.subfacet_mut(t).v[1]);
    const SurfaceAudit a = audit_surface(m);
    bool orientation = false;
    for (const auto& v : a.violations) orientation |= starts(v, "surface.orientation");
    EXPECT_TRUE(orientation) << describe(a);
  }
  {
    SurfaceMesh m = good;
    int i = 0;
    while (!m.subfacet(t).constrained[i] && i < 2) ++i;
    m.subfacet_mut(t).constrained[i] = !m.subfacet(t).constrained[i];
    EXPECT_TRUE(starts(first_violation(m), "surface.conformity") ||
                starts(first_violation(m), "surface.adjacency"))
        << first_violation(m);
  }
  {
    SurfaceMesh m = good;
    m.kill_subfacet(t);
    const SurfaceAudit a = audit_surface(m);
    bool area = false;
    for (const auto& v : a.violations) area |= starts(v, "surface.area");
    EXPECT_TRUE(area) << describe(a);
  }
  {
    SurfaceMesh m = build_surface(an.domain);
    m.d = good.d;  // unrefined: too long, too large
    EXPECT_TRUE(starts(first_violation(m), "surface.size")) << first_violation(m);
  }
  {
    // A vertex forced into a closed diametral ball: commit a cavity whose status says
    // Encroaches (the operations never do). Facet 0 of the box is [0,3]x[0,2]x{0}.
    SurfaceMesh m = build_surface(an.domain);
    const Point p{1.5, 0.2, 0};
    const std::uint32_t g = *m.find_subsegment(0, 1);  // (0,0,0)-(3,0,0)
    const FacetCavity c = build_facet_cavity(m, 0, p, m.subfacets_on_edge(0, 0, 1), std::nullopt);
    ASSERT_EQ(c.status, CavityStatus::Encroaches);
    ASSERT_EQ(c.encroached, std::vector<std::uint32_t>{g});
    commit_facet_cavity(m, c, m.add_vertex(p, {HomeKind::Facet, 0}));
    const SurfaceAudit a = audit_surface(m);
    bool enc = false;
    for (const auto& v : a.violations) enc |= starts(v, "surface.encroachment: vertex 8 is in the closed diametral");
    EXPECT_TRUE(enc) << describe(a);
  }
  {
    // A non-Delaunay diagonal: the rectangle's other diagonal (cocircular corners: the
    // symbolic perturbation makes exactly one of the two Delaunay).
    SurfaceMesh m = build_surface(an.domain);
    const std::uint32_t s0 = m.facet_subfacets(0)[0];
    int i = 0;
    while (m.subfacet(s0).nbr[i] < 0) ++i;
    flip_by_hand(m, s0, i);
    const SurfaceAudit a = audit_surface(m);
    bool del = false;
    for (const auto& v : a.violations) del |= starts(v, "surface.delaunay");
    EXPECT_TRUE(del) << describe(a);
  }
}

}  // namespace
}  // namespace pdr::surface::test
