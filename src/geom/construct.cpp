// Floating-point circumcenters and midpoints (construct.hpp), computed relative to the
// first vertex (differences first, so large absolute coordinates do not cost accuracy)
// in the cross-product form of Cramer's rule. Error bounds: see construct.hpp; they follow
// from counting roundings per term as in filter.hpp (numerator K = 12, denominator K = 8
// for the tetrahedron; K = 14 and 11 for the triangle) plus one division.
#include "geom/construct.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "geom/encroach.hpp"
#include "geom/exact.hpp"

namespace pdr::construct {
namespace {

constexpr double kU = 0x1p-53;
// The accuracy asked of a circumcenter, relative to its radius (construct.hpp).
constexpr double kRelative = 0x1p-24;

Point sub(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
Point cross(const Point& p, const Point& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
double dot(const Point& p, const Point& q) { return (p[0] * q[0] + p[1] * q[1]) + p[2] * q[2]; }
Point add(const Point& p, const Point& q) { return {p[0] + q[0], p[1] + q[1], p[2] + q[2]}; }
double max_norm(const Point& u, const Point& v) { return std::sqrt(std::max(dot(u, u), dot(v, v))); }

// x~ is accurate when the bound e on each coordinate's error is at most kRelative of the
// radius it computed; R' = 2 |x~| + L stands in for the unknown true radius in the bound.
bool accurate(const Point& x, double e_of_radius(double, double, double), double L,
              double den) {
  const double r = std::sqrt(dot(x, x));
  if (!std::isfinite(r) || !(r >= L / 2 * (1 - 0x1p-20))) return false;
  return e_of_radius(2 * r + L, L, den) <= kRelative * r;
}

bool collinear(const Point& a, const Point& b, const Point& c) {
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    if (exact::orient2d(pa, pb, pc) != Sign::Zero) return false;
  }
  return true;
}

Point rounded_offset(const std::array<mpq_class, 3>& x, const Point& a) {
  Point o;
  for (int i = 0; i < 3; ++i) o[i] = mpq_class(x[i] - mpq_class(a[i])).get_d();
  return o;
}

Point circumcenter_offset_float(const Point& a, const Point& b, const Point& c, const Point& d,
                                double& L, double& den) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(d, a);
  const Point vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w);
  den = 2 * dot(u, vw);
  L = std::sqrt(std::max({lu, lv, lw}));
  Point x;
  for (int i = 0; i < 3; ++i) x[i] = ((lu * vw[i] + lv * wu[i]) + lw * uv[i]) / den;
  return x;
}

Point triangle_offset_float(const Point& a, const Point& b, const Point& c, double& L,
                            double& nn) {
  const Point u = sub(b, a), v = sub(c, a);
  const Point n = cross(u, v);
  const Point vn = cross(v, n), nu = cross(n, u);
  const double lu = dot(u, u), lv = dot(v, v);
  nn = dot(n, n);
  L = max_norm(u, v);
  const double den = 2 * nn;
  Point x;
  for (int i = 0; i < 3; ++i) x[i] = (lu * vn[i] + lv * nu[i]) / den;
  return x;
}

}  // namespace

Point midpoint(const Point& a, const Point& b) {
  return {0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1], 0.5 * a[2] + 0.5 * b[2]};
}

Point circumcenter_offset(const Point& a, const Point& b, const Point& c, const Point& d) {
  double L = 0, den = 0;
  const Point x = circumcenter_offset_float(a, b, c, d, L, den);
  // The bound of construct.hpp, with |D| >= |D~| / 2 (guaranteed by the proviso, asked
  // with a factor 2 to spare: 12 (9u) L^3 < |D~| / 4).
  const double ad = std::fabs(den);
  if (12 * 9 * kU * L * L * L < ad / 4 &&
      accurate(x, [](double R, double L, double ad) {
        return 13 * kU * (6 * L * L * L * L + 12 * R * L * L * L) / (ad / 2) + kU * R;
      }, L, ad))
    return x;
  if (exact::orient3d(a, b, c, d) == Sign::Zero) return x;  // precondition broken: as is
  return rounded_offset(exact::circumcenter(a, b, c, d), a);
}

Point circumcenter(const Point& a, const Point& b, const Point& c, const Point& d) {
  return add(a, circumcenter_offset(a, b, c, d));
}

double circumradius2(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point x = circumcenter_offset(a, b, c, d);
  return dot(x, x);
}

Point triangle_circumcenter_offset(const Point& a, const Point& b, const Point& c) {
  double L = 0, nn = 0;
  const Point x = triangle_offset_float(a, b, c, L, nn);
  // The bound of construct.hpp with 8 A^2 = 2 |n|^2 >= |n~|^2 / 2, guaranteed when the
  // error of n~ (at most 3u L^2 a component) is below |n~| / 4: 24 u L^2 < |n~|.
  if (24 * kU * L * L < std::sqrt(nn) &&
      accurate(x, [](double R, double L, double nn) {
        const double l4 = L * L * L * L;
        return 15 * kU * (8 * l4 * L + 24 * R * l4) / (nn / 2) + kU * R;
      }, L, nn))
    return x;
  if (collinear(a, b, c)) return x;  // precondition broken: as is
  return rounded_offset(exact::triangle_circumcenter(a, b, c), a);
}

Point triangle_circumcenter(const Point& a, const Point& b, const Point& c) {
  return add(a, triangle_circumcenter_offset(a, b, c));
}

double triangle_circumradius2(const Point& a, const Point& b, const Point& c) {
  const Point x = triangle_circumcenter_offset(a, b, c);
  return dot(x, x);
}

}  // namespace pdr::construct
