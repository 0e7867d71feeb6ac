// Enclosures of circumballs (paper §1.1: a tet's circumsphere, a subsegment's diametral
// sphere, a subfacet's equatorial sphere) as intervals, and boxes that provably contain the
// closed balls, for grid queries. Nothing is decided here; exact predicates decide.
//
// Argument. The centre and squared radius are evaluated with interval arithmetic
// (interval.hpp), so the true centre c and radius r satisfy c_i in [clo_i, chi_i] and
// r <= rhi (rhi an upper bound of sqrt of the r^2 interval). Then the closed ball lies in
// [clo_i - rhi, chi_i + rhi] (each computed rounding outward). When the interval
// determinant straddles zero (badly conditioned simplex), the exact rational centre and
// radius (geom/exact.hpp, or gmpxx) are converted to intervals instead: mpq_get_d truncates
// toward zero, and widening by one ulp either way encloses the rational.
#pragma once

#include <optional>

#include "check/grid.hpp"
#include "check/interval.hpp"

namespace pdr::check {

struct BallEnclosure {
  IVec center;
  Interval r2;  // squared radius
};

// Circumball of a tet; precondition orient3d(a,b,c,d) != 0. First from one plain
// evaluation with a proven a-priori error bound (detail::circumball_bounded), else with
// every step in interval arithmetic, else exactly.
BallEnclosure circumball(const Point& a, const Point& b, const Point& c, const Point& d);

namespace detail {
// The plain evaluation's enclosure (its proof in circumball.cpp), or nullopt where its
// guards fail: a coordinate difference not 0 and out of [2^-250, 2^250], or a determinant
// whose sign the bound leaves open.
std::optional<BallEnclosure> circumball_bounded(const Point& a, const Point& b, const Point& c,
                                                const Point& d);
}  // namespace detail
// Diametral ball of segment ab.
BallEnclosure diametral_ball(const Point& a, const Point& b);
// Equatorial ball of triangle abc; precondition: a, b, c not collinear.
BallEnclosure equatorial_ball(const Point& a, const Point& b, const Point& c);

// A box containing the closed ball.
Box enclosing_box(const BallEnclosure& ball);

// Whether p lies provably strictly outside the closed ball: a lower bound of p's squared
// distance to every centre in the enclosure exceeds the squared radius's upper bound. Per
// axis the gap from p to the centre's interval is rounded down (interval_detail::down is
// at most the exact value: interval.hpp), so are its square and the sum; a "false" says
// nothing. A cheap filter before an exact sign: a candidate of a box query that lies in the
// box's corners (a flat tet's huge circumball meets much of the mesh's box) costs a few
// flops instead of a predicate.
inline bool surely_outside(const BallEnclosure& ball, const Point& p) {
  using interval_detail::down;
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const Interval& c = ball.center[i];
    double g = 0;
    if (p[i] < c.lo)
      g = down(c.lo - p[i]);
    else if (p[i] > c.hi)
      g = down(p[i] - c.hi);
    if (g > 0) d2 = down(d2 + down(g * g));
  }
  return d2 > ball.r2.hi;
}

}  // namespace pdr::check
