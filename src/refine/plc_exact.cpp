// Exact helpers for the domain analysis (paper §1.1); see plc_exact.hpp.
#include "refine/plc_exact.hpp"

#include <cmath>

#include "geom/predicates.hpp"
#include "geom/stage2.hpp"

namespace pdr::refine {

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
  // Filter: each of the three terms reaches the sum through at most 5 roundings (two
  // differences, the product, two additions), so the error is below 6u * sum |term|
  // (Higham's gamma_5 < 6u); 1e-15 > 9u leaves a margin. Tiny magnitudes could underflow:
  // those take the exact path.
  double sum = 0, perm = 0;
  for (int k = 0; k < 3; ++k) {
    const double t = (a[k] - o[k]) * (b[k] - o[k]);
    sum += t;
    perm += std::fabs(t);
  }
  if (perm == 0) return Sign::Zero;
  if (perm > 1e-250 && std::isfinite(perm)) {
    const double bound = 1e-15 * perm;
    if (sum > bound) return Sign::Positive;
    if (sum < -bound) return Sign::Negative;
  }
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

}  // namespace pdr::refine
