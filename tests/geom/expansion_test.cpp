// Expansion arithmetic (expansion.hpp) against GMP: every operation is exact and returns
// a valid expansion (increasing magnitude, nonoverlapping, zero-free), whose sign is the
// sign of its value. Built with -ffp-contract=off like pdr_geom (see CMakeLists.txt).
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "geom/expansion.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

using expansion::Expansion;

mpq_class value(const double* c, int n) {
  mpq_class s = 0;
  for (int i = 0; i < n; ++i) s += mpq_class(c[i]);
  return s;
}
template <int N>
mpq_class value(const Expansion<N>& e) {
  return value(e.c, e.n);
}

// Exponent of the least significant nonzero bit of x != 0.
int low_bit(double x) {
  int e;
  const double m = std::frexp(std::fabs(x), &e);  // x = m 2^e, m in [0.5, 1)
  auto bits = static_cast<std::uint64_t>(std::ldexp(m, 53));
  int k = e - 53;
  while ((bits & 1) == 0) {
    bits >>= 1;
    ++k;
  }
  return k;
}

// Valid: nonzero components, each one's highest bit below the next one's lowest bit.
bool valid(const double* c, int n) {
  for (int i = 0; i < n; ++i)
    if (c[i] == 0 || !std::isfinite(c[i])) return false;
  for (int i = 0; i + 1 < n; ++i)
    if (std::ilogb(c[i]) >= low_bit(c[i + 1])) return false;
  return true;
}

// A random valid expansion with up to N components, grown from wide doubles.
template <int N>
Expansion<N> random_expansion(geomgen::Rng& r, int lo, int hi) {
  Expansion<N> e;
  const int terms = r.integer(0, N - 1);
  for (int t = 0; t < terms; ++t) {
    double h[N];
    const int n = expansion::grow(e.c, e.n, r.wide(lo, hi), h);
    for (int i = 0; i < n; ++i) e.c[i] = h[i];
    e.n = n;
  }
  return e;
}

RC_GTEST_PROP(Expansion, GrowAndSumAreExact, ()) {
  geomgen::Rng r(geomgen::rc_seed());
  const auto e = random_expansion<12>(r, -500, 500);
  const auto f = random_expansion<12>(r, -500, 500);
  RC_ASSERT(valid(e.c, e.n));
  const auto s = e + f;
  RC_ASSERT(valid(s.c, s.n));
  RC_ASSERT(value(s) == value(e) + value(f));
  const auto d = e - f;
  RC_ASSERT(valid(d.c, d.n));
  RC_ASSERT(value(d) == value(e) - value(f));
  RC_ASSERT(to_int(d.sign()) == sgn(value(d)));
  RC_ASSERT(to_int((e - e).sign()) == 0);
}

RC_GTEST_PROP(Expansion, ScaleAndProductAreExact, ()) {
  geomgen::Rng r(geomgen::rc_seed());
  const auto e = random_expansion<8>(r, -200, 200);
  const auto f = random_expansion<6>(r, -200, 200);
  const double b = r.wide(-200, 200);
  const auto s = e * b;
  RC_ASSERT(valid(s.c, s.n));
  RC_ASSERT(value(s) == value(e) * mpq_class(b));
  const auto p = e * f;
  RC_ASSERT(valid(p.c, p.n));
  RC_ASSERT(value(p) == value(e) * value(f));
  RC_ASSERT(to_int(p.sign()) == sgn(value(p)));
}

RC_GTEST_PROP(Expansion, CompressKeepsValueAndValidity, ()) {
  geomgen::Rng r(geomgen::rc_seed());
  const auto e = random_expansion<10>(r, -200, 200) * random_expansion<6>(r, -200, 200);
  const auto c = expansion::compressed(e);
  RC_ASSERT(valid(c.c, c.n));
  RC_ASSERT(c.n <= e.n);
  RC_ASSERT(value(c) == value(e));
  RC_ASSERT(c.sign() == e.sign());
  // The largest component approximates the value to within an ulp or so.
  if (c.n > 0) {
    const double top = c.c[c.n - 1];
    RC_ASSERT(std::fabs(top - value(c).get_d()) <= 0x1p-51 * std::fabs(top));
  }
}

RC_GTEST_PROP(Expansion, CrossDifferenceIsExact, ()) {
  geomgen::Rng r(geomgen::rc_seed());
  const double a = r.wide(-300, 300), b = r.wide(-300, 300);
  const double c = r.coin() ? a : r.wide(-300, 300), d = r.coin() ? b : r.wide(-300, 300);
  const auto x = expansion::cross_difference(a, b, c, d);
  RC_ASSERT(valid(x.c, x.n));
  RC_ASSERT(value(x) == mpq_class(a) * b - mpq_class(c) * d);
}

TEST(Expansion, CancellationLeavesNoZeros) {
  // (1 + 2^-60) - 1 - 2^-60 is exactly zero; each step must eliminate zero components.
  const auto e = expansion::single(1.0) + expansion::single(0x1p-60);
  EXPECT_EQ(e.n, 2);
  const auto z = (e - expansion::single(1.0)) - expansion::single(0x1p-60);
  EXPECT_EQ(z.n, 0);
  EXPECT_EQ(z.sign(), Sign::Zero);
  const auto p = expansion::product(1 + 0x1p-52, 1 - 0x1p-52);  // 1 - 2^-104
  EXPECT_EQ(p.n, 2);
  EXPECT_EQ(p.sign(), Sign::Positive);
  EXPECT_EQ(value(p), 1 - mpq_class(1, 1) / (mpz_class(1) << 104));
}

}  // namespace
}  // namespace pdr
