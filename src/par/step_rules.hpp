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

class StepRules {
 public:
  virtual ~StepRules() = default;
  // Whether real tet t of s needs a step (Fig. 7: a bad tet of the submesh).
  virtual bool wants(const Submesh& s, TetId t) const = 0;
  // Where the step for real tet t of s inserts (its circumcenter).
  virtual Point point(const Submesh& s, TetId t) const = 0;
  // Cavity c is complete in s (conflict tets and ring real tets of s). True: commit it,
  // the new tets get `inside` = 1; false: the step is deferred (counted by the caller).
  virtual bool accept(const Submesh& s, const Cavity& c) = 0;
  // The tag of a committed point's vertex (Submesh::tag).
  virtual std::uint8_t new_vertex_tag() const { return 0; }
};

}  // namespace pdr::par
