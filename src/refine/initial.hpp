// The initial tetrahedralization T_o (paper §2.1 step 3, "add the vertices in D_o by
// Delaunay insertion into an empty Delaunay tetrahedralization T_o. Then, remove all
// tetrahedra in T_o which lie outside of Ω").
//
// build_initial: the Delaunay tetrahedralization of D_o's vertices (bulk_insert, ids not
// renumbered beyond skipping unused input points), then
//   - conformity: every live subfacet of D_o should be a face and every subsegment an edge
//     of T_o (for an admissible domain the subfacets are unencroached after §2.1, so their
//     equatorial balls are empty and they are Delaunay faces); outside the theory some may
//     not be: they are listed (VolumeMesh::missing_subfacets, missing_subsegments) and the
//     refinement restores them first (refine/conformity.hpp);
//   - classification: a flood fill from the ghost tets over all faces, the flag toggling
//     across the subfacets of separating facets (VolumeMesh::face_flips: the cells of Ω,
//     domain/domain.hpp; an internal facet keeps it); on a conforming
//     T_o an inconsistent parity (a face reached with two flags) throws
//     RefineError("volume.parity: ..."); otherwise the flags are provisional;
//   - volume holes (conforming T_o): the tet containing each hole point must be outside,
//     else RefineError("volume.hole: ...").
// "Remove" is a flag: outside tets stay in T (it covers the hull) and are never refined.
#pragma once

#include <cstdint>
#include <span>

#include "refine/volume_mesh.hpp"

namespace pdr::refine {

VolumeMesh build_initial(SurfaceMesh surf, std::span<const Point> holes,
                         std::uint64_t seed = 0x5EED);

}  // namespace pdr::refine
