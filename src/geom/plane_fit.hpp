// The least-squares plane of a set of points, in floating point: a classification of
// imprecise input (a facet given in decimal is rarely exactly planar) and a place to put
// new vertices, never a decision (docs/design.md §6).
//
// The plane passes through the points' centroid; its unit normal is the eigenvector of the
// smallest eigenvalue of the scatter matrix sum (p - c)(p - c)^T, found by cyclic Jacobi
// rotations. It minimises the sum of squared distances, so a facet planar within tolerance
// T (every vertex within T times its diameter of this plane: domain/plane.hpp) puts every
// point of its convex hull within that distance too: the facet's vertices and every point
// placed on this plane lie in one slab of half-width T times the diameter, which is what
// the check takes as "on the facet" (check/domain.hpp, with a margin).
#pragma once

#include <span>

#include "geom/point.hpp"

namespace pdr::geom {

struct FittedPlane {
  Point centroid{};     // of the points
  Point normal{};       // unit; the zero vector when all points coincide
  double diameter = 0;  // the diagonal of the points' bounding box
};

// Precondition: at least one point.
FittedPlane fit_plane(std::span<const Point> pts);

// The signed distance of p from the plane (positive on the normal's side).
double signed_distance(const FittedPlane& plane, const Point& p);

}  // namespace pdr::geom
