// Floating-point constructions (construct.hpp) against exact rational circumcenters: the
// error stays within the documented a-priori bounds (checked with a factor 2 of slack).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geom/construct.hpp"
#include "geom/encroach.hpp"
#include "geom/exact.hpp"
#include "geom/predicates.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

constexpr double u = 0x1p-53;

double d(const mpq_class& x) { return x.get_d(); }

double len(const Point& p, const Point& q) {
  return std::sqrt(exact::squared_distance(p, q).get_d());
}

TEST(Construct, MidpointIsRoundedOnceAndNeverOverflows) {
  EXPECT_EQ(construct::midpoint({1, 2, 3}, {3, 4, 6}), (Point{2, 3, 4.5}));
  const double big = 0x1.fffffffffffffp+1023;
  EXPECT_EQ(construct::midpoint({big, -big, 0}, {big, -big, 0}), (Point{big, -big, 0}));
}

TEST(Construct, TetCircumcenterWithinBound) {
  geomgen::Rng r(11);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const bool lattice = i % 2 == 1;
    const auto p = geomgen::space_case<4>(
        r, lattice ? geomgen::Kind::Lattice : geomgen::Kind::Unit, 30);
    if (orient3d(p[0], p[1], p[2], p[3]) == Sign::Zero) continue;
    const auto c = exact::circumcenter(p[0], p[1], p[2], p[3]);
    const Point x = construct::circumcenter_offset(p[0], p[1], p[2], p[3]);
    const Point y = construct::circumcenter(p[0], p[1], p[2], p[3]);
    const double L = std::max({len(p[0], p[1]), len(p[0], p[2]), len(p[0], p[3])});
    const double D = 2 * std::fabs(exact::volume6(p[0], p[1], p[2], p[3]).get_d());
    const double R = std::sqrt(exact::circumradius2(p[0], p[1], p[2], p[3]).get_d());
    if (12 * 9 * u * L * L * L >= D / 2) continue;  // outside the bound's precondition
    const double bound = 13 * u * (6 * L * L * L * L + 12 * R * L * L * L) / D + u * R;
    for (int k = 0; k < 3; ++k) {
      const mpq_class xk = c[k] - mpq_class(p[0][k]);
      EXPECT_LE(std::fabs(d(mpq_class(x[k]) - xk)), 2 * bound) << i;
      EXPECT_LE(std::fabs(d(mpq_class(y[k]) - c[k])),
                2 * (bound + u * std::fabs(c[k].get_d())))
          << i;
    }
    const double r2 = construct::circumradius2(p[0], p[1], p[2], p[3]);
    EXPECT_LE(std::fabs(r2 - R * R), 2 * (2 * bound * R + 3 * u * R * R)) << i;
    ++checked;
  }
  EXPECT_GT(checked, 1500);
}

TEST(Construct, TriangleCircumcenterWithinBound) {
  geomgen::Rng r(12);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto p = geomgen::space_case<3>(
        r, i % 2 ? geomgen::Kind::Lattice : geomgen::Kind::Unit, 30);
    const Point& a = p[0];
    const Point& b = p[1];
    const Point& c = p[2];
    // Exact center: the circumcenter of a, b, c and q = a + n, projected onto the plane.
    const mpq_class ux = mpq_class(b[0]) - a[0], uy = mpq_class(b[1]) - a[1],
                    uz = mpq_class(b[2]) - a[2];
    const mpq_class vx = mpq_class(c[0]) - a[0], vy = mpq_class(c[1]) - a[1],
                    vz = mpq_class(c[2]) - a[2];
    const std::array<mpq_class, 3> n = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    const mpq_class n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (sgn(n2) == 0) continue;
    const Point q = {a[0] + n[0].get_d(), a[1] + n[1].get_d(), a[2] + n[2].get_d()};
    if (orient3d(a, b, c, q) == Sign::Zero) continue;
    const auto s = exact::circumcenter(a, b, c, q);
    const mpq_class t = ((s[0] - a[0]) * n[0] + (s[1] - a[1]) * n[1] + (s[2] - a[2]) * n[2]) / n2;
    const double L = std::max(len(a, b), len(a, c));
    const double A = std::sqrt(n2.get_d()) / 2;
    mpq_class R2 = 0;
    std::array<mpq_class, 3> m;
    for (int k = 0; k < 3; ++k) {
      m[k] = s[k] - t * n[k];
      R2 += (m[k] - a[k]) * (m[k] - a[k]);
    }
    const double R = std::sqrt(R2.get_d());
    const double bound =
        15 * u * (8 * std::pow(L, 5) + 24 * R * std::pow(L, 4)) / (8 * A * A) + u * R;
    if (bound > R) continue;  // nearly collinear: the bound says nothing
    const Point x = construct::triangle_circumcenter_offset(a, b, c);
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(std::fabs(d(mpq_class(x[k]) - (m[k] - a[k]))), 2 * bound) << i;
    const double r2 = construct::triangle_circumradius2(a, b, c);
    EXPECT_LE(std::fabs(r2 - R * R), 2 * (2 * bound * R + 3 * u * R * R)) << i;
    const Point y = construct::triangle_circumcenter(a, b, c);
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(std::fabs(d(mpq_class(y[k]) - m[k])),
                2 * (bound + u * std::fabs(m[k].get_d())));
    ++checked;
  }
  EXPECT_GT(checked, 1500);
}

// Nearly flat tetrahedra and nearly collinear triangles (four points near a circle, three
// near a line, perturbed by a few ulps of non-dyadic coordinates): the floating-point
// formula is far off there, so the construction falls back to the exact center; either
// way the result is within 2^-22 R of the true center in every coordinate.
TEST(Construct, CircumcentersOfSliversAreAccurate) {
  geomgen::Rng r(13);
  int far_off = 0;
  for (int i = 0; i < 400; ++i) {
    const double s = 0.1 + 0.01 * (i % 7);
    std::array<Point, 4> p;
    for (int k = 0; k < 4; ++k) {
      const double t = 1.7 * k + 0.3 * (i % 5);
      // On the circle of radius s in the plane y = 0.05, nudged off it by an ulp or so.
      p[k] = {0.05 + s * std::cos(t), 0.05 + (k == 3 ? 0x1p-56 * (1 + i % 3) : 0.0),
              0.05 + s * std::sin(t)};
    }
    if (orient3d(p[0], p[1], p[2], p[3]) == Sign::Zero) continue;
    const auto c = exact::circumcenter(p[0], p[1], p[2], p[3]);
    const double R = std::sqrt(exact::circumradius2(p[0], p[1], p[2], p[3]).get_d());
    const Point x = construct::circumcenter(p[0], p[1], p[2], p[3]);
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(std::fabs(d(mpq_class(x[k]) - c[k])), 0x1p-22 * R) << i;
    // The plain formula is not within that bound on most of these (the test is not vacuous).
    const double L = std::max({len(p[0], p[1]), len(p[0], p[2]), len(p[0], p[3])});
    far_off += 12 * 9 * u * L * L * L >= 2 * std::fabs(exact::volume6(p[0], p[1], p[2], p[3]).get_d()) / 4;
  }
  EXPECT_GT(far_off, 100);
  for (int i = 0; i < 200; ++i) {
    const Point a = {0.1, 0.3, 0.7}, b = {0.1 + 0.1 * (1 + i % 9), 0.3, 0.7};
    const Point c = {0.1 + 0.05 * (1 + i % 4), 0.3 + 0x1p-50 * (1 + i % 5), 0.7};
    const auto q = exact::triangle_circumcenter(a, b, c);
    const double R = std::sqrt(exact::triangle_circumradius2(a, b, c).get_d());
    const Point x = construct::triangle_circumcenter(a, b, c);
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(std::fabs(d(mpq_class(x[k]) - q[k])), 0x1p-22 * R + 0x1p-52 * std::fabs(q[k].get_d())) << i;
  }
}

}  // namespace
}  // namespace pdr
