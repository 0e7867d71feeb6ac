// The checkers' exact signs: every stage agrees with GMP whenever it decides, on random,
// near-degenerate and grid input; sign conventions; interval enclosures.
#include <cmath>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include "check/circumball.hpp"
#include "check/interval.hpp"
#include "check/signs.hpp"
#include "geom/exact.hpp"

namespace pdr::check {
namespace {

// Points: arbitrary doubles, small dyadic grid points, or grid points nudged by an ulp.
rc::Gen<Point> point_gen() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-8, 9)),
                   [](const std::vector<int>& v) { return Point{v[0] * 0.25, v[1] * 0.25, v[2] * 0.25}; }),
      rc::gen::map(rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-8, 9)),
                   [](const std::vector<int>& v) {
                     return Point{std::nextafter(v[0] * 0.25, 1.0), v[1] * 0.25, v[2] * 0.25 + 1e-17};
                   }),
      rc::gen::map(rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-1000000, 1000001)),
                   [](const std::vector<int>& v) { return Point{v[0] / 3e5, v[1] / 7e5, v[2] / 1.1e6}; }));
}

RC_GTEST_PROP(Signs, Orient3dAgreesWithGmp, ()) {
  const Point a = *point_gen(), b = *point_gen(), c = *point_gen(), d = *point_gen();
  const Sign ref = exact::orient3d(a, b, c, d);
  RC_ASSERT(signs::orient3d(a, b, c, d) == ref);
  if (auto s = signs::orient3d_filter(a, b, c, d)) RC_ASSERT(*s == ref);
  if (auto s = signs::orient3d_int(a, b, c, d)) RC_ASSERT(*s == ref);
  RC_ASSERT(signs::det3(a, b, a, c, a, d) == ref);
}

RC_GTEST_PROP(Signs, InsphereAgreesWithGmp, ()) {
  const Point a = *point_gen(), b = *point_gen(), c = *point_gen(), d = *point_gen(), e = *point_gen();
  const Sign ref = exact::insphere(a, b, c, d, e);
  RC_ASSERT(signs::insphere(a, b, c, d, e) == ref);
  if (auto s = signs::insphere_filter(a, b, c, d, e)) RC_ASSERT(*s == ref);
  if (auto s = signs::insphere_int(a, b, c, d, e)) RC_ASSERT(*s == ref);
}

RC_GTEST_PROP(Signs, Det3OfDifferencesAgreesWithGmp, ()) {
  const Point a0 = *point_gen(), a1 = *point_gen(), b0 = *point_gen(), b1 = *point_gen(),
              c0 = *point_gen(), c1 = *point_gen();
  using Q = mpq_class;
  auto d = [](const Point& p, const Point& q, int i) -> Q { return Q(q[i]) - Q(p[i]); };
  const Q ux = d(a0, a1, 0), uy = d(a0, a1, 1), uz = d(a0, a1, 2);
  const Q vx = d(b0, b1, 0), vy = d(b0, b1, 1), vz = d(b0, b1, 2);
  const Q wx = d(c0, c1, 0), wy = d(c0, c1, 1), wz = d(c0, c1, 2);
  const Q det = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  RC_ASSERT(signs::det3(a0, a1, b0, b1, c0, c1) == sign_of(sgn(det)));
}

// p inside the equatorial sphere of abc iff |p - o|^2 < |a - o|^2, o solved directly from
// (o - a).u = |u|^2 / 2, (o - a).v = |v|^2 / 2, (o - a).n = 0 by Cramer's rule.
RC_GTEST_PROP(Signs, EquatorialAgreesWithDirectCircumcenter, ()) {
  const Point a = *point_gen(), b = *point_gen(), c = *point_gen(), p = *point_gen();
  using Q = mpq_class;
  using V = std::array<Q, 3>;
  auto sub = [](const Point& x, const Point& y) { return V{Q(x[0]) - y[0], Q(x[1]) - y[1], Q(x[2]) - y[2]}; };
  auto dot = [](const V& x, const V& y) { return Q(x[0] * y[0] + x[1] * y[1] + x[2] * y[2]); };
  auto cross = [](const V& x, const V& y) {
    return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  const V u = sub(b, a), v = sub(c, a), n = cross(u, v);
  RC_PRE(sgn(dot(n, n)) != 0);
  auto det = [&](const V& r0, const V& r1, const V& r2) { return dot(r0, cross(r1, r2)); };
  const Q D = det(u, v, n);
  const V rhs = {dot(u, u) / 2, dot(v, v) / 2, Q(0)};
  V o;  // o - a
  for (int i = 0; i < 3; ++i) {
    V c0 = {u[0], v[0], n[0]}, c1 = {u[1], v[1], n[1]}, c2 = {u[2], v[2], n[2]};
    V* cols[3] = {&c0, &c1, &c2};
    *cols[i] = rhs;
    o[i] = det(V{c0[0], c1[0], c2[0]}, V{c0[1], c1[1], c2[1]}, V{c0[2], c1[2], c2[2]}) / D;
  }
  const V w = sub(p, a);
  const V pw = {w[0] - o[0], w[1] - o[1], w[2] - o[2]};
  const Sign ref = sign_of(sgn(dot(o, o) - dot(pw, pw)));
  RC_ASSERT(signs::equatorial(a, b, c, p) == ref);
}

RC_GTEST_PROP(Signs, DotAgreesWithGmp, ()) {
  const Point p = *point_gen(), a = *point_gen(), q = *point_gen(), b = *point_gen();
  using Q = mpq_class;
  Q s = 0;
  for (int i = 0; i < 3; ++i) s += (Q(p[i]) - a[i]) * (Q(q[i]) - b[i]);
  RC_ASSERT(signs::dot(p, a, q, b) == sign_of(sgn(s)));
}

TEST(Signs, Conventions) {
  const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  EXPECT_EQ(signs::orient3d(a, b, c, d), Sign::Positive);
  EXPECT_EQ(signs::insphere(a, b, c, d, {0.25, 0.25, 0.25}), Sign::Positive);
  EXPECT_EQ(signs::insphere(a, b, c, d, {1, 1, 1}), Sign::Zero);
  EXPECT_EQ(signs::insphere(a, b, c, d, {2, 2, 2}), Sign::Negative);
  EXPECT_EQ(signs::insphere(b, a, c, d, {0.25, 0.25, 0.25}), Sign::Negative);
  EXPECT_EQ(signs::equatorial(b, c, d, {0.3, 0.3, 0.3}), Sign::Positive);
  EXPECT_EQ(signs::equatorial(b, c, d, a), Sign::Positive);  // |a - o|^2 = 1/3 < 2/3
  EXPECT_EQ(signs::equatorial(b, c, d, {-1, -1, -1}), Sign::Negative);
  // Triangle (0,0,0), (2,0,0), (0,2,0): centre (1,1,0), r^2 = 2.
  EXPECT_EQ(signs::equatorial(a, {2, 0, 0}, {0, 2, 0}, {2, 1, 1}), Sign::Zero);
  EXPECT_EQ(signs::equatorial(a, {2, 0, 0}, {0, 2, 0}, {2, 1, 1.0625}), Sign::Negative);
}

// Far-apart magnitudes defeat the integer stage and the filter's range guard: GMP decides.
TEST(Signs, ExtremeMagnitudesFallBackToGmp) {
  const Point a{1e-200, 0, 0}, b{1e200, 0, 0}, c{0, 1e-200, 0}, d{0, 0, 1e-200};
  EXPECT_EQ(signs::orient3d(a, b, c, d), exact::orient3d(a, b, c, d));
  EXPECT_EQ(signs::insphere(a, b, c, d, {1e-201, 1e-201, 1e-201}),
            exact::insphere(a, b, c, d, {1e-201, 1e-201, 1e-201}));
}

// lo <= x for an interval end that may be infinite (an unbounded end encloses trivially;
// GMP cannot convert an infinity, so it is compared as a double).
bool below(double lo, const mpq_class& x) { return std::isinf(lo) ? lo < 0 : mpq_class(lo) <= x; }
bool above(double hi, const mpq_class& x) { return std::isinf(hi) ? hi > 0 : x <= mpq_class(hi); }

RC_GTEST_PROP(Interval, CircumballEnclosesTheExactCenter, ()) {
  const Point a = *point_gen(), b = *point_gen(), c = *point_gen(), d = *point_gen();
  RC_PRE(exact::orient3d(a, b, c, d) != Sign::Zero);
  const BallEnclosure ball = circumball(a, b, c, d);
  const auto x = exact::circumcenter(a, b, c, d);
  for (int i = 0; i < 3; ++i) {
    RC_ASSERT(!std::isnan(ball.center[i].lo) && !std::isnan(ball.center[i].hi));
    RC_ASSERT(below(ball.center[i].lo, x[i]));
    RC_ASSERT(above(ball.center[i].hi, x[i]));
  }
  const mpq_class r2 = exact::circumradius2(a, b, c, d);
  RC_ASSERT(!std::isnan(ball.r2.lo) && !std::isnan(ball.r2.hi));
  RC_ASSERT(below(ball.r2.lo, r2));
  RC_ASSERT(above(ball.r2.hi, r2));
  const Box box = enclosing_box(ball);
  for (const Point* p : {&a, &b, &c, &d})
    for (int i = 0; i < 3; ++i) RC_ASSERT(box.lo[i] <= (*p)[i] && (*p)[i] <= box.hi[i]);
}

// The plain evaluation with its proven bound (detail::circumball_bounded) on tets of every
// scale (2^-240 .. 2^240 about a random origin), nearly flat ones (the fourth point within
// 2^-k of the plane of the other three) and ones at its guard: where it answers, its
// enclosure holds the exact centre and squared radius.
RC_GTEST_PROP(Interval, BoundedCircumballEnclosesTheExactCenter, ()) {
  const int scale = *rc::gen::inRange(-240, 241);
  const auto coordinate = [&] {
    return rc::gen::map(rc::gen::inRange(-1000000, 1000001),
                        [scale](int k) { return std::ldexp(k / 1e6, scale); });
  };
  const Point origin{*rc::gen::inRange(-1000, 1001) * 0.37, *rc::gen::inRange(-1000, 1001) * 0.11, 0.5};
  const auto point = [&] {
    const Point o = *rc::gen::oneOf(rc::gen::just(Point{0, 0, 0}), rc::gen::just(origin));
    return Point{o[0] + *coordinate(), o[1] + *coordinate(), o[2] + *coordinate()};
  };
  // Or coordinates a few ulps around small multiples of 2^-250, the guard: cross
  // components that cancel to about 2^-552, and subnormal products |u|^2 x.
  const auto near_guard = [&] {
    Point p;
    for (int i = 0; i < 3; ++i) {
      double x = std::ldexp(*rc::gen::inRange(-3, 4), -250);
      for (int k = *rc::gen::inRange(-3, 4); k != 0; k += k > 0 ? -1 : 1)
        x = std::nextafter(x, k > 0 ? INFINITY : -INFINITY);
      p[i] = x;
    }
    return p;
  };
  const bool guard = *rc::gen::inRange(0, 4) == 0;
  const Point a = guard ? near_guard() : point(), b = guard ? near_guard() : point(),
              c = guard ? near_guard() : point();
  Point d = guard ? near_guard() : point();
  if (!guard && *rc::gen::arbitrary<bool>()) {  // nearly flat: d near the plane of a, b, c
    const double s = *rc::gen::inRange(-3, 4) * 0.5, t = *rc::gen::inRange(-3, 4) * 0.25;
    const int lift = *rc::gen::inRange(10, 60);
    for (int i = 0; i < 3; ++i)
      d[i] = a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]) + std::ldexp(*coordinate(), -lift);
  }
  RC_PRE(exact::orient3d(a, b, c, d) != Sign::Zero);
  const auto ball = detail::circumball_bounded(a, b, c, d);
  RC_TAG(ball ? "bounded" : "fallback");
  if (!ball) return;
  const auto x = exact::circumcenter(a, b, c, d);
  for (int i = 0; i < 3; ++i) {
    RC_ASSERT(ball->center[i].finite());
    RC_ASSERT(below(ball->center[i].lo, x[i]));
    RC_ASSERT(above(ball->center[i].hi, x[i]));
  }
  const mpq_class r2 = exact::circumradius2(a, b, c, d);
  RC_ASSERT(below(ball->r2.lo, r2));
  RC_ASSERT(above(ball->r2.hi, r2));
}

TEST(Interval, BoundedCircumballIsTakenWhereItsGuardsHold) {
  const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  const auto ball = detail::circumball_bounded(a, b, c, d);
  ASSERT_TRUE(ball.has_value());
  for (int i = 0; i < 3; ++i) {
    EXPECT_LE(ball->center[i].lo, 0.5);
    EXPECT_GE(ball->center[i].hi, 0.5);
    EXPECT_LT(ball->center[i].hi - ball->center[i].lo, 1e-14);  // tight
  }
  // A difference below 2^-250 (or above 2^250): the interval evaluation instead.
  EXPECT_FALSE(detail::circumball_bounded(a, {0x1p-260, 0, 0}, {0, 0x1p-260, 0}, {0, 0, 0x1p-260}));
  EXPECT_FALSE(detail::circumball_bounded(a, {0x1p260, 0, 0}, c, d));
  // Flat beyond what the bound resolves (d a hair off the plane of a, b, c, whose
  // coordinates round): the determinant's sign is left open.
  const Point p{1, 0.1, 0.2}, q{0.3, 1, 0.7};
  EXPECT_FALSE(detail::circumball_bounded(a, p, q, {0.65, 0.55, 0.45 + 0x1p-60}));
  EXPECT_TRUE(detail::circumball_bounded(a, p, q, {0.65, 0.55, 0.5}));
}

// Squared distances of points of every magnitude: small dyadic, arbitrary, tiny (down to
// subnormal differences), huge (up to overflow), and pairs an ulp apart.
RC_GTEST_PROP(Interval, SquaredDistanceEnclosesTheExactValue, ()) {
  const int scale = *rc::gen::inRange(-1074, 1024);
  const auto coordinate = [&] {
    return rc::gen::map(rc::gen::inRange(-1000000, 1000001),
                        [scale](int k) { return std::ldexp(k / 1e6, scale); });
  };
  Point a{}, b{};
  for (int i = 0; i < 3; ++i) {
    a[i] = *coordinate();
    b[i] = *rc::gen::oneOf(coordinate(), rc::gen::just(std::nextafter(a[i], INFINITY)),
                           rc::gen::just(a[i]));
  }
  const Interval x = squared_distance(a, b);
  RC_ASSERT(!std::isnan(x.lo) && !std::isnan(x.hi));
  RC_ASSERT(x.lo >= 0 || !x.finite());  // the whole line after an overflow
  const mpq_class l2 = exact::squared_distance(a, b);
  RC_ASSERT(below(x.lo, l2));
  RC_ASSERT(above(x.hi, l2));
  // Tight: within a few ulps of the value, or of the smallest subnormal.
  if (x.finite()) RC_ASSERT(x.hi - x.lo <= 0x1p-48 * x.hi + 0x1p-1070);
}

TEST(Interval, SquaredDistanceOfExtremesIsEnclosed) {
  const double big = 0x1p1000, tiny = 0x1p-1074;
  for (const auto& [a, b] : std::vector<std::pair<Point, Point>>{
           {{0, 0, 0}, {tiny, tiny, tiny}},
           {{0, 0, 0}, {0x1p-540, 0, 0}},
           {{-big, 0, 0}, {big, 0, 0}},  // overflows: the whole line
           {{1, 1, 1}, {std::nextafter(1.0, 2.0), 1, 1}},
           {{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}}}) {
    const Interval x = squared_distance(a, b);
    const mpq_class l2 = exact::squared_distance(a, b);
    EXPECT_TRUE(below(x.lo, l2) && above(x.hi, l2)) << a[0] << " " << b[0];
  }
  EXPECT_FALSE(squared_distance({-big, 0, 0}, {big, 0, 0}).finite());
}

}  // namespace
}  // namespace pdr::check
