// The combinatorial half of surface_to_plc (internal to pdr_io; steps 1-4 of surface.hpp):
// duplicate vertices merged, faces checked for degeneracy and planarity, every edge joining
// two or more faces, faces reoriented so that the two faces of every edge of exactly two run
// along it in opposite directions. The geometric half (coplanar facets, loops, hole points) is
// surface_facets.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/precision.hpp"
#include "io/surface.hpp"

namespace pdr::io {

struct SurfaceTopology {
  std::vector<Point> points;              // distinct points
  std::vector<std::uint32_t> input_of;    // point -> its first input point
  std::vector<std::uint32_t> corners;     // as Surface::corners, renumbered and reoriented
  std::vector<std::uint8_t> planar;       // per face: every corner exactly on `plane`'s plane
  std::vector<std::array<std::uint32_t, 3>> plane;  // per face: three non-collinear corners
  // Per face: the other face across the edge from corner i to corner i+1, at
  // neighbour[face_start[f] + i]; kNoNeighbour where three or more faces share the edge.
  std::vector<std::uint32_t> neighbour;
  static constexpr std::uint32_t kNoNeighbour = ~std::uint32_t{0};

  std::span<const std::uint32_t> face(const Surface& s, std::size_t f) const {
    return {corners.data() + s.face_start[f], s.face_start[f + 1] - s.face_start[f]};
  }
};

// Step 0b of surface.hpp (surface_split.cpp): the surface with its faces that are not
// planar within the tolerance split into triangles; nullopt when no face is.
std::optional<Surface> split_nonplanar_faces(const Surface& s, const PlanarityTolerance& tolerance);

// Steps 1-4 of surface.hpp; throws InputError naming the face, edge or vertex at fault.
SurfaceTopology build_topology(const Surface& s);

// "face 12" (faces numbered from 1), for messages.
std::string face_name(const Surface& s, std::size_t f);
// "vertex 7 (x, y, z)", or "(x, y, z)" when the file does not number its vertices.
std::string vertex_name(const Surface& s, const SurfaceTopology& t, std::uint32_t v);
// Throws InputError(source, line of face f, "face N: <problem>").
[[noreturn]] void face_fail(const Surface& s, std::size_t f, const std::string& problem);

// The two coordinates of p other than `axis`, in cyclic order (axis+1, axis+2): orient2d
// of projected points has the sign of the axis component of the normal of their plane.
inline std::array<double, 2> drop_axis(const Point& p, int axis) {
  return {p[(axis + 1) % 3], p[(axis + 2) % 3]};
}

}  // namespace pdr::io
