// Squared Euclidean distances between points, segments and triangles, in floating point.
//
// These serve the distance d of paper §2.1, which only says how finely the boundary is
// subdivided initially; d is a report and a size, never a combinatorial decision (STYLE
// §6), so it is computed in double. Each result carries a relative error of a few units
// in the last place of the inputs' coordinate differences; callers that need a strict
// lower bound of the true distance may shrink d by a relative 1e-12.
#pragma once

#include "geom/point.hpp"

namespace pdr::refine {

double dist2_point_point(const Point& p, const Point& q);
double dist2_point_segment(const Point& p, const Point& a, const Point& b);
double dist2_point_triangle(const Point& p, const Point& a, const Point& b, const Point& c);
double dist2_segment_segment(const Point& p, const Point& q, const Point& r, const Point& s);
// Preconditions: the segment does not pass through the triangle, the triangles do not
// intersect (true for unrelated components of a valid domain).
double dist2_segment_triangle(const Point& p, const Point& q, const Point& a, const Point& b,
                              const Point& c);
double dist2_triangle_triangle(const Point& a, const Point& b, const Point& c, const Point& d,
                               const Point& e, const Point& f);

}  // namespace pdr::refine
