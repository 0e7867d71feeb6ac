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

}  // namespace pdr
