// The breadth-first parallel search for a distributed cavity (paper §4.2), as two local
// steps that the protocol alternates:
//   at the root, root_cavity(): locate p and build its cavity in the root's own store; the
//     search stops at proxies (mesh/tet_store.hpp), and the proxies met (the walk's last
//     step, or the ring of the cavity) name the tets the root must fetch, grouped by the
//     submesh each proxy names;
//   at a submesh asked for tets, fetch_set(): for a walk (the root's walk left its store),
//     the tet where this submesh's own walk towards p from the requested tet stops (it
//     holds p, or faces the next submesh); otherwise the requested tets themselves; and,
//     for each of those that conflicts with p, the conflict region grown from it through
//     this submesh's tets, plus the ring of what was grown (the face neighbours that do
//     not conflict). A walk thus crosses a submesh in one round, not one tet per round.
//     The submesh then migrates these tets to the root (Submesh::take), which adds them
//     (Submesh::give), replacing the proxies, and runs root_cavity() again.
// Each round moves every tet of the cavity that some fetched face reaches, and the
// cavity is face-connected (Delaunay), so the rounds end with a cavity and ring that are
// all in the root's store: the same cavity the sequential kernel would build on the
// whole mesh (tested against it), ready to commit locally. The ring moves too: the root
// reads the closure (encroachment, Fig. 2) and relinks the new tets to it.
#pragma once

#include <functional>
#include <map>
#include <span>
#include <vector>

#include "delaunay/cavity.hpp"
#include "delaunay/walk.hpp"
#include "par/slot_set.hpp"
#include "par/submesh.hpp"

namespace pdr::par {

struct RootCavity {
  // Rejected: the `reject` test of root_cavity() stopped the search at a conflict tet.
  enum class Kind { Complete, Remote, OnVertex, Rejected } kind = Kind::Complete;
  Cavity cavity;                                  // Complete: all local, ring included
  std::map<ActorId, std::vector<Side>> fetch;     // Remote: tets behind the proxies met,
                                                  // by the submesh each proxy names
  bool walk = false;                              // Remote: the walk left the store
};

class CavitySearch {
 public:
  // Locates p from `hint` (a live real tet of s) and builds its cavity in s. The result
  // lives in this object (its buffers are reused) until the next call. `hint_conflicts`:
  // p is hint's circumcenter (a tet's step), so hint is in conflict with p when the exact
  // test says so, and the cavity grows from it without the walk to p (the conflict region
  // is connected, and holds the tet that holds p). `reject`, when given, is asked about
  // each conflict tet as it joins; true stops the search (Rejected).
  using Reject = std::function<bool(TetId)>;
  const RootCavity& root_cavity(const Submesh& s, const Point& p, TetId hint,
                                bool hint_conflicts = false, const Reject& reject = {});
  // The tets of s to migrate to the root for the requested tets `wanted` (those s holds;
  // the others are skipped: the caller redirects them), each once; for a walk, the tet
  // where the walk stopped comes first (the root goes on from it). `reject`, when given,
  // is asked about each conflict tet grown here as it joins, as in root_cavity(); true
  // stops the search: `rejected`, and no tets.
  struct FetchSet {
    std::vector<TetId> tets;
    bool rejected = false;
  };
  FetchSet fetch_set(const Submesh& s, const Point& p, std::span<const Gid> wanted, bool walk,
                     const Reject& reject = {});

 private:
  WalkRng rng_;
  CavityBuilder builder_;
  Cavity part_;
  RootCavity root_;
  SlotSet taken_;  // fetch_set()'s tets so far
};

}  // namespace pdr::par
