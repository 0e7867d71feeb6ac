// The filters of geom/filter_kit.hpp driven to their bounds: inputs rounded off the
// sphere or the threshold each filter decides about, so that |value| is a few rounding
// errors and the filter's bound matters. Whenever a filter answers, its sign must equal
// the GMP reference's; every test also requires that the filter was unsure on some inputs
// (they reached the bound) and answered on others (it is not vacuously unsure). A filter
// whose coefficient is below its derived count answers wrongly here.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <random>

#include "geom/encroach.hpp"
#include "geom/filter_kit.hpp"

namespace pdr::filter {
namespace {

constexpr int kCases = 20000;

struct Tally {
  int answered = 0, unsure = 0;
  void add(Filtered f) { (f == Filtered::Unsure ? unsure : answered)++; }
  void expect_both() const {
    EXPECT_GT(unsure, 0) << "no input reached the bound";
    EXPECT_GT(answered, 0) << "the filter never answered";
  }
};

class Gen {
 public:
  explicit Gen(unsigned seed) : rng_(seed) {}
  // A coordinate of random magnitude in [2^-8, 2^8], non-dyadic.
  double coord() {
    std::uniform_real_distribution<double> x(-1, 1);
    std::uniform_int_distribution<int> e(-8, 8);
    return std::ldexp(x(rng_), e(rng_));
  }
  Point point() { return {coord(), coord(), coord()}; }
  // 1 +- 2^-j, j in [10, 60]: from clearly off the threshold down to below its rounding.
  double jitter() {
    std::uniform_int_distribution<int> j(10, 60);
    return 1 + ((rng_() & 1) ? 1 : -1) * std::ldexp(1.0, -j(rng_));
  }
  Point direction() {
    std::normal_distribution<double> g;
    Point d{g(rng_), g(rng_), g(rng_)};
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d) x /= l;
    return d;
  }

 private:
  std::mt19937_64 rng_;
};

Point along(const Point& o, const Point& dir, double r) {
  return {o[0] + r * dir[0], o[1] + r * dir[1], o[2] + r * dir[2]};
}

mpq_class q_dist2(const Point& a, const Point& b) {
  mpq_class s = 0;
  for (int k = 0; k < 3; ++k) {
    const mpq_class e = mpq_class(a[k]) - mpq_class(b[k]);
    s += e * e;
  }
  return s;
}

Sign q_sign(const mpq_class& x) { return sign_of(sgn(x)); }

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

}  // namespace
}  // namespace pdr::filter
