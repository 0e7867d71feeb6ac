// GMP reference implementation of the predicates and measures of exact.hpp.
//
// Every predicate is written as the sign of a (lifted) determinant over the rationals,
// evaluated by Gaussian elimination in mpq_class: doubles convert to mpq exactly, so the
// result is the exact sign for every finite input, with no range restriction. The *_sos
// variants follow the definition literally: the lift column of the matrix is perturbed by
// infinitesimals ordered by sos_order.hpp, and the cofactor of each perturbed entry is
// computed as a determinant with that column replaced by a unit vector. Nothing here
// shares code with the adaptive predicates (expansion.hpp), which this file checks.
//
// Lifted forms (rows are points, see predicates.hpp for the conventions):
//   incircle(a,b,c,d)    = sign det[x y x^2+y^2 1]          (4x4, rows a,b,c,d)
//   insphere(a,b,c,d,e)  = -sign det[x y z |p|^2 1]         (5x5, rows a,b,c,d,e)
//   incircle3(a,b,c,d)   = insphere(a,b,c,q,d) with q = a + (b-a)x(c-a), for which
//                          orient3d(a,b,c,q) = |n|^2 > 0; Zero if a,b,c are collinear.
#include "geom/exact.hpp"

#include <cstddef>
#include <utility>

#include "geom/sos_order.hpp"

namespace pdr::exact {
namespace {

using Q = mpq_class;
using QPoint = std::array<Q, 3>;
template <std::size_t N>
using Matrix = std::array<std::array<Q, N>, N>;

Sign sign_q(const Q& x) { return sign_of(sgn(x)); }

QPoint to_q(const Point& p) { return {Q(p[0]), Q(p[1]), Q(p[2])}; }

// Determinant by Gaussian elimination with exact rational pivots.
template <std::size_t N>
Q det(Matrix<N> m) {
  Q result = 1;
  for (std::size_t col = 0; col < N; ++col) {
    std::size_t pivot = col;
    while (pivot < N && sgn(m[pivot][col]) == 0) ++pivot;
    if (pivot == N) return Q(0);
    if (pivot != col) {
      std::swap(m[pivot], m[col]);
      result = -result;
    }
    result *= m[col][col];
    for (std::size_t r = col + 1; r < N; ++r) {
      if (sgn(m[r][col]) == 0) continue;
      const Q f = m[r][col] / m[col][col];
      for (std::size_t c = col; c < N; ++c) m[r][c] -= f * m[col][c];
    }
  }
  return result;
}

// Sign of the perturbed determinant det(m + sum_i eps_i e_i e_lift^T), eps ordered by
// `order` (dominant first): sign of D0, else of the first nonzero cofactor.
template <std::size_t N>
Sign perturbed_sign(const Matrix<N>& m, std::size_t lift,
                    const std::array<int, N>& order) {
  const Sign d0 = sign_q(det(m));
  if (d0 != Sign::Zero) return d0;
  for (const int i : order) {
    Matrix<N> c = m;
    for (std::size_t r = 0; r < N; ++r) c[r][lift] = (static_cast<int>(r) == i) ? 1 : 0;
    const Sign s = sign_q(det(c));
    if (s != Sign::Zero) return s;
  }
  return Sign::Zero;
}

Matrix<4> incircle_matrix(const double* const (&p)[4]) {
  Matrix<4> m;
  for (std::size_t i = 0; i < 4; ++i) {
    const Q x(p[i][0]), y(p[i][1]);
    m[i] = {x, y, x * x + y * y, Q(1)};
  }
  return m;
}

Matrix<5> insphere_matrix(const std::array<QPoint, 5>& p) {
  Matrix<5> m;
  for (std::size_t i = 0; i < 5; ++i) {
    const QPoint& q = p[i];
    m[i] = {q[0], q[1], q[2], q[0] * q[0] + q[1] * q[1] + q[2] * q[2], Q(1)};
  }
  return m;
}

QPoint sub(const QPoint& a, const QPoint& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
QPoint cross(const QPoint& u, const QPoint& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
Q dot(const QPoint& u, const QPoint& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
Q det3(const QPoint& u, const QPoint& v, const QPoint& w) { return dot(u, cross(v, w)); }

// The 5x5 insphere matrix of incircle3: rows a, b, c, q = a + n, d. Precondition n != 0.
Matrix<5> incircle3_matrix(const Point& a, const Point& b, const Point& c, const Point& d,
                           const QPoint& n) {
  const QPoint qa = to_q(a);
  const QPoint q = {qa[0] + n[0], qa[1] + n[1], qa[2] + n[2]};
  return insphere_matrix({qa, to_q(b), to_q(c), q, to_q(d)});
}

QPoint normal(const Point& a, const Point& b, const Point& c) {
  const QPoint qa = to_q(a);
  return cross(sub(to_q(b), qa), sub(to_q(c), qa));
}

bool is_zero(const QPoint& n) { return sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0; }

}  // namespace

Sign orient2d(const double* a, const double* b, const double* c) {
  const Q ux = Q(b[0]) - Q(a[0]), uy = Q(b[1]) - Q(a[1]);
  const Q vx = Q(c[0]) - Q(a[0]), vy = Q(c[1]) - Q(a[1]);
  return sign_q(ux * vy - uy * vx);
}

Sign incircle(const double* a, const double* b, const double* c, const double* d) {
  return sign_q(det(incircle_matrix({a, b, c, d})));
}

Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sign_q(volume6(a, b, c, d));
}

Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e) {
  return -sign_q(det(insphere_matrix({to_q(a), to_q(b), to_q(c), to_q(d), to_q(e)})));
}

Sign incircle3(const Point& a, const Point& b, const Point& c, const Point& d) {
  const QPoint n = normal(a, b, c);
  if (is_zero(n)) return Sign::Zero;
  return -sign_q(det(incircle3_matrix(a, b, c, d, n)));
}

Sign incircle_sos(const double* a, const double* b, const double* c, const double* d) {
  const auto order = sos::dominance_order2<4>({a, b, c, d});
  return perturbed_sign(incircle_matrix({a, b, c, d}), 2, order);
}

Sign insphere_sos(const Point& a, const Point& b, const Point& c, const Point& d,
                  const Point& e) {
  const auto order = sos::dominance_order<5>({&a, &b, &c, &d, &e});
  return -perturbed_sign(insphere_matrix({to_q(a), to_q(b), to_q(c), to_q(d), to_q(e)}), 3,
                         order);
}

Sign incircle3_sos(const Point& a, const Point& b, const Point& c, const Point& d) {
  const QPoint n = normal(a, b, c);
  if (is_zero(n)) return Sign::Zero;
  // Only a, b, c, d are perturbed; q is an auxiliary point. Its cofactor would be
  // +-orient3d(a,b,c,d) = 0 anyway for coplanar input, so leaving it out changes nothing.
  const auto order4 = sos::dominance_order<4>({&a, &b, &c, &d});
  constexpr std::array<int, 4> row = {0, 1, 2, 4};  // matrix row of a, b, c, d
  const Matrix<5> m = incircle3_matrix(a, b, c, d, n);
  const Sign d0 = sign_q(det(m));
  if (d0 != Sign::Zero) return -d0;
  for (const int i : order4) {
    Matrix<5> cof = m;
    for (std::size_t r = 0; r < 5; ++r) cof[r][3] = (static_cast<int>(r) == row[i]) ? 1 : 0;
    const Sign s = sign_q(det(cof));
    if (s != Sign::Zero) return -s;
  }
  return Sign::Zero;
}

mpq_class squared_distance(const Point& a, const Point& b) {
  const QPoint u = sub(to_q(a), to_q(b));
  return dot(u, u);
}

std::array<mpq_class, 3> circumcenter(const Point& a, const Point& b, const Point& c,
                                      const Point& d) {
  // Center x = a + y with 2 (p - a) . y = |p - a|^2 for p = b, c, d; Cramer's rule.
  const QPoint qa = to_q(a);
  const QPoint u = sub(to_q(b), qa), v = sub(to_q(c), qa), w = sub(to_q(d), qa);
  const Q lu = dot(u, u), lv = dot(v, v), lw = dot(w, w);
  const Q den = 2 * det3(u, v, w);
  // y = (lu (v x w) + lv (w x u) + lw (u x v)) / (2 det[u, v, w]).
  const QPoint vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  std::array<mpq_class, 3> x;
  for (std::size_t i = 0; i < 3; ++i) x[i] = qa[i] + (lu * vw[i] + lv * wu[i] + lw * uv[i]) / den;
  return x;
}

mpq_class circumradius2(const Point& a, const Point& b, const Point& c, const Point& d) {
  const std::array<mpq_class, 3> x = circumcenter(a, b, c, d);
  const QPoint y = sub(x, to_q(a));
  return dot(y, y);
}

mpq_class volume6(const Point& a, const Point& b, const Point& c, const Point& d) {
  const QPoint qa = to_q(a);
  return det3(sub(to_q(b), qa), sub(to_q(c), qa), sub(to_q(d), qa));
}

}  // namespace pdr::exact
