// Subsegment splitting (paper §2.1 step 1 "subdividing subsegments"; Fig. 2 "Refine(s)").
//
// split_subsegment inserts the floating-point midpoint of subsegment s = (u, w)
// (construct::midpoint: where, not whether) as a new vertex whose home is s's segment,
// replaces s by (u, m) and (m, w) (ids: s and a new one), and updates the triangulation of
// every facet containing the segment: m is on the boundary of each (on an interior segment
// of a facet, inside it), so each facet gets one Bowyer-Watson cavity seeded by its
// subfacets on uw (surface/cavity.hpp). All cavities are built before anything changes;
// if one is not star-shaped (excluded by the exact arguments for exactly collinear and
// coplanar points; a midpoint of a tilted subsegment is within an ulp of the line, so the
// new subfacets next to it may be a hair's breadth off the old boundary, which the audit
// measures exactly) nothing changes and SurfaceError names the facet.
// No encroachment test: paper §2.1, "the 90° condition and d make midpoints safe"; the
// cavities still report the subsegments m encroaches (for inadmissible domains).
// split_subsegment_at does the same at a caller's point p (the concentric-shell split near
// an acute input vertex, refine/split.hpp). Precondition: p lies on the open subsegment up
// to the rounding of its construction (a point a + t (b - a) in double, like the midpoint).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "surface/cavity.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::surface {

struct SplitResult {
  std::uint32_t vertex = 0;                // the midpoint
  std::uint32_t new_subsegment = 0;        // (m, w); s itself became (u, m)
  std::vector<std::uint32_t> subfacets;    // the new subfacets, in all facets
  std::vector<std::uint32_t> encroached;   // other subsegments m's closed ball test hits
};

SplitResult split_subsegment(SurfaceMesh& m, std::uint32_t s);
SplitResult split_subsegment_at(SurfaceMesh& m, std::uint32_t s, const Point& p);

// The same in two steps, for a caller that must decide before anything changes: the facet
// cavities of p (read-only), with `failure` naming the facet whose cavity is not
// star-shaped (empty when every one is), then their commit (precondition: no failure, and
// nothing changed since the plan).
struct SplitPlan {
  Point p{};
  std::vector<FacetCavity> cavities;
  std::string failure;
};
SplitPlan plan_split(const SurfaceMesh& m, std::uint32_t s, const Point& p);
SplitResult commit_split(SurfaceMesh& m, std::uint32_t s, const SplitPlan& plan);

}  // namespace pdr::surface
