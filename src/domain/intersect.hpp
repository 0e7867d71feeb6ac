// Exact intersection tests between closed segments and triangles in 3D.
//
// Paper §1.1: the components of the boundary (vertices, segments, facets) may meet only in
// the components they share. After domain/facets.cpp has triangulated every facet, "facet F
// and facet G meet properly" becomes "every triangle of F meets every triangle of G only
// in the vertices and edges they share", which these functions decide exactly (orient3d /
// orient2d only, no constructed points).
//
// The *_conflict functions take vertex ids so that shared vertices are recognised by
// identity: they return true when the two simplices intersect in anything more than the
// simplex spanned by their shared vertices. Triangles must be non-degenerate and segments
// of positive length; distinct ids must name distinct points.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "domain/exact.hpp"
#include "geom/point.hpp"

namespace pdr::domain {

// Closed sets in the plane.
bool segments_meet_2d(const P2& a, const P2& b, const P2& c, const P2& d);
bool point_in_triangle_2d(const P2& a, const P2& b, const P2& c, const P2& x);

// Closed segment pq and closed triangle abc in 3D, any relative position.
bool segment_meets_triangle(const Point& p, const Point& q, const Point& a, const Point& b,
                            const Point& c);
// Closed segments pq and rs in 3D.
bool segments_meet(const Point& p, const Point& q, const Point& r, const Point& s);
// Closed triangle abc contains x (3D).
bool point_in_triangle(const Point& a, const Point& b, const Point& c, const Point& x);

using Tri3 = std::array<std::uint32_t, 3>;
using Seg2 = std::array<std::uint32_t, 2>;

bool triangles_conflict(const Tri3& s, const Tri3& t, const std::vector<Point>& pts);
bool segment_triangle_conflict(const Seg2& s, const Tri3& t, const std::vector<Point>& pts);
bool segments_conflict(const Seg2& s, const Seg2& t, const std::vector<Point>& pts);

}  // namespace pdr::domain
