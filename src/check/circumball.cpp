// Interval enclosures of circumballs (see circumball.hpp for the argument).
#include "check/circumball.hpp"

#include <gmpxx.h>

#include <cmath>
#include <optional>

#include "check/qvec.hpp"
#include "geom/exact.hpp"

namespace pdr::check {
namespace {

Interval enclose(const mpq_class& q) {
  const double d = q.get_d();  // truncated toward zero
  if (!std::isfinite(d) || std::fabs(d) >= 0x1p1000) return Interval::whole();
  return {interval_detail::down(d), interval_detail::up(d)};
}

using namespace qvec;

}  // namespace

namespace detail {

// Proof of circumball_bounded (the notation of interval.hpp's squared_distance: u = 2^-53,
// the standard model fl(x op y) = (x op y)(1 + e), |e| <= u, for a normal result; a product
// that is subnormal is (x y) + g, |g| <= 2^-1075; sums and differences that are subnormal
// are exact).
//
// With U = b - a, V = c - a, W = d - a exactly, the circumcentre is a + N / (2 D) where
// N = |U|^2 (V x W) + |V|^2 (W x U) + |W|^2 (U x V) and D = U . (V x W), each component of N
// a sum of monomials of degree 4 in the coordinates of U, V, W, and D one of degree 3.
// Computed: u_i = fl(b_i - a_i) = U_i (1 + e), likewise v, w; the guard below admits only
// coordinates 0 or of magnitude in [2^-250, 2^250].
//   - Every product of two of them is 0 or in [2^-500, 2^500], normal. A cross component
//     fl(p - q) of two such products is 0 or at least 2^-552 (p and q are multiples of
//     2^-552), and |u|^2 = fl(fl(u0 u0 + u1 u1) + u2 u2) is 0 or at least 2^-500. So
//     fl(|u|^2 x) may be subnormal (one g, at most 2^-1075), and fl(u_i x) is normal (at
//     least 2^-802). Nothing exceeds 2^1006: no overflow.
//   - Each monomial of N reaches the computed value through at most 12 rounding factors
//     (4 input differences; |u|^2: a product and two sums; the cross component: a product
//     and a difference; the product |u|^2 x; the sum of three terms: two), so
//     |fl(N_i) - N_i| <= gamma_12 S + 3 (1 + u)^2 2^-1075, S the sum of the monomials'
//     absolute values, gamma_k = k u / (1 - k u). Each monomial of D: at most 8 (3 inputs,
//     the cross component's 2, the product, the two sums): |fl(D) - D| <= gamma_8 S_D.
//   - The same sums with absolute values (P below, PD), computed on the rounded
//     coordinates, add nonnegative normal terms (a nonzero term is at least 2^-1000, by the
//     bounds above): P >= S_rounded (1 - u)^8 and S <= S_rounded (1 - u)^-4, so
//     S <= P (1 - u)^-12; likewise S_D <= PD (1 - u)^-8.
//   - A g arises only from a nonzero |u|^2 x, and then P holds the term |u|^2 (|p| + |q|)
//     >= 2^-1000 (1 - u)^2, so 3 (1 + u)^2 2^-1075 < 2^-73 P.
// Hence |fl(N_i) - N_i| < (gamma_12 (1 - u)^-12 + 2^-73) P < 16 u P = 2^-49 P, and
// |fl(D) - D| < 2^-49 PD: the errors E below, rounded up (interval_detail::up), enclose
// them. Where D's enclosure keeps its sign, N / (2 D) is enclosed by interval division, and
// the centre and the squared radius |N / (2 D)|^2 by interval arithmetic. Any guard failed,
// or anything not finite: nullopt (circumball() then evaluates every step as an interval).
std::optional<BallEnclosure> circumball_bounded(const Point& a, const Point& b, const Point& c,
                                                const Point& d) {
  using interval_detail::make, interval_detail::up;
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
  for (const double* x : {u, v, w})
    for (int i = 0; i < 3; ++i) {
      const double m = std::fabs(x[i]);
      if (m != 0 && !(m >= 0x1p-250 && m <= 0x1p250)) return std::nullopt;  // NaN too
    }
  // X = v x w, Y = w x u, Z = u x v, and their absolute sums.
  const double X[3] = {v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0]};
  const double Y[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
  const double Z[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const auto abs_cross = [](const double* p, const double* q, double* out) {
    out[0] = std::fabs(p[1] * q[2]) + std::fabs(p[2] * q[1]);
    out[1] = std::fabs(p[2] * q[0]) + std::fabs(p[0] * q[2]);
    out[2] = std::fabs(p[0] * q[1]) + std::fabs(p[1] * q[0]);
  };
  double PX[3], PY[3], PZ[3];
  abs_cross(v, w, PX);
  abs_cross(w, u, PY);
  abs_cross(u, v, PZ);
  const double su = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const double sv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double sw = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const double D = u[0] * X[0] + u[1] * X[1] + u[2] * X[2];
  const double PD = std::fabs(u[0]) * PX[0] + std::fabs(u[1]) * PX[1] + std::fabs(u[2]) * PX[2];
  const double ED = up(0x1p-49 * PD);
  const Interval two_d = Interval(2) * make(D - ED, D + ED);
  if (!interval_sign(two_d)) return std::nullopt;
  IVec off;
  for (int i = 0; i < 3; ++i) {
    const double N = su * X[i] + sv * Y[i] + sw * Z[i];
    const double EN = up(0x1p-49 * (su * PX[i] + sv * PY[i] + sw * PZ[i]));
    off[static_cast<std::size_t>(i)] = make(N - EN, N + EN) / two_d;
    if (!off[static_cast<std::size_t>(i)].finite()) return std::nullopt;
  }
  BallEnclosure ball{ivec(a) + off, norm2(off)};
  for (const Interval& x : ball.center)
    if (!x.finite()) return std::nullopt;  // a huge |a|: the other evaluations
  if (!ball.r2.finite()) return std::nullopt;
  return ball;
}

}  // namespace detail

BallEnclosure circumball(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (const auto fast = detail::circumball_bounded(a, b, c, d)) return *fast;
  // c - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 det[u, v, w]).
  const IVec ia = ivec(a);
  const IVec u = ivec(b) - ia, v = ivec(c) - ia, w = ivec(d) - ia;
  const IVec vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const Interval det2 = Interval(2) * dot(u, vw);
  if (interval_sign(det2)) {
    const IVec num = norm2(u) * vw + norm2(v) * wu + norm2(w) * uv;
    const IVec off = {num[0] / det2, num[1] / det2, num[2] / det2};
    if (off[0].finite() && off[1].finite() && off[2].finite())
      return {ia + off, norm2(off)};
  }
  const auto x = exact::circumcenter(a, b, c, d);
  return {{enclose(x[0]), enclose(x[1]), enclose(x[2])}, enclose(exact::circumradius2(a, b, c, d))};
}

BallEnclosure diametral_ball(const Point& a, const Point& b) {
  const IVec ia = ivec(a), ib = ivec(b);
  const Interval half(0.5);
  const IVec center = half * (ia + ib);
  return {center, Interval(0.25) * norm2(ib - ia)};
}

BallEnclosure equatorial_ball(const Point& a, const Point& b, const Point& c) {
  // o - a = ((|u|^2 v - |v|^2 u) x n) / (2 |n|^2), n = u x v.
  const IVec ia = ivec(a);
  const IVec u = ivec(b) - ia, v = ivec(c) - ia;
  const IVec n = cross(u, v);
  const Interval nn2 = Interval(2) * norm2(n);
  if (nn2.lo > 0) {
    const IVec m = cross(norm2(u) * v - norm2(v) * u, n);
    const IVec off = {m[0] / nn2, m[1] / nn2, m[2] / nn2};
    if (off[0].finite() && off[1].finite() && off[2].finite())
      return {ia + off, norm2(off)};
  }
  const QVec qu = qdiff(b, a), qv = qdiff(c, a);
  const QVec qn = qcross(qu, qv);
  const Q den = 2 * qdot(qn, qn);
  if (sgn(den) == 0) return {{Interval::whole(), Interval::whole(), Interval::whole()}, Interval::whole()};
  const Q uu = qdot(qu, qu), vv = qdot(qv, qv);
  const QVec t = {uu * qv[0] - vv * qu[0], uu * qv[1] - vv * qu[1], uu * qv[2] - vv * qu[2]};
  QVec off = qcross(t, qn);
  for (Q& x : off) x /= den;
  return {{Interval(a[0]) + enclose(off[0]), Interval(a[1]) + enclose(off[1]),
           Interval(a[2]) + enclose(off[2])},
          enclose(qdot(off, off))};
}

Box enclosing_box(const BallEnclosure& ball) {
  const Interval r = sqrt(ball.r2);
  Box box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = (ball.center[i] - Interval(r.hi)).lo;
    box.hi[i] = (ball.center[i] + Interval(r.hi)).hi;
  }
  return box;
}

}  // namespace pdr::check
