// The output mesh listed by the ranks from their own submeshes, without the assembly at
// rank 0 (docs/parallel.md, "The mesh listed by the ranks").
//
// After the parallel phase every tet is held by exactly one submesh (par/submesh.hpp M1),
// so the mesh is the union of the submeshes' real tets. When the sequential completion
// would have nothing to do (app/parallel.cpp decides, on every rank alike), each rank can
// list its part of the output mesh — the points its submeshes made, its inside tets, their
// boundary faces with the facets' markers — and rank 0 only joins the parts. The
// completion has nothing to do when no step was deferred, the completion would resume the
// phase's run (RefineOptions::resumed_h: M_o met Theorem 1's hypotheses) and nothing is
// encroached around the points the phase put on ∂Ω, the only points it inserted without
// testing the elements they encroach (par/assembly.hpp: the same test, there on rank 0's
// D, here on the submeshes' labels, M4).
//
// Vertex numbers: M_o's vertices keep their ids (a global id below M_o's vertex count is
// that id); the vertex that submesh k made with serial i (par/submesh.hpp made_vertex)
// gets first[k] + i, where the submeshes' made vertices follow M_o's in the order the parts
// are joined: rank 0's submeshes (0, P, 2P, ...), then rank 1's, and so on. Submesh k's
// serials are dense, 0 .. made[k] - 1: each commit makes exactly one vertex
// (Submesh::insert), whose point the actor lists in commit order
// (InsertionActor::committed_points).
//
// Boundary faces, as delaunay/export.hpp's to_mesh_data lists them: the faces of inside
// tets whose tet across is a ghost or outside, oriented as in the inside tet. The caller
// lists parts only when every facet separates the domain from its outside (no internal
// facets, no region attributes): the inside flags change across a face exactly when it is
// a subfacet (the phase keeps them so: par/refinement_rules.hpp commit), so the boundary
// faces of an inside tet are its faces that are subfacets, read off the labels alone, with
// no tet across read (it may be at another rank, behind a proxy).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh_data.hpp"
#include "par/submesh.hpp"
#include "refine/quality.hpp"

namespace pdr::par {

// Output vertex numbers (above). `made[k]`: how many vertices submesh k made, for each
// submesh of a run on `ranks` ranks (submesh k on rank k mod ranks).
class VertexNumbers {
 public:
  VertexNumbers(std::size_t m0_vertices, std::span<const std::uint64_t> made, int ranks);
  // The number of the vertex with global id g; throws std::logic_error when g names no
  // vertex of the run.
  std::uint32_t operator()(Gid g) const;
  std::size_t total() const { return total_; }

 private:
  std::size_t n0_;
  std::vector<std::uint64_t> made_, first_;
  std::size_t total_ = 0;
};

// Whether submesh s's part can stand for the assembled mesh's (above): no tet of s is
// marked deferred, and no subsegment edge or subfacet face of a tet holding a vertex made
// on ∂Ω in the phase is encroached (strictly, by a vertex of that tet: refine/guard.hpp's
// find_encroached on the labels, as par/assembly.hpp runs it on D).
bool part_is_final(const Submesh& s);

// Appends submesh s's part to `out`: its inside tets, numbered by `num`, their boundary
// faces with the markers of their facets (facet_markers[label], 0 beyond), and adds their
// quality figures to `q`. Points are not listed here (the actor's committed points are).
void add_part(const Submesh& s, const VertexNumbers& num, std::span<const int> facet_markers,
              MeshData& out, refine::QualityRange& q);

// Whether every edge of `faces` is an edge of an even number of them: a closed surface
// (the boundary of the domain, or of several bodies touching along edges).
bool surface_closed(std::span<const Tri> faces);

// The edges of an odd number of `faces`, as min << 32 | max of their vertex numbers,
// sorted. A surface listed in parts closes exactly when the parts' odd edges, all
// together, pair up (`edges_pair_up`: every value an even number of times): an edge's
// count over the whole surface is the sum of its counts in the parts.
std::vector<std::uint64_t> odd_edges(std::span<const Tri> faces);
bool edges_pair_up(std::vector<std::uint64_t> edges);

}  // namespace pdr::par
