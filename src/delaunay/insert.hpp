// CavityCommitter: retriangulate a cavity in one step (paper §1.2 steps 3-4).
//
// T_{i+1} = (T_i - C_p) ∪ B_p, where B_p joins p to every boundary face of H_p.
// The new tet for boundary half-face (t,f) is t with slot f replaced by p. Since the cavity
// is star-shaped from p, p lies strictly on the same side of face f as t's old vertex, so
// the new tet is positive whenever t was (and a ghost tet stays a ghost with the ghost in
// slot 3, or becomes a finite tet when f = 3); its face f is glued to t's old neighbour.
// The three other faces of a new tet each hold p and one edge of the cavity boundary; the
// boundary is a closed, consistently oriented surface, so each directed edge (a,b) of one
// boundary triangle meets the reversed edge (b,a) of exactly one other. A small open
// addressing table keyed on directed edges pairs them. Slots of C_p are reused for the
// first |C_p| new tets; the table and buffers are kept between commits, so a commit
// allocates nothing once warm.
#pragma once

#include <cstdint>
#include <vector>

#include "delaunay/cavity.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

class CavityCommitter {
 public:
  // Preconditions: `c` was built on `s` as it is now; v is the vertex id of c.point.
  // Returns a new tet incident to v (a finite one when there is one).
  TetId commit(TetStore& s, const Cavity& c, VertexId v);

 private:
  struct Slot {
    std::uint64_t key;
    HalfFace value;
    std::uint32_t stamp;
  };
  void reset_table(std::size_t entries);
  // Returns the half-face stored under the reversed edge (b,a) if present; otherwise
  // stores `h` under (a,b) and returns kNoHalfFace.
  HalfFace match_or_store(VertexId a, VertexId b, HalfFace h);

  std::vector<VertexId> verts_;   // 4 per new tet
  std::vector<HalfFace> outer_;   // outside half-face of each new tet
  std::vector<TetId> ids_;        // id of each new tet
  std::vector<Slot> table_;
  std::uint32_t stamp_ = 0;
  int table_bits_ = 0;
};

}  // namespace pdr
