// to_mesh_data (export.hpp).
#include "delaunay/export.hpp"

#include <cassert>

#include "mesh/tables.hpp"

namespace pdr {

namespace {

template <class Keep>
MeshData export_region(const Delaunay& dt, Keep keep) {
  const TetStore& s = dt.store();
  MeshData m;
  m.points.assign(dt.points().begin(), dt.points().end());
  for (TetId t = 0; t < s.slots(); ++t) {
    // A later tet's neighbours, scattered over the store, requested meanwhile.
    if (constexpr TetId kAhead = 8; t + kAhead < s.slots() && s.is_alive(t + kAhead))
      for (int f = 0; f < 4; ++f) s.prefetch(s.neighbour(t + kAhead, f));
    if (!s.is_alive(t) || s.is_ghost(t) || !keep(t)) continue;
    const VertexId* v = s.vertices(t);
    m.tets.push_back({v[0], v[1], v[2], v[3]});
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (!s.is_ghost(u) && keep(u)) continue;
      const auto& fv = tables::kFaceVertex[f];
      m.faces.push_back({v[fv[0]], v[fv[1]], v[fv[2]]});
    }
  }
  return m;
}

}  // namespace

MeshData to_mesh_data(const Delaunay& dt) {
  return export_region(dt, [](TetId) { return true; });
}

MeshData to_mesh_data(const Delaunay& dt, std::span<const std::uint8_t> keep) {
  assert(keep.size() >= dt.store().slots());
  return export_region(dt, [keep](TetId t) { return keep[t] != 0; });
}

void restore_input_order(MeshData& m, std::span<const VertexId> input_index) {
  assert(input_index.size() == m.points.size());
  std::vector<Point> points(m.points.size());
  for (std::size_t v = 0; v < points.size(); ++v) points[input_index[v]] = m.points[v];
  m.points = std::move(points);
  for (Tet& t : m.tets)
    for (auto& v : t) v = input_index[v];
  for (Tri& f : m.faces)
    for (auto& v : f) v = input_index[v];
  if (!m.point_markers.empty()) {
    std::vector<int> markers(m.point_markers.size());
    for (std::size_t v = 0; v < markers.size(); ++v) markers[input_index[v]] = m.point_markers[v];
    m.point_markers = std::move(markers);
  }
}

}  // namespace pdr
