// Encroachment and size tests by element id (paper §1.1, §2.1); see surface/encroach.hpp.
#include "surface/encroach.hpp"

#include <gmpxx.h>

#include <array>

#include "geom/encroach.hpp"
#include "geom/filter_kit.hpp"

namespace pdr::surface {

namespace {

mpq_class q_diff(double x, double y) { return mpq_class(x) - mpq_class(y); }

}  // namespace

bool subsegment_encroached_by(const SurfaceMesh& m, std::uint32_t s, const Point& p) {
  const Subsegment& g = m.subsegment(s);
  return in_diametral_ball(m.point(g.v[0]), m.point(g.v[1]), p) != Sign::Negative;
}

bool subfacet_encroached_by(const SurfaceMesh& m, std::uint32_t t, const Point& p) {
  const Subfacet& f = m.subfacet(t);
  return in_equatorial_ball(m.point(f.v[0]), m.point(f.v[1]), m.point(f.v[2]), p) !=
         Sign::Negative;
}

bool length2_at_least(const Point& a, const Point& b, double d, double k) {
  const Filtered f = filter::length2_minus(a, b, d, k);
  if (f != Filtered::Unsure) return f == Filtered::Positive;
  mpq_class l = 0;
  for (int i = 0; i < 3; ++i) {
    const mpq_class e = q_diff(b[i], a[i]);
    l += e * e;
  }
  return l >= mpq_class(k) * mpq_class(d) * mpq_class(d);
}

bool circumradius2_at_least(const Point& a, const Point& b, const Point& c, double d, double k) {
  const Filtered f = filter::circumradius2_minus(a, b, c, d, k);
  if (f != Filtered::Unsure) return f == Filtered::Positive;
  std::array<mpq_class, 3> qu, qv, qw;
  for (int i = 0; i < 3; ++i) {
    qu[i] = q_diff(b[i], a[i]);
    qv[i] = q_diff(c[i], a[i]);
    qw[i] = q_diff(b[i], c[i]);
  }
  auto qdot = [](const std::array<mpq_class, 3>& p, const std::array<mpq_class, 3>& q) {
    return mpq_class(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  };
  const std::array<mpq_class, 3> n{qu[1] * qv[2] - qu[2] * qv[1], qu[2] * qv[0] - qu[0] * qv[2],
                                   qu[0] * qv[1] - qu[1] * qv[0]};
  const mpq_class lhs = qdot(qu, qu) * qdot(qv, qv) * qdot(qw, qw);
  return lhs >= 4 * mpq_class(k) * mpq_class(d) * mpq_class(d) * qdot(n, n);
}

bool subsegment_too_long(const SurfaceMesh& m, std::uint32_t s, double d) {
  const Subsegment& g = m.subsegment(s);
  return length2_at_least(m.point(g.v[0]), m.point(g.v[1]), d, 4);
}

bool subfacet_too_large(const SurfaceMesh& m, std::uint32_t t, double d) {
  const Subfacet& f = m.subfacet(t);
  return circumradius2_at_least(m.point(f.v[0]), m.point(f.v[1]), m.point(f.v[2]), d, 2);
}

}  // namespace pdr::surface
