// Exact floating-point expansion arithmetic (stage 2 of the adaptive predicates).
//
// After J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates", Discrete Comput. Geom. 18 (1997), §2 (written here from the
// paper's definitions and theorems; no code is taken from predicates.c).
//
// An expansion is a sum of doubles c[0] + ... + c[n-1] kept *nonoverlapping* and in
// increasing order of magnitude, with zero components removed ("zero elimination"). Its
// value is exact; its sign is the sign of its largest component c[n-1] (or zero if n = 0).
// The error-free transformations below (two_sum: Knuth; two_product: Dekker's split, or one
// fused multiply-add where the target has one) return a rounded result x and its exact
// error y, with a op b = x + y exactly, provided no overflow and no underflow occur.
//
// Invariants: every operation returns a nonoverlapping, increasing, zero-free expansion
// whose exact value is the exact result (paper Theorems 10, 13, 19 with round-to-nearest-
// even). Capacities are compile-time template arguments: Expansion<N> holds at most N
// components, and each operation returns a type big enough for its worst case, so no
// heap allocation and no overflow of the fixed arrays can happen.
//
// Precondition: every translation unit that includes this header must be compiled with
// -ffp-contract=off (a contracted a*b-c breaks Dekker's product and the split); pdr_geom
// defines PDR_GEOM_FP_STRICT for exactly that reason, and tests/geom checks it.
#pragma once

#ifndef PDR_GEOM_FP_STRICT
#error "expansion.hpp needs -ffp-contract=off; define PDR_GEOM_FP_STRICT with that flag"
#endif

#include <cmath>

#include "geom/point.hpp"

namespace pdr::expansion {

// x = fl(a + b), y = a + b - x exactly (Knuth's TwoSum; no precondition on |a|, |b|).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_part = x - a;
  const double a_part = x - b_part;
  y = (a - a_part) + (b - b_part);
}

// x = fl(a - b), y = a - b - x exactly.
inline void two_diff(double a, double b, double& x, double& y) { two_sum(a, -b, x, y); }

// a = hi + lo with hi, lo holding at most 26 significant bits each (Dekker, Veltkamp).
// Precondition: |a| <= 2^995 (so that (2^27 + 1) * a does not overflow).
inline void split(double a, double& hi, double& lo) {
  constexpr double splitter = 134217729.0;  // 2^27 + 1
  const double t = splitter * a;
  const double big = t - a;
  hi = t - big;
  lo = a - hi;
}

// x = fl(a * b), y = a * b - x exactly.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  y = __builtin_fma(a, b, -x);
#else
  // Dekker: the four half-products are exact, and each subtraction below is exact.
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  const double e1 = x - ah * bh;
  const double e2 = e1 - al * bh;
  const double e3 = e2 - ah * bl;
  y = al * bl - e3;
#endif
}

// --- Operations on raw component arrays. Output arrays must not alias the inputs. ---

// h = e + b (Grow-Expansion, Theorem 10). Capacity of h: n + 1.
inline int grow(const double* e, int n, double b, double* h) {
  int k = 0;
  double q = b;
  for (int i = 0; i < n; ++i) {
    double s, t;
    two_sum(q, e[i], s, t);
    if (t != 0) h[k++] = t;
    q = s;
  }
  if (q != 0) h[k++] = q;
  return k;
}

// h = e + f (Fast-Expansion-Sum, Theorem 13: merge by magnitude, then a chain of two-sums).
// Capacity of h: n + m.
inline int sum(const double* e, int n, const double* f, int m, double* h) {
  int i = 0, j = 0, k = 0;
  const auto next = [&]() {
    if (j >= m || (i < n && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  if (n + m == 0) return 0;
  double q = next();
  while (i < n || j < m) {
    double s, t;
    two_sum(q, next(), s, t);
    if (t != 0) h[k++] = t;
    q = s;
  }
  if (q != 0) h[k++] = q;
  return k;
}

// h = e * b (Scale-Expansion, Theorem 19). Capacity of h: 2n.
inline int scale(const double* e, int n, double b, double* h) {
  if (n == 0 || b == 0) return 0;
  int k = 0;
  double q, t;
  two_product(e[0], b, q, t);
  if (t != 0) h[k++] = t;
  for (int i = 1; i < n; ++i) {
    double p_hi, p_lo, s, u;
    two_product(e[i], b, p_hi, p_lo);
    two_sum(q, p_lo, s, u);
    if (u != 0) h[k++] = u;
    two_sum(p_hi, s, q, u);  // Fast-Two-Sum in the paper; Two-Sum gives the same result
    if (u != 0) h[k++] = u;
  }
  if (q != 0) h[k++] = q;
  return k;
}

// h = e with fewer components (Compress, paper §2.8 and Theorem 23): a top-down pass of
// two-sums gathers the value into few large components, a bottom-up pass makes them
// nonoverlapping again. The value is unchanged (every step is a two-sum); the output is
// nonoverlapping with at most n components. Products of expansions cost the product of
// the lengths, so the stages compress before multiplying. h may not alias e.
inline int compress(const double* e, int n, double* h) {
  if (n == 0) return 0;
  // Pass 1 writes the gathered components to h[bottom..n-1], pass 2 rewrites h from 0.
  int bottom = n - 1;
  double q = e[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    double s, t;
    two_sum(q, e[i], s, t);
    if (t != 0) {
      h[bottom--] = s;
      q = t;
    } else {
      q = s;
    }
  }
  h[bottom] = q;
  int top = 0;
  for (int i = bottom + 1; i < n; ++i) {
    double s, t;
    two_sum(h[i], q, s, t);
    if (t != 0) h[top++] = t;
    q = s;
  }
  h[top++] = q;
  return top;
}

// --- Fixed-capacity expansions with compile-time size tracking. ---

template <int N>
struct Expansion {
  static_assert(N > 0);
  double c[N];  // components [0, n): increasing magnitude, nonoverlapping, nonzero
  int n = 0;

  Sign sign() const { return n == 0 ? Sign::Zero : sign_of(c[n - 1]); }
  // An approximation of the value (the sum of the components, largest last).
  double estimate() const {
    double s = 0;
    for (int i = 0; i < n; ++i) s += c[i];
    return s;
  }
};

template <int N>
Expansion<N> compressed(const Expansion<N>& e) {
  Expansion<N> r;
  r.n = compress(e.c, e.n, r.c);
  return r;
}

inline Expansion<1> single(double a) {
  Expansion<1> r;
  if (a != 0) r.c[r.n++] = a;
  return r;
}

inline Expansion<2> from_pair(double x, double y) {  // x the rounded value, y its error
  Expansion<2> r;
  if (y != 0) r.c[r.n++] = y;
  if (x != 0) r.c[r.n++] = x;
  return r;
}

inline Expansion<2> product(double a, double b) {
  double x, y;
  two_product(a, b, x, y);
  return from_pair(x, y);
}

inline Expansion<2> difference(double a, double b) {
  double x, y;
  two_diff(a, b, x, y);
  return from_pair(x, y);
}

template <int A>
Expansion<A> operator-(const Expansion<A>& e) {
  Expansion<A> r;
  r.n = e.n;
  for (int i = 0; i < e.n; ++i) r.c[i] = -e.c[i];
  return r;
}

template <int A, int B>
Expansion<A + B> operator+(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<A + B> r;
  r.n = sum(e.c, e.n, f.c, f.n, r.c);
  return r;
}

template <int A, int B>
Expansion<A + B> operator-(const Expansion<A>& e, const Expansion<B>& f) {
  return e + (-f);
}

template <int A>
Expansion<2 * A> operator*(const Expansion<A>& e, double b) {
  Expansion<2 * A> r;
  r.n = scale(e.c, e.n, b, r.c);
  return r;
}

// e * f as the sum over the components of f of e scaled by them. Capacity 2AB.
template <int A, int B>
Expansion<2 * A * B> operator*(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<2 * A * B> r;
  double other[2 * A * B];
  double part[2 * A];
  double* cur = r.c;
  double* next = other;
  int n = 0;
  for (int j = 0; j < f.n; ++j) {
    const int np = scale(e.c, e.n, f.c[j], part);
    n = sum(cur, n, part, np, next);
    double* t = cur;
    cur = next;
    next = t;
  }
  if (cur != r.c)
    for (int i = 0; i < n; ++i) r.c[i] = cur[i];
  r.n = n;
  return r;
}

// a*b - c*d, exactly.
inline Expansion<4> cross_difference(double a, double b, double c, double d) {
  return product(a, b) - product(c, d);
}

}  // namespace pdr::expansion
