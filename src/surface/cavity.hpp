// FacetCavity: one Bowyer-Watson step in one facet (paper §1.2, in 2D; used by §2.1 step 2
// and by Fig. 2's "Retriangulate C_p ∩ D in D"). A cavity is a value: built read-only,
// then committed in one step, or dropped (docs/design.md §10).
//
// build_facet_cavity collects, by depth-first search from the seeds, the subfacets of the
// facet whose circle holds p (chart_incircle > 0, surface/chart.hpp), never crossing a
// subsegment. Seeds: for a new vertex inside the facet, the subfacet it is the
// circumcenter of (it must conflict, else the cavity is SeedNotInConflict); for the
// midpoint of subsegment {a, b}, the one or two subfacets on it (taken without a test:
// the edge ab disappears).
// Then, exactly:
//   encroached  the subsegments on the cavity's boundary whose closed diametral ball holds
//               p (geom/encroach.hpp). For a vertex inside the facet, any such subsegment
//               makes the cavity Encroaches. Completeness (exact arithmetic, coplanar
//               points, facet triangulation Delaunay with unencroached subsegments): if p
//               lies in a closed diametral ball on the facet side of some subsegment, or
//               outside the facet, some encroached subsegment is on the boundary: the
//               unconstrained cavity is star-shaped from p and contains the seed, so the
//               walk from the seed to p inside it meets a subsegment with conflicting
//               subfacets on both sides, and two circles through a and b that both hold p
//               meet only inside the diametral ball of ab (or p is on ab itself). Outside
//               the theory a facet vertex may encroach a subsegment, and a circumcenter
//               can then lie beyond it yet outside its ball: a boundary subsegment with p
//               on or beyond it (chart_orient, exact) counts as encroached too.
//   star shape  p strictly left of every boundary edge in the chart, each vertex starting
//               and ending at most one boundary edge, one loop (a path from b to a for a
//               boundary split), every vertex of the cavity on it. Then the fan from p is a
//               valid triangulation of the cavity. A violation (excluded by the exact
//               arguments for coplanar points) makes the cavity NotStarShaped.
// commit_facet_cavity deletes the cavity's subfacets and fans p to the boundary, keeping
// neighbours, subsegment marks (for a split, the two halves) and incidences.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace pdr::surface {

enum class CavityStatus : std::uint8_t { Ok, Encroaches, SeedNotInConflict, NotStarShaped };

struct CavityEdge {
  std::uint32_t u = 0, w = 0;  // directed: the cavity on its left in the chart
  std::int32_t outer = -1;     // the subfacet across it (outside the cavity); -1: none
  bool constrained = false;    // the edge is a subsegment
};

struct FacetCavity {
  std::uint32_t facet = 0;
  Point p{};
  std::optional<std::array<std::uint32_t, 2>> split;  // the subsegment p splits
  std::vector<std::uint32_t> tris;                    // subfacets in conflict with p
  std::vector<CavityEdge> boundary;
  std::vector<std::uint32_t> encroached;  // boundary subsegments whose closed ball holds p
  CavityStatus status = CavityStatus::Ok;
};

// Preconditions: seeds are live subfacets of `facet`; with `split` = {a, b}, the seeds are
// the subfacets of the facet on edge ab and p is the vertex that splits it.
FacetCavity build_facet_cavity(const SurfaceMesh& m, std::uint32_t facet, const Point& p,
                               const std::vector<std::uint32_t>& seeds,
                               const std::optional<std::array<std::uint32_t, 2>>& split);

// Precondition: c.status == Ok, c built on the current mesh, `vertex` is the vertex at
// c.p. Returns the new subfacets.
std::vector<std::uint32_t> commit_facet_cavity(SurfaceMesh& m, const FacetCavity& c,
                                               std::uint32_t vertex);

const char* cavity_status_name(CavityStatus s);

}  // namespace pdr::surface
