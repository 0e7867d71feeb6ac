// The filters of geom/filter_kit.hpp driven to their bounds: inputs rounded off the
// sphere or the threshold each filter decides about, so that |value| is a few rounding
// errors and the filter's bound matters. Whenever a filter answers, its sign must equal
// the GMP reference's; every test also requires that the filter was unsure on some inputs
// (they reached the bound) and answered on others (it is not vacuously unsure). A filter
// whose coefficient is below its derived count answers wrongly here.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "geom/encroach.hpp"
#include "geom/filter_kit.hpp"
#include "kit_inputs.hpp"

namespace pdr::filter {
namespace {

TEST(FilterKit, DiametralBallAtItsSphere) {
  Gen g(1);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point(), b = g.point();
    const Point mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
    const Point p = along(mid, g.direction(), std::sqrt(q_dist2(a, b).get_d()) / 2 * g.jitter());
    const Filtered f = in_diametral_ball(a, b, p);
    t.add(f);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), exact::in_diametral_ball(a, b, p));
    }
  }
  t.expect_both();
}

TEST(FilterKit, EquatorialBallAtItsSphere) {
  Gen g(2);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point(), b = g.point(), c = g.point();
    const auto o = exact::triangle_circumcenter(a, b, c);
    const Point center{o[0].get_d(), o[1].get_d(), o[2].get_d()};
    const double r = std::sqrt(exact::triangle_circumradius2(a, b, c).get_d());
    const Point p = along(center, g.direction(), r * g.jitter());
    const Filtered f = in_equatorial_ball(a, b, c, p);
    t.add(f);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), exact::in_equatorial_ball(a, b, c, p)) << i;
    }
  }
  t.expect_both();
}

TEST(FilterKit, LengthAtItsThreshold) {
  Gen g(3);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point();
    const double d = std::fabs(g.coord()) + 0x1p-8, k = (i % 2) ? 4 : 2;
    const Point b = along(a, g.direction(), std::sqrt(k) * d * g.jitter());
    const Filtered f = length2_minus(a, b, d, k);
    t.add(f);
    const mpq_class exact = q_dist2(a, b) - mpq_class(k) * mpq_class(d) * mpq_class(d);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_sign(exact)) << i;
    }
  }
  t.expect_both();
}

TEST(FilterKit, CircumradiusAtItsThreshold) {
  Gen g(4);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point(), b = g.point(), c = g.point();
    const double k = (i % 2) ? 4 : 2;
    const mpq_class r2 = exact::triangle_circumradius2(a, b, c);
    const double d = std::sqrt(r2.get_d() / k) * g.jitter();  // R^2 close to k d^2
    const Filtered f = circumradius2_minus(a, b, c, d, k);
    t.add(f);
    const mpq_class exact = r2 - mpq_class(k) * mpq_class(d) * mpq_class(d);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_sign(exact)) << i;
    }
  }
  t.expect_both();
}

using QVec = std::array<mpq_class, 3>;
QVec q_of(const Point& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

TEST(FilterKit, Dot3AtRightAngles) {
  Gen g(5);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point o = g.point(), p = g.point();
    // q - o orthogonal to p - o up to rounding, then nudged along p - o by a jitter.
    const Point e = sub(p, o), r = g.direction();
    const Point perp = cross(e, r);
    const double s = (g.jitter() - 1) * std::sqrt(dot(perp, perp) / dot(e, e));
    const Point q{o[0] + perp[0] + s * e[0], o[1] + perp[1] + s * e[1],
                  o[2] + perp[2] + s * e[2]};
    const Filtered f = dot3(o, p, q);
    t.add(f);
    mpq_class exact = 0;
    for (int k = 0; k < 3; ++k)
      exact += (mpq_class(p[k]) - mpq_class(o[k])) * (mpq_class(q[k]) - mpq_class(o[k]));
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_sign(exact)) << i;
    }
  }
  t.expect_both();
}

// A rational point on (or a jitter off) the plane of a, b, c, known as its rounding with
// the error bound domain/exact.hpp's make_rat uses. Cases, by i % 3: 0 that point; 1 its
// rounding taken as exact (err = 0: the rounding part of the bound alone); 2 the rounding
// moved by up to err per coordinate (the error part of the bound alone).
struct NearPoint {
  QVec q;
  Point d;
  double err;
};
NearPoint near_plane(Gen& g, const Point& a, const Point& b, const Point& c, int i) {
  const mpq_class s(g.coord()), t(g.coord());
  const QVec qa = q_of(a), qb = q_of(b), qc = q_of(c);
  const Point off = g.direction();
  const double h = (g.jitter() - 1) * 16;
  NearPoint n;
  double m = 0;
  for (int k = 0; k < 3; ++k) {
    n.q[k] = qa[k] + s * (qb[k] - qa[k]) + t * (qc[k] - qa[k]) + mpq_class(h * off[k]);
    n.d[k] = n.q[k].get_d();
    m = std::max(m, std::fabs(n.d[k]));
  }
  n.err = 0x1p-51 * m + 0x1p-1000;
  if (i % 3 == 0) return n;
  for (int k = 0; k < 3; ++k) n.q[k] = mpq_class(n.d[k]);
  if (i % 3 == 1) {
    n.err = 0;
    return n;
  }
  const Point delta = g.direction();  // components in [-1, 1]
  for (int k = 0; k < 3; ++k) n.q[k] += mpq_class(n.err * delta[k]);
  return n;
}

TEST(FilterKit, Orient3dNearAtItsPlane) {
  Gen g(6);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point(), b = g.point(), c = g.point();
    const NearPoint o = near_plane(g, a, b, c, i);
    const Filtered f = orient3d_near(a, b, c, o.d, o.err);
    t.add(f);
    const QVec qa = q_of(a), qb = q_of(b), qc = q_of(c);
    QVec u, v, w;
    for (int k = 0; k < 3; ++k) u[k] = qb[k] - qa[k], v[k] = qc[k] - qa[k], w[k] = o.q[k] - qa[k];
    const mpq_class exact = (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] +
                            (u[0] * v[1] - u[1] * v[0]) * w[2];
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_sign(exact)) << i;
    }
  }
  t.expect_both();
}

TEST(FilterKit, Orient2dNearAtItsLine) {
  Gen g(7);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point(), b = g.point();
    const NearPoint o = near_plane(g, a, b, b, i);  // on the line ab, or a jitter off it
    const Filtered f = orient2d_near(0, 1, a, b, o.d, o.err);
    t.add(f);
    const mpq_class ux = mpq_class(b[0]) - mpq_class(a[0]), uy = mpq_class(b[1]) - mpq_class(a[1]);
    const mpq_class wx = o.q[0] - mpq_class(a[0]), wy = o.q[1] - mpq_class(a[1]);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_sign(mpq_class(ux * wy - uy * wx))) << i;
    }
  }
  t.expect_both();
}

}  // namespace
}  // namespace pdr::filter
