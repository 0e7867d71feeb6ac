// Exact helpers for the domain analysis (paper §1.1); see domain/exact.hpp.
#include "domain/exact.hpp"

#include <algorithm>
#include <cmath>

#include "geom/filter_kit.hpp"
#include "geom/predicates.hpp"
#include "geom/stage2.hpp"

namespace pdr::domain {

Sign orient2d(const P2& a, const P2& b, const P2& c) {
  return pdr::orient2d(a.data(), b.data(), c.data());
}

Sign orient2d_dropping(int drop, const Point& a, const Point& b, const Point& c) {
  const Projection pr{drop, false};
  return orient2d(pr(a), pr(b), pr(c));
}

int nondegenerate_drop(const Point& a, const Point& b, const Point& c) {
  return stage2::plane_axis(a, b, c);
}

bool collinear(const Point& a, const Point& b, const Point& c) {
  for (int k = 0; k < 3; ++k)
    if (orient2d_dropping(k, a, b, c) != Sign::Zero) return false;
  return true;
}

bool strictly_between(const Point& a, const Point& b, const Point& c) {
  for (int k = 0; k < 3; ++k) {
    if (a[k] == b[k]) continue;
    const double lo = std::min(a[k], b[k]), hi = std::max(a[k], b[k]);
    return lo < c[k] && c[k] < hi;
  }
  return false;
}

bool on_closed_segment(const P2& a, const P2& b, const P2& c) {
  return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= c[1] && c[1] <= std::max(a[1], b[1]);
}

namespace {

mpq_class qdiff(double x, double y) { return mpq_class(x) - mpq_class(y); }

}  // namespace

Sign dot_sign(const Point& o, const Point& a, const Point& b) {
  const Filtered f = filter::dot3(o, a, b);  // geom/filter_kit.hpp: K = 5
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
  mpq_class s = 0;
  for (int k = 0; k < 3; ++k) s += qdiff(a[k], o[k]) * qdiff(b[k], o[k]);
  return sign_of(sgn(s));
}

Sign dihedral_cos_sign(const Point& p, const Point& q, const Point& a, const Point& b) {
  std::array<mpq_class, 3> u, x, y;
  for (int k = 0; k < 3; ++k) {
    u[k] = qdiff(q[k], p[k]);
    x[k] = qdiff(a[k], p[k]);
    y[k] = qdiff(b[k], p[k]);
  }
  auto dot = [](const std::array<mpq_class, 3>& s, const std::array<mpq_class, 3>& t) {
    mpq_class r = s[0] * t[0];
    r += s[1] * t[1];
    r += s[2] * t[2];
    return r;
  };
  const mpq_class v = dot(u, u) * dot(x, y) - dot(u, x) * dot(u, y);
  return sign_of(sgn(v));
}

QPoint to_q(const Point& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

Sign orient3d_q(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  const mpq_class bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const mpq_class cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const mpq_class dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  const mpq_class det =
      bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
  return sign_of(sgn(det));
}

RatPoint make_rat(const QPoint& q) {
  RatPoint r;
  r.q = q;
  double m = 0;
  for (int k = 0; k < 3; ++k) {
    r.d[k] = q[k].get_d();  // truncates: |q - d| < ulp(d) <= 2^-52 |d| (or a subnormal)
    m = std::max(m, std::fabs(r.d[k]));
  }
  r.err = 0x1p-51 * m + 0x1p-1000;
  return r;
}

RatPoint make_rat(const Point& p) { return {to_q(p), p, 0}; }

// Filters: geom/filter_kit.hpp's orient3d_near and orient2d_near (a determinant linear in
// o, evaluated at o's double approximation, with o's error carried by the gradient).
Sign orient3d_rat(const Point& a, const Point& b, const Point& c, const RatPoint& o) {
  const Filtered f = filter::orient3d_near(a, b, c, o.d, o.err);
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
  return orient3d_q(to_q(a), to_q(b), to_q(c), o.q);
}

Sign orient2d_rat(int drop, const Point& a, const Point& b, const RatPoint& o) {
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  const Filtered f = filter::orient2d_near(i, j, a, b, o.d, o.err);
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
  const mpq_class qux = qdiff(b[i], a[i]), quy = qdiff(b[j], a[j]);
  const mpq_class qwx = o.q[i] - mpq_class(a[i]), qwy = o.q[j] - mpq_class(a[j]);
  return sign_of(sgn(mpq_class(qux * qwy - quy * qwx)));
}

}  // namespace pdr::domain
