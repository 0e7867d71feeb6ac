// The reference: the same predicates evaluated in GMP rationals, plus exact measures.
//
// Slow and obviously right. Tests compare every adaptive predicate against these, and the
// checkers (src/check) use them behind their own floating-point filters, so the oracle does
// not share the expansion arithmetic it is meant to check. Same conventions as
// predicates.hpp (including the *_sos variants, implemented here from the definition).
#pragma once

#include <gmpxx.h>

#include "geom/point.hpp"

namespace pdr::exact {

Sign orient2d(const double* a, const double* b, const double* c);
Sign incircle(const double* a, const double* b, const double* c, const double* d);
Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d);
Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e);
Sign incircle3(const Point& a, const Point& b, const Point& c, const Point& d);
Sign incircle_sos(const double* a, const double* b, const double* c, const double* d);
Sign insphere_sos(const Point& a, const Point& b, const Point& c, const Point& d,
                  const Point& e);
Sign incircle3_sos(const Point& a, const Point& b, const Point& c, const Point& d);

// Exact rational measures, for checkers.
mpq_class squared_distance(const Point& a, const Point& b);
// Squared circumradius of a non-degenerate tetrahedron (precondition: orient3d != 0).
mpq_class circumradius2(const Point& a, const Point& b, const Point& c, const Point& d);
// Exact circumcenter of a non-degenerate tetrahedron.
std::array<mpq_class, 3> circumcenter(const Point& a, const Point& b, const Point& c,
                                      const Point& d);
// Six times the signed volume, det[b-a, c-a, d-a].
mpq_class volume6(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace pdr::exact
