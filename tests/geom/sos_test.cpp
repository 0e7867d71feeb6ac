// Symbolic perturbation (sos.cpp) against its definition (exact.cpp) and its laws:
// equal to the exact predicate when that is nonzero; never Zero for a non-degenerate
// simplex; antisymmetric in all arguments (the perturbation belongs to the point, not to
// its position); incircle3_sos is the restriction of insphere_sos to the plane,
// incircle3_sos(a,b,c,d) == insphere_sos(a,b,c,q,d) * orient3d(a,b,c,q) for any q off the
// plane, checked on cocircular coplanar lattice sets; and on z = const it is incircle_sos
// made orientation-free.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "geom/exact.hpp"
#include "geom/predicates.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

using geomgen::Kind;
using geomgen::Rng;

// Degenerate inputs are what SoS is for: draw mostly grids, lattices and repeats.
Kind degenerate_kind(Rng& r) {
  constexpr Kind kinds[] = {Kind::Grid, Kind::Lattice, Kind::Lattice, Kind::NearDegenerate,
                            Kind::Unit};
  return kinds[r.integer(0, 4)];
}

Rng seeded() { return Rng(geomgen::rc_seed()); }

template <std::size_t N>
bool distinct(const std::array<Point, N>& p) {
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j)
      if (p[i] == p[j]) return false;
  return true;
}

TEST(Sos, AdaptiveMatchesDefinition) {
  for (int i = 0; i < 1500; ++i) {
    Rng r(9000 + i);
    const Kind kind = static_cast<Kind>(i % geomgen::kKinds);
    const auto s = geomgen::space_case<5>(r, kind, geomgen::kInsphereRange);
    EXPECT_EQ(insphere_sos(s[0], s[1], s[2], s[3], s[4]),
              exact::insphere_sos(s[0], s[1], s[2], s[3], s[4]))
        << "seed " << 9000 + i;
    const auto p = geomgen::plane_case<4>(r, kind, geomgen::kIncircleRange);
    EXPECT_EQ(incircle3_sos(p[0], p[1], p[2], p[3]), exact::incircle3_sos(p[0], p[1], p[2], p[3]))
        << "seed " << 9000 + i;
    const auto f = geomgen::flat_case<4>(r, kind, geomgen::kIncircleRange);
    EXPECT_EQ(incircle_sos(f[0].data(), f[1].data(), f[2].data(), f[3].data()),
              exact::incircle_sos(f[0].data(), f[1].data(), f[2].data(), f[3].data()))
        << "seed " << 9000 + i;
  }
}

RC_GTEST_PROP(Sos, InsphereSosRefinesInsphereAndIsNeverZero, ()) {
  Rng r = seeded();
  const auto p = geomgen::space_case<5>(r, degenerate_kind(r), geomgen::kInsphereRange);
  const Sign plain = insphere(p[0], p[1], p[2], p[3], p[4]);
  const Sign sos = insphere_sos(p[0], p[1], p[2], p[3], p[4]);
  if (plain != Sign::Zero) RC_ASSERT(sos == plain);
  if (orient3d(p[0], p[1], p[2], p[3]) != Sign::Zero) RC_ASSERT(sos != Sign::Zero);
}

RC_GTEST_PROP(Sos, InsphereSosIsAntisymmetricInAllFive, ()) {
  Rng r = seeded();
  const auto p = geomgen::space_case<5>(r, degenerate_kind(r), geomgen::kInsphereRange);
  RC_PRE(distinct(p));
  const int i = r.integer(0, 4), j = (i + r.integer(1, 4)) % 5;
  auto q = p;
  std::swap(q[i], q[j]);
  RC_ASSERT(insphere_sos(q[0], q[1], q[2], q[3], q[4]) ==
            -insphere_sos(p[0], p[1], p[2], p[3], p[4]));
}

RC_GTEST_PROP(Sos, IncircleSosLaws, ()) {
  Rng r = seeded();
  const auto f = geomgen::flat_case<4>(r, degenerate_kind(r), geomgen::kIncircleRange);
  const double *a = f[0].data(), *b = f[1].data(), *c = f[2].data(), *d = f[3].data();
  const Sign sos = incircle_sos(a, b, c, d);
  const Sign plain = incircle(a, b, c, d);
  if (plain != Sign::Zero) RC_ASSERT(sos == plain);
  if (orient2d(a, b, c) != Sign::Zero) RC_ASSERT(sos != Sign::Zero);
  if (f[0] != f[1] && f[0] != f[2] && f[0] != f[3] && f[1] != f[2] && f[1] != f[3] &&
      f[2] != f[3]) {
    RC_ASSERT(incircle_sos(b, a, c, d) == -sos);
    RC_ASSERT(incircle_sos(d, b, c, a) == -sos);
    RC_ASSERT(incircle_sos(b, c, a, d) == sos);
  }
}

RC_GTEST_PROP(Sos, Incircle3SosLaws, ()) {
  Rng r = seeded();
  const auto p = geomgen::plane_case<4>(r, degenerate_kind(r), geomgen::kIncircleRange);
  const Sign sos = incircle3_sos(p[0], p[1], p[2], p[3]);
  const Sign plain = incircle3(p[0], p[1], p[2], p[3]);
  if (plain != Sign::Zero) RC_ASSERT(sos == plain);
  const bool collinear = stage2::plane_axis(p[0], p[1], p[2]) < 0;
  RC_ASSERT((sos == Sign::Zero) == collinear);
  // Orientation-free in a, b, c.
  RC_ASSERT(incircle3_sos(p[1], p[0], p[2], p[3]) == sos);
  RC_ASSERT(incircle3_sos(p[2], p[0], p[1], p[3]) == sos);
}

// The consistency of facet triangulations with the tetrahedralization.
RC_GTEST_PROP(Sos, Incircle3SosIsInsphereSosOnThePlane, ()) {
  Rng r = seeded();
  const Kind kind = r.coin() ? Kind::Lattice : degenerate_kind(r);
  const auto p = geomgen::plane_case<4>(r, kind, geomgen::kInsphereRange - 8);
  double m = 0;
  for (const Point& x : p)
    for (double c : x) m = std::max(m, std::fabs(c));
  const double s = m > 0 ? std::ldexp(1.0, std::ilogb(m)) : 1.0;
  const Point g = r.grid_point(6);
  Point q;
  for (int k = 0; k < 3; ++k) q[k] = geomgen::fit(p[0][k] + g[k] * s, geomgen::kInsphereRange);
  const Sign side = orient3d(p[0], p[1], p[2], q);
  RC_PRE(side != Sign::Zero);
  RC_CLASSIFY(incircle3(p[0], p[1], p[2], p[3]) == Sign::Zero, "cocircular");
  RC_ASSERT(incircle3_sos(p[0], p[1], p[2], p[3]) ==
            insphere_sos(p[0], p[1], p[2], q, p[3]) * side);
}

RC_GTEST_PROP(Sos, Incircle3SosIsIncircleSosOnFlatPlanes, ()) {
  Rng r = seeded();
  const auto f = geomgen::flat_case<4>(r, degenerate_kind(r), geomgen::kIncircleRange);
  const double level = r.coin() ? 0.0 : r.wide(-90, 90);
  std::array<Point, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = {f[k][0], f[k][1], level};
  RC_ASSERT(incircle3_sos(p[0], p[1], p[2], p[3]) ==
            incircle_sos(f[0].data(), f[1].data(), f[2].data(), f[3].data()) *
                orient2d(f[0].data(), f[1].data(), f[2].data()));
}

// Cocircular and cospherical lattice sets: every call is degenerate, SoS decides.
TEST(Sos, CosphericalLatticeNeverZero) {
  std::array<Point, 30> sphere;  // the 30 integer points with |p|^2 = 9, shifted
  int n = 0;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z)
        if (x * x + y * y + z * z == 9) sphere[n++] = {x + 0.5, y - 0.25, z + 1.0};
  ASSERT_EQ(n, 30);
  int zero_plain = 0;
  for (int i = 0; i < 2000; ++i) {
    Rng r(i);
    std::array<int, 5> k;
    for (int& x : k) x = r.integer(0, 29);
    const Point &a = sphere[k[0]], &b = sphere[k[1]], &c = sphere[k[2]], &d = sphere[k[3]],
                &e = sphere[k[4]];
    if (orient3d(a, b, c, d) == Sign::Zero || e == a || e == b || e == c || e == d) continue;
    zero_plain += insphere(a, b, c, d, e) == Sign::Zero;
    EXPECT_NE(insphere_sos(a, b, c, d, e), Sign::Zero);
  }
  EXPECT_GT(zero_plain, 1000);
}

}  // namespace
}  // namespace pdr
