// Assembly: the whole mesh at rank 0 from the submeshes' tets after the parallel phase
// (docs/parallel.md, "Gather and assemble").
//
// Every tet of the mesh, ghosts included, is held by exactly one submesh once the phase
// has terminated (par/submesh.hpp M1), and a face between two submeshes is closed on both
// sides by proxies naming each other's tets (M2, M3). So the union of the submeshes' real
// tets is the mesh, glued along the faces inside each submesh (its store's adjacency) and
// along the proxy faces (by their vertices: a face of the mesh is shared by exactly two
// tets). A Piece is one submesh's real tets, their vertices and that adjacency; assemble()
// replaces rank 0's M_o by the union of the pieces. M_o's vertices keep their ids (global
// id = M_o's vertex id: par/submesh.hpp), so D and its maps stay valid; the vertices made
// in the phase are appended, off ∂Ω.
//
// This is the same mesh that inserting the committed points into M_o gives (the Delaunay
// tetrahedralization of a point set is unique under the symbolic perturbation, and the
// inside flags change only across subfacets): tested tet by tet against that insertion.
// It costs a pass over the tets instead of a point location and a cavity per committed
// point.
//
// The phase's steps on ∂Ω (par/refinement_rules.hpp) are then made in D with the
// sequential kernel's operations at the committed points: the subsegment splits first
// (surface/split.hpp split_subsegment_at), each after those that made its ends, then the
// subfacet circumcenters (located in their facet, surface/locate.hpp, and inserted by a
// facet cavity, surface/cavity.hpp). The final D does not depend on that order (each
// facet's triangulation is the Delaunay triangulation of its vertices, unique under the
// symbolic perturbation), and no circumcenter encroaches a subsegment of the final D
// (it encroached none of its closure when committed, and later splits only shrink the
// diametral balls), so every facet cavity is valid. Each new vertex is mapped to its D
// vertex. For the domains the phase takes these steps in (exact constructions on ∂Ω)
// this is the change the phase made to its labels; an element of D at a new vertex that
// is not an edge or face of T is listed as missing (VolumeMesh::missing_subfacets),
// which the completion restores as it restores T_o's (refine/conformity.hpp). The same
// stars are searched for encroached elements (Assembled::encroached): the points on ∂Ω
// are the only ones the phase inserted without testing the elements they encroach.
#pragma once

#include <array>
#include <cstring>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "par/refinement_rules.hpp"
#include "par/submesh.hpp"
#include "par/wire.hpp"
#include "refine/volume_mesh.hpp"

namespace pdr::par {

// A tet of a piece: its vertices (indices into Piece::vertices, kGhostVertex for the
// ghost), in the store's orientation; per face, the tet across as 4 * index + its face
// index, or kAcrossProxy: in another piece; its inside flag (bit 0) and its deferred mark
// (bit 1: Submesh::deferred).
struct PieceTet {
  std::array<std::uint32_t, 4> v{};
  std::array<std::uint32_t, 4> across{};
  std::uint8_t inside = 0;
};
inline constexpr std::uint32_t kAcrossProxy = 0xFFFFFFFFu;

struct Piece {
  std::vector<VertexRecord> vertices;  // those of its tets
  std::vector<PieceTet> tets;
};

// Submesh s's real tets (ghosts included, proxies not).
Piece piece_of(const Submesh& s);

// Appends the piece to w, and reads one back.
void put_piece(WireWriter& w, const Piece& p);
Piece get_piece(WireReader& r);

// A piece read where it lies: in a gathered message (get_piece_view, without copying it)
// or in a Piece. What it points at must outlive it.
class PieceView {
 public:
  PieceView() = default;
  explicit PieceView(const Piece& p);
  std::size_t vertex_count() const { return nv_; }
  std::size_t tet_count() const { return nt_; }
  VertexRecord vertex(std::size_t i) const { return read<VertexRecord>(v_, i); }
  PieceTet tet(std::size_t i) const { return read<PieceTet>(t_, i); }

 private:
  friend PieceView get_piece_view(WireReader& r);
  template <class T>
  static T read(const std::byte* at, std::size_t i) {
    T x;
    std::memcpy(&x, at + i * sizeof(T), sizeof(T));
    return x;
  }
  std::size_t nv_ = 0, nt_ = 0;
  const std::byte* v_ = nullptr;
  const std::byte* t_ = nullptr;
};
PieceView get_piece_view(WireReader& r);

struct Assembled {
  std::size_t added = 0;        // vertices appended
  std::vector<TetId> deferred;  // the tets marked deferred, by their new ids
  // Elements of D encroached (strictly, refine/guard.hpp) among those of the tets around
  // the phase's points on ∂Ω: Lemma 1 says none in an admissible domain; the completion
  // trusts the phase only when none is (app/parallel.cpp, RefineOptions::resumed_h).
  std::size_t encroached = 0;
};

// Replaces m's tets by the union of `pieces` (the submeshes of a partition of m after the
// parallel phase): m's vertices keep their ids, the pieces' vertices with global ids from
// m.dt.num_points() on are appended (off ∂Ω, vclass Interior, unless `steps` puts one on
// ∂Ω), the inside flags come with the tets. Throws std::logic_error when the pieces do
// not glue into a closed mesh (a face left open, or met by more than two tets), or a
// step cannot be made in D (a split of a subsegment D does not have, a point outside
// its facet or with an invalid facet cavity).
Assembled assemble(refine::VolumeMesh& m, std::span<const Piece> pieces,
                   std::span<const SurfaceStep> steps = {});

// The same, a piece at a time (rank 0 reads the gathered pieces where they lie, so that
// they are never held twice): Assembly a(m); a.add(piece)...; a.finish(m). add() numbers
// the piece's vertices (in piece order, so the ids do not depend on threads) and gives its
// tets the next slots; finish() writes the tets into those slots on every core (a tet's
// neighbours within its piece are known by their index, so each tet is written alone),
// then glues the faces between pieces. The pieces must stay alive until finish().
class Assembly {
 public:
  explicit Assembly(const refine::VolumeMesh& m);
  void add(const PieceView& p);
  // m: the mesh given to the constructor.
  Assembled finish(refine::VolumeMesh& m, std::span<const SurfaceStep> steps = {});

 private:
  struct Added {  // a piece given to add()
    PieceView piece;
    TetId first = 0;            // the slot of its tet 0
    std::vector<VertexId> map;  // its vertices' ids
  };
  struct OpenFace {  // a face towards another piece: its vertex ids, sorted
    std::array<VertexId, 3> key;
    HalfFace h;
  };
  // Writes tets [begin, end) of piece `a` into their slots; faces towards other pieces go
  // to `open`, deferred tets to `deferred`. Throws std::logic_error on a malformed piece.
  void write_tets(const Added& a, std::size_t begin, std::size_t end, std::vector<OpenFace>& open,
                  std::vector<TetId>& deferred);
  VertexId vertex(Gid g) const;
  // add(): where the id of vertex g, made in the phase, is kept (by maker and serial,
  // par/submesh.hpp made_vertex); kNoVertex there until a piece brings it.
  VertexId* fresh_slot(Gid g);
  // Returns how many elements are encroached around the steps' points (Assembled).
  std::size_t change_d(refine::VolumeMesh& m, std::span<const SurfaceStep> steps) const;
  std::size_t n0_;
  std::vector<Point> points_;
  std::vector<std::vector<VertexId>> fresh_;  // vertices made in the parallel phase
  std::vector<TetId> fresh_tet_;             // per vertex made: a tet holding it
  std::vector<Added> added_;
  std::size_t tets_ = 0;  // slots given so far
  TetStore st_;
  std::vector<std::uint8_t> inside_;
  Assembled out_;
};

}  // namespace pdr::par
