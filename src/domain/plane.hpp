// The plane of a facet: exact when the input is exactly planar, classified by a documented
// relative tolerance when it is not (paper §1.1 facets are planar; input files written in
// decimal floating point rarely are exactly).
//
// Planarity classification (the only tolerance of the domain analysis; it classifies
// imprecise input and never steers a later decision):
//   - exact: every vertex v of the facet has orient3d(t0, t1, t2, v) == 0 for the defining
//     triple below;
//   - planar within tolerance: otherwise, when every vertex lies within
//     tol * diameter of the least-squares plane through the facet's vertices, where
//     diameter is the diagonal of the facet's bounding box (at most sqrt(3) times the true
//     diameter) and tol is PlcOptions::planarity_tolerance (default 1e-9, like TetGen -T),
//     or within four times the uncertainty of coordinates written with fewer digits
//     (io/precision.hpp: a 7-digit file's small faces);
//   - not planar: anything else (an input error).
//
// The plane "as the kernel sees it" is the defining triple: three non-collinear input
// vertices chosen well conditioned (t0 farthest from the centroid, t1 farthest from t0, t2
// maximising the area of t0 t1 t2). Later stages use orient3d(t0, t1, t2, .) as the
// facet's plane, `projection` (drop the coordinate of the largest normal component; `swap`
// makes t0 t1 t2 counter-clockwise) as its 2D chart, and spheres centred exactly on the
// plane through t0, t1, t2 for the facet's in-circle test (surface/chart.hpp), so vertices
// off the plane (within tolerance, or rounded constructions) are decided as the 3D
// Delaunay tetrahedralization decides them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "domain/exact.hpp"
#include "geom/point.hpp"
#include "io/precision.hpp"

namespace pdr::domain {

struct FacetPlane {
  std::array<std::uint32_t, 3> triple{};  // defining vertices (global ids), non-collinear
  Projection projection;                  // chart: t0 t1 t2 counter-clockwise
  Point normal{};                         // unit normal of the least-squares plane (report)
  Point centroid{};                       // of the facet's vertices (report)
  double diameter = 0;                    // bounding-box diagonal of the facet's vertices
  double max_deviation = 0;               // max distance to the fitted plane / diameter
  bool exact = false;                     // exactly planar (see above)
};

enum class PlaneStatus : std::uint8_t { Ok, Collinear, NotPlanar };

struct PlaneFit {
  PlaneStatus status = PlaneStatus::Ok;
  FacetPlane plane;
  std::uint32_t worst = 0;  // the vertex farthest from the fitted plane
};

// Precondition: verts holds at least one id, all distinct points.
PlaneFit fit_facet_plane(const std::vector<Point>& pts, const std::vector<std::uint32_t>& verts,
                         const io::PlanarityTolerance& tolerance);

// Distance of p to the fitted plane, relative to the facet's diameter.
double relative_deviation(const FacetPlane& plane, const Point& p);

}  // namespace pdr::domain
