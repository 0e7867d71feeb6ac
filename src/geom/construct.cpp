// Floating-point circumcenters and midpoints (construct.hpp), computed relative to the
// first vertex (differences first, so large absolute coordinates do not cost accuracy)
// in the cross-product form of Cramer's rule. Error bounds: see construct.hpp; they follow
// from counting roundings per term as in filter.hpp (numerator K = 12, denominator K = 8
// for the tetrahedron; K = 14 and 11 for the triangle) plus one division.
#include "geom/construct.hpp"

namespace pdr::construct {
namespace {

Point sub(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
Point cross(const Point& p, const Point& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
double dot(const Point& p, const Point& q) { return (p[0] * q[0] + p[1] * q[1]) + p[2] * q[2]; }
Point add(const Point& p, const Point& q) { return {p[0] + q[0], p[1] + q[1], p[2] + q[2]}; }

}  // namespace

Point midpoint(const Point& a, const Point& b) {
  return {0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1], 0.5 * a[2] + 0.5 * b[2]};
}

Point circumcenter_offset(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(d, a);
  const Point vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w);
  const double den = 2 * dot(u, vw);
  Point x;
  for (int i = 0; i < 3; ++i) x[i] = ((lu * vw[i] + lv * wu[i]) + lw * uv[i]) / den;
  return x;
}

Point circumcenter(const Point& a, const Point& b, const Point& c, const Point& d) {
  return add(a, circumcenter_offset(a, b, c, d));
}

double circumradius2(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point x = circumcenter_offset(a, b, c, d);
  return dot(x, x);
}

Point triangle_circumcenter_offset(const Point& a, const Point& b, const Point& c) {
  const Point u = sub(b, a), v = sub(c, a);
  const Point n = cross(u, v);
  const Point vn = cross(v, n), nu = cross(n, u);
  const double lu = dot(u, u), lv = dot(v, v);
  const double den = 2 * dot(n, n);
  Point x;
  for (int i = 0; i < 3; ++i) x[i] = (lu * vn[i] + lv * nu[i]) / den;
  return x;
}

Point triangle_circumcenter(const Point& a, const Point& b, const Point& c) {
  return add(a, triangle_circumcenter_offset(a, b, c));
}

double triangle_circumradius2(const Point& a, const Point& b, const Point& c) {
  const Point x = triangle_circumcenter_offset(a, b, c);
  return dot(x, x);
}

}  // namespace pdr::construct
