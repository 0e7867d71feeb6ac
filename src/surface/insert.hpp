// Subfacet refinement at the circumcenter (paper §2.1 step 2 "insert the circumcenters of
// subfacets"; Fig. 2 "Refine(f)" for a subfacet, "if p encroaches subsegment s then
// Refine(s)").
//
// plan_circumcenter computes where (the circumcenter of the subfacet in 3D,
// construct::triangle_circumcenter, moved onto the facet's plane along the chart's dropped
// axis by place_on_facet, surface/chart.hpp) and builds the facet cavity seeded by the
// subfacet (surface/cavity.hpp), read-only. Its outcome:
//   Inserted    (after commit) the point encroaches no subsegment and its cavity is valid;
//   Encroaches  the point lies in the closed diametral ball of the listed subsegments on
//               the cavity's boundary (this covers "falls outside the facet": a
//               circumcenter separated from its subfacet by a subsegment encroaches it);
//               the caller splits them instead (Fig. 2);
//   Rejected    the cavity is degenerate (not star-shaped, or the subfacet does not
//               conflict with its own rounded circumcenter), excluded by the exact
//               arguments for coplanar points; the caller reports it.
// insert_circumcenter = plan + commit when the plan is Inserted.
// A vertex a tetrahedron's circumcenter sends onto a facet (§3) is a subfacet
// circumcenter too: the volume refinement calls the same function.
#pragma once

#include <cstdint>
#include <vector>

#include "surface/cavity.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::surface {

enum class InsertOutcome : std::uint8_t { Inserted, Encroaches, Rejected };

struct InsertResult {
  InsertOutcome outcome = InsertOutcome::Rejected;
  Point point{};                          // the placed circumcenter
  std::uint32_t vertex = 0;               // Inserted: its id
  std::vector<std::uint32_t> subfacets;   // Inserted: the new subfacets
  std::vector<std::uint32_t> encroached;  // Encroaches: subsegments to split instead
  CavityStatus cavity = CavityStatus::Ok;  // Rejected: why
};

// Where the circumcenter of subfacet t goes (precondition: t alive).
Point subfacet_circumcenter(const SurfaceMesh& m, std::uint32_t t);
FacetCavity plan_circumcenter(const SurfaceMesh& m, std::uint32_t t);
InsertResult insert_circumcenter(SurfaceMesh& m, std::uint32_t t);

}  // namespace pdr::surface
