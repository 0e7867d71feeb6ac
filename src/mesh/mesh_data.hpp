// MeshData: a tetrahedral mesh as plain arrays, the exchange format between the kernel,
// the readers/writers and the checkers (the checkers' read-only view is over this).
//
// Invariants a *valid* mesh keeps (src/check decides them; readers do not assume them):
//   - every index in tets/faces is < points.size();
//   - every tet is positively oriented: orient3d(p[t0], p[t1], p[t2], p[t3]) > 0;
//   - faces, when present, are the boundary triangles, each oriented so that its normal
//     (b-a)x(c-a) points out of the mesh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geom/point.hpp"

namespace pdr {

using Tet = std::array<std::uint32_t, 4>;
using Tri = std::array<std::uint32_t, 3>;

struct MeshData {
  std::vector<Point> points;
  std::vector<Tet> tets;
  std::vector<Tri> faces;            // boundary faces; may be empty
  std::vector<int> face_markers;     // empty or faces.size() entries
  std::vector<int> point_markers;    // empty or points.size() entries
  std::vector<int> tet_regions;      // empty or tets.size() entries (region attribute)
};

}  // namespace pdr
