// Encroachment predicates (paper §1.1): is a point in the diametral ball of a subsegment,
// or in the equatorial ball of a subfacet? Exact, like every predicate of pdr_geom.
//
// Paper §1.1: "The diametral sphere of a subsegment s is the unique smallest sphere
// circumscribing its vertices"; "the equatorial sphere of a subfacet f is the unique
// smallest sphere circumscribing its vertices, with center and radius in the plane of f";
// "a subsegment or subfacet is encroached if its smallest closed circumscribing sphere
// encloses a vertex ... other than its vertices". Both predicates return
//   Positive: p strictly inside the ball, Zero: p on its sphere, Negative: outside,
// so "encroached (closed ball)" is `!= Sign::Negative` and "strictly inside" `== Positive`.
//
// The polynomials (u = b - a, v = c - a, w = p - a, n = u x v, N = |n|^2):
//   diametral:   Positive iff (p - a).(p - b) < 0 (Thales); sign of -(p - a).(p - b).
//   equatorial:  the circumcenter of abc in its plane is a + X / (2N) with
//                X = |u|^2 (v x n) + |v|^2 (n x u) (construct.hpp, exact here), and a lies
//                on the sphere, so |p - o|^2 < r^2  iff  |w|^2 - w.X / N < 0; the sign
//                returned is that of w.X - N |w|^2 (degree 6; N > 0).
// Evaluation: the floating-point filters of geom/filter_kit.hpp (their error bounds are
// derived there: 6u and 20u), used only when every coordinate difference is 0 or in
// [2^-150, 2^150]; otherwise, or when the filter is unsure, GMP rationals decide.
// No range limit on the exact path. Laws (tests/geom/encroach_test.cpp): the result equals
// the GMP reference; swapping a and b (or permuting a, b, c) does not change it; vertices of
// the element are on the sphere; the exact circumcenter is inside and equidistant.
#pragma once

#include <gmpxx.h>

#include <array>

#include "geom/point.hpp"

namespace pdr {

// Precondition: a != b.
Sign in_diametral_ball(const Point& a, const Point& b, const Point& p);
// Precondition: a, b, c not collinear (N > 0); callers hold proper triangles.
Sign in_equatorial_ball(const Point& a, const Point& b, const Point& c, const Point& p);

// The sign of R(abc)^2 - R(def)^2, exactly: which of two triangles has the larger
// circumradius (Fig. 2's "the largest encroached subfacet"). Precondition: both proper.
// Laws: antisymmetric (swapping the triangles flips the sign); invariant under a
// permutation of either triangle's vertices. A filter (geom/filter_kit.hpp) first; GMP
// when it is unsure (equal or nearly equal radii).
Sign compare_circumradius(const Point& a, const Point& b, const Point& c, const Point& d,
                          const Point& e, const Point& f);

namespace exact {

// The circumcenter of triangle abc in its plane, as exact rationals (precondition: a, b,
// c not collinear), and the squared circumradius.
std::array<mpq_class, 3> triangle_circumcenter(const Point& a, const Point& b, const Point& c);
mpq_class triangle_circumradius2(const Point& a, const Point& b, const Point& c);
// The GMP references of the two predicates above (no filter).
Sign in_diametral_ball(const Point& a, const Point& b, const Point& p);
Sign in_equatorial_ball(const Point& a, const Point& b, const Point& c, const Point& p);

}  // namespace exact
}  // namespace pdr
