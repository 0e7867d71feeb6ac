// The partitioned output of a parallel run (`mpirun -np P pdr mesh ... --formats vtu`):
// PREFIX.pvtu, a VTK parallel unstructured grid that ParaView opens as one mesh, with one
// piece per rank, PREFIX_p<r>.vtu, holding that rank's tets with the rank as the cell field
// "owner" (the pieces together are exactly the mesh written as PREFIX.vtu).
//
// Which rank a tet belongs to. The final mesh is made on rank 0 (docs/parallel.md), so
// ownership is read from the vertices: a point committed in the parallel phase belongs to
// the rank that committed it; a vertex of M_o to the METIS part of one of its inside tets
// (the smallest); a vertex added by the completion to nobody. A tet belongs to the owner of
// its lexicographically smallest committed vertex, else of its smallest M_o vertex with an
// owner, else to rank 0: the pieces are the ranks' regions as the parallel phase left them,
// up to the tets the completion remade. When the ranks listed the mesh themselves
// (app/parallel.hpp ListedMesh), a tet belongs to the rank that listed it.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "geom/point.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::app {

struct PointHash {
  std::size_t operator()(const Point& p) const;
};

struct VertexOwners {
  int parts = 0;
  std::unordered_map<Point, std::uint32_t, PointHash> committed;  // by exact coordinates
  std::unordered_map<Point, std::uint32_t, PointHash> initial;
};

// The owner of every tet of `mesh` (rule above).
std::vector<std::uint32_t> tet_owners(const MeshData& mesh, const VertexOwners& owners);

// Writes PREFIX_p<r>.vtu for r < parts and PREFIX.pvtu, all or nothing (temporary files
// renamed at the end); returns their paths.
std::vector<std::string> write_partitioned_vtu(const MeshData& mesh,
                                               const std::vector<std::uint32_t>& owner,
                                               int parts, const std::string& prefix);

}  // namespace pdr::app
