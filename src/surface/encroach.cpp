// Encroachment and size tests by element id (paper §1.1, §2.1); see surface/encroach.hpp.
#include "surface/encroach.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <optional>

#include "geom/encroach.hpp"

namespace pdr::surface {

namespace {

constexpr double kUnit = 0x1p-53;

bool in_range(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m >= 0x1p-150 && m <= 0x1p150);
}

// Decides value >= 0 from a filtered value and its error bound; nullopt when unsure.
std::optional<bool> at_least_zero(double value, double bound) {
  if (value > bound) return true;
  if (value < -bound) return false;
  return std::nullopt;
}

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
  bool ok = in_range(d);
  double lhs = 0;
  for (int i = 0; i < 3; ++i) {
    const double e = b[i] - a[i];
    ok = ok && in_range(e);
    lhs += e * e;
  }
  if (ok) {
    // lhs: depth 4, all terms nonnegative; rhs: depth 2.
    const double rhs = k * d * d;
    if (const auto r = at_least_zero(lhs - rhs, 8 * kUnit * (lhs + rhs))) return *r;
  }
  mpq_class l = 0;
  for (int i = 0; i < 3; ++i) {
    const mpq_class e = q_diff(b[i], a[i]);
    l += e * e;
  }
  return l >= mpq_class(k) * mpq_class(d) * mpq_class(d);
}

bool circumradius2_at_least(const Point& a, const Point& b, const Point& c, double d, double k) {
  Point u, v, w;
  bool ok = in_range(d);
  for (int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = b[i] - c[i];
    ok = ok && in_range(u[i]) && in_range(v[i]) && in_range(w[i]);
  }
  if (ok) {
    auto dot = [](const Point& p, const Point& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
    const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const Point na{std::fabs(u[1] * v[2]) + std::fabs(u[2] * v[1]),
                   std::fabs(u[2] * v[0]) + std::fabs(u[0] * v[2]),
                   std::fabs(u[0] * v[1]) + std::fabs(u[1] * v[0])};
    const double lhs = dot(u, u) * dot(v, v) * dot(w, w);
    const double scale = 4 * k * d * d;
    // Depth at most 9 on either side; the absolute program replaces n by na.
    const double value = lhs - scale * dot(n, n);
    const double bar = lhs + scale * dot(na, na);
    if (const auto r = at_least_zero(value, 16 * kUnit * bar)) return *r;
  }
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
