// bulk_insert: the Delaunay tetrahedralization of a whole point set.
//
// 1. Order the points: BRIO rounds with a Hilbert sort per round (spatial_sort.hpp).
// 2. First tet: the first point a in that order, the first b != a, the first c not
//    collinear with a,b (orient2d of the three coordinate projections, all zero iff
//    collinear), the first d with orient3d(a,b,c,d) != 0. Exact predicates only; if
//    there is no such c or d, the status says the input is collinear or coplanar and the
//    triangulation stays empty.
// 3. Insert the rest in order, each walk starting from the previous insertion's tet.
// Exact duplicates are found by the walk (walk.hpp) and reported, never inserted: the
// copy met first in insertion order is kept (the order is fixed by the seed).
// Renumbering (default): the points are stored in insertion order, so that vertices that
// are close in space are close in memory (the cavity search reads their coordinates; in
// input order they would be scattered). Vertex v of the result is input point
// input_index[v]; restore_input_order() (export.hpp) maps a MeshData back.
// Paper §1.2 (each insertion) and §2 (the initial Delaunay tetrahedralization).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "delaunay/delaunay.hpp"

namespace pdr {

struct BulkOptions {
  std::uint64_t seed = 0x5EED;  // shuffle of the BRIO rounds
  std::size_t min_round = 1000;  // BRIO: smallest round, inserted in Hilbert order
  bool spatial_sort = true;      // false: insert in the given order (tests)
  bool renumber = true;          // store points in insertion order (see above)
};

enum class BulkStatus : std::uint8_t {
  Ok,
  TooFewPoints,   // fewer than 2 distinct points
  AllCollinear,   // at least 2 distinct points, all on one line
  AllCoplanar,    // not collinear, but all on one plane
};

struct Duplicate {  // indices into the input points
  VertexId id;    // the point that was not inserted
  VertexId kept;  // the inserted point with the same coordinates
};

struct BulkResult {
  BulkStatus status = BulkStatus::Ok;
  std::string message;                // empty when Ok; starts with the status name
  std::vector<Duplicate> duplicates;  // in insertion order
  std::vector<VertexId> input_index;  // vertex id -> input index (identity if !renumber)
};

// Inserts every point of dt (all of dt.points()). Precondition: dt.empty().
BulkResult bulk_insert(Delaunay& dt, const BulkOptions& options = {});

}  // namespace pdr
