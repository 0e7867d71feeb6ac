// CavityCommitter: retriangulate a cavity in one step (paper §1.2 steps 3-4).
//
// T_{i+1} = (T_i - C_p) ∪ B_p, where B_p joins p to every boundary face of H_p.
// The new tet for boundary half-face (t,f) is t with slot f replaced by p. Since the cavity
// is star-shaped from p, p lies strictly on the same side of face f as t's old vertex, so
// the new tet is positive whenever t was (and a ghost tet stays a ghost with the ghost in
// slot 3, or becomes a finite tet when f = 3); its face f is glued to t's old neighbour.
//
// The three other faces of a new tet each hold p and one edge of the cavity boundary. The
// boundary is a closed, consistently oriented triangulated sphere, so the directed edge
// (a,b) of one boundary triangle meets the reversed edge (b,a) of exactly one other, and
// the two new tets on those triangles are neighbours. To pair them without searching, the
// boundary vertices get local numbers 0..L-1 (a per-vertex stamp array) and an L x L table
// records, for each directed edge (a,b), the new tet's face that holds it; the neighbour of
// that face is then read at (b,a). Two branch-free passes, no hashing. For very large
// cavities (L > dense_limit, e.g. many cospherical points) an open-addressing table keyed
// on directed edges replaces the L x L table.
// Slots of C_p are reused for the first |C_p| new tets. All buffers are kept between
// commits, so a commit allocates nothing once warm.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "delaunay/cavity.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

class CavityCommitter {
 public:
  // dense_limit: most boundary vertices paired through the L x L table (tests pass 0 to
  // exercise the hashed path).
  explicit CavityCommitter(std::uint32_t dense_limit = 128) : dense_limit_(dense_limit) {}

  // Preconditions: `c` was built on `s` as it is now; v is the vertex id of c.point; every
  // vertex id in `s` is < vertex_count. Returns a new tet incident to v (a finite one when
  // there is one).
  TetId commit(TetStore& s, const Cavity& c, VertexId v, std::size_t vertex_count);
  // The tets made by the last commit (valid until the next one).
  std::span<const TetId> created() const { return ids_; }

 private:
  struct Slot {
    std::uint64_t key;
    HalfFace value;
    std::uint32_t stamp;
  };
  void number_boundary_vertices(std::size_t nb, std::size_t vertex_count);
  void pair_dense(TetStore& s, std::size_t nb);
  void pair_hashed(TetStore& s, std::size_t nb);
  // Returns the half-face stored under the reversed edge (b,a) if present; otherwise
  // stores `h` under (a,b) and returns kNoHalfFace.
  HalfFace match_or_store(VertexId a, VertexId b, HalfFace h);

  std::uint32_t dense_limit_;
  std::vector<VertexId> verts_;     // 4 per new tet
  std::vector<std::uint32_t> local_;  // 3 per new tet: local numbers of its boundary face
  std::vector<int> faces_;          // boundary face index (slot of v) per new tet
  std::vector<TetId> ids_;          // id of each new tet
  std::uint32_t locals_ = 0;        // L
  // Per vertex id: [2v] = stamp of the last commit that numbered it, [2v+1] = number;
  // the ghost vertex uses the entry after the last vertex.
  std::vector<std::uint32_t> vertex_local_;
  std::uint32_t commit_stamp_ = 0;
  std::vector<HalfFace> edge_face_;  // L x L
  std::vector<Slot> table_;          // hashed fallback
  std::uint32_t table_stamp_ = 0;
  int table_bits_ = 0;
};

}  // namespace pdr
