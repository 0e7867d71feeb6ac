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

// What a step does with its complete cavity (Fig. 2): insert its point (Commit), leave
// it (Defer: a tet's step is deferred to the sequential completion, a step on ∂Ω is
// dropped), or refine an element of D first: Split, the subsegment {a, b} (Refine(s):
// insert its midpoint `p`), Facet, the subfacet {a, b, c} (Refine(f): insert its
// circumcenter `p`). `near` is a closure tet holding the element, where the new point's
// search starts; the tet whose step this was is tried again after it.
struct Verdict {
  enum class Kind : std::uint8_t { Commit, Defer, Split, Facet };
  Kind kind = Kind::Defer;
  Gid a = kNoGid, b = kNoGid, c = kNoGid;
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
  // Cavity c of a step on ∂Ω (the point of a Split or Facet verdict for the element with
  // global vertex ids a, b, c; c = kNoGid for a subsegment) is complete in s: Commit
  // (commit(s, c) next), Split (Refine(f)'s point encroaches that subsegment), or Defer
  // (the step is dropped).
  virtual Verdict accept_surface(const Submesh&, const Cavity&, Gid, Gid, Gid) { return {}; }
  // Whether these rules may defer a tet's step before its cavity is whole (defers_at);
  // false: the search asks nothing per tet.
  virtual bool defers_early() const { return false; }
  // Whether tet u, as it joins the conflict region of a tet's step at point p, already
  // decides accept() (asked only when defers_early()): a reason other than 0 only when
  // accept() would then Defer whatever else the cavity holds, so that the search stops
  // there and the step is deferred without building (and migrating) the rest of a far
  // circumcenter's cavity. The submesh holding u may be the step's root or one asked for
  // the tets behind the root's proxies: u's verdict reads only u.
  virtual std::uint8_t defers_at(const Submesh&, TetId, const Point&) { return 0; }
  // A step that defers_at() stopped (at its root or at another submesh) is deferred:
  // count it by the reason defers_at() gave.
  virtual void count_early_deferral(std::uint8_t) {}
  // Commits the cavity that accept() or accept_surface() just accepted: the new vertex
  // and tets with their inside flags (and D's labels, for a step on ∂Ω). Returns the
  // vertex.
  virtual VertexId commit(Submesh& s, const Cavity& c) { return s.insert(c, 1, new_vertex_tag()); }
  // The tag of a committed tet circumcenter's vertex (Submesh::tag).
  virtual std::uint8_t new_vertex_tag() const { return 0; }
};

}  // namespace pdr::par
