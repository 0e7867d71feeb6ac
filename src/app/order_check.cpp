// The order-independence check (order_check.hpp): DT(V) rebuilt in another order contains
// every mesh tet.
#include "app/order_check.hpp"

#include <algorithm>

#include "delaunay/bulk.hpp"
#include "delaunay/delaunay.hpp"

namespace pdr::app {

namespace {

using Quad = std::array<std::uint32_t, 4>;

Quad sorted(Quad q) {
  std::sort(q.begin(), q.end());
  return q;
}

}  // namespace

OrderCheck check_order_independence(const MeshData& mesh, std::uint64_t seed) {
  OrderCheck r;
  r.seed = seed;
  r.tets = mesh.tets.size();
  Delaunay dt(mesh.points);
  BulkOptions o;
  o.seed = seed;
  o.renumber = false;  // vertex ids stay the mesh's
  const BulkResult b = bulk_insert(dt, o);
  std::vector<Quad> all;
  if (b.status == BulkStatus::Ok) {
    const TetStore& s = dt.store();
    all.reserve(s.live());
    for (TetId t = 0; t < s.slots(); ++t)
      if (s.is_alive(t) && !s.is_ghost(t)) {
        const VertexId* v = s.vertices(t);
        all.push_back(sorted({v[0], v[1], v[2], v[3]}));
      }
    std::sort(all.begin(), all.end());
  }
  for (const auto& t : mesh.tets) {
    const Quad q = sorted({t[0], t[1], t[2], t[3]});
    if (std::binary_search(all.begin(), all.end(), q)) continue;
    if (r.missing++ < 10) r.first.push_back(q);
  }
  return r;
}

}  // namespace pdr::app
