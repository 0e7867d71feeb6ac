// Exact helpers for the domain analysis (paper §1.1); see domain/exact.hpp.
#include "domain/exact.hpp"

#include <algorithm>
#include <cmath>

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

// Filters. For a determinant D that is linear in o, D(o) = D(d) + g.(o - d) with g its
// gradient in o, so |D(o) - D_fl(d)| <= |D(d) - D_fl(d)| + |g|_1 err. The rounding part is
// below 16u times the permanent (a few roundings per term, Higham's gamma_k, k <= 10),
// taken as 1e-14 * permanent; |g|_1 is computed from rounded differences, so it is
// enlarged by 1%. Tiny or huge magnitudes (possible underflow, overflow) go exact.
Sign orient3d_rat(const Point& a, const Point& b, const Point& c, const RatPoint& o) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = o.d[0] - a[0], wy = o.d[1] - a[1], wz = o.d[2] - a[2];
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double det = nx * wx + ny * wy + nz * wz;
  const double perm = (std::fabs(uy * vz) + std::fabs(uz * vy)) * std::fabs(wx) +
                      (std::fabs(uz * vx) + std::fabs(ux * vz)) * std::fabs(wy) +
                      (std::fabs(ux * vy) + std::fabs(uy * vx)) * std::fabs(wz);
  const double grad = std::fabs(nx) + std::fabs(ny) + std::fabs(nz);
  const double bound = 1e-14 * perm + 1.01 * grad * o.err;
  if (std::isfinite(bound) && perm > 1e-250) {
    if (det > bound) return Sign::Positive;
    if (det < -bound) return Sign::Negative;
  }
  return orient3d_q(to_q(a), to_q(b), to_q(c), o.q);
}

Sign orient2d_rat(int drop, const Point& a, const Point& b, const RatPoint& o) {
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  const double ux = b[i] - a[i], uy = b[j] - a[j];
  const double wx = o.d[i] - a[i], wy = o.d[j] - a[j];
  const double det = ux * wy - uy * wx;
  const double perm = std::fabs(ux * wy) + std::fabs(uy * wx);
  const double bound = 1e-14 * perm + 1.01 * (std::fabs(ux) + std::fabs(uy)) * o.err;
  if (std::isfinite(bound) && perm > 1e-250) {
    if (det > bound) return Sign::Positive;
    if (det < -bound) return Sign::Negative;
  }
  const mpq_class qux = qdiff(b[i], a[i]), quy = qdiff(b[j], a[j]);
  const mpq_class qwx = o.q[i] - mpq_class(a[i]), qwy = o.q[j] - mpq_class(a[j]);
  return sign_of(sgn(mpq_class(qux * qwy - quy * qwx)));
}

}  // namespace pdr::domain
