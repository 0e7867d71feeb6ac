// StepRules: what a rank's event loop (par/insertion_actor.hpp) does with the tets it holds,
// when it refines instead of inserting given points (ParRefinement, paper Fig. 7).
//
// The loop owns the protocol (searches, locks, migration, setbacks, termination); the
// rules own the mesh's meaning: which tets need a step, where the step inserts, and
// whether a complete cavity may be committed. Every decision reads only the root's store:
// the cavity and its closure are all there when accept() is asked (par/cavity_search.hpp),
// so a step decides exactly as the sequential step would on the whole mesh.
#pragma once

#include <cstdint>

#include "delaunay/cavity.hpp"
#include "geom/point.hpp"
#include "mesh/tet_store.hpp"
#include "par/submesh.hpp"

namespace pdr::par {

// What a tet's step does with its complete cavity (Fig. 2): insert its point, leave the
// tet to the sequential completion, or refine the subsegment {a, b} that the point
// encroaches first (Refine(s): insert its midpoint `p`; `near` is a closure tet with that
// edge, where the midpoint's search starts; the tet is tried again after it).
struct Verdict {
  enum class Kind : std::uint8_t { Commit, Defer, Split };
  Kind kind = Kind::Defer;
  Gid a = kNoGid, b = kNoGid;
  Point p{};
  Gid near = kNoGid;
};

class StepRules {
 public:
  virtual ~StepRules() = default;
  // Whether real tet t of s needs a step (Fig. 7: a bad tet of the submesh).
  virtual bool wants(const Submesh& s, TetId t) const = 0;
  // Where the step for real tet t of s inserts (its circumcenter).
  virtual Point point(const Submesh& s, TetId t) const = 0;
  // Cavity c of a tet's step is complete in s (conflict tets and ring real tets of s).
  // Commit: commit(s, c) next; Defer: the step is deferred (counted by the caller).
  virtual Verdict accept(const Submesh& s, const Cavity& c) = 0;
  // Cavity c of the midpoint of subsegment {a, b} (global vertex ids) is complete in s:
  // true when it may be committed (commit(s, c) next); false drops the step.
  virtual bool accept_split(const Submesh&, const Cavity&, Gid, Gid) { return false; }
  // Commits the cavity that accept() or accept_split() just accepted: the new vertex and
  // tets with their inside flags (and D's labels, for a split). Returns the vertex.
  virtual VertexId commit(Submesh& s, const Cavity& c) { return s.insert(c, 1, new_vertex_tag()); }
  // The tag of a committed tet circumcenter's vertex (Submesh::tag).
  virtual std::uint8_t new_vertex_tag() const { return 0; }
};

}  // namespace pdr::par
