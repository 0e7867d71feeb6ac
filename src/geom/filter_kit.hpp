// The floating-point filters of the mesher's measures (encroachment and size tests; paper
// §1.1, §2.1, Lemma 1), in one place with the pieces they share. Each filter evaluates a
// polynomial in double together with a bound on its rounding error and returns its sign
// when the value is farther from 0 than the bound, else Unsure; the caller then decides
// with GMP rationals. The predicates' own stage-1 filters are in filter.hpp.
//
// Error bound (the argument of filter.hpp). For a straight-line program, count along every
// path from a leaf to the root the roundings met: a rounded leaf difference counts 1, a
// product counts the counts of its two operands plus 1, a sum the larger of its operands'
// counts plus 1 (an operation that cannot round, such as negation, 0 + x, or a product by
// a power of two, counts 0). If K bounds the count of every path, the computed value
// differs from the exact one by at most gamma_K = K u / (1 - K u) times the same program
// evaluated on absolute values (Higham, Accuracy and Stability of Numerical Algorithms,
// Lemma 3.1 and §3.1), u = 2^-53. The absolute program is computed in double with the same
// tree, so its computed value P satisfies P >= (1 - u)^K P_exact, and the computed bound
// (K + 1) u P (one more rounding) exceeds gamma_K P_exact whenever (K + 1)(2K + 1) u <= 1:
// a filter with coefficient (K + 1) u never answers wrongly.
// Range: the argument assumes no underflow and no overflow. Every filter here requires
// each coordinate difference (and each length bound d) to be 0 or in [2^-150, 2^150]
// (entry_in_range); its polynomials have degree at most 6 in them, so every nonzero
// product lies in [2^-900, 2^900] and a sum that cancels below 2^-1022 is exact.
// Tests: tests/geom/filter_kit_test.cpp drives each filter to its bound (inputs rounded off
// a sphere or a threshold) and compares every answer with GMP.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "geom/filter.hpp"
#include "geom/point.hpp"

namespace pdr::filter {

// A filter's precondition on a coordinate difference or a length: 0 or in [2^-150, 2^150].
inline bool entry_in_range(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m >= 0x1p-150 && m <= 0x1p150);
}
inline bool entry_in_range(const Point& x) {
  return entry_in_range(x[0]) && entry_in_range(x[1]) && entry_in_range(x[2]);
}

// The sign of a value whose error is at most `bound`; Unsure when |value| <= bound.
inline Filtered sign_beyond(double value, double bound) {
  if (value > bound) return Filtered::Positive;
  if (value < -bound) return Filtered::Negative;
  return Filtered::Unsure;
}

// Vector pieces. Counts: sub 1 (from exact inputs); cross of operands with counts i, j:
// i + j + 2; dot: i + j + 3 (the products, then two sums, left to right).
inline Point sub(const Point& p, const Point& q) {
  return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline Point cross(const Point& p, const Point& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
inline double dot(const Point& p, const Point& q) {
  return (p[0] * q[0] + p[1] * q[1]) + p[2] * q[2];
}
// The absolute programs of cross and dot: every product's absolute value, every - a +.
inline Point cross_abs(const Point& p, const Point& q) {
  const Point a{std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])};
  const Point b{std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2])};
  return {a[1] * b[2] + a[2] * b[1], a[2] * b[0] + a[0] * b[2], a[0] * b[1] + a[1] * b[0]};
}
inline double dot_abs(const Point& p, const Point& q) {
  return (std::fabs(p[0] * q[0]) + std::fabs(p[1] * q[1])) + std::fabs(p[2] * q[2]);
}

// Diametral ball (paper §1.1): the sign of -(p - a).(p - b), Positive iff p is strictly
// inside the ball with diameter ab. e = p - a, f = p - b: count 1; products 3; two sums:
// K = 5, coefficient 6u.
inline Filtered in_diametral_ball(const Point& a, const Point& b, const Point& p) {
  const Point e = sub(p, a), f = sub(p, b);
  if (!entry_in_range(e) || !entry_in_range(f)) return Filtered::Unsure;
  return sign_beyond(-dot(e, f), 6 * unit_roundoff * dot_abs(e, f));
}

// Equatorial ball (paper §1.1): the sign of w.X - N |w|^2 with u = b - a, v = c - a,
// w = p - a, n = u x v, N = n.n, X = |u|^2 (v x n) + |v|^2 (n x u) (encroach.hpp).
// Counts: u, v, w 1; n 4; v x n and n x u 7; |u|^2, |v|^2, |w|^2 5; X_i = products 13, sum
// 14; w.X: products 16, sums 18; N: 11; N |w|^2: 17; the difference: K = 19, coefficient
// 20u. (The comment this replaces counted 11 and used 16u: too small.)
inline Filtered in_equatorial_ball(const Point& a, const Point& b, const Point& c,
                                   const Point& p) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(p, a);
  if (!entry_in_range(u) || !entry_in_range(v) || !entry_in_range(w)) return Filtered::Unsure;
  const Point n = cross(u, v), vn = cross(v, n), nu = cross(n, u);
  const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w), n2 = dot(n, n);
  Point x;
  for (int i = 0; i < 3; ++i) x[i] = lu * vn[i] + lv * nu[i];
  const double value = dot(w, x) - n2 * lw;
  const Point na = cross_abs(u, v), vna = cross_abs(v, na), nua = cross_abs(na, u);
  Point xa;
  for (int i = 0; i < 3; ++i) xa[i] = lu * vna[i] + lv * nua[i];
  const double bar = dot_abs(w, xa) + dot(na, na) * lw;
  return sign_beyond(value, 20 * unit_roundoff * bar);
}

// |b - a|^2 - k d^2 for a small integer k > 0 (exact in double). Counts: e 1, e_i^2 3,
// the running sum from 0 (0 + x is exact) 5; k d^2: 2; the difference: K = 6, coefficient
// 7u. Positive / Zero-or-Negative decide ">= k d^2" only when certain.
inline Filtered length2_minus(const Point& a, const Point& b, double d, double k) {
  const Point e = sub(b, a);
  if (!entry_in_range(e) || !entry_in_range(d)) return Filtered::Unsure;
  const double lhs = (e[0] * e[0] + e[1] * e[1]) + e[2] * e[2];
  const double rhs = k * d * d;
  return sign_beyond(lhs - rhs, 7 * unit_roundoff * (lhs + rhs));
}

// |u|^2 |v|^2 |w|^2 - 4 k d^2 |u x v|^2 with u = b - a, v = c - a, w = b - c: the sign of
// R(abc)^2 - k d^2 for a proper triangle (R^2 = |u|^2 |v|^2 |w|^2 / (4 |u x v|^2)).
// Counts: dots 5; |u|^2 |v|^2 11, times |w|^2 17; n = u x v 4, n.n 11; 4 k d d: 4k exact
// (k a small integer), then 2; times n.n 14; the difference: K = 18, coefficient 19u.
// (The comment this replaces counted 9 and used 16u: too small.)
inline Filtered circumradius2_minus(const Point& a, const Point& b, const Point& c, double d,
                                    double k) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(b, c);
  if (!entry_in_range(u) || !entry_in_range(v) || !entry_in_range(w) || !entry_in_range(d))
    return Filtered::Unsure;
  const double lhs = dot(u, u) * dot(v, v) * dot(w, w);
  const double scale = 4 * k * d * d;
  const Point na = cross_abs(u, v);
  const Point n = cross(u, v);
  const double value = lhs - scale * dot(n, n);
  const double bar = lhs + scale * dot(na, na);
  return sign_beyond(value, 19 * unit_roundoff * bar);
}

// (p - o).(q - o) (paper §1.1 angles between related components: the sign of a cosine).
// Counts: differences 1, products 3, the running sum from 0 (0 + x is exact) 5: K = 5,
// coefficient 6u. In range a nonzero product is at least 2^-300, so a zero absolute sum
// means every product is exactly zero: Zero is then certain.
inline Filtered dot3(const Point& o, const Point& p, const Point& q) {
  const Point e = sub(p, o), f = sub(q, o);
  if (!entry_in_range(e) || !entry_in_range(f)) return Filtered::Unsure;
  const double abs = dot_abs(e, f);
  if (abs == 0) return Filtered::Zero;
  return sign_beyond(dot(e, f), 6 * unit_roundoff * abs);
}

// orient3d(a, b, c, o) for a point o known as a double approximation `od` with
// |o_k - od_k| <= err per coordinate (a rational point rounded, domain/exact.hpp). The
// determinant n.(o - a), n = (b - a) x (c - a), is linear in o, so
//   |D(o) - D_fl(od)| <= |D(od) - D_fl(od)| + |n_exact|_1 err.
// Rounding: differences 1, n 4, n_k w_k 6, two sums: K = 8, coefficient 9u on the absolute
// program. |n_exact|_1 <= |n_fl|_1 + gamma_4 |n|_abs (n's own rounding, which matters when
// n cancels), bounded by (|n_fl|_1 + 5u |n|_abs); the factor 1 + 2^-6 covers the few
// roundings of computing that term and the bound itself.
inline Filtered orient3d_near(const Point& a, const Point& b, const Point& c, const Point& od,
                              double err) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(od, a);
  if (!entry_in_range(u) || !entry_in_range(v) || !entry_in_range(w) || !entry_in_range(err))
    return Filtered::Unsure;
  const Point n = cross(u, v), na = cross_abs(u, v);
  const double det = dot(n, w);
  const double perm = (na[0] * std::fabs(w[0]) + na[1] * std::fabs(w[1])) +
                      na[2] * std::fabs(w[2]);
  const double grad = (std::fabs(n[0]) + std::fabs(n[1])) + std::fabs(n[2]) +
                      5 * unit_roundoff * ((na[0] + na[1]) + na[2]);
  return sign_beyond(det, 9 * unit_roundoff * perm + (1 + 0x1p-6) * grad * err);
}

// orient2d of the projections keeping coordinates i, j of a, b and a point o known as `od`
// within err per coordinate (as above): D = ux wy - uy wx with u = b - a, w = o - a, linear
// in o with gradient (-uy, ux). Rounding: differences 1, products 3, difference 4: K = 4,
// coefficient 5u. |u_exact|_1 <= (1 + u) |u_fl|_1; the factor 1 + 2^-6 covers it and the
// bound's own roundings.
inline Filtered orient2d_near(int i, int j, const Point& a, const Point& b, const Point& od,
                              double err) {
  const double ux = b[i] - a[i], uy = b[j] - a[j];
  const double wx = od[i] - a[i], wy = od[j] - a[j];
  if (!entry_in_range(ux) || !entry_in_range(uy) || !entry_in_range(wx) ||
      !entry_in_range(wy) || !entry_in_range(err))
    return Filtered::Unsure;
  const double l = ux * wy, r = uy * wx;
  const double perm = std::fabs(l) + std::fabs(r);
  return sign_beyond(l - r, 5 * unit_roundoff * perm +
                                (1 + 0x1p-6) * (std::fabs(ux) + std::fabs(uy)) * err);
}

// Brackets. Some measures are compared as products of squares (the tet tests below), whose
// degree in the coordinate differences is too high for the one-program argument within the
// range above. A Bracket carries a closed interval around a nonnegative real through
// products and sums, each rounded operation widened on its own, underflow and overflow
// included: for the computed result r of one rounded operation on nonnegative operands whose
// exact result is t, either r >= 2^-1000, then no underflow occurred, r = t (1 + delta) with
// |delta| <= u, and r (1 - 4u) <= t <= r (1 + 4u) even after rounding those products; or
// r < 2^-1000, then 0 <= t < 2^-999. An overflowed bound is infinite (or NaN from inf * 0);
// callers treat a non-finite bound as unsure.
struct Bracket {
  double lo, hi;
};
inline constexpr double kBracketTiny = 0x1p-1000;
inline double round_down(double r) { return r < kBracketTiny ? 0 : r * (1 - 4 * unit_roundoff); }
inline double round_up(double r) {
  return r < kBracketTiny ? 2 * kBracketTiny : r * (1 + 4 * unit_roundoff);
}
// The exact nonnegative value x.
inline Bracket exactly(double x) { return {x, x}; }
// |t| for a real t known as x with |t - x| <= err (err >= 0).
inline Bracket magnitude_within(double x, double err) {
  const double a = std::fabs(x);
  return {a > err ? round_down(a - err) : 0, round_up(a + err)};
}
inline Bracket operator*(Bracket p, Bracket q) {
  return {round_down(p.lo * q.lo), round_up(p.hi * q.hi)};
}
inline Bracket operator+(Bracket p, Bracket q) {
  return {round_down(p.lo + q.lo), round_up(p.hi + q.hi)};
}
// Positive when every value of p exceeds every value of q, Negative when every value of p
// is below every value of q; Unsure when they overlap or a bound is not finite.
inline Filtered compare(Bracket p, Bracket q) {
  if (!std::isfinite(p.hi) || !std::isfinite(q.hi)) return Filtered::Unsure;
  if (p.lo > q.hi) return Filtered::Positive;
  if (p.hi < q.lo) return Filtered::Negative;
  return Filtered::Unsure;
}

// The circumsphere of a tet (paper §1.1, radius-edge ratio): with u = b - a, v = c - a,
// w = d - a, D = u.(v x w) and X = |u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v), the
// circumcenter is a + X / (2D) and R^2 = |X|^2 / (4 D^2).
// Counts: u, v, w 1; the crosses 4; |.|^2 5; the products 10; X_i's two sums: K = 12,
// coefficient 13u. D: products 1 + 4 + 1 = 6, two sums: K = 8, coefficient 9u. Each
// component then enters a Bracket (magnitude_within), squared and summed there. Range: the
// differences as entry_in_range (X has degree 4, D degree 3). nullopt when out of range or
// when D's sign is not certain (a flat or nearly flat tet: GMP decides).
struct TetMeasures {
  Bracket x2, d2;  // |X|^2 and D^2
};
inline std::optional<TetMeasures> tet_measures(const Point& a, const Point& b, const Point& c,
                                               const Point& d) {
  const Point u = sub(b, a), v = sub(c, a), w = sub(d, a);
  if (!entry_in_range(u) || !entry_in_range(v) || !entry_in_range(w)) return std::nullopt;
  const Point vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const Point vwa = cross_abs(v, w), wua = cross_abs(w, u), uva = cross_abs(u, v);
  const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w);
  const double det = dot(u, vw), det_abs = dot_abs(u, vwa);
  const Bracket dm = magnitude_within(det, 9 * unit_roundoff * det_abs);
  if (dm.lo == 0) return std::nullopt;
  TetMeasures m{{0, 0}, dm * dm};
  for (int i = 0; i < 3; ++i) {
    const double x = (lu * vw[i] + lv * wu[i]) + lw * uv[i];
    const double xa = (lu * vwa[i] + lv * wua[i]) + lw * uva[i];
    const Bracket xm = magnitude_within(x, 13 * unit_roundoff * xa);
    m.x2 = m.x2 + xm * xm;
  }
  return m;
}

// The squared length of a tet's shortest edge. Each |e|^2: differences 1, squares 3, two
// sums: K = 5, coefficient 6u (the absolute program is the value itself). The minimum of
// the six lies between the minima of the lower and of the upper ends.
inline std::optional<Bracket> shortest_edge2(const Point& a, const Point& b, const Point& c,
                                            const Point& d) {
  const Point* p[4] = {&a, &b, &c, &d};
  Bracket best{INFINITY, INFINITY};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Point e = sub(*p[i], *p[j]);
      if (!entry_in_range(e)) return std::nullopt;
      const double l2 = dot(e, e);
      const Bracket l = magnitude_within(l2, 6 * unit_roundoff * l2);
      best = {std::min(best.lo, l.lo), std::min(best.hi, l.hi)};
    }
  return best;
}

// The tet tests of the refinement loop (paper §3, Fig. 2), for a tet with D != 0:
//   R^2 - B^2 lmin^2:  |X|^2 against 4 B^2 lmin^2 D^2
//   R^2 - L^2:         |X|^2 against 4 L^2 D^2
//   6 vol - 6V:        D^2 against (6V)^2
// B, L, V: any positive doubles (the Brackets absorb their rounding and range).
inline Filtered ratio_minus(const TetMeasures& m, Bracket lmin2, double bound) {
  const Bracket b{bound, bound};
  return compare(m.x2, exactly(4) * b * b * lmin2 * m.d2);
}
inline Filtered radius_minus(const TetMeasures& m, double size) {
  const Bracket l{size, size};
  return compare(m.x2, exactly(4) * l * l * m.d2);
}
inline Filtered volume_minus(const TetMeasures& m, double max_volume) {
  const Bracket v6 = exactly(6) * exactly(max_volume);
  return compare(m.d2, v6 * v6);
}

// The facet chart (surface/chart.hpp): with e1 = t1 - t0, e2 = t2 - t0, a point q seen from
// d has the chart coordinates x = e1.(q - d), y = e2.(q - d) and the lift difference
// w = sum_k (q_k - d_k)((q_k - t0_k) + (d_k - t0_k)) = |q - t0|^2 - |d - t0|^2.
// Counts: x, y: differences 1, products 3, two sums: 5; w: the factors 1 and 2, products 4,
// two sums: 6.
struct ChartRow {
  double x, y, w, xa, ya, wa;  // the values and their absolute programs
};
inline ChartRow chart_row(const Point& e1, const Point& e2, const Point& t0, const Point& q,
                          const Point& d) {
  const Point e = sub(q, d), sq = sub(q, t0), sd = sub(d, t0);
  const Point s{sq[0] + sd[0], sq[1] + sd[1], sq[2] + sd[2]};
  const Point sa{std::fabs(sq[0]) + std::fabs(sd[0]), std::fabs(sq[1]) + std::fabs(sd[1]),
                 std::fabs(sq[2]) + std::fabs(sd[2])};
  const Point ea{std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])};
  return {dot(e1, e), dot(e2, e), dot(e, s), dot_abs(e1, e), dot_abs(e2, e), dot(ea, sa)};
}
inline bool chart_row_in_range(const Point& t0, const Point& q, const Point& d) {
  return entry_in_range(sub(q, d)) && entry_in_range(sub(q, t0)) && entry_in_range(sub(d, t0));
}

// The chart orientation of a, b, c: det [e1.(b - a) e1.(c - a); e2.(b - a) e2.(c - a)].
// Counts: entries 5, products 11, the difference: K = 12, coefficient 13u.
inline Filtered chart_orient(const Point& t0, const Point& t1, const Point& t2, const Point& a,
                             const Point& b, const Point& c) {
  const Point e1 = sub(t1, t0), e2 = sub(t2, t0), u = sub(b, a), v = sub(c, a);
  if (!entry_in_range(e1) || !entry_in_range(e2) || !entry_in_range(u) || !entry_in_range(v))
    return Filtered::Unsure;
  const double xb = dot(e1, u), xc = dot(e1, v), yb = dot(e2, u), yc = dot(e2, v);
  const double bar = dot_abs(e1, u) * dot_abs(e2, v) + dot_abs(e1, v) * dot_abs(e2, u);
  return sign_beyond(xb * yc - xc * yb, 13 * unit_roundoff * bar);
}

// The chart in-circle determinant (surface/chart.hpp): rows (x, y, w) of a, b, c seen from d,
//   x_a (y_b w_c - y_c w_b) + x_b (y_c w_a - y_a w_c) + x_c (y_a w_b - y_b w_a).
// Counts: y w 5 + 6 + 1 = 12, the difference 13, times x 19, two sums: K = 21, coefficient
// 22u. Degree 6 in the differences.
inline Filtered chart_incircle(const Point& t0, const Point& t1, const Point& t2,
                               const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point e1 = sub(t1, t0), e2 = sub(t2, t0);
  if (!entry_in_range(e1) || !entry_in_range(e2) || !chart_row_in_range(t0, a, d) ||
      !chart_row_in_range(t0, b, d) || !chart_row_in_range(t0, c, d))
    return Filtered::Unsure;
  const ChartRow ra = chart_row(e1, e2, t0, a, d), rb = chart_row(e1, e2, t0, b, d),
                 rc = chart_row(e1, e2, t0, c, d);
  const double det = (ra.x * (rb.y * rc.w - rc.y * rb.w) + rb.x * (rc.y * ra.w - ra.y * rc.w)) +
                     rc.x * (ra.y * rb.w - rb.y * ra.w);
  const double bar = (ra.xa * (rb.ya * rc.wa + rc.ya * rb.wa) +
                      rb.xa * (rc.ya * ra.wa + ra.ya * rc.wa)) +
                     rc.xa * (ra.ya * rb.wa + rb.ya * ra.wa);
  return sign_beyond(det, 22 * unit_roundoff * bar);
}

// Which of two triangles has the larger circumradius (Fig. 2's "largest encroached
// subfacet"): R^2 = |ab|^2 |bc|^2 |ca|^2 / (4 |ab x ac|^2), so R1^2 - R2^2 has the sign of
// L1 N2 - L2 N1, L the product of the squared edge lengths, N = |ab x ac|^2. Counts: each
// |e|^2 K = 5 (coefficient 6u, its own absolute value); a cross component K = 3
// (coefficient 4u of the absolute program). Both enter Brackets and the products are
// carried there (degree 10: beyond double's range a bound is infinite, hence Unsure).
// Range: the edges as entry_in_range. Unsure when a triangle may be flat (N's lower end
// 0) or the brackets overlap (equal radii among them): GMP decides.
inline Filtered circumradius_compare(const Point& a, const Point& b, const Point& c,
                                     const Point& d, const Point& e, const Point& f) {
  struct Parts {
    Bracket l, n;
  };
  const auto parts = [](const Point& p, const Point& q, const Point& r) -> std::optional<Parts> {
    const Point u = sub(q, p), v = sub(r, p), w = sub(r, q);
    if (!entry_in_range(u) || !entry_in_range(v) || !entry_in_range(w)) return std::nullopt;
    const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w);
    const double k = 6 * unit_roundoff;
    Parts out{magnitude_within(lu, k * lu) * magnitude_within(lv, k * lv) *
                  magnitude_within(lw, k * lw),
              {0, 0}};
    const Point n = cross(u, v), na = cross_abs(u, v);
    for (int i = 0; i < 3; ++i) {
      const Bracket m = magnitude_within(n[i], 4 * unit_roundoff * na[i]);
      out.n = out.n + m * m;
    }
    if (out.n.lo == 0) return std::nullopt;
    return out;
  };
  const auto x = parts(a, b, c), y = parts(d, e, f);
  if (!x || !y) return Filtered::Unsure;
  return compare(x->l * y->n, y->l * x->n);
}

}  // namespace pdr::filter
