// Placement planes anchored at sharp features (surface/anchor.hpp): on a thin notch given in
// floating point, the notch's walls are placed on planes through both ends of the notch's
// edge and its floor and roof on planes through the tip; exact facets keep the analysis'
// plane; an anchored plane is never more than twice as far from the facet's vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "domain/analysis.hpp"
#include "support/outside_fixtures.hpp"
#include "support/plc_fixtures.hpp"
#include "surface/anchor.hpp"

namespace pdr::surface::test {
using namespace pdr::test;
namespace {

// A prism over the square [-1,1]^2 with a notch of `degrees` from the middle of its right
// side to the tip (-0.2, 0) (vertex 3 below, 10 above): facet 0 the floor, 1 the roof,
// 4 and 5 the notch's walls.
Plc notched_prism(double degrees) {
  const double half = 1.2 * std::tan(degrees * std::numbers::pi / 360);
  return prism({{-1, -1}, {1, -1}, {1, -half}, {-0.2, 0}, {1, half}, {1, 1}, {-1, 1}}, 0, 0.6);
}

bool holds(const std::array<std::uint32_t, 3>& t, std::uint32_t v) {
  return std::find(t.begin(), t.end(), v) != t.end();
}

double farthest(const Plc& plc, const domain::DomainFacet& F, const std::array<std::uint32_t, 3>& t) {
  const Point &a = plc.points[t[0]], &b = plc.points[t[1]], &c = plc.points[t[2]];
  const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double d = 0;
  for (const std::uint32_t w : F.vertices) {
    const Point& p = plc.points[w];
    d = std::max(d, std::fabs(n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2])) / len);
  }
  return d;
}

TEST(PlacementPlane, ThinNotchPrintedWithSevenDigitsIsAnchoredAtItsEdge) {
  for (const double degrees : {3.0, 5.0, 20.0}) {
    const Plc plc = printed(rotated(notched_prism(degrees), 0.7, 2.1, 4.4), 7);
    const domain::DomainAnalysis a = domain::analyze(plc);
    const domain::PlcDomain& dom = a.domain;
    ASSERT_FALSE(dom.facets[4].plane.exact);  // else the test tests nothing
    for (const std::uint32_t wall : {4u, 5u}) {
      const auto t = placement_plane(dom, wall).triple;
      EXPECT_TRUE(holds(t, 3) && holds(t, 10)) << degrees << " degrees, wall " << wall;
    }
    EXPECT_TRUE(holds(placement_plane(dom, 0).triple, 3)) << degrees << " degrees, floor";
    EXPECT_TRUE(holds(placement_plane(dom, 1).triple, 10)) << degrees << " degrees, roof";
    for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
      const domain::FacetPlane p = placement_plane(dom, f);
      EXPECT_LE(farthest(plc, dom.facets[f], p.triple), 2 * farthest(plc, dom.facets[f], dom.facets[f].plane.triple))
          << "facet " << f;
      // Counter-clockwise in the facet's projection, as the chart needs.
      EXPECT_EQ(domain::orient2d(p.projection(plc.points[p.triple[0]]), p.projection(plc.points[p.triple[1]]),
                                 p.projection(plc.points[p.triple[2]])),
                Sign::Positive);
    }
  }
}

TEST(PlacementPlane, ExactFacetsKeepTheAnalysisPlane) {
  const Plc plc = notched_prism(3);
  const domain::DomainAnalysis a = domain::analyze(plc);
  for (std::uint32_t f = 0; f < a.domain.facets.size(); ++f) {
    ASSERT_TRUE(a.domain.facets[f].plane.exact);
    EXPECT_EQ(placement_plane(a.domain, f).triple, a.domain.facets[f].plane.triple);
  }
}

}  // namespace
}  // namespace pdr::surface::test
