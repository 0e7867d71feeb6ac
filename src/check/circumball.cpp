// Interval enclosures of circumballs (see circumball.hpp for the argument).
#include "check/circumball.hpp"

#include <gmpxx.h>

#include <cmath>

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

BallEnclosure circumball(const Point& a, const Point& b, const Point& c, const Point& d) {
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
