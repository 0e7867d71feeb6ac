// Inputs for the filter kit's bound tests (filter_kit_test.cpp, filter_kit_tet_test.cpp):
// coordinates of random magnitude, jitters from clearly off a threshold to below its
// rounding, and the tally that makes each test show it reached the bound.
#pragma once

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geom/filter.hpp"
#include "geom/point.hpp"

namespace pdr::filter {

inline constexpr int kCases = 20000;

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

inline Point along(const Point& o, const Point& dir, double r) {
  return {o[0] + r * dir[0], o[1] + r * dir[1], o[2] + r * dir[2]};
}

inline mpq_class q_dist2(const Point& a, const Point& b) {
  mpq_class s = 0;
  for (int k = 0; k < 3; ++k) {
    const mpq_class e = mpq_class(a[k]) - mpq_class(b[k]);
    s += e * e;
  }
  return s;
}

inline Sign q_sign(const mpq_class& x) { return sign_of(sgn(x)); }

}  // namespace pdr::filter
