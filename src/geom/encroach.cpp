// Encroachment predicates (paper §1.1): filters and GMP references; see encroach.hpp for
// the polynomials and the error argument. Compiled in pdr_geom with -ffp-contract=off; the
// bounds hold with or without contraction (a fused operation rounds once instead of twice).
#include "geom/encroach.hpp"

#include <cmath>

namespace pdr {
namespace {

using QVec = std::array<mpq_class, 3>;
constexpr double kUnit = 0x1p-53;

// The filter's precondition on a coordinate difference: 0 or in [2^-150, 2^150].
bool in_range(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m >= 0x1p-150 && m <= 0x1p150);
}
bool in_range(const Point& x) { return in_range(x[0]) && in_range(x[1]) && in_range(x[2]); }

Point sub(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
Point cross(const Point& p, const Point& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
// |p| x |q| with the products' absolute values summed: the absolute program of cross().
Point cross_abs(const Point& p, const Point& q) {
  const Point a{std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])};
  const Point b{std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2])};
  return {a[1] * b[2] + a[2] * b[1], a[2] * b[0] + a[0] * b[2], a[0] * b[1] + a[1] * b[0]};
}
double dot(const Point& p, const Point& q) { return (p[0] * q[0] + p[1] * q[1]) + p[2] * q[2]; }
double dot_abs(const Point& p, const Point& q) {
  return (std::fabs(p[0] * q[0]) + std::fabs(p[1] * q[1])) + std::fabs(p[2] * q[2]);
}

Sign decide(double value, double bound) {
  if (value > bound) return Sign::Positive;
  if (value < -bound) return Sign::Negative;
  return Sign::Zero;  // unsure: the caller falls back to GMP
}

QVec q_of(const Point& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }
QVec q_sub(const QVec& p, const QVec& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
QVec q_cross(const QVec& p, const QVec& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
mpq_class q_dot(const QVec& p, const QVec& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
Sign q_sign(const mpq_class& x) { return sign_of(sgn(x)); }

// X = |u|^2 (v x n) + |v|^2 (n x u) and N = |n|^2 for u = b - a, v = c - a (exact).
struct QCircum {
  QVec x;
  mpq_class n2;
};
QCircum q_circum(const Point& a, const Point& b, const Point& c) {
  const QVec qa = q_of(a);
  const QVec u = q_sub(q_of(b), qa), v = q_sub(q_of(c), qa);
  const QVec n = q_cross(u, v);
  const QVec vn = q_cross(v, n), nu = q_cross(n, u);
  const mpq_class lu = q_dot(u, u), lv = q_dot(v, v);
  QCircum r;
  for (int i = 0; i < 3; ++i) r.x[i] = lu * vn[i] + lv * nu[i];
  r.n2 = q_dot(n, n);
  return r;
}

}  // namespace

Sign in_diametral_ball(const Point& a, const Point& b, const Point& p) {
  const Point e = sub(p, a), f = sub(p, b);
  if (in_range(e) && in_range(f)) {
    // Depth 4 (difference, product, two sums): |error| <= gamma_4 * sum |e_k f_k|.
    const Sign s = decide(-dot(e, f), 8 * kUnit * dot_abs(e, f));
    if (s != Sign::Zero) return s;
  }
  return exact::in_diametral_ball(a, b, p);
}

Sign in_equatorial_ball(const Point& a, const Point& b, const Point& c, const Point& p) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(p, a);
  if (in_range(u) && in_range(v) && in_range(w)) {
    const Point n = cross(u, v), vn = cross(v, n), nu = cross(n, u);
    const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w), n2 = dot(n, n);
    Point x;
    for (int i = 0; i < 3; ++i) x[i] = lu * vn[i] + lv * nu[i];
    const double value = dot(w, x) - n2 * lw;
    // The absolute program: same operations on absolute values, + for every -.
    const Point na = cross_abs(u, v);
    const Point vna = cross_abs(v, na), nua = cross_abs(na, u);
    Point xa;
    for (int i = 0; i < 3; ++i) xa[i] = lu * vna[i] + lv * nua[i];
    const double bar = dot_abs(w, xa) + dot(na, na) * lw;
    // Depth 11: |error| <= gamma_11 * bar (<= 11.1u * bar as computed); margin to 16u.
    const Sign s = decide(value, 16 * kUnit * bar);
    if (s != Sign::Zero) return s;
  }
  return exact::in_equatorial_ball(a, b, c, p);
}

namespace exact {

std::array<mpq_class, 3> triangle_circumcenter(const Point& a, const Point& b, const Point& c) {
  const QCircum k = q_circum(a, b, c);
  std::array<mpq_class, 3> o;
  for (int i = 0; i < 3; ++i) o[i] = mpq_class(a[i]) + k.x[i] / (2 * k.n2);
  return o;
}

mpq_class triangle_circumradius2(const Point& a, const Point& b, const Point& c) {
  const QCircum k = q_circum(a, b, c);
  return q_dot(k.x, k.x) / (4 * k.n2 * k.n2);
}

Sign in_diametral_ball(const Point& a, const Point& b, const Point& p) {
  const QVec qp = q_of(p);
  return -q_sign(q_dot(q_sub(qp, q_of(a)), q_sub(qp, q_of(b))));
}

Sign in_equatorial_ball(const Point& a, const Point& b, const Point& c, const Point& p) {
  const QCircum k = q_circum(a, b, c);
  const QVec w = q_sub(q_of(p), q_of(a));
  return q_sign(q_dot(w, k.x) - k.n2 * q_dot(w, w));
}

}  // namespace exact
}  // namespace pdr
