// The fp-contract guard (docs/design.md §7): pdr_geom must be compiled without floating-point
// contraction, and its error-free transformations must be exact as compiled there.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "geom/fp_probe.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

TEST(FpContract, ProbeRoundsTwice) {
  // (1 + 2^-30)(1 - 2^-30) = 1 - 2^-60 rounds to 1, so a*b - 1 is 0 in two steps but
  // -2^-60 when fused.
  volatile double a = 1 + 0x1p-30, b = 1 - 0x1p-30, c = -1;
  ASSERT_NE(std::fma(a, b, c), 0.0);  // the inputs do separate the two evaluations
  EXPECT_EQ(detail::fp_contract_probe(a, b, c), 0.0)
      << "fp-contract: pdr_geom fuses a*b+c; build it with -ffp-contract=off";
  EXPECT_NE(detail::fp_contract_probe(a, b, c), std::fma(a, b, c));
}

mpq_class q(double x) { return mpq_class(x); }

TEST(FpContract, TwoProductIsExactOnHardCases) {
  const double cases[][2] = {{1 + 0x1p-52, 1 - 0x1p-52},
                             {0x1.fffffffffffffp+0, 0x1.fffffffffffffp+0},
                             {3.0, 0.1},
                             {-0x1.123456789abcdp+200, 0x1.fedcba9876543p-300},
                             {0x1.fffffffffffffp+994, 0x1.8000000000001p+0}};  // split limit
  for (const auto& c : cases) {
    double x, y;
    detail::probe_two_product(c[0], c[1], x, y);
    EXPECT_EQ(q(x) + q(y), q(c[0]) * q(c[1])) << c[0] << " * " << c[1];
    EXPECT_EQ(x, c[0] * c[1]);
  }
}

RC_GTEST_PROP(FpContract, TwoSumIsExact, ()) {
  const double a = *geomgen::wide_double(-600, 600), b = *geomgen::wide_double(-600, 600);
  double x, y;
  detail::probe_two_sum(a, b, x, y);
  RC_ASSERT(x == a + b);
  RC_ASSERT(q(x) + q(y) == q(a) + q(b));
}

RC_GTEST_PROP(FpContract, TwoProductIsExact, ()) {
  // Exponents kept so that neither the product nor its error under/overflows.
  const double a = *geomgen::wide_double(-400, 400), b = *geomgen::wide_double(-400, 400);
  double x, y;
  detail::probe_two_product(a, b, x, y);
  RC_ASSERT(x == a * b);
  RC_ASSERT(q(x) + q(y) == q(a) * q(b));
}

}  // namespace
}  // namespace pdr
