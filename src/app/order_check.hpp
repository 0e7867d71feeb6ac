// Order independence of the result (paper §3 Remark 1; §4 Remark 2 and Lemma 2 for the
// parallel layer): the mesh must be the Delaunay tetrahedralization of its own vertex set,
// restricted to the domain, whatever order the vertices were inserted in.
//
// check_order_independence rebuilds DT(V) of the mesh's vertices from scratch by bulk
// insertion in a seeded BRIO order (not the order the mesher inserted them in) and looks up
// every mesh tet, as its sorted vertex quadruple, among DT(V)'s. Symbolic perturbation makes
// DT(V) unique (docs/design.md §5), so every mesh tet must be found. With the checker's
// validity.* (the tets form a tetrahedralization) and conformity.volume (they fill exactly
// the domain), inclusion is equality with DT(V) restricted to the domain.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/mesh_data.hpp"

namespace pdr::app {

struct OrderCheck {
  std::uint64_t seed = 0;
  std::size_t tets = 0;                               // mesh tets looked up
  std::size_t missing = 0;                            // not tets of the rebuilt DT(V)
  std::vector<std::array<std::uint32_t, 4>> first;    // the first missing ones (sorted ids)
  bool ok() const { return missing == 0; }
};

OrderCheck check_order_independence(const MeshData& mesh, std::uint64_t seed);

}  // namespace pdr::app
