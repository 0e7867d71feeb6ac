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

#include <cmath>

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

}  // namespace pdr::filter
