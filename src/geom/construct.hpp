// Floating-point constructions: *where* to insert a point, never whether (docs/design.md §6).
//
// Refinement inserts circumcenters and midpoints (paper §2-3: a skinny tetrahedron is
// split at its circumcenter, an encroached subsegment at its midpoint, an encroached
// subfacet at its circumcenter). These are computed in double precision; all decisions
// (in cavity? encroached? skinny?) are made by the exact predicates on the constructed
// point as it is. The a-priori error bounds below are first order in u = 2^-53, valid
// without overflow or underflow. The circumcenters evaluate their bound: when it exceeds
// 2^-24 of the radius (a nearly flat tetrahedron, a nearly collinear triangle, whose
// floating-point center can land anywhere along the normal), the center is computed
// exactly (GMP) and rounded. So an inserted circumcenter is within about 2^-23 R of the
// true one, as the proofs of §3 need (a new vertex is about R from every other vertex),
// and reported ratios (circumradius2) are accurate for slivers too.
#pragma once

#include "geom/point.hpp"

namespace pdr::construct {

// Midpoint of ab, computed as a/2 + b/2: one rounding, |error_i| <= u |m_i|.
Point midpoint(const Point& a, const Point& b);

// Circumcenter of tetrahedron abcd minus a (the accurate part): with u = b-a, v = c-a,
// w = d-a and D = 2 det[u, v, w],  x = (|u|^2 v x w + |v|^2 w x u + |w|^2 u x v) / D.
// Precondition: orient3d(a,b,c,d) != 0 (else the result is infinite or NaN).
// Error, L = max(|u|, |v|, |w|), R = |x|:  |x~_i - x_i| <= 13u (6 L^4 + 12 R L^3) / |D|
// + u R, provided 12 (9u) L^3 < |D|/2; D = 12 * volume, so the error grows as the
// tetrahedron flattens (about 100 u R for a regular tetrahedron).
Point circumcenter_offset(const Point& a, const Point& b, const Point& c, const Point& d);
// a + circumcenter_offset(...): one more rounding, + u |center_i|.
Point circumcenter(const Point& a, const Point& b, const Point& c, const Point& d);
// |circumcenter_offset|^2: relative error about 2 * (error of x) / R + 3u.
double circumradius2(const Point& a, const Point& b, const Point& c, const Point& d);

// Circumcenter of triangle abc in its plane, minus a: with u = b-a, v = c-a, n = u x v,
//   x = (|u|^2 (v x n) + |v|^2 (n x u)) / (2 |n|^2).
// Precondition: a, b, c not collinear. Error, L = max(|u|, |v|), A = |n|/2 the area:
// |x~_i - x_i| <= 15u (8 L^5 + 24 R L^4) / (8 A^2) + u R.
Point triangle_circumcenter_offset(const Point& a, const Point& b, const Point& c);
Point triangle_circumcenter(const Point& a, const Point& b, const Point& c);
double triangle_circumradius2(const Point& a, const Point& b, const Point& c);

}  // namespace pdr::construct
