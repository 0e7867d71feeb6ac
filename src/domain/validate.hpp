// Validation of a piecewise linear complex as a polyhedral domain (paper §1.1).
//
// build_domain checks, in this order, and throws InputError("file:line: <invariant>:
// problem; what to do") at the first failure:
//   1. coordinates are finite; no two vertices are equal (exact comparison);
//   2. polygon indices are in range; no polygon is empty, repeats a vertex consecutively
//      (or in a 2-vertex polygon), visits a vertex twice, or has all vertices collinear;
//   3. edges are split at input vertices in their interior (a vertex of one facet may lie
//      inside another facet's edge, as in TetGen); a polygon through its own vertex is
//      self-intersecting;
//   4. every face (facet with a polygon of >= 3 vertices) is planar: exactly, or within
//      the relative tolerance of domain/plane.hpp (those facets are counted); its polygons
//      are simple and do not cross (exact, in the facet's projection); facet hole points
//      lie within the tolerance of the plane, inside the facet's polygons, off its edges;
//      no polygon lies outside the facet's region;
//   5. facets, segments and stray vertices meet only in shared vertices and segments
//      (exact triangle/segment tests over a bounding-volume hierarchy, no all-pairs loop);
//   6. the boundary is closed: every segment bounds an even number of facet sides;
//   7. volume hole points lie inside the closed boundary, in a void, off every facet.
// Supported: facets with several polygons (outer boundaries, inner polygons that are
// holes when a facet hole point marks them, interior segments and points), collinear
// overlapping edges of different facets, vertices inside other facets' edges, several
// shells (voids, disjoint bodies), non-manifold segments (4, 6, ... sides).
// Not supported: internal facets separating two regions of the domain (their segments
// bound an odd number of sides), vertices strictly inside another facet's interior unless
// listed as a 1-vertex polygon of that facet.
#pragma once

#include "domain/domain.hpp"
#include "mesh/plc.hpp"

namespace pdr::domain {

PlcDomain build_domain(const Plc& plc, const PlcOptions& options = {});

}  // namespace pdr::domain
