// Flat tets on a facet (issue #3): a tet of T whose four vertices all lie on one facet of D.
//
// On an exactly planar facet with exactly coplanar vertices such a tet cannot exist (its
// orientation would be zero). On a tilted facet rounding puts constructed vertices a few
// ulps off the plane, and a near-cocircular quadruple a, b, c, d of the facet may then be a
// Delaunay sliver of T: two of its faces are subfacets (the facet's choice of diagonal,
// surface_chart.hpp), the other two lie on the facet too. When the sliver is on the
// domain's side it is a tet of the mesh with volume within rounding of zero and faces on
// the facet that are not subfacets. The refinement treats it as bad and refines its largest
// subfacet face at the circumcenter (Fig. 2 Refine(f)): that point is within rounding of
// the centre of the subfacet's equatorial sphere, so strictly inside the sliver's
// circumsphere (whose centre lies on the subfacet's axis), and the sliver is gone.
#pragma once

#include <cstdint>
#include <optional>

#include "refine/refine_mesh.hpp"

namespace pdr::refine {

// The subfacet of largest circumradius among the faces of finite tet t, when t has a
// subfacet face of a facet f and its fourth vertex is a vertex of f's triangulation;
// nullopt otherwise.
std::optional<std::uint32_t> flat_on_facet(const VolumeMesh& m, TetId t);

}  // namespace pdr::refine
