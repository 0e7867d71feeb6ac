// Examples for the GMP reference (exact.hpp): hand-checked signs of each predicate, the
// sign conventions of predicates.hpp, and the exact measures.
#include "geom/exact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pdr {
namespace {

const Point o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};

TEST(ExactOrient, UnitSimplexIsPositive) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
  EXPECT_EQ(exact::orient2d(a, b, c), Sign::Positive);
  EXPECT_EQ(exact::orient2d(b, a, c), Sign::Negative);
  EXPECT_EQ(exact::orient3d(o, ex, ey, ez), Sign::Positive);
  EXPECT_EQ(exact::orient3d(ex, o, ey, ez), Sign::Negative);
  EXPECT_EQ(exact::orient3d(o, ex, ey, Point{5, 7, 0}), Sign::Zero);
}

TEST(ExactIncircle, InsideIsPositiveForCounterClockwise) {
  const double a[2] = {1, 0}, b[2] = {0, 1}, c[2] = {-1, 0};
  const double in[2] = {0, 0}, on[2] = {0, -1}, out[2] = {2, 2};
  EXPECT_EQ(exact::incircle(a, b, c, in), Sign::Positive);
  EXPECT_EQ(exact::incircle(b, a, c, in), Sign::Negative);
  EXPECT_EQ(exact::incircle(a, b, c, on), Sign::Zero);
  EXPECT_EQ(exact::incircle(a, b, c, out), Sign::Negative);
}

TEST(ExactInsphere, InsideIsPositiveForPositiveTet) {
  const Point in{0.1, 0.1, 0.1}, on{1, 1, 1}, out{2, 2, 2};
  EXPECT_EQ(exact::insphere(o, ex, ey, ez, in), Sign::Positive);
  EXPECT_EQ(exact::insphere(ex, o, ey, ez, in), Sign::Negative);
  EXPECT_EQ(exact::insphere(o, ex, ey, ez, on), Sign::Zero);
  EXPECT_EQ(exact::insphere(o, ex, ey, ez, out), Sign::Negative);
}

TEST(ExactIncircle3, OrientationFree) {
  // The circle through (1,0,0), (0,1,0), (0,0,1) has center (1/3,1/3,1/3).
  const Point c{1.0 / 3, 1.0 / 3, 1.0 / 3};  // not exactly the center, but inside
  EXPECT_EQ(exact::incircle3(ex, ey, ez, c), Sign::Positive);
  EXPECT_EQ(exact::incircle3(ey, ex, ez, c), Sign::Positive);
  const Point far{2, -1, 0};  // on the plane x + y + z = 1, outside
  EXPECT_EQ(exact::incircle3(ex, ey, ez, far), Sign::Negative);
  const Point on{1, 0, 0};
  EXPECT_EQ(exact::incircle3(ey, ez, Point{0.5, 0.5, 0}, Point{0, 0.5, 0.5}), Sign::Positive);
  EXPECT_EQ(exact::incircle3(ex, ey, ez, on), Sign::Zero);
  EXPECT_EQ(exact::incircle3(o, ex, Point{2, 0, 0}, ey), Sign::Zero);  // collinear a,b,c
}

TEST(ExactSos, NeverZeroOnNonDegenerateInput) {
  const Point cube[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  EXPECT_EQ(exact::insphere(cube[0], cube[1], cube[2], cube[4], cube[7]), Sign::Zero);
  EXPECT_NE(exact::insphere_sos(cube[0], cube[1], cube[2], cube[4], cube[7]), Sign::Zero);
  EXPECT_NE(exact::incircle3_sos(cube[0], cube[1], cube[2], cube[3]), Sign::Zero);
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1}, d[2] = {1, 1};
  EXPECT_NE(exact::incircle_sos(a, b, c, d), Sign::Zero);
  EXPECT_EQ(exact::incircle_sos(a, b, c, d), -exact::incircle_sos(b, a, c, d));
}

// The reference has no range limit: a lattice sphere scaled by 2^+-1000 and down to the
// smallest subnormal (products of coordinates underflow or overflow in double) keeps
// every exact sign.
TEST(ExactRange, ExtremeScales) {
  const double lattice[6][3] = {{3, 4, 0}, {-3, 4, 0}, {0, 0, 5}, {0, -5, 0}, {4, 0, 3},
                                {5, 0, 0}};
  for (const double s : {0x1p-1000, 0x1p-1074, 0x1p+1000, 0x1p+1019}) {
    Point p[6];
    for (int k = 0; k < 6; ++k)
      for (int i = 0; i < 3; ++i) p[k][i] = lattice[k][i] * s;
    EXPECT_EQ(exact::insphere(p[0], p[1], p[2], p[3], p[5]), Sign::Zero) << s;
    const Sign o = exact::orient3d(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(o, Sign::Negative) << s;
    Point in = p[5];
    in[0] = std::nextafter(in[0], 0.0);  // one ulp inside
    EXPECT_EQ(exact::insphere(p[0], p[1], p[2], p[3], in), o) << s;
    EXPECT_NE(exact::insphere_sos(p[0], p[1], p[2], p[3], p[5]), Sign::Zero) << s;
  }
}

TEST(ExactMeasures, UnitSimplex) {
  EXPECT_EQ(exact::volume6(o, ex, ey, ez), 1);
  EXPECT_EQ(exact::squared_distance(ex, ey), 2);
  const auto c = exact::circumcenter(o, ex, ey, ez);
  EXPECT_EQ(c[0], mpq_class(1, 2));
  EXPECT_EQ(c[1], mpq_class(1, 2));
  EXPECT_EQ(c[2], mpq_class(1, 2));
  EXPECT_EQ(exact::circumradius2(o, ex, ey, ez), mpq_class(3, 4));
}

}  // namespace
}  // namespace pdr
