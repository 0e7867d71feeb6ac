// Helpers shared by the mesh readers and writers; see mesh_assembly.hpp.
#include "io/mesh_assembly.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace pdr::io {

std::size_t PointRoles::drop_high_order_only(MeshData& mesh) const {
  if (!any_high_order_) return 0;
  constexpr std::uint32_t kGone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> map(role_.size(), kGone);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < role_.size(); ++i) {
    if (role_[i] == kHighOrder) continue;
    map[i] = next;
    mesh.points[next] = mesh.points[i];
    if (!mesh.point_markers.empty()) mesh.point_markers[next] = mesh.point_markers[i];
    ++next;
  }
  const std::size_t dropped = role_.size() - next;
  mesh.points.resize(next);
  if (!mesh.point_markers.empty()) mesh.point_markers.resize(next);
  for (Tet& t : mesh.tets)
    for (std::uint32_t& v : t) v = map[v];
  for (Tri& f : mesh.faces)
    for (std::uint32_t& v : f) v = map[v];
  return dropped;
}

void drop_if_all_zero(std::vector<int>& markers) {
  if (std::all_of(markers.begin(), markers.end(), [](int m) { return m == 0; })) {
    markers.clear();
    markers.shrink_to_fit();
  }
}

void check_writable(const MeshData& mesh, const std::string& target) {
  const std::size_t n = mesh.points.size();
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("cannot write '" + target + "': " + what);
  };
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (std::uint32_t v : mesh.tets[t])
      if (v >= n) fail("tet " + std::to_string(t) + " has vertex " + std::to_string(v) +
                       " but there are " + std::to_string(n) + " points");
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::uint32_t v : mesh.faces[f])
      if (v >= n) fail("face " + std::to_string(f) + " has vertex " + std::to_string(v) +
                       " but there are " + std::to_string(n) + " points");
  if (!mesh.point_markers.empty() && mesh.point_markers.size() != n)
    fail("point_markers has " + std::to_string(mesh.point_markers.size()) + " entries for " +
         std::to_string(n) + " points");
  if (!mesh.face_markers.empty() && mesh.face_markers.size() != mesh.faces.size())
    fail("face_markers has " + std::to_string(mesh.face_markers.size()) + " entries for " +
         std::to_string(mesh.faces.size()) + " faces");
  if (!mesh.tet_regions.empty() && mesh.tet_regions.size() != mesh.tets.size())
    fail("tet_regions has " + std::to_string(mesh.tet_regions.size()) + " entries for " +
         std::to_string(mesh.tets.size()) + " tets");
}

}  // namespace pdr::io
