// Encroachment predicates (encroach.hpp, paper §1.1): the filtered predicates against the
// GMP references on random, wide-range and exactly degenerate inputs (points on the
// sphere), and the laws: symmetry in the element's vertices, vertices on the sphere, the
// exact circumcenter inside and equidistant from the three vertices.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "geom/encroach.hpp"
#include "geom/exact.hpp"
#include "geom/predicates.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

bool collinear3(const Point& a, const Point& b, const Point& c) {
  const mpq_class ux = mpq_class(b[0]) - a[0], uy = mpq_class(b[1]) - a[1],
                  uz = mpq_class(b[2]) - a[2];
  const mpq_class vx = mpq_class(c[0]) - a[0], vy = mpq_class(c[1]) - a[1],
                  vz = mpq_class(c[2]) - a[2];
  return uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0;
}

TEST(Encroach, DiametralExamples) {
  const Point a{0, 0, 0}, b{2, 0, 0};
  EXPECT_EQ(in_diametral_ball(a, b, {1, 0.5, 0}), Sign::Positive);
  EXPECT_EQ(in_diametral_ball(a, b, {1, 1, 0}), Sign::Zero);   // on the sphere (Thales)
  EXPECT_EQ(in_diametral_ball(a, b, {1, 0, 1}), Sign::Zero);
  EXPECT_EQ(in_diametral_ball(a, b, {1, 1.5, 0}), Sign::Negative);
  EXPECT_EQ(in_diametral_ball(a, b, a), Sign::Zero);           // endpoints on the sphere
  EXPECT_EQ(in_diametral_ball(a, b, {1, 0, 0}), Sign::Positive);
  // A few ulps off the sphere are decided exactly.
  EXPECT_EQ(in_diametral_ball(a, b, {1, std::nextafter(1.0, 2.0), 0}), Sign::Negative);
  EXPECT_EQ(in_diametral_ball(a, b, {1, std::nextafter(1.0, 0.0), 0}), Sign::Positive);
}

TEST(Encroach, EquatorialExamples) {
  // Right triangle in z = 0: circumcenter (1,1,0), r^2 = 2.
  const Point a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
  EXPECT_EQ(in_equatorial_ball(a, b, c, {2, 2, 0}), Sign::Zero);  // cocircular
  EXPECT_EQ(in_equatorial_ball(a, b, c, {1, 1, 1}), Sign::Positive);
  EXPECT_EQ(in_equatorial_ball(a, b, c, {1, 2, 1}), Sign::Zero);  // |p-o|^2 = 1 + 1 = 2
  EXPECT_EQ(in_equatorial_ball(a, b, c, {1, 1, 2}), Sign::Negative);
  EXPECT_EQ(in_equatorial_ball(a, b, c, {2, 2, 1e-300}), Sign::Negative);
  EXPECT_EQ(in_equatorial_ball(a, b, c, {std::nextafter(2.0, 0.0), 2, 0}), Sign::Positive);
  const auto o = exact::triangle_circumcenter(a, b, c);
  EXPECT_EQ(o[0], 1);
  EXPECT_EQ(o[1], 1);
  EXPECT_EQ(o[2], 0);
  EXPECT_EQ(exact::triangle_circumradius2(a, b, c), 2);
}

TEST(Encroach, FilterAgreesWithGmp) {
  geomgen::Rng r(7);
  for (int i = 0; i < 20000; ++i) {
    const int kind = i % 4;
    Point a, b, c, p;
    if (kind == 0) {
      a = r.unit_point(), b = r.unit_point(), c = r.unit_point(), p = r.unit_point();
    } else if (kind == 1) {
      a = r.grid_point(3), b = r.grid_point(3), c = r.grid_point(3), p = r.grid_point(3);
    } else if (kind == 2) {
      a = r.wide_point(-60, 60), b = r.wide_point(-60, 60), c = r.wide_point(-60, 60);
      p = r.wide_point(-60, 60);
    } else {  // near the sphere: a vertex (on it) moved by a few ulps
      a = r.unit_point(), b = r.unit_point(), c = r.unit_point();
      p = r.nudge(a, 2);
    }
    if (a != b) {
      ASSERT_EQ(in_diametral_ball(a, b, p), exact::in_diametral_ball(a, b, p)) << i;
    }
    if (!collinear3(a, b, c)) {
      ASSERT_EQ(in_equatorial_ball(a, b, c, p), exact::in_equatorial_ball(a, b, c, p)) << i;
    }
  }
}

// Which triangle has the larger circumradius (Fig. 2's largest encroached subfacet): the
// filtered comparison agrees with GMP on random triangles, on congruent copies (exact
// ties: the copy is the triangle with its vertices rotated, or translated by a power of
// two, which is exact), and on copies with one vertex moved by an ulp or two (the
// filter's bound); it is antisymmetric; out of the filter's range it is still exact.
TEST(Encroach, CircumradiusComparisonAgreesWithGmp) {
  const auto reference = [](const Point& a, const Point& b, const Point& c, const Point& d,
                            const Point& e, const Point& f) {
    const int k = cmp(exact::triangle_circumradius2(a, b, c), exact::triangle_circumradius2(d, e, f));
    return k > 0 ? Sign::Positive : (k < 0 ? Sign::Negative : Sign::Zero);
  };
  geomgen::Rng r(17);
  int ties = 0, near = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point a = r.unit_point(), b = r.unit_point(), c = r.unit_point();
    if (collinear3(a, b, c)) continue;
    Point d, e, f;
    switch (i % 4) {
      case 0: d = r.unit_point(), e = r.unit_point(), f = r.unit_point(); break;
      case 1: d = b, e = c, f = a; break;  // the same triangle
      case 2: {                            // translated exactly by a power of two
        const Point t{4, -8, 16};
        d = {a[0] + t[0], a[1] + t[1], a[2] + t[2]};
        e = {b[0] + t[0], b[1] + t[1], b[2] + t[2]};
        f = {c[0] + t[0], c[1] + t[1], c[2] + t[2]};
        break;
      }
      default: d = r.nudge(a, 2), e = b, f = c; break;  // a vertex moved by a few ulps
    }
    if (collinear3(d, e, f)) continue;
    const Sign want = reference(a, b, c, d, e, f);
    ties += want == Sign::Zero;
    near += i % 4 == 3;
    ASSERT_EQ(compare_circumradius(a, b, c, d, e, f), want) << i;
    ASSERT_EQ(compare_circumradius(d, e, f, a, b, c), -want) << i;
  }
  EXPECT_GT(ties, 1000);
  EXPECT_GT(near, 1000);
  const double t = 0x1p-200;  // below the filter's range
  EXPECT_EQ(compare_circumradius({0, 0, 0}, {2 * t, 0, 0}, {0, 2 * t, 0}, {0, 0, 0}, {t, 0, 0},
                                 {0, t, 0}),
            Sign::Positive);
}

TEST(Encroach, OutOfFilterRangeStillExact) {
  const double t = 0x1p-200;
  const Point a{0, 0, 0}, b{2 * t, 0, 0}, c{0, 2 * t, 0};
  EXPECT_EQ(in_diametral_ball(a, b, {t, t / 2, 0}), Sign::Positive);
  EXPECT_EQ(in_equatorial_ball(a, b, c, {2 * t, 2 * t, 0}), Sign::Zero);
  EXPECT_EQ(in_equatorial_ball(a, b, c, {t, t, t}), Sign::Positive);
  const double big = 0x1p400;
  EXPECT_EQ(in_diametral_ball({0, 0, 0}, {big, 0, 0}, {big / 2, big / 2, 0}), Sign::Zero);
}

RC_GTEST_PROP(EncroachLaws, SymmetryAndVerticesOnSphere, ()) {
  geomgen::Rng r(*rc::gen::arbitrary<std::uint64_t>());
  const Point a = r.grid_point(4), b = r.grid_point(4), c = r.grid_point(4),
              p = r.grid_point(4);
  RC_PRE(!collinear3(a, b, c));
  RC_ASSERT(in_diametral_ball(a, b, p) == in_diametral_ball(b, a, p));
  RC_ASSERT(in_diametral_ball(a, b, a) == Sign::Zero);
  const Sign s = in_equatorial_ball(a, b, c, p);
  RC_ASSERT(in_equatorial_ball(b, c, a, p) == s);
  RC_ASSERT(in_equatorial_ball(c, b, a, p) == s);
  RC_ASSERT(in_equatorial_ball(a, b, c, a) == Sign::Zero);
  RC_ASSERT(in_equatorial_ball(a, b, c, c) == Sign::Zero);
  // The exact circumcenter is equidistant and lies in the plane of abc.
  const auto o = exact::triangle_circumcenter(a, b, c);
  const mpq_class r2 = exact::triangle_circumradius2(a, b, c);
  for (const Point& v : {a, b, c}) {
    mpq_class s2 = 0;
    for (int k = 0; k < 3; ++k) s2 += (o[k] - v[k]) * (o[k] - v[k]);
    RC_ASSERT(s2 == r2);
  }
}

RC_GTEST_PROP(EncroachLaws, EquatorialContainsTheSubsegmentBallOfTheHypotenuse, ()) {
  // For a right triangle the equatorial sphere is the diametral sphere of the hypotenuse:
  // the two predicates agree on every point of the plane of the triangle.
  geomgen::Rng r(*rc::gen::arbitrary<std::uint64_t>());
  const double x = r.integer(1, 9), y = r.integer(1, 9);
  const Point a{0, 0, 0}, b{x, 0, 0}, c{0, y, 0};
  const Point p{double(r.integer(-10, 10)), double(r.integer(-10, 10)), 0};
  RC_ASSERT(in_equatorial_ball(a, b, c, p) == in_diametral_ball(b, c, p));
}

}  // namespace
}  // namespace pdr
