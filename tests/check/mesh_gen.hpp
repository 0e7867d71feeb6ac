// Test meshes for pdr_check: structured cube grids (Kuhn/Freudenthal: every cube split
// into 6 tets along its main diagonal, conforming across cubes), their box domain, small
// hand-made meshes, and the brute-force Delaunay oracle (GMP only, no grid, no filter).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "geom/exact.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/plc.hpp"

namespace pdr::check::test {

inline std::uint32_t grid_id(int n, int i, int j, int k) {
  return static_cast<std::uint32_t>(i + (n + 1) * (j + (n + 1) * k));
}

// n^3 cubes of side `side` starting at the origin, 6 positive tets each. Every vertex of a
// cube lies on its circumsphere: lots of cospherical (never inside) vertices.
inline MeshData kuhn_grid(int n, double side = 1.0) {
  MeshData m;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.points.push_back({i * side, j * side, k * side});
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms) {
          std::array<int, 3> c = {i, j, k};
          Tet t{};
          t[0] = grid_id(n, c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = grid_id(n, c[0], c[1], c[2]);
          }
          if (exact::orient3d(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) ==
              Sign::Negative)
            std::swap(t[1], t[2]);
          m.tets.push_back(t);
        }
  return m;
}

// The box [0, n*side]^3 as a PLC: 8 corners, 6 quadrilateral facets.
inline Plc box_domain(int n, double side = 1.0) {
  Plc d;
  const double L = n * side;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) d.points.push_back({i * L, j * L, k * L});
  auto id = [](int i, int j, int k) { return static_cast<std::uint32_t>(i + 2 * j + 4 * k); };
  const std::vector<std::vector<std::uint32_t>> quads = {
      {id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), id(0, 1, 0)}, {id(0, 0, 1), id(1, 0, 1), id(1, 1, 1), id(0, 1, 1)},
      {id(0, 0, 0), id(1, 0, 0), id(1, 0, 1), id(0, 0, 1)}, {id(0, 1, 0), id(1, 1, 0), id(1, 1, 1), id(0, 1, 1)},
      {id(0, 0, 0), id(0, 1, 0), id(0, 1, 1), id(0, 0, 1)}, {id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1)}};
  for (const auto& q : quads) {
    PlcFacet f;
    f.polygons.push_back(q);
    d.facets.push_back(f);
  }
  return d;
}

// Brute-force Delaunay oracle: for every non-degenerate tet and every vertex not in it,
// the exact insphere sign times the exact orientation (GMP only).
struct OracleVerdict {
  std::set<std::uint64_t> violating_tets;
  std::uint64_t violating_pairs = 0, cospherical = 0;
};

inline OracleVerdict delaunay_oracle(const MeshData& m) {
  OracleVerdict v;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const Tet& k = m.tets[t];
    const Point &a = m.points[k[0]], &b = m.points[k[1]], &c = m.points[k[2]], &d = m.points[k[3]];
    const Sign o = exact::orient3d(a, b, c, d);
    if (o == Sign::Zero) continue;
    for (std::uint32_t p = 0; p < m.points.size(); ++p) {
      if (std::find(k.begin(), k.end(), p) != k.end()) continue;
      const Sign s = exact::insphere(a, b, c, d, m.points[p]) * o;
      if (s == Sign::Zero) ++v.cospherical;
      if (s != Sign::Positive) continue;
      ++v.violating_pairs;
      v.violating_tets.insert(t);
    }
  }
  return v;
}

}  // namespace pdr::check::test
