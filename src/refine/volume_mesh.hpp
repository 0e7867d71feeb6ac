// VolumeMesh: the Delaunay mesh M = (D, T) of paper §1.1 during refinement: the surface
// triangulation D (surface/surface_mesh.hpp) and the Delaunay tetrahedralization T of all vertices
// (delaunay/delaunay.hpp), which covers the convex hull; the tets of T inside Ω are
// flagged, the others are kept (the kernel needs a closed hull) but never refined or
// written.
//
// Invariants (checked by audit_volume, refine/audit.hpp):
//   - every live subfacet of D is a face of T and every subsegment an edge (§1.1 "the
//     subsegments and subfacets in D appear in T");
//   - inside[t] for a finite tet t is 1 iff t lies in Ω: across a face of T the flag
//     changes exactly when the face is a subfacet of a separating facet (face_flips; the
//     facets of an internal shell have Ω on both sides, domain/domain.hpp), ghost tets are
//     outside;
//   - d2s / s2d map T's vertex ids to D's and back (kNone: a vertex of T off ∂Ω);
//   - vclass[v] (parallel to d2s) says where T's vertex v lies: Segment for an input
//     vertex or a vertex on a segment (the only vertices a subsegment can end at), Facet
//     for a vertex inside a facet, Interior off ∂Ω. The lookups below test it first: one
//     byte per vertex rejects almost every edge and face of T without touching D.
// Side arrays are indexed by TetId and grow with the store (tet ids are stable while
// alive; a freed slot gets a new flag when it is reused).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "delaunay/delaunay.hpp"
#include "mesh/tables.hpp"
#include "refine/maybe_id.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::refine {

// The surface mesh's vocabulary (src/surface), which the volume refinement refines with T.
using surface::HomeKind;
using surface::Subfacet;
using surface::Subsegment;
using surface::SurfaceMesh;

enum class VertexClass : std::uint8_t { Interior = 0, Facet = 1, Segment = 2 };

// A failure of the volume refinement that the theory excludes for admissible input (a
// subfacet missing from T, a cavity the exact arguments rule out); the message starts with
// the name of the invariant.
class RefineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct VolumeMesh {
  Delaunay dt;
  SurfaceMesh surf;
  std::vector<std::uint8_t> inside;  // per tet slot
  std::vector<std::uint32_t> d2s;    // T vertex -> D vertex or kNone
  std::vector<std::uint32_t> s2d;    // D vertex -> T vertex or kNone
  std::vector<VertexClass> vclass;   // T vertex -> where it lies (see above)
  // Elements of D that T_o lacks (refine/initial.hpp); the refinement restores them.
  std::vector<std::uint32_t> missing_subfacets, missing_subsegments;

  // Records T's vertex v (the next one: v == d2s.size()) as D's vertex surf_vertex
  // (kNone: off ∂Ω), in d2s, s2d and vclass.
  void map_vertex(VertexId v, std::uint32_t surf_vertex);
  // Maps T's vertex v, recorded off ∂Ω, to D's vertex surf_vertex instead (the parallel
  // run's subsegment splits, made in D after T: par/assembly.hpp).
  void remap_vertex(VertexId v, std::uint32_t surf_vertex);

  // Ghost and unknown vertices are Interior.
  VertexClass vertex_class(VertexId v) const {
    return v < vclass.size() ? vclass[v] : VertexClass::Interior;
  }
  // The subfacet of D with T vertices {a, b, c}, if any.
  MaybeId subfacet(VertexId a, VertexId b, VertexId c) const {
    if (vertex_class(a) == VertexClass::Interior || vertex_class(b) == VertexClass::Interior ||
        vertex_class(c) == VertexClass::Interior)
      return {};
    return find_subfacet(a, b, c);
  }
  // The subsegment of D with T vertices {a, b}, if any.
  MaybeId subsegment(VertexId a, VertexId b) const {
    if (vertex_class(a) != VertexClass::Segment || vertex_class(b) != VertexClass::Segment)
      return {};
    return find_subsegment(a, b);
  }
  // Face f of tet t as a subfacet, if it is one (ghost vertices are Interior: never on one).
  MaybeId face_subfacet(TetId t, int f) const {
    const VertexId* v = dt.store().vertices(t);
    return subfacet(v[tables::kFaceVertex[f][0]], v[tables::kFaceVertex[f][1]],
                    v[tables::kFaceVertex[f][2]]);
  }
  // Whether `inside` changes across face f of tet t: the face is a subfacet of a facet with
  // Ω on one side only (an internal facet has Ω on both: domain/domain.hpp).
  bool face_flips(TetId t, int f) const {
    const MaybeId sf = face_subfacet(t, f);
    return sf && surf.facets[surf.subfacet(*sf).facet].separates;
  }
  bool is_inside(TetId t) const { return t < inside.size() && inside[t] != 0; }
  std::size_t inside_tets() const;

 private:
  // subfacet() and subsegment() past the class filter.
  MaybeId find_subfacet(VertexId a, VertexId b, VertexId c) const;
  MaybeId find_subsegment(VertexId a, VertexId b) const;
};

// Adds p (the point of cavity c, built on m.dt's current triangulation) to T as a new
// vertex, commits c, maps the vertex to D's vertex `surf_vertex` (kNone: off ∂Ω), and
// flags the new tets: each takes the flag of its neighbour across the face opposite the new
// vertex (an old face), toggled when that face is a subfacet. Precondition: D already holds
// its final subfacets for this insertion (the toggled faces are old ones, which a surface
// update does not change unless it deletes them, and then they are in c, not on its
// boundary). Returns the vertex; `star` receives the new tets (its star in T).
VertexId commit_point(VolumeMesh& m, const Cavity& c, std::uint32_t surf_vertex,
                      std::vector<TetId>& star);

// The star of vertex v in T (ghost tets included), from `start`, a live tet incident to v.
void vertex_star(const VolumeMesh& m, VertexId v, TetId start, std::vector<TetId>& star);

}  // namespace pdr::refine
