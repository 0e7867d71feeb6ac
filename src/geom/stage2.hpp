// Stage 2 of the adaptive predicates: exact signs by expansion arithmetic (expansion.hpp).
//
// Called by predicates.hpp when the filter (filter.hpp) is unsure; callable alone (tests
// compare each against the GMP reference, exact.hpp). Every function returns the exact
// sign of the same polynomial as the predicate of the same name in predicates.hpp, within
// the input range documented in filter.hpp. No heap allocation: fixed-size stack arrays.
//
// Method: when every coordinate difference to the translation point is exact in double
// (checked with two_diff, the common case for grid-like and nearby points), the translated
// determinant is evaluated; otherwise the untranslated lifted determinant, expanded along
// its lift (or constant) column into orientation minors (Shewchuk 1997, §4.4 does the same).
#pragma once

#include "geom/point.hpp"

namespace pdr::stage2 {

Sign orient2d(const double* a, const double* b, const double* c);
Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d);
Sign incircle(const double* a, const double* b, const double* c, const double* d);
Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e);
// Precondition: a, b, c, d coplanar. Zero if a, b, c are collinear.
Sign incircle3(const Point& a, const Point& b, const Point& c, const Point& d);

// A coordinate axis k with n_k != 0 for n = (b - a) x (c - a), preferring the largest
// |n_k|; -1 if a, b, c are collinear. The projection onto coordinates ((k+1)%3, (k+2)%3)
// maps a, b, c to a triangle of orientation sign(n_k).
int plane_axis(const Point& a, const Point& b, const Point& c);
// orient2d of the projections of a, b, c onto coordinates ((k+1)%3, (k+2)%3).
Sign orient2d_projected(int k, const Point& a, const Point& b, const Point& c);

}  // namespace pdr::stage2
