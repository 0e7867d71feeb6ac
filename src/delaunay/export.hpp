// Export a triangulation as MeshData (mesh/mesh_data.hpp).
//
// points: every point of the Delaunay object, ids unchanged (duplicates and points not
// inserted are kept, unreferenced); tets: the finite live tets in store order, vertex
// slots as stored, so each is positive; faces: the boundary of the exported region, each
// face oriented out of it (mesh/tables.hpp) -- for the whole triangulation, the convex
// hull. With a `keep` mask (indexed by tet id, ghost entries ignored) only the tets with
// keep[t] != 0 are exported and faces bound that region: this is how a caller that has
// classified tets (e.g. inside/outside a domain) removes the others.
#pragma once

#include <cstdint>
#include <span>

#include "delaunay/delaunay.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr {

MeshData to_mesh_data(const Delaunay& dt);
MeshData to_mesh_data(const Delaunay& dt, std::span<const std::uint8_t> keep);

// Renumber m's points so that vertex v becomes input_index[v] (BulkResult::input_index,
// a permutation of 0..points-1); tets and faces are relabelled alike.
void restore_input_order(MeshData& m, std::span<const VertexId> input_index);

}  // namespace pdr
