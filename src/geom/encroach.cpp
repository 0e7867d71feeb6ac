// Encroachment predicates (paper §1.1): the filters of filter_kit.hpp, then the GMP
// references; see encroach.hpp for the polynomials. Compiled in pdr_geom with -ffp-contract=off; the
// bounds hold with or without contraction (a fused operation rounds once instead of twice).
#include "geom/encroach.hpp"

#include "geom/filter_kit.hpp"

namespace pdr {
namespace {

using QVec = std::array<mpq_class, 3>;

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
  const Filtered f = filter::in_diametral_ball(a, b, p);
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
  return exact::in_diametral_ball(a, b, p);
}

Sign in_equatorial_ball(const Point& a, const Point& b, const Point& c, const Point& p) {
  const Filtered f = filter::in_equatorial_ball(a, b, c, p);
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
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
Sign compare_circumradius(const Point& a, const Point& b, const Point& c, const Point& d,
                          const Point& e, const Point& f) {
  const Filtered quick = filter::circumradius_compare(a, b, c, d, e, f);
  if (quick != Filtered::Unsure) return quick == Filtered::Positive ? Sign::Positive : Sign::Negative;
  const int c3 = cmp(exact::triangle_circumradius2(a, b, c), exact::triangle_circumradius2(d, e, f));
  return c3 > 0 ? Sign::Positive : (c3 < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace pdr
