// The surface mesh before refinement (paper §2.1, the start of steps 1 and 2): the input
// vertices, each segment as one subsegment, and each face's region triangulated by the
// Delaunay triangulation of its input vertices restricted to the region.
//
// build_surface copies from the domain::PlcDomain what the surface mesh keeps (segments with their
// facets, facet charts and boundaries, source lines), takes each face's triangulation from
// the domain analysis (input vertices as corners, conforming to the segments, holes
// removed: domain/domain.hpp) and makes it constrained Delaunay by Lawson flips
// (make_facet_delaunay, surface/build.cpp). Input points on no segment or facet (isolated
// vertices) keep their ids and home Input, like every input vertex.
// Constrained Delaunay is what a region needs before its segments are refined; once no
// subsegment is encroached (paper §2.1 step 1, for admissible domains) every subsegment is
// an edge of the unconstrained Delaunay triangulation of the facet's vertices (its closed
// diametral disk holds no other vertex), so the constrained triangulation is then "the
// Delaunay triangulation of the vertices of F" restricted to F.
#pragma once

#include <cstdint>

#include "domain/domain.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::surface {

SurfaceMesh build_surface(const domain::PlcDomain& dom);

// Lawson flips on facet f until every unconstrained interior edge is locally Delaunay under
// chart_incircle. Throws SurfaceError if stuck (surface/build.cpp).
void make_facet_delaunay(SurfaceMesh& m, std::uint32_t f);

}  // namespace pdr::surface
