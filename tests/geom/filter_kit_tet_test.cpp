// The tet and chart filters of geom/filter_kit.hpp driven to their bounds, as in
// filter_kit_test.cpp: every answer must equal the GMP reference's sign, and every test must
// reach the bound (some unsure answers) and decide elsewhere. The Bracket arithmetic is
// driven into underflow and overflow, where a relative margin alone would be wrong.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "geom/exact.hpp"
#include "geom/filter_kit.hpp"
#include "kit_inputs.hpp"

namespace pdr::filter {
namespace {

struct Tet {
  Point a, b, c, d;
};

// A random tet that is not flat (GMP says so).
Tet random_tet(Gen& g) {
  for (;;) {
    Tet t{g.point(), g.point(), g.point(), g.point()};
    if (exact::volume6(t.a, t.b, t.c, t.d) != 0) return t;
  }
}

mpq_class q_shortest_edge2(const Tet& t) {
  const Point* p[4] = {&t.a, &t.b, &t.c, &t.d};
  mpq_class best = q_dist2(t.a, t.b);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) best = std::min(best, q_dist2(*p[i], *p[j]));
  return best;
}

// Runs `filtered` (nullopt measures count as unsure) and compares with `exact`'s sign.
template <class Filter>
void expect_agrees(Tally& t, const Tet& tet, Filter filtered, const mpq_class& exact, int i) {
  const auto m = tet_measures(tet.a, tet.b, tet.c, tet.d);
  const Filtered f = m ? filtered(*m) : Filtered::Unsure;
  t.add(f);
  if (f != Filtered::Unsure) {
    ASSERT_EQ(static_cast<Sign>(f), q_sign(exact)) << i;
  }
}

TEST(FilterKitTet, RatioAtItsThreshold) {
  Gen g(11);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Tet tet = random_tet(g);
    const mpq_class r2 = exact::circumradius2(tet.a, tet.b, tet.c, tet.d);
    const mpq_class l2 = q_shortest_edge2(tet);
    const double bound = std::sqrt(mpq_class(r2 / l2).get_d()) * g.jitter();
    const auto lmin2 = shortest_edge2(tet.a, tet.b, tet.c, tet.d);
    ASSERT_TRUE(lmin2);
    const mpq_class exact = r2 - mpq_class(bound) * mpq_class(bound) * l2;
    expect_agrees(t, tet, [&](const TetMeasures& m) { return ratio_minus(m, *lmin2, bound); },
                  exact, i);
  }
  t.expect_both();
}

TEST(FilterKitTet, RadiusAtItsThreshold) {
  Gen g(12);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Tet tet = random_tet(g);
    const mpq_class r2 = exact::circumradius2(tet.a, tet.b, tet.c, tet.d);
    const double size = std::sqrt(r2.get_d()) * g.jitter();
    const mpq_class exact = r2 - mpq_class(size) * mpq_class(size);
    expect_agrees(t, tet, [&](const TetMeasures& m) { return radius_minus(m, size); }, exact, i);
  }
  t.expect_both();
}

TEST(FilterKitTet, VolumeAtItsThreshold) {
  Gen g(13);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Tet tet = random_tet(g);
    const mpq_class v6 = abs(exact::volume6(tet.a, tet.b, tet.c, tet.d));
    const double volume = v6.get_d() / 6 * g.jitter();
    const mpq_class exact = v6 - 6 * mpq_class(volume);
    expect_agrees(t, tet, [&](const TetMeasures& m) { return volume_minus(m, volume); }, exact,
                  i);
  }
  t.expect_both();
}

// The shortest edge's bracket holds the exact squared length, for tets with edges of
// nearly equal length (the minimum switches between edges within rounding).
TEST(FilterKitTet, ShortestEdgeBracketHoldsTheExactLength) {
  Gen g(18);
  for (int i = 0; i < kCases; ++i) {
    const Point a = g.point();
    const double r = std::fabs(g.coord()) + 0x1p-8;
    const Point b = along(a, g.direction(), r), c = along(a, g.direction(), r * g.jitter()),
                d = along(a, g.direction(), r * g.jitter());
    const auto l2 = shortest_edge2(a, b, c, d);
    ASSERT_TRUE(l2);
    const mpq_class exact = q_shortest_edge2({a, b, c, d});
    ASSERT_LE(mpq_class(l2->lo), exact) << i;
    ASSERT_GE(mpq_class(l2->hi), exact) << i;
  }
}

// Tets scaled by 2^s with s in [-140, 140]: the squares and products of the measures span
// [2^-1200, 2^1200], so they underflow and overflow; thresholds at the bound as above. Scaling
// by a power of two is exact, so the GMP answers scale with the tet.
TEST(FilterKitTet, AnswersStayRightWhereProductsUnderflowOrOverflow) {
  Gen g(14);
  std::mt19937 rng(14);
  std::uniform_int_distribution<int> scale(-140, 140);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    Tet tet = random_tet(g);
    const int s = scale(rng);
    for (Point* p : {&tet.a, &tet.b, &tet.c, &tet.d})
      for (double& x : *p) x = std::ldexp(x, s);
    const mpq_class r2 = exact::circumradius2(tet.a, tet.b, tet.c, tet.d);
    const mpq_class v6 = abs(exact::volume6(tet.a, tet.b, tet.c, tet.d));
    const double size = std::sqrt(r2.get_d()) * g.jitter();
    const double volume = v6.get_d() / 6 * g.jitter();
    if (i % 2) {
      expect_agrees(t, tet, [&](const TetMeasures& m) { return radius_minus(m, size); },
                    mpq_class(r2 - mpq_class(size) * mpq_class(size)), i);
    } else {
      expect_agrees(t, tet, [&](const TetMeasures& m) { return volume_minus(m, volume); },
                    mpq_class(v6 - 6 * mpq_class(volume)), i);
    }
  }
  t.expect_both();
}

// The Bracket operations on operands whose products fall below the normal range: the exact
// product or sum must lie in the computed bracket.
TEST(FilterKitTet, BracketsHoldTheirValueThroughUnderflow) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> mant(0.5, 1);
  std::uniform_int_distribution<int> ex(-560, -480);
  int underflowed = 0;
  for (int i = 0; i < kCases; ++i) {
    const double x = std::ldexp(mant(rng), ex(rng)), y = std::ldexp(mant(rng), ex(rng));
    const Bracket p = exactly(x) * exactly(y), s = p + p;
    const mpq_class q = mpq_class(x) * mpq_class(y);
    ASSERT_LE(mpq_class(p.lo), q) << i;
    ASSERT_GE(mpq_class(p.hi), q) << i;
    ASSERT_LE(mpq_class(s.lo), 2 * q) << i;
    ASSERT_GE(mpq_class(s.hi), 2 * q) << i;
    if (x * y < std::numeric_limits<double>::min()) ++underflowed;
  }
  EXPECT_GT(underflowed, kCases / 4);
  const Bracket big = exactly(0x1p600) * exactly(0x1p600);
  EXPECT_FALSE(std::isfinite(big.hi));
  EXPECT_EQ(compare(big, exactly(1)), Filtered::Unsure);
}

// The chart of a random facet plane t0 t1 t2 (surface/chart.hpp).
struct Chart {
  Point t0, t1, t2;
};
using QVec = std::array<mpq_class, 3>;
QVec q_sub(const Point& p, const Point& q) {
  return {mpq_class(p[0]) - q[0], mpq_class(p[1]) - q[1], mpq_class(p[2]) - q[2]};
}
mpq_class q_dot(const QVec& p, const QVec& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }

Sign q_chart_orient(const Chart& ch, const Point& a, const Point& b, const Point& c) {
  const QVec e1 = q_sub(ch.t1, ch.t0), e2 = q_sub(ch.t2, ch.t0), u = q_sub(b, a),
             v = q_sub(c, a);
  return q_sign(mpq_class(q_dot(e1, u) * q_dot(e2, v) - q_dot(e1, v) * q_dot(e2, u)));
}

Sign q_chart_incircle(const Chart& ch, const Point& a, const Point& b, const Point& c,
                      const Point& d) {
  const QVec e1 = q_sub(ch.t1, ch.t0), e2 = q_sub(ch.t2, ch.t0);
  const Point* p[3] = {&a, &b, &c};
  mpq_class x[3], y[3], w[3];
  for (int i = 0; i < 3; ++i) {
    const QVec e = q_sub(*p[i], d), sq = q_sub(*p[i], ch.t0), sd = q_sub(d, ch.t0);
    x[i] = q_dot(e1, e);
    y[i] = q_dot(e2, e);
    w[i] = q_dot(sq, sq) - q_dot(sd, sd);
  }
  return q_sign(mpq_class(x[0] * (y[1] * w[2] - y[2] * w[1]) + x[1] * (y[2] * w[0] - y[0] * w[2]) +
                          x[2] * (y[0] * w[1] - y[1] * w[0])));
}

TEST(FilterKitChart, OrientAtItsLine) {
  Gen g(16);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Chart ch{g.point(), g.point(), g.point()};
    const Point a = g.point(), b = g.point();
    // c on the chart line of a and b (moved along the plane's normal, which the chart does
    // not see), then a jitter off it within the plane's directions.
    const Point n = cross(sub(ch.t1, ch.t0), sub(ch.t2, ch.t0)), e = sub(b, a);
    const double s = g.coord(), h = g.coord() / std::sqrt(dot(n, n));
    const Point off = g.direction();
    const double j = (g.jitter() - 1) * std::sqrt(dot(e, e));
    Point c;
    for (int k = 0; k < 3; ++k) c[k] = a[k] + s * e[k] + h * n[k] + j * off[k];
    const Filtered f = chart_orient(ch.t0, ch.t1, ch.t2, a, b, c);
    t.add(f);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_chart_orient(ch, a, b, c)) << i;
    }
  }
  t.expect_both();
}

TEST(FilterKitChart, IncircleAtItsSphere) {
  Gen g(17);
  Tally t;
  for (int i = 0; i < kCases; ++i) {
    const Chart ch{g.point(), g.point(), g.point()};
    const Point a = g.point(), b = g.point(), c = g.point();
    // The centre o = t0 + s e1 + r e2 equidistant from a, b, c, solved in GMP:
    // 2 o.(q - a) = |q|^2 - |a|^2 for q = b, c.
    const QVec e1 = q_sub(ch.t1, ch.t0), e2 = q_sub(ch.t2, ch.t0), t0 = q_sub(ch.t0, {0, 0, 0});
    const QVec qa = q_sub(a, {0, 0, 0}), ub = q_sub(b, a), uc = q_sub(c, a);
    const mpq_class m11 = 2 * q_dot(e1, ub), m12 = 2 * q_dot(e2, ub), m21 = 2 * q_dot(e1, uc),
                    m22 = 2 * q_dot(e2, uc);
    const QVec qb = q_sub(b, {0, 0, 0}), qc = q_sub(c, {0, 0, 0});
    const mpq_class r1 = q_dot(qb, qb) - q_dot(qa, qa) - 2 * q_dot(t0, ub);
    const mpq_class r2 = q_dot(qc, qc) - q_dot(qa, qa) - 2 * q_dot(t0, uc);
    const mpq_class det = m11 * m22 - m12 * m21;
    if (det == 0) continue;
    const mpq_class s = (r1 * m22 - m12 * r2) / det, r = (m11 * r2 - r1 * m21) / det;
    Point o;
    for (int k = 0; k < 3; ++k) o[k] = mpq_class(t0[k] + s * e1[k] + r * e2[k]).get_d();
    const double radius = std::sqrt(q_dist2(o, a).get_d());
    const Point d = along(o, g.direction(), radius * g.jitter());
    const Filtered f = chart_incircle(ch.t0, ch.t1, ch.t2, a, b, c, d);
    t.add(f);
    if (f != Filtered::Unsure) {
      ASSERT_EQ(static_cast<Sign>(f), q_chart_incircle(ch, a, b, c, d)) << i;
    }
  }
  t.expect_both();
}

}  // namespace
}  // namespace pdr::filter
