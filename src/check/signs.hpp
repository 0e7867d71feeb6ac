// The checkers' own exact signs: a floating-point filter with a proven bound, an exact
// 128-bit integer stage for short-mantissa input, then GMP rationals (geom/exact.hpp or
// gmpxx directly). Independent of the kernel's expansion arithmetic (geom/predicates.hpp),
// which the checkers are meant to check. Conventions are those of geom/predicates.hpp.
//
// Stage 1, static filters (orient3d, det3, insphere). The determinant is evaluated in
// exactly the shape analysed by Shewchuk, "Adaptive Precision Floating-Point Arithmetic and
// Fast Robust Geometric Predicates" (DCG 18, 1997), §4.3 and §4.5: entries are rounded
// differences of two input doubles, then 2x2 minors, then products with a third entry (and
// a lift), summed. Its absolute error is below errbound * permanent, with errbound
// (7 + 56 eps) eps for the 3x3 determinant and (16 + 224 eps) eps for the 4x4 lifted one
// (eps = 2^-53), permanent being the same expression with every term replaced by its
// absolute value. The proof assumes no overflow or underflow; we enforce it by requiring
// every difference to be 0 or within [2^-150, 2^150]: then every product of entries is a
// normal number, a sum that falls below 2^-1022 is exact (doubles are multiples of
// 2^-1074), and the only underflow left is a small minor times an entry, whose absolute
// error (2^-1075, times at most the lifts, < 2^302) is covered by an added slack of 2^-1000
// (orient3d, det3) and 2^-700 (insphere). Otherwise the filter says "unsure".
// Zero certificate (orient3d, det3, orient2d): a rounded difference is zero only when the
// two doubles are equal, and with entries in range a product of nonzero entries is not
// zero; so a permanent that is exactly zero means every term of the exact determinant has
// an exactly zero factor, and the sign is Zero (coplanar points on an axis-parallel plane,
// collinear points on an axis-parallel line), decided without the later stages.
// Stage 2, integers: if all coordinates involved are integer multiples of one power of two
// 2^e with quotients below 2^40 (3x3), 2^22 (lifted 4x4) or 2^60 (2x2), the determinant
// is computed exactly in __int128 (bounds: 3x3 < 2^126, 4x4 < 2^122, 2x2 < 2^123). Catches the exact zeros of
// structured meshes (cospherical and coplanar vertices) without GMP.
// Stage 3: GMP rationals.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "geom/point.hpp"

namespace pdr::check::signs {

// Exact evaluations (stage 3) performed by the calling thread since it started; checkers
// report the difference as a count ("exact_evaluations").
std::uint64_t exact_evaluations();

// The filters' precondition on an entry (a coordinate difference): 0 or in [2^-150, 2^150].
// Outside it every sign above is still exact (stages 2 and 3); floating-point measures
// computed from such entries may underflow or overflow.
bool entry_in_range(double d);

// orient3d(a,b,c,d) = sign det[b-a, c-a, d-a].
Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d);
// det3(a0,a1,b0,b1,c0,c1) = sign det[a1-a0, b1-b0, c1-c0].
Sign det3(const Point& a0, const Point& a1, const Point& b0, const Point& b1, const Point& c0,
          const Point& c1);
// insphere(a,b,c,d,e) > 0: e strictly inside the sphere abcd when orient3d(a,b,c,d) > 0.
Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e);
// sign((p - a) . (q - b)).
Sign dot(const Point& p, const Point& a, const Point& q, const Point& b);
// Equatorial sphere of triangle abc (the sphere through a, b, c centred in their plane):
// Positive when p is strictly inside, Zero on it, Negative outside. Precondition: a, b, c
// not collinear (then Zero is returned).
Sign equatorial(const Point& a, const Point& b, const Point& c, const Point& p);
// orient2d of the projections dropping coordinate `drop` (0, 1, 2): the points
// (p[(drop+1)%3], p[(drop+2)%3]).
Sign orient2d(const Point& a, const Point& b, const Point& c, int drop);

// orient3d(a, b, c, q) for many q against one plane: the 2x2 minors of (b-a, c-a) are
// computed once; evaluating w . (u x v) with w = q - a is the same 3x3 expansion (along
// another row), so the same bound applies.
class Plane {
 public:
  Plane() = default;
  Plane(const Point& a, const Point& b, const Point& c);
  Sign orient(const Point& q) const;  // = orient3d(a, b, c, q), exactly

 private:
  const Point *a_ = nullptr, *b_ = nullptr, *c_ = nullptr;
  std::array<double, 3> n_{}, abs_{};
  bool ok_ = false;
};

// The stages alone, for tests (nullopt: this stage cannot decide).
std::optional<Sign> orient3d_filter(const Point& a, const Point& b, const Point& c,
                                    const Point& d);
std::optional<Sign> insphere_filter(const Point& a, const Point& b, const Point& c,
                                    const Point& d, const Point& e);
std::optional<Sign> orient3d_int(const Point& a, const Point& b, const Point& c,
                                 const Point& d);
std::optional<Sign> insphere_int(const Point& a, const Point& b, const Point& c,
                                 const Point& d, const Point& e);

}  // namespace pdr::check::signs
