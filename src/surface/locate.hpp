// Point location in one facet's triangulation (used by the rotation copies around sharp
// axes, refine/axis_zones.hpp): which subfacet of facet f holds a point near its plane.
//
// locate_in_facet walks from the subfacets of f at vertex `from` across an edge whose line
// separates the current subfacet from q in the facet's chart (chart_orient, exact on the
// projected doubles: surface/chart.hpp), preferring an edge with a subfacet of f across it:
// a visibility walk. It ends at a subfacet whose closed chart triangle holds q. When it
// reaches the facet's boundary with q beyond it (q outside, or the facet not convex
// between `from` and q), or cycles (the chart triangulation is a regular triangulation,
// on which a visibility walk can cycle in principle), every subfacet of f is tested
// instead. Decisions are exact; only q, a constructed point, is rounded.
#pragma once

#include <cstdint>
#include <optional>

#include "surface/surface_mesh.hpp"

namespace pdr::surface {

struct FacetLocation {
  std::uint32_t subfacet = 0;
  bool on_subsegment = false;  // q is on a constrained edge of it (a subsegment)
};

// Precondition: `from` is a vertex of facet f's triangulation. nullopt: q lies outside f.
std::optional<FacetLocation> locate_in_facet(const SurfaceMesh& m, std::uint32_t f,
                                             const Point& q, std::uint32_t from);

}  // namespace pdr::surface
