// Differential tests: every adaptive predicate (filter + stage 2, and stage 2 alone) gives
// the sign of the GMP reference, on random doubles over the whole documented exponent
// range, near-degenerate inputs (a few ulps off a plane, sphere or circle) and exactly
// degenerate ones (integer grids, lattice spheres and circles, repeated points), scaled to
// the edges of the range. Also the filter alone: never wrong when it answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstdint>
#include <string>

#include "geom/exact.hpp"
#include "geom/filter.hpp"
#include "geom/predicates.hpp"
#include "geom/stage2.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

using geomgen::Kind;
using geomgen::Rng;

// Cases per input kind; PDR_GEOM_SOAK=<factor> multiplies it for long runs.
int cases_per_kind() {
  static const int n = [] {
    const char* soak = std::getenv("PDR_GEOM_SOAK");
    return 1000 * (soak ? std::max(1, std::atoi(soak)) : 1);
  }();
  return n;
}

std::string describe(std::uint64_t seed, Kind kind) {
  return "seed " + std::to_string(seed) + " kind " + std::to_string(static_cast<int>(kind));
}

// Checks filter (when sure), adaptive and stage-2 signs against the reference.
void expect_agree(Filtered f, Sign adaptive, Sign stage2, Sign exact, const std::string& what) {
  if (f != Filtered::Unsure) {
    EXPECT_EQ(static_cast<Sign>(f), exact) << "filter, " << what;
  }
  EXPECT_EQ(adaptive, exact) << "adaptive, " << what;
  EXPECT_EQ(stage2, exact) << "stage 2, " << what;
}

template <class Body>
void for_all_cases(std::uint64_t salt, Body body) {
  for (int k = 0; k < geomgen::kKinds; ++k) {
    for (int i = 0; i < cases_per_kind(); ++i) {
      const std::uint64_t seed = salt * 1000003u + static_cast<std::uint64_t>(k * 100000 + i);
      Rng r(seed);
      body(r, static_cast<Kind>(k), describe(seed, static_cast<Kind>(k)));
    }
  }
}

TEST(Predicates, Orient2dMatchesGmp) {
  for_all_cases(1, [](Rng& r, Kind kind, const std::string& what) {
    const auto p = geomgen::flat_case<3>(r, kind, geomgen::kOrient2dRange);
    const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data();
    expect_agree(filter::orient2d(a, b, c), orient2d(a, b, c), stage2::orient2d(a, b, c),
                 exact::orient2d(a, b, c), what);
  });
}

TEST(Predicates, Orient3dMatchesGmp) {
  for_all_cases(2, [](Rng& r, Kind kind, const std::string& what) {
    const auto p = geomgen::space_case<4>(r, kind, geomgen::kOrient3dRange);
    expect_agree(filter::orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data()),
                 orient3d(p[0], p[1], p[2], p[3]), stage2::orient3d(p[0], p[1], p[2], p[3]),
                 exact::orient3d(p[0], p[1], p[2], p[3]), what);
  });
}

TEST(Predicates, IncircleMatchesGmp) {
  for_all_cases(3, [](Rng& r, Kind kind, const std::string& what) {
    const auto q = geomgen::flat_case<4>(r, kind, geomgen::kIncircleRange);
    const double *a = q[0].data(), *b = q[1].data(), *c = q[2].data(), *d = q[3].data();
    expect_agree(filter::incircle(a, b, c, d), incircle(a, b, c, d),
                 stage2::incircle(a, b, c, d), exact::incircle(a, b, c, d), what);
  });
}

TEST(Predicates, InsphereMatchesGmp) {
  for_all_cases(4, [](Rng& r, Kind kind, const std::string& what) {
    const auto p = geomgen::space_case<5>(r, kind, geomgen::kInsphereRange);
    expect_agree(
        filter::insphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()),
        insphere(p[0], p[1], p[2], p[3], p[4]), stage2::insphere(p[0], p[1], p[2], p[3], p[4]),
        exact::insphere(p[0], p[1], p[2], p[3], p[4]), what);
  });
}

TEST(Predicates, Incircle3MatchesGmp) {
  for_all_cases(5, [](Rng& r, Kind kind, const std::string& what) {
    const auto p = geomgen::plane_case<4>(r, kind, geomgen::kIncircleRange);
    expect_agree(filter::incircle3(p[0].data(), p[1].data(), p[2].data(), p[3].data()),
                 incircle3(p[0], p[1], p[2], p[3]), stage2::incircle3(p[0], p[1], p[2], p[3]),
                 exact::incircle3(p[0], p[1], p[2], p[3]), what);
  });
}

// The filter answers on almost all well-separated random input (it is a filter, not a
// formality) and only says Zero when the determinant is exactly zero.
TEST(Filter, AnswersOnRandomInput) {
  Rng r(77);
  int unsure = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point a = r.unit_point(), b = r.unit_point(), c = r.unit_point(), d = r.unit_point(),
                e = r.unit_point();
    unsure += filter::orient3d(a.data(), b.data(), c.data(), d.data()) == Filtered::Unsure;
    unsure += filter::insphere(a.data(), b.data(), c.data(), d.data(), e.data()) ==
              Filtered::Unsure;
  }
  EXPECT_LT(unsure, 40);
  // On the plane z = x + y: det = 0 but the permanent is not, so only stage 2 can tell.
  const Point o{0, 0, 0}, x{1, 0, 1}, y{0, 1, 1}, xy{1, 1, 2};
  EXPECT_EQ(filter::orient3d(o.data(), x.data(), y.data(), xy.data()), Filtered::Unsure);
  EXPECT_EQ(orient3d(o, x, y, xy), Sign::Zero);
  // A repeated point, or all four on z = 0: every term has a zero factor, P = 0.
  EXPECT_EQ(filter::orient3d(o.data(), o.data(), y.data(), x.data()), Filtered::Zero);
  const Point x0{1, 0, 0}, y0{0, 1, 0}, xy0{1, 1, 0};
  EXPECT_EQ(filter::orient3d(o.data(), x0.data(), y0.data(), xy0.data()), Filtered::Zero);
}

// Coordinates at the edges of each documented range, and far from 1 on both sides.
TEST(Predicates, ExtremeScales) {
  const double lattice[5][3] = {{3, 4, 0}, {-3, 4, 0}, {0, 0, 5}, {0, -5, 0}, {4, 0, 3}};
  const double near_on[3] = {5, 0, 0};
  for (int e : {-120, -60, -1, 0, 1, 60, 120}) {
    std::array<Point, 6> p;
    for (int k = 0; k < 5; ++k)
      for (int i = 0; i < 3; ++i) p[k][i] = std::ldexp(lattice[k][i] + 1, e);
    for (int i = 0; i < 3; ++i) p[5][i] = std::ldexp(near_on[i] + 1, e);
    EXPECT_EQ(insphere(p[0], p[1], p[2], p[3], p[4]), Sign::Zero) << e;
    EXPECT_EQ(insphere(p[0], p[1], p[2], p[3], p[5]), Sign::Zero) << e;
    Point off = p[5];
    off[0] = std::nextafter(off[0], 0.0);  // one ulp inside the sphere
    const Sign o = orient3d(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(insphere(p[0], p[1], p[2], p[3], off), o) << e;
    EXPECT_EQ(exact::insphere(p[0], p[1], p[2], p[3], off), o) << e;
  }
  for (double s : {1e-130, 1e-100, 1e100, 1e130}) {  // orient2d's range is 2^+-450
    const double a[2] = {s, s}, b[2] = {3 * s, 2 * s};
    const double c[2] = {5 * s, 3 * s};  // collinear unless 3s, 5s were rounded
    EXPECT_EQ(orient2d(a, b, c), exact::orient2d(a, b, c)) << s;
    const double d[2] = {std::nextafter(5 * s, 0.0), 3 * s};
    EXPECT_EQ(orient2d(a, b, d), exact::orient2d(a, b, d)) << s;
  }
}

// Outside the filters' range (found by fuzz_predicates over the whole double range): a unit
// square and right tetrahedron scaled by 2^-1074 (every product underflows to zero, so the
// permanent is zero and the filter says Zero), and an incircle whose deciding term is a
// product that underflows while a huge lift keeps the permanent large (the filter said -1,
// the exact sign is +1). The predicates must give the GMP reference's signs.
TEST(Predicates, OutsideTheRangeTheFilterIsNotTrusted) {
  const double t = 0x1p-1074;
  const double a[2] = {0, 0}, b[2] = {t, 0}, c[2] = {0, t};
  EXPECT_EQ(orient2d(a, b, c), Sign::Positive);
  EXPECT_EQ(orient2d(a, b, c), exact::orient2d(a, b, c));
  const Point o{0, 0, 0}, x{t, 0, 0}, y{0, t, 0}, z{0, 0, t};
  EXPECT_EQ(orient3d(o, x, y, z), exact::orient3d(o, x, y, z));
  EXPECT_NE(orient3d(o, x, y, z), Sign::Zero);
  const double p[4][2] = {{-0x1.9cf6113e0fb51p-751, 0x1.0cb80a9e9e4f6p+389},
                          {-0x1.60be2b2655143p-229, -0x1.36c4e206bcf1ep-702},
                          {0x1.20df6c7a484ecp-920, -0x1.94a303fc7213dp-933},
                          {0x1.522deca9abc22p-653, 0x1.a7291fda766c1p-940}};
  EXPECT_EQ(incircle(p[0], p[1], p[2], p[3]), exact::incircle(p[0], p[1], p[2], p[3]));
  EXPECT_EQ(exact::incircle(p[0], p[1], p[2], p[3]), Sign::Positive);
}

}  // namespace
}  // namespace pdr
