// The laws listed in predicates.hpp, as RapidCheck properties over every input kind of
// geom_generators.hpp (random, near-degenerate, degenerate): permutation parity, the
// orientation dependence of incircle/insphere, orientation-freedom of incircle3, and the
// agreement of incircle3 with insphere and with the planar incircle.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "geom/predicates.hpp"
#include "geom_generators.hpp"

namespace pdr {
namespace {

using geomgen::Kind;
using geomgen::Rng;

struct Draw {
  Rng rng;
  Kind kind;
};
Draw draw() {
  const auto seed = geomgen::rc_seed();
  const int kind = *rc::gen::inRange(0, geomgen::kKinds);
  RC_TAG(kind);
  return {Rng(seed), static_cast<Kind>(kind)};
}

// Sign of a permutation given as an index array.
template <std::size_t N>
int parity(const std::array<int, N>& perm) {
  int inversions = 0;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) inversions += perm[i] > perm[j];
  return inversions % 2 == 0 ? 1 : -1;
}

template <std::size_t N>
std::array<int, N> random_permutation(Rng& r) {
  std::array<int, N> perm;
  for (std::size_t i = 0; i < N; ++i) perm[i] = static_cast<int>(i);
  std::shuffle(perm.begin(), perm.end(), r.engine());
  return perm;
}

RC_GTEST_PROP(Laws, Orient2dFollowsPermutationParity, ()) {
  Draw d = draw();
  const auto p = geomgen::flat_case<3>(d.rng, d.kind, geomgen::kOrient2dRange);
  const auto s = random_permutation<3>(d.rng);
  RC_ASSERT(to_int(orient2d(p[s[0]].data(), p[s[1]].data(), p[s[2]].data())) ==
            parity(s) * to_int(orient2d(p[0].data(), p[1].data(), p[2].data())));
}

RC_GTEST_PROP(Laws, Orient3dFollowsPermutationParity, ()) {
  Draw d = draw();
  const auto p = geomgen::space_case<4>(d.rng, d.kind, geomgen::kOrient3dRange);
  const auto s = random_permutation<4>(d.rng);
  RC_ASSERT(to_int(orient3d(p[s[0]], p[s[1]], p[s[2]], p[s[3]])) ==
            parity(s) * to_int(orient3d(p[0], p[1], p[2], p[3])));
}

// incircle: odd permutations of the first three negate; the product with orient2d(a,b,c)
// ("d inside the circle", orientation-free) is invariant.
RC_GTEST_PROP(Laws, IncircleFollowsParityOfFirstThree, ()) {
  Draw d = draw();
  const auto p = geomgen::flat_case<4>(d.rng, d.kind, geomgen::kIncircleRange);
  const auto s = random_permutation<3>(d.rng);
  const Sign base = incircle(p[0].data(), p[1].data(), p[2].data(), p[3].data());
  const Sign perm = incircle(p[s[0]].data(), p[s[1]].data(), p[s[2]].data(), p[3].data());
  RC_ASSERT(to_int(perm) == parity(s) * to_int(base));
}

RC_GTEST_PROP(Laws, InsphereFollowsParityOfFirstFour, ()) {
  Draw d = draw();
  const auto p = geomgen::space_case<5>(d.rng, d.kind, geomgen::kInsphereRange);
  const auto s = random_permutation<4>(d.rng);
  const Sign base = insphere(p[0], p[1], p[2], p[3], p[4]);
  RC_ASSERT(to_int(insphere(p[s[0]], p[s[1]], p[s[2]], p[s[3]], p[4])) ==
            parity(s) * to_int(base));
  // "Inside" does not depend on the orientation: insphere * orient3d is invariant.
  RC_ASSERT(insphere(p[s[0]], p[s[1]], p[s[2]], p[s[3]], p[4]) *
                orient3d(p[s[0]], p[s[1]], p[s[2]], p[s[3]]) ==
            base * orient3d(p[0], p[1], p[2], p[3]));
}

RC_GTEST_PROP(Laws, Incircle3IsOrientationFree, ()) {
  Draw d = draw();
  const auto p = geomgen::plane_case<4>(d.rng, d.kind, geomgen::kIncircleRange);
  const auto s = random_permutation<3>(d.rng);
  RC_ASSERT(incircle3(p[s[0]], p[s[1]], p[s[2]], p[3]) == incircle3(p[0], p[1], p[2], p[3]));
}

// incircle3 is insphere restricted to the plane: for any q off the plane,
// incircle3(a,b,c,d) = insphere(a,b,c,q,d) * orient3d(a,b,c,q).
RC_GTEST_PROP(Laws, Incircle3AgreesWithInsphere, ()) {
  Draw d = draw();
  const auto p = geomgen::plane_case<4>(d.rng, d.kind, geomgen::kInsphereRange - 8);
  double m = 0;  // q = a + g * 2^ilogb(max |coordinate|), g a random integer vector
  for (const Point& x : p)
    for (double c : x) m = std::max(m, std::fabs(c));
  const double s = m > 0 ? std::ldexp(1.0, std::ilogb(m)) : 1.0;
  const Point g = d.rng.grid_point(6);
  Point q;
  for (int k = 0; k < 3; ++k) q[k] = geomgen::fit(p[0][k] + g[k] * s, geomgen::kInsphereRange);
  const Sign side = orient3d(p[0], p[1], p[2], q);
  RC_PRE(side != Sign::Zero);
  RC_ASSERT(incircle3(p[0], p[1], p[2], p[3]) == insphere(p[0], p[1], p[2], q, p[3]) * side);
}

// On a plane z = level, incircle3 is the planar incircle made orientation-free.
RC_GTEST_PROP(Laws, Incircle3AgreesWithIncircleOnFlatPlanes, ()) {
  Draw d = draw();
  const auto f = geomgen::flat_case<4>(d.rng, d.kind, geomgen::kIncircleRange);
  const double level = d.rng.coin() ? 0.0 : d.rng.wide(-90, 90);
  std::array<Point, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = {f[k][0], f[k][1], level};
  RC_ASSERT(incircle3(p[0], p[1], p[2], p[3]) ==
            incircle(f[0].data(), f[1].data(), f[2].data(), f[3].data()) *
                orient2d(f[0].data(), f[1].data(), f[2].data()));
}

}  // namespace
}  // namespace pdr
