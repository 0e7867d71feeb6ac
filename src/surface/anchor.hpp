// The plane a facet planar only within tolerance puts its new vertices on, anchored at its
// sharpest segment (issue #11: facet triangulations and T agree near sharp edges).
//
// A facet given in floating point (a rotated part, coordinates printed with a few digits) is
// planar only to its deviation delta. Its new vertices go on the plane through a defining
// triple of its vertices (surface/chart.hpp place_on_facet); the other input vertices lie
// up to a few delta off that plane. Where two facets meet along a segment s at a small angle
// theta (a thin notch: a dihedral near 0 or 360 degrees), a facet whose placement plane
// misses an end of s puts vertices within delta / sin(theta) of s on the wrong side of the
// other facet, and the refinement repairs what that breaks at ever smaller scales (a 3-degree
// notch printed with 7 digits: tens of thousands of repairs toward its tip). A plane through
// both ends of s lies on s exactly, so near s the two facets' planes meet exactly along s at
// theta, as the input means.
//
// placement_plane: for an exactly planar facet, the domain analysis' plane. Otherwise the
// facet's sharpest feature below 80 degrees anchors it: a segment s = ab at the smallest
// angle to another facet through it (the angle between the two facets' half-planes at s, in
// [0, 180] degrees) gives the triple (a, b, c), c the facet's vertex farthest from the line
// ab; a corner v whose angle in the facet is within that of 0 or 360 degrees (the floor of
// a thin notch) gives (v, the vertex farthest from v, the vertex spanning the largest
// triangle with them), the defining triple's rule from another start, which keeps its
// placement bound. Ordered counter-clockwise in the facet's projection, and kept only when
// no vertex of the facet lies farther from its plane than twice as far as from the
// analysis' plane (so the placement bound of surface/chart.hpp, which the check's tolerance
// follows, keeps its order). Floating-point angles and distances only choose the plane new
// vertices are placed on; no decision of the mesher depends on them.
#pragma once

#include <cstdint>

#include "domain/domain.hpp"

namespace pdr::surface {

domain::FacetPlane placement_plane(const domain::PlcDomain& dom, std::uint32_t f);

}  // namespace pdr::surface
