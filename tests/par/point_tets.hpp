// A mesh's finite tets as their four points, each tet's points sorted and the tets sorted:
// the same list for any numbering of the same tetrahedralization, so meshes built by
// different runs (parallel, sequential) compare with ==.
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "mesh/tet_store.hpp"
#include "geom/point.hpp"

namespace pdr::par::test {

using PointTet = std::array<double, 12>;

inline void add_finite_tets(const TetStore& s, std::span<const Point> pts, std::vector<PointTet>& out) {
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.vertex(t, 3) >= kFirstSpecialVertex) continue;
    const VertexId* v = s.vertices(t);
    std::array<Point, 4> p{pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]};
    std::sort(p.begin(), p.end());
    PointTet q;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t k = 0; k < 3; ++k) q[3 * i + k] = p[i][k];
    out.push_back(q);
  }
}

inline std::vector<PointTet> sorted(std::vector<PointTet> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace pdr::par::test
