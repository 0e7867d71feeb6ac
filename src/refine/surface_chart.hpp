// FacetChart: how pdr sees a facet in 2D (paper §2.1 step 2: "a Delaunay triangulation of
// the vertices of F"), and where it puts new vertices on it.
//
// Chart. The facet's projection (plc_plane.hpp): drop the coordinate of the largest normal
// component of the defining triple t0 t1 t2, swap so that t0 t1 t2 is counter-clockwise.
// Projection only drops a coordinate, so chart_orient is exact (orient2d on the projected
// doubles) and is valid for any points near the plane: it is the orientation of their
// shadows. Every validity decision of a facet triangulation (a subfacet is
// counter-clockwise, a cavity is star-shaped) uses it.
//
// In-circle. chart_incircle(a, b, c, d) is the sign of the lifted determinant
//     | A - D   L(a) - L(d) |
//     | B - D   L(b) - L(d) |     A = chart(a) ..., L(p) = |p - t0|^2 (3D distance),
//     | C - D   L(c) - L(d) |
// with symbolic perturbation of L by the lexicographic rank of the 3D points (the
// incircle_sos cofactor table of predicates.hpp, chart orientations as cofactors).
//   - For coplanar a, b, c, d it is the 3D circle test: on a plane, L equals |p|^2 up to an
//     affine function (for any origin t0), so "L(d) below the plane through the lifted
//     a, b, c" is "d inside the circle through a, b, c". Hence, with o = chart_orient(a, b, c)
//     != 0: chart_incircle * o == incircle3 when that is nonzero, and == incircle3_sos in
//     every case (same dominance order, cofactors equal up to the constant sign relating
//     two projections of one plane). So on an exactly planar facet with exactly coplanar
//     vertices the facet triangulation is the one incircle3_sos defines, the restriction of
//     insphere_sos: it agrees with the 3D Delaunay tetrahedralization (src/delaunay).
//   - For any points it is a *consistent* predicate: one lifting map p -> (chart(p), L(p))
//     plus one perturbation, so the triangulations it defines are regular triangulations
//     (lower convex hulls), unique and reached by any insertion order; Bowyer-Watson and
//     Lawson flips are correct with it. incircle3 on points a few ulps off their common
//     plane is "unspecified" (predicates.hpp) and depends on the argument order, so pdr
//     never relies on it for constructed points; chart_incircle is exact for whatever
//     doubles the points are.
//   Alternatives rejected: the 2D incircle of the chart images is consistent but is not
//   the 3D circle test on a tilted facet (a projection maps circles to ellipses), so its
//   triangulation would not be a face set of the 3D Delaunay tetrahedralization;
//   incircle3_sos on the 3D points is the right test on coplanar points but may be
//   inconsistent (argument-order dependent) a few ulps off the plane, and Bowyer-Watson
//   cavities then need repair. chart_incircle equals the latter where it is specified and
//   stays a lifting elsewhere.
// Limitation (near-planar facets). When facet vertices are not exactly coplanar (a facet
// planar only within tolerance, or constructed points on a tilted plane, which rounding
// puts a few ulps off it), the chart triangulation is Delaunay for the lifted map, i.e. for
// circles up to relative perturbations of order the points' distance to a common plane over
// the facet size; the 3D Delaunay tetrahedralization may then resolve a near-cocircular
// quadruple of the facet differently (a sliver against the facet), so "every subfacet is a
// face of the 3D DT" holds exactly only on exactly planar facets with exactly coplanar
// vertices. audit_surface reports such quadruples (off-plane) and any resulting
// encroachment.
//
// Placement. place_on_facet keeps the chart coordinates of p and recomputes the dropped
// coordinate k from the plane through t0, t1, t2 (the facet's plane as the domain analysis
// defines it): p_k = t0_k - (n_i (p_i - t0_i) + n_j (p_j - t0_j)) / n_k, n = (t1-t0)x(t2-t0)
// in double, |n_k| >= |n| / sqrt(3). The chart position, which the triangulation decisions
// see, is exactly the constructed one; the point is within a few ulps (relative to |p - t0|
// and |p|) of the plane, and exactly on it when the facet is axis-parallel (n_i = n_j = 0
// exactly, so p_k = t0_k). Exact coplanarity of constructed points is not guaranteed by
// rounding otherwise; no decision depends on it (see above).
#pragma once

#include "geom/point.hpp"
#include "refine/plc_exact.hpp"
#include "refine/plc_plane.hpp"

namespace pdr::refine {

struct FacetChart {
  Projection projection;  // t0 t1 t2 counter-clockwise
  Point origin{};         // t0: a point of the plane and the lift's origin
  Point normal{};         // (t1 - t0) x (t2 - t0), in double: placement only
  P2 operator()(const Point& p) const { return projection(p); }
};

// Precondition: plane.triple holds three non-collinear ids into pts.
FacetChart make_chart(const FacetPlane& plane, const std::vector<Point>& pts);

// orient2d of the chart images: Positive when a, b, c are counter-clockwise in the chart.
Sign chart_orient(const FacetChart& ch, const Point& a, const Point& b, const Point& c);

// The lifted in-circle test with symbolic perturbation (above). Positive: d inside the
// circle of a, b, c when they are counter-clockwise in the chart (negated when clockwise).
// Never Zero when chart_orient(a, b, c) != 0 and d differs from a, b, c.
Sign chart_incircle(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                    const Point& d);
// The unperturbed lifted determinant's sign, exact (filter, then GMP). For tests.
Sign chart_incircle_raw(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                        const Point& d);

// p moved along the dropped axis onto the facet's plane (above).
Point place_on_facet(const FacetChart& ch, Point p);

}  // namespace pdr::refine
