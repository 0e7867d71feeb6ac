// Interval: closed floating-point intervals that provably enclose a real value.
//
// Used by the checkers' filters for the polynomials that have no hand-proven static error
// bound (circumballs, radius-edge ratios, equatorial spheres, dot products) and for every
// floating-point box that must contain an exact set (grid queries).
//
// Invariant and proof. Every operation is evaluated in IEEE-754 double with round-to-nearest
// and its result r is widened to (at least) [prev(r), next(r)], its neighbouring doubles.
// The exact result x of the operation on the (exact) endpoints rounds to r, so no double
// lies strictly between x and r; hence prev(r) <= x <= next(r). (Widening is done with
// interval_detail::down/up, which provably reach at least prev(r) and next(r).) Operations are monotone in
// each endpoint (multiplication takes the min/max of the four endpoint products), so the
// widened result encloses the exact result for every value in the operands. This holds for
// subnormal results too (rounding to nearest on the subnormal grid). Any non-finite endpoint
// (overflow, or inf - inf) makes the interval the whole line, whose sign is unknown; the
// checkers then fall back to exact rationals. Requires -ffp-contract=off (set on pdr_check):
// a fused multiply-add would still be enclosed, but the widening argument is per operation.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "geom/point.hpp"

namespace pdr::check {

struct Interval {
  double lo = 0, hi = 0;

  constexpr Interval() = default;
  constexpr Interval(double x) : lo(x), hi(x) {}  // NOLINT: exact doubles convert implicitly
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  static Interval whole() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {-inf, inf};
  }
  bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }
};

namespace interval_detail {
// Widening by delta(r) = |r| 2^-52 + 2^-1074 (both terms computed exactly or rounded up
// past |r| 2^-52: a sum of positives rounds to at least its larger term). For normal r,
// delta >= ulp(r) >= the gap to either neighbour of r; for tiny r, delta >= 2^-1074, the
// subnormal gap. So r - delta <= prev(r) exactly, and rounding it to nearest cannot go
// above prev(r), a double: down(r) <= prev(r) and likewise up(r) >= next(r). Cheaper than
// std::nextafter, at most a couple of ulps wider.
inline double delta(double r) { return std::fabs(r) * 0x1p-52 + 0x1p-1074; }
inline double down(double x) { return x - delta(x); }
inline double up(double x) { return x + delta(x); }
inline Interval make(double lo, double hi) {
  const double l = down(lo), h = up(hi);
  if (!(std::isfinite(l) && std::isfinite(h))) return Interval::whole();
  return {l, h};
}
}  // namespace interval_detail

inline Interval operator+(const Interval& a, const Interval& b) {
  if (!a.finite() || !b.finite()) return Interval::whole();
  return interval_detail::make(a.lo + b.lo, a.hi + b.hi);
}
inline Interval operator-(const Interval& a, const Interval& b) {
  if (!a.finite() || !b.finite()) return Interval::whole();
  return interval_detail::make(a.lo - b.hi, a.hi - b.lo);
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator*(const Interval& a, const Interval& b) {
  if (!a.finite() || !b.finite()) return Interval::whole();
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return interval_detail::make(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}));
}
inline Interval square(const Interval& a) {
  if (!a.finite()) return Interval::whole();
  const double l2 = a.lo * a.lo, h2 = a.hi * a.hi;
  if (a.lo >= 0) return interval_detail::make(l2, h2);
  if (a.hi <= 0) return interval_detail::make(h2, l2);
  const Interval r = interval_detail::make(0, std::max(l2, h2));
  return {0, r.hi};
}
inline Interval operator/(const Interval& a, const Interval& b) {
  if (!a.finite() || !b.finite() || (b.lo <= 0 && b.hi >= 0)) return Interval::whole();
  const double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo, p4 = a.hi / b.hi;
  return interval_detail::make(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}));
}
inline Interval sqrt(const Interval& a) {
  if (!a.finite()) return Interval::whole();
  const double l = a.lo > 0 ? interval_detail::down(std::sqrt(a.lo)) : 0.0;
  return {std::max(l, 0.0), interval_detail::up(std::sqrt(std::max(a.hi, 0.0)))};
}

// The sign of every value in the interval, or nullopt when it straddles (or touches) zero
// or is not finite.
inline std::optional<Sign> interval_sign(const Interval& a) {
  if (a.lo > 0 && std::isfinite(a.hi)) return Sign::Positive;
  if (a.hi < 0 && std::isfinite(a.lo)) return Sign::Negative;
  return std::nullopt;
}

using IVec = std::array<Interval, 3>;

inline IVec ivec(const Point& p) { return {Interval(p[0]), Interval(p[1]), Interval(p[2])}; }
inline IVec operator-(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline IVec operator+(const IVec& a, const IVec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline IVec operator*(const Interval& s, const IVec& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Interval dot(const IVec& a, const IVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Interval norm2(const IVec& a) { return square(a[0]) + square(a[1]) + square(a[2]); }
inline IVec cross(const IVec& a, const IVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// |b - a|^2 enclosed from one plain evaluation, widened once (norm2(ivec(b) - ivec(a))
// widens each of its eight operations, and the radius-edge check makes six per tet).
//
// Proof. Let u = 2^-53 and D_i = b_i - a_i exactly, L = D_0^2 + D_1^2 + D_2^2. In IEEE-754
// double with round-to-nearest: d_i = fl(b_i - a_i) = D_i (1 + e_i), |e_i| <= u (a
// difference that is subnormal is exact); q_i = fl(d_i d_i) = d_i^2 (1 + f_i) + g_i,
// |f_i| <= u, |g_i| <= 2^-1075 (underflow); s1 = fl(q_0 + q_1) = (q_0 + q_1)(1 + h_1) and
// s = fl(s1 + q_2) = (s1 + q_2)(1 + h_2), |h_j| <= u (sums are exact when subnormal). Every
// q_i >= 0, so each term of L reaches s with a factor in [(1 - u)^5, (1 + u)^5] and the g_i
// add at most 3 2^-1075 (1 + u)^2 < 2^-1073:
//   s (1 + u)^-5 - 2^-1073 <= L <= s (1 - u)^-5 + 2^-1073,
// and (1 + u)^-5 >= 1 - 5u, (1 - u)^-5 <= 1 + 6u. Both factors are doubles (1 - 5u: the
// spacing below 1 is u; 1 + 6u = 1 + 3 2^-52), and each bound is computed in two rounded
// operations, each widened by interval_detail::down/up. An overflow makes s infinite: the
// whole line (exact arithmetic decides). Requires -ffp-contract=off, as everything here.
inline Interval squared_distance(const Point& a, const Point& b) {
  using interval_detail::down;
  using interval_detail::up;
  const double d0 = b[0] - a[0], d1 = b[1] - a[1], d2 = b[2] - a[2];
  const double s = (d0 * d0 + d1 * d1) + d2 * d2;
  if (!std::isfinite(s)) return Interval::whole();
  constexpr double kLow = 1 - 5 * 0x1p-53, kHigh = 1 + 6 * 0x1p-53, kTiny = 0x1p-1073;
  const double lo = down(down(s * kLow) - kTiny), hi = up(up(s * kHigh) + kTiny);
  if (!std::isfinite(hi)) return Interval::whole();
  return {std::max(lo, 0.0), hi};
}

}  // namespace pdr::check
