// The constrained triangulation of facets (domain/ctri.hpp): its invariants, and the
// constrained Delaunay property, on degenerate point sets (grids: many collinear and
// cocircular points) with and without constraints.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "domain/ctri.hpp"
#include "geom/predicates.hpp"

namespace pdr::domain {
namespace {

double area2(const P2& a, const P2& b, const P2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Twice the area of the convex hull (monotone chain with exact orient2d).
double hull_area2(std::vector<P2> p) {
  std::sort(p.begin(), p.end());
  std::vector<P2> h;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = h.size();
    for (const P2& q : p) {
      while (h.size() >= start + 2 && orient2d(h[h.size() - 2], h.back(), q) != Sign::Positive) h.pop_back();
      h.push_back(q);
    }
    h.pop_back();
    std::reverse(p.begin(), p.end());
  }
  double a = 0;
  for (std::size_t i = 1; i + 1 < h.size(); ++i) a += area2(h[0], h[i], h[i + 1]);
  return a;
}

// Counter-clockwise triangles; symmetric neighbours across shared edges (opposite
// directions); constraint flags agree on both sides.
void check_invariants(const Ct2& ct) {
  const auto& t = ct.tris();
  for (std::size_t i = 0; i < t.size(); ++i) {
    RC_ASSERT(orient2d(ct.points()[t[i].v[0]], ct.points()[t[i].v[1]], ct.points()[t[i].v[2]]) ==
              Sign::Positive);
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = t[i].n[k];
      if (n < 0) continue;
      const std::uint32_t a = t[i].v[(k + 1) % 3], b = t[i].v[(k + 2) % 3];
      int back = -1;
      for (int j = 0; j < 3; ++j)
        if (t[n].n[j] == static_cast<std::int32_t>(i)) back = j;
      RC_ASSERT(back >= 0);
      const std::uint32_t c = t[n].v[(back + 1) % 3], d = t[n].v[(back + 2) % 3];
      RC_ASSERT(a == d);
      RC_ASSERT(b == c);
      RC_ASSERT(t[i].fixed[k] == t[n].fixed[back]);
    }
  }
}

// Constrained Delaunay: across every unconstrained edge, the fourth vertex is not strictly
// inside the triangle's circumcircle.
void check_delaunay(const Ct2& ct) {
  const auto& t = ct.tris();
  const auto& p = ct.points();
  for (std::size_t i = 0; i < t.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = t[i].n[k];
      if (n < 0 || t[i].fixed[k]) continue;
      std::uint32_t d = 0;
      for (const std::uint32_t v : t[n].v)
        if (v != t[i].v[(k + 1) % 3] && v != t[i].v[(k + 2) % 3]) d = v;
      RC_ASSERT(incircle(p[t[i].v[0]].data(), p[t[i].v[1]].data(), p[t[i].v[2]].data(),
                         p[d].data()) != Sign::Positive);
    }
}

// Distinct points of a small integer grid, scaled.
rc::Gen<std::vector<P2>> grid_points() {
  return rc::gen::map(rc::gen::container<std::vector<std::pair<int, int>>>(
                          rc::gen::pair(rc::gen::inRange(0, 7), rc::gen::inRange(0, 7))),
                      [](std::vector<std::pair<int, int>> v) {
                        std::sort(v.begin(), v.end());
                        v.erase(std::unique(v.begin(), v.end()), v.end());
                        std::vector<P2> p;
                        for (auto [x, y] : v) p.push_back({0.25 * x, 0.25 * y});
                        return p;
                      });
}

RC_GTEST_PROP(PlcCt2, TriangulatesTheConvexHull, ()) {
  const std::vector<P2> p = *grid_points();
  Ct2 ct;
  const Ct2Outcome r = ct.build(p, {});
  if (r.status == Ct2Status::Collinear) {
    RC_SUCCEED("collinear");
  }
  RC_ASSERT(r.status == Ct2Status::Ok);
  check_invariants(ct);
  check_delaunay(ct);
  double a = 0;
  std::set<std::uint32_t> used;
  for (const Ct2Tri& t : ct.tris()) {
    a += area2(p[t.v[0]], p[t.v[1]], p[t.v[2]]);
    used.insert(t.v.begin(), t.v.end());
  }
  RC_ASSERT(std::fabs(a - hull_area2(p)) <= 1e-12);
  RC_ASSERT(used.size() == p.size());
}

RC_GTEST_PROP(PlcCt2, RecoversThePolygonOfAStar, ()) {
  // A star-shaped polygon about the centre of a grid: vertices at distinct angles, sorted.
  const int n = *rc::gen::inRange(3, 14);
  std::vector<std::pair<double, P2>> by_angle;
  std::set<std::pair<int, int>> seen;
  for (int i = 0; i < 40 && static_cast<int>(by_angle.size()) < n; ++i) {
    const int x = *rc::gen::inRange(-6, 7), y = *rc::gen::inRange(-6, 7);
    if ((x == 0 && y == 0) || !seen.insert({x, y}).second) continue;
    const double ang = std::atan2(static_cast<double>(y), static_cast<double>(x));
    bool clash = false;  // two vertices on one ray would make the polygon touch itself
    for (auto& [a, q] : by_angle) clash = clash || (q[0] * y - q[1] * x == 0 && q[0] * x + q[1] * y > 0);
    if (!clash) by_angle.push_back({ang, {static_cast<double>(x), static_cast<double>(y)}});
  }
  RC_PRE(by_angle.size() >= 3u);
  std::sort(by_angle.begin(), by_angle.end());
  std::vector<P2> p;
  for (auto& [a, q] : by_angle) p.push_back(q);
  std::vector<std::array<std::uint32_t, 2>> cons;
  double poly = 0;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    cons.push_back({i, static_cast<std::uint32_t>((i + 1) % p.size())});
    poly += area2({0, 0}, p[i], p[(i + 1) % p.size()]);
  }
  RC_PRE(poly > 0);
  // Extra interior-free points outside the polygon's hull make the recovery work harder.
  for (int k = 0; k < 5; ++k) p.push_back({-9.0 + k, 9.5 - 0.25 * k * k});
  Ct2 ct;
  const Ct2Outcome r = ct.build(p, cons);
  if (r.status == Ct2Status::ThroughVertex || r.status == Ct2Status::Crossing) {
    // Possible only if the star polygon is not simple (a vertex on another edge).
    RC_SUCCEED("non-simple star");
  }
  RC_ASSERT(r.status == Ct2Status::Ok);
  check_invariants(ct);
  check_delaunay(ct);
  const std::vector<Ct2Region> reg = ct.regions({});
  double inside = 0;
  for (std::size_t t = 0; t < ct.tris().size(); ++t)
    if (reg[t] == Ct2Region::Inside) {
      const auto& v = ct.tris()[t].v;
      inside += area2(p[v[0]], p[v[1]], p[v[2]]);
    }
  RC_ASSERT(std::fabs(inside - poly) <= 1e-9 * std::max(1.0, poly));
}

TEST(PlcCt2, ReportsCrossingAndThroughVertex) {
  Ct2 ct;
  EXPECT_EQ(ct.build({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, 2}, {1, 3}}).status, Ct2Status::Crossing);
  EXPECT_EQ(ct.build({{0, 0}, {1, 1}, {2, 2}, {0, 2}}, {{0, 2}}).status, Ct2Status::ThroughVertex);
  EXPECT_EQ(ct.build({{0, 0}, {1, 1}, {0, 0}}, {}).status, Ct2Status::Duplicate);
  EXPECT_EQ(ct.build({{0, 0}, {1, 1}, {3, 3}}, {}).status, Ct2Status::Collinear);
}

TEST(PlcCt2, HolesAreFloodedFromTheirSeed) {
  // Square with a square inside; a hole seed in the inner square removes it.
  std::vector<P2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  std::vector<std::array<std::uint32_t, 2>> c{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  Ct2 ct;
  ASSERT_EQ(ct.build(p, c).status, Ct2Status::Ok);
  const Ct2Location loc = ct.locate({2, 2.5});
  ASSERT_GE(loc.tri, 0);
  const std::vector<Ct2Region> reg = ct.regions({loc.tri});
  double inside = 0, hole = 0;
  for (std::size_t t = 0; t < ct.tris().size(); ++t) {
    const auto& v = ct.tris()[t].v;
    const double a = area2(p[v[0]], p[v[1]], p[v[2]]) / 2;
    (reg[t] == Ct2Region::Inside ? inside : hole) += a;
  }
  EXPECT_DOUBLE_EQ(inside, 12);
  EXPECT_DOUBLE_EQ(hole, 4);
}

}  // namespace
}  // namespace pdr::domain
