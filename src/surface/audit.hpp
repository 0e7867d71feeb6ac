// audit_surface: the exact invariants of the surface mesh D (paper §1.1, §2.1; the surface
// half of Lemma 1's invariant 1), as data (docs/design.md §8: never prints). Slow and thorough: for
// tests, fuzzing and the audit assertion level.
//
// Structure (surface/audit.cpp):
//   surface.homes        input vertices keep their ids; a segment vertex lies on that
//                        segment's chain, a facet vertex only in that facet's subfacets;
//                        the incidence lists are exact.
//   surface.chains       each segment's subsegments form one chain from a to b whose
//                        vertices advance strictly along b - a (exact dot products).
//   surface.orientation  every subfacet is counter-clockwise in its facet's chart.
//   surface.adjacency    neighbours are alive, in the same facet, share the edge and point
//                        back; an edge without a neighbour is a subsegment.
//   surface.conformity   an edge is marked constrained iff it is a subsegment of a segment
//                        of its facet; boundary chains appear once in their direction,
//                        interior segments' chains once in each direction; every other
//                        directed edge has its reverse (so the subfacets tile the region).
//   surface.area         the subfacets' chart areas sum exactly (GMP) to the area enclosed
//                        by the facet's boundary chains.
//   surface.delaunay     every interior edge (subsegments included) is locally Delaunay
//                        under chart_incircle; where the four points are exactly coplanar,
//                        incircle3_sos agrees (counted as coplanar_edges; the others, a few
//                        ulps off a common plane, as off_plane_edges).
//   surface.size         (when the mesh has d) subsegments shorter than 2d and subfacet
//                        circumradii below d√2 (paper §2.1 properties 2 and 3).
// Balls (surface/audit.cpp), over all vertices of the surface (grid-free: sorted by x):
//   surface.encroachment no vertex other than its endpoints in the closed diametral ball of
//                        a subsegment; no vertex strictly inside the equatorial ball of a
//                        subfacet, and none on its sphere unless it is a vertex of the same
//                        facet (cocircular in the facet: counted as `cocircular`, decided
//                        by the symbolic perturbation, which the 3D triangulation shares).
//                        A violation by a vertex of the same facet that is not exactly
//                        coplanar with the subfacet is also counted as off_plane_balls: on
//                        a tilted or near-planar facet, a near-cocircular quadruple a few
//                        ulps off a common plane (surface/chart.hpp, limitation); such a
//                        subfacet usually still is a face of the 3D Delaunay
//                        tetrahedralization (a sphere through it can move off the
//                        offending vertex), but the paper's closed-ball invariant fails.
// Violations beyond max_reported are counted, not described.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "surface/surface_mesh.hpp"

namespace pdr::surface {

struct SurfaceAudit {
  std::vector<std::string> violations;  // "surface.<invariant>: ..."
  std::size_t violation_count = 0;
  std::size_t max_reported = 50;
  std::size_t coplanar_edges = 0, off_plane_edges = 0;
  std::size_t cocircular = 0;
  std::size_t off_plane_balls = 0;
  bool ok() const { return violation_count == 0; }
  void add(std::string message) {
    if (violations.size() < max_reported) violations.push_back(std::move(message));
    ++violation_count;
  }
};

SurfaceAudit audit_surface(const SurfaceMesh& m, std::size_t max_reported = 50);

// The two halves, appending to `out`.
void audit_surface_structure(const SurfaceMesh& m, SurfaceAudit& out);
void audit_surface_balls(const SurfaceMesh& m, SurfaceAudit& out);

}  // namespace pdr::surface
