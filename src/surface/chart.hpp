// FacetChart: how pdr sees a facet in 2D (paper §2.1 step 2: "a Delaunay triangulation of
// the vertices of F"), and where it puts new vertices on it.
//
// Chart. The facet's projection (domain/plane.hpp): drop the coordinate of the largest normal
// component of the defining triple t0 t1 t2, swap so that t0 t1 t2 is counter-clockwise.
// domain::Projection only drops a coordinate, so chart_orient is exact (orient2d on the projected
// doubles) and is valid for any points near the plane: it is the orientation of their
// shadows. Every validity decision of a facet triangulation (a subfacet is
// counter-clockwise, a cavity is star-shaped) uses it.
//
// In-circle: spheres centred on the facet's plane. chart_incircle(a, b, c, d) asks whether d
// is strictly inside the sphere through a, b, c whose centre lies on the facet's plane P
// (the plane through t0, t1, t2, exactly as the kernel sees it). With e1 = t1 - t0,
// e2 = t2 - t0 (exact), a centre o = t0 + s e1 + r e2 and the lift L(p) = |p - t0|^2,
// |p - o|^2 - rho^2 = L(p) - 2 s e1.(p - t0) - 2 r e2.(p - t0) + const: the spheres centred
// on P are the planes of the lifted space (X, Y, L), X = e1.(p - t0), Y = e2.(p - t0), and
// the test is the sign of the lifted determinant
//     | X(a) - X(d)   Y(a) - Y(d)   L(a) - L(d) |
//     | X(b) - X(d)   Y(b) - Y(d)   L(b) - L(d) |
//     | X(c) - X(d)   Y(c) - Y(d)   L(c) - L(d) |
// with symbolic perturbation of L by the lexicographic rank of the 3D points (the
// incircle_sos cofactor table of predicates.hpp, with plane_orient, the orientation in the
// (X, Y) chart, as cofactors); see surface/chart.cpp.
//   - Restricted Delaunay. The facet triangulation this test defines is the Delaunay
//     triangulation of the facet's vertices restricted to P: a triangle abc is in it iff
//     the sphere through a, b, c centred on P has no vertex inside, i.e. iff the Voronoi
//     edge dual to abc in 3D crosses P. Every such triangle is a face of the 3D Delaunay
//     tetrahedralization of the facet's vertices, with the same perturbation
//     (insphere_sos lifts |p|^2 by the same ranks), and it stays a face of the
//     tetrahedralization of all vertices as long as no other vertex is inside that
//     sphere. Vertices a few ulps off P (rounded constructions on a tilted facet, facets
//     planar only within tolerance) change nothing in this argument: the sphere is centred
//     on P, so it is within rounding of the equatorial sphere of abc, which the refinement
//     keeps free of other vertices (paper §1.1 "encroached").
//   - Coplanar points. For coplanar a, b, c, d every sphere through a, b, c meets their
//     plane in their circle: the test is the 3D circle test, and with o = chart_orient(a,
//     b, c) != 0, chart_incircle * o == incircle3 when that is nonzero and == incircle3_sos
//     in every case (same dominance order, cofactors equal up to the constant sign relating
//     two projections of one plane): on exactly planar facets with exactly coplanar
//     vertices the facet triangulation is the restriction of insphere_sos.
//   - Consistency. One lifting map plus one perturbation: the triangulations it defines
//     are regular triangulations of the (X, Y) chart (lower convex hulls), unique and
//     reached by any insertion order; Bowyer-Watson and Lawson flips are correct with it.
//     The sign is reported relative to the orientation of a, b, c in the projection chart
//     (chart_orient, which the facet meshes keep counter-clockwise); the two charts agree
//     on every triangle except ones within rounding of degenerate.
//   Rejected: a lift with centres on the coordinate plane x_k = t0_k (this file's first
//   version: the dropped-coordinate chart with the same L). Consistent too, but on a tilted
//   facet its spheres are centred up to the facet's size away from the plane, so a rounded
//   near-cocircular quadruple (every rectangle of a refined tilted face) was decided
//   against the 3D tetrahedralization about once in 300 subfacets; the 2D incircle of the
//   chart images (circles map to ellipses); the 3D equatorial-ball test alone (exact
//   witness for T, but not a lifting, so flips and cavities could cycle off the plane).
// Placement. place_on_facet keeps the chart coordinates of p and recomputes the dropped
// coordinate k from the plane through t0, t1, t2 (the facet's plane as the domain analysis
// defines it): p_k = t0_k - (n_i (p_i - t0_i) + n_j (p_j - t0_j)) / n_k, n = (t1-t0)x(t2-t0)
// in double, |n_k| >= |n| / sqrt(3). The chart position, which the triangulation decisions
// see, is exactly the constructed one; the point is within a few ulps (relative to |p - t0|
// and |p|) of the plane, and exactly on it when the facet is axis-parallel (n_i = n_j = 0
// exactly, so p_k = t0_k). Exact coplanarity of constructed points is not guaranteed by
// rounding otherwise; no decision depends on it (see above).
//   On a facet planar only within tolerance T (every vertex within T diam of its
// least-squares plane L, diam its bounding-box diagonal) the plane through t0, t1, t2 lies
// within 7 T diam of L over the facet: a point x of the facet is t0 + l1 (t1 - t0) + l2
// (t2 - t0) with |l2| <= 1 (t2 maximises the area with t0 and t1), |l1| <= 2 (t1 is the
// farthest vertex from t0, and so at least as far as x and t2), so |1 - l1 - l2| <= 4, and
// the plane's offset from L at x, l0 d0 + l1 d1 + l2 d2 with |d_i| <= T diam, is at most
// 7 T diam. The check counts vertices within 8T diam of L as on such a facet
// (check::Options::inexact_facet_tolerance). Placing on L instead keeps new points within
// T diam, but every input vertex of the facet then lies off the placement plane, and
// near-cocircular quadruples of new points around one cascade into flat-tet repairs
// toward it (a rotated star prism printed with 9 digits: 17,577 repairs and an edge of
// 1.8e-13 at 20,000 vertices, instead of 7 repairs and 2,325 vertices); through t0, t1,
// t2 three of them lie on it.
#pragma once

#include "domain/exact.hpp"
#include "domain/plane.hpp"
#include "geom/point.hpp"

namespace pdr::surface {

struct FacetChart {
  domain::Projection projection;  // t0 t1 t2 counter-clockwise
  Point origin{};         // t0: a point of the plane and the lift's origin
  Point t1{}, t2{};       // the rest of the defining triple: the plane of the in-circle test
  Point normal{};         // (t1 - t0) x (t2 - t0), in double: placement only
  domain::P2 operator()(const Point& p) const { return projection(p); }
};

// Precondition: plane.triple holds three non-collinear ids into pts.
FacetChart make_chart(const domain::FacetPlane& plane, const std::vector<Point>& pts);

// orient2d of the chart images: Positive when a, b, c are counter-clockwise in the chart.
Sign chart_orient(const FacetChart& ch, const Point& a, const Point& b, const Point& c);

// The plane-centred in-circle test with symbolic perturbation (above). Positive: d inside
// the sphere through a, b, c centred on the facet's plane when they are counter-clockwise
// in the chart (negated when clockwise). Never Zero when chart_orient(a, b, c) != 0,
// plane_orient(a, b, c) != 0 and d differs from a, b, c.
Sign chart_incircle(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                    const Point& d);
// The unperturbed lifted determinant's sign (relative to the (X, Y) chart), exact (filter,
// then GMP). For tests.
Sign chart_incircle_raw(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                        const Point& d);

// Orientation of a, b, c in the (X, Y) chart of the facet's plane, exact: the sign of
// ((t1 - t0) x (t2 - t0)) . ((b - a) x (c - a)). Positive for t0, t1, t2.
Sign plane_orient(const FacetChart& ch, const Point& a, const Point& b, const Point& c);

// p moved along the dropped axis onto the facet's plane (above).
Point place_on_facet(const FacetChart& ch, Point p);

}  // namespace pdr::surface
