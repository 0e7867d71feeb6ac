// VolumeMesh: the Delaunay mesh M = (D, T) of paper §1.1 during refinement: the surface
// triangulation D (surface_mesh.hpp) and the Delaunay tetrahedralization T of all vertices
// (delaunay/delaunay.hpp), which covers the convex hull; the tets of T inside Ω are
// flagged, the others are kept (the kernel needs a closed hull) but never refined or
// written.
//
// Invariants (checked by audit_volume, refine_audit.hpp):
//   - every live subfacet of D is a face of T and every subsegment an edge (§1.1 "the
//     subsegments and subfacets in D appear in T");
//   - inside[t] for a finite tet t is 1 iff t lies in Ω: across a face of T the flag
//     changes exactly when the face is a subfacet (Ω is the set of points from which a ray
//     crosses ∂Ω an odd number of times, plc_domain.hpp), ghost tets are outside;
//   - d2s / s2d map T's vertex ids to D's and back (kNone: a vertex of T off ∂Ω).
// Side arrays are indexed by TetId and grow with the store (tet ids are stable while
// alive; a freed slot gets a new flag when it is reused).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "delaunay/delaunay.hpp"
#include "refine/surface_mesh.hpp"

namespace pdr::refine {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

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

  // The subfacet of D with T vertices {a, b, c}, if any.
  std::optional<std::uint32_t> subfacet(VertexId a, VertexId b, VertexId c) const;
  // The subsegment of D with T vertices {a, b}, if any.
  std::optional<std::uint32_t> subsegment(VertexId a, VertexId b) const;
  // Face f of tet t as a subfacet, if it is one (ghost vertices are never on one).
  std::optional<std::uint32_t> face_subfacet(TetId t, int f) const;
  bool is_inside(TetId t) const { return t < inside.size() && inside[t] != 0; }
  std::size_t inside_tets() const;
};

// The tets incident to vertex v, by a walk over faces from `start` (a live tet incident
// to v); `out` is cleared first. `mark` is scratch indexed by tet slot (resized here),
// all zero between calls.
void star_of(const TetStore& s, VertexId v, TetId start, std::vector<TetId>& out,
             std::vector<std::uint8_t>& mark);

// Adds p (the point of cavity c, built on m.dt's current triangulation) to T as a new
// vertex, commits c, maps the vertex to D's vertex `surf_vertex` (kNone: off ∂Ω), and
// flags the new tets: each takes the flag of its neighbour across the face opposite the new
// vertex (an old face), toggled when that face is a subfacet. Precondition: D already holds
// its final subfacets for this insertion (the toggled faces are old ones, which a surface
// update does not change unless it deletes them, and then they are in c, not on its
// boundary). Returns the vertex; `star` receives the new tets.
VertexId commit_point(VolumeMesh& m, const Cavity& c, std::uint32_t surf_vertex,
                      std::vector<TetId>& star, std::vector<std::uint8_t>& mark);

}  // namespace pdr::refine
