// Facet charts: construction, exact chart orientation and placement on the facet's plane
// (paper §2.1 step 2); see surface_chart.hpp. The in-circle test is in surface_incircle.cpp.
#include "refine/surface_chart.hpp"

namespace pdr::refine {

FacetChart make_chart(const FacetPlane& plane, const std::vector<Point>& pts) {
  FacetChart ch;
  ch.projection = plane.projection;
  const Point& t0 = pts[plane.triple[0]];
  const Point& t1 = pts[plane.triple[1]];
  const Point& t2 = pts[plane.triple[2]];
  ch.origin = t0;
  ch.t1 = t1;
  ch.t2 = t2;
  const Point u{t1[0] - t0[0], t1[1] - t0[1], t1[2] - t0[2]};
  const Point v{t2[0] - t0[0], t2[1] - t0[1], t2[2] - t0[2]};
  ch.normal = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return ch;
}

Sign chart_orient(const FacetChart& ch, const Point& a, const Point& b, const Point& c) {
  return orient2d(ch(a), ch(b), ch(c));
}

Point place_on_facet(const FacetChart& ch, Point p) {
  const int k = ch.projection.drop, i = (k + 1) % 3, j = (k + 2) % 3;
  const Point& o = ch.origin;
  const Point& n = ch.normal;
  // n[k] != 0: the chart drops the largest normal component, nonzero for a proper triple
  // (a rounded cross product of a proper triple could still vanish for extreme inputs;
  // then p stays as constructed).
  if (n[k] == 0) return p;
  p[k] = o[k] - (n[i] * (p[i] - o[i]) + n[j] * (p[j] - o[j])) / n[k];
  return p;
}

}  // namespace pdr::refine
