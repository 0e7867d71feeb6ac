// InsertionActor: one rank's event loop for distributed Delaunay insertion, the protocol
// of docs/parallel.md (paper §4.2-4.4) without the refinement rules: each rank holds one
// submesh and a queue of points; it inserts them one search at a time, while it serves
// the other ranks' searches. ParRefinement will run the refinement step in the same loop.
//
// A search for point p at its root:
//   round: root_cavity (par/cavity_search.hpp) in the root's store. Complete: commit
//     (Submesh::insert), done. Remote: lock the tets of the root's part of the closure
//     (for a walk, the tet it stopped at), send FETCH to each submesh a proxy names, and
//     wait for every reply: TETS (the tets, migrated here and added at once) or REFUSE.
//     A proxy naming this rank means tets are on their way here: the round is run again
//     on a later step, once they have come.
//   all replies in: if any was REFUSE, a setback: unlock, and p waits a seeded random
//     back-off of 1..8·2^min(k,6) steps after its k-th setback (§4.3), then starts again;
//     else the next round.
// Serving a FETCH: every requested tet must be here (else REFUSE: the requester's claim is
// stale, and a relink notice is on its way to it), and none of the tets fetch_set() would
// send may be locked by this rank's own search (else REFUSE: closures of concurrent
// searches never overlap, §4.1); then the tets migrate to the root (TETS), and the relink
// notices go to the ranks they name (RELINK).
// Termination (par/termination.hpp): a rank is idle when it has no search, no point
// waiting (back-off included) and nothing unread.
// Every commit is made on a closure that lies wholly in one rank's store, in one step of a
// single-threaded loop, so no two commits share a closure tet: Lemma 2's condition. The
// result is the Delaunay tetrahedralization of all points, which the symbolic
// perturbation makes unique (tested against the sequential kernel).
// A rank whose store has no tet left passes its points on (POINT) to the next rank.
//
// Refinement (ParRefinement, paper Fig. 7), with StepRules (par/step_rules.hpp): a second
// queue, taken after the first, holds tets (by slot, a compact FIFO: most entries are of
// tets a later commit deleted, dropped by one look at their slot). A
// tet's step inserts rules.point() (its circumcenter), searched as above from the tet
// itself; a complete cavity is committed only when
// rules.accept() says so (else the step is deferred), and its new inside tets that the
// rules want are queued. Tets that arrive by migration are queued when the rules want
// them, so every wanted tet is in the queue of the rank that holds it. While its search
// waits for replies, a rank takes further steps whose cavity and ring are all here and
// unlocked (the search's part of its closure and the tets that arrived for it are locked):
// they commit at once, in the same single-threaded loop, so no two commits share a
// closure tet still; the waiting search reruns its round from scratch when the replies
// are in. A step whose cavity touches a locked tet, or a step on ∂Ω with no tet here to
// start from, waits (parked) until the search ends; a step that needs other ranks, or a
// given point, waits for a search of its own, and no later wait looks at it again. A queued tet that has left (migrated or deleted) is dropped when its turn comes. A tet whose step was
// deferred is marked (the mark moves with it) and not queued again: without the mark, two
// ranks whose deferred steps share closure tets pass them back and forth for ever.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <vector>

#include <boost/circular_buffer.hpp>

#include "mesh/growing_array.hpp"
#include "par/cavity_search.hpp"
#include "par/slot_set.hpp"
#include "par/step_rules.hpp"
#include "par/submesh.hpp"
#include "par/termination.hpp"
#include "par/wire.hpp"
#include "par/transport.hpp"

namespace pdr::par {

struct InsertionStats {
  std::uint64_t commits = 0, rounds = 0, setbacks = 0, duplicates = 0;
  std::uint64_t fetches_served = 0, refused = 0, tets_sent = 0, points_passed = 0;
  std::uint64_t fetches_rejected = 0;  // of the fetches served, those answered with a
                                       // deferral (StepRules::defers_at, at a tet here)
  std::uint64_t deferred = 0, gone = 0;  // refinement: steps the rules refused; queue
                                         // entries whose slot held no tet to step at
                                         // their turn, and steps whose tet had left
  std::uint64_t deferred_early = 0;  // of the deferred, those the rules decided at a tet
                                     // of a partial cavity (StepRules::defers_at)
  std::uint64_t local_while_waiting = 0;  // steps committed while a search waited
  std::uint64_t splits = 0;        // commits that split a subsegment (Refine(s))
  std::uint64_t facet_points = 0;  // commits of a subfacet's circumcenter (Refine(f))
  // The paper's Table 1, in seconds of this rank (docs/parallel.md says how each is
  // measured): searches that committed, without and with other ranks; work done while a
  // search of this rank waited for replies, its own steps and requests served; searches
  // that ended in a setback; polls that found nothing, and those while work was queued.
  double completed_local_s = 0, completed_distributed_s = 0;
  double masked_local_s = 0, masked_distributed_s = 0;
  double setback_s = 0, served_s = 0, other_s = 0;
  double poll_s = 0, poll_excess_s = 0;
};

// Field by field (several actors of one rank: par/par_refinement.hpp).
InsertionStats& operator+=(InsertionStats& a, const InsertionStats& b);

class InsertionActor {
 public:
  // The actor's transport (its rank is the submesh's id: the rank's own transport, or an
  // ActorMux port); `seed` seeds the back-off; `rules` (optional, outliving the actor):
  // refinement.
  InsertionActor(Transport& t, Submesh sub, std::uint64_t seed, StepRules* rules = nullptr);

  void add_point(const Point& p) { ready().push_back({p}); }
  // Refinement: queues every tet of the submesh the rules want.
  void add_wanted_tets();
  // One loop iteration; true once the run has terminated everywhere.
  bool step() {
    auto now = std::chrono::steady_clock::now();
    return step(now);
  }
  // The same, for a loop that chains its clock readings (two a step): `now` is this
  // step's start, the previous step's last reading or a fresh one; it is set to this
  // step's last reading, at the end of its poll or of its work, before its termination
  // step (whose time the next step's poll then counts).
  bool step(std::chrono::steady_clock::time_point& now);

  const Submesh& submesh() const { return sub_; }
  // The submesh, given up once the phase has ended (the actor is then done with).
  Submesh release_submesh() { return std::move(sub_); }
  const InsertionStats& stats() const { return stats_; }
  bool idle() const {
    return !active_ && !has_ready() && delayed_.empty() && parked_.empty();
  }
  // The last step() handled a message or did work of its own; a search of this rank waits
  // for replies (the idle policy's sleeps stay short then: par/idle.hpp).
  bool worked() const { return worked_; }
  bool waiting() const { return active_ && !again_; }
  // Refinement: the points this rank committed, in order.
  const std::vector<Point>& committed_points() const { return committed_; }

 private:
  struct Waiting {
    Point p{};
    Gid tet = kNoGid;  // refinement: the tet whose step this is (p is its circumcenter)
    TetId slot = kNoTet;  // where `tet` was when queued (Submesh::find_tet's hint)
    // Refinement, a step on ∂Ω (tet is kNoGid): the subsegment {a, b} whose midpoint p
    // is (c is kNoGid), or the subfacet {a, b, c} whose circumcenter it is, a tet near
    // it where its search starts, and the tet whose step asked for it (`origin`: queued
    // again, when it is here, once this step ends; it is queued afresh, its own setbacks
    // counted from zero. An older queue entry of its slot may step it meanwhile, which
    // Fig. 2's any order allows).
    Gid a = kNoGid, b = kNoGid, c = kNoGid, near = kNoGid, origin = kNoGid;
    std::uint32_t setbacks = 0;
    std::uint64_t wake = 0;  // step at which it may start again
    bool parked = false;     // local_step() found it needs other ranks: not tried
                             // locally again
  };
  struct Search {
    std::uint64_t id = 0;
    Waiting w;
    Gid hint = kNoGid;
    int outstanding = 0;
    bool refused = false;
    std::uint8_t rejected = 0;  // a reply's deferral reason (StepRules::defers_at)
    bool walk = false;
  };

  // Steps to look at while a search waits (local_step): ready_ (where a step set back
  // after it needed other ranks may be, local_step moves it to remote_) and the queue;
  // not remote_.
  bool has_local() const { return !ready_.empty() || tets_head_ < tets_.size(); }
  bool has_ready() const { return has_local() || !remote_.empty(); }
  // The next step to take: ready_'s first, else (`remote`: no search waits) remote_'s
  // first, else the tet in the first queued slot that holds one to step (tets_ below;
  // the other entries are skipped and counted as gone, at most `skips` of them). False:
  // none.
  bool next_ready(Waiting& w, int& skips, bool remote);
  // A tet of this submesh whose step the rules may want: in Ω, not deferred, no ghost.
  // want() queues only such tets, and a queue entry steps only such a tet.
  bool may_step(TetId t) const {
    return !sub_.store().is_ghost(t) && sub_.inside(t) && !sub_.deferred(t);
  }

  void receive(int from, std::span<const std::byte> m);
  void serve_fetch(WireReader& r);
  void take_tets(WireReader& r);
  // A reply to the active search: tets (nothing to note), a refusal (a locked tet:
  // setback) or a deferral with its reason (the search ends once every reply is in).
  void reply_in(bool refused, std::uint8_t rejected = 0);
  // Step w of a tet is deferred for `reason` (StepRules::defers_at) before its cavity was
  // whole: counted as such, and marked (defer).
  void defer_early(const Waiting& w, std::uint8_t reason);
  // The active search's step is deferred so, unless its tet has left; the search ends.
  void end_search_deferred(std::uint8_t reason);
  void round();  // one round of the active search
  void setback();
  // A step deferred (a tet's: marked, counted) or dropped (a step on ∂Ω: its origin
  // queued again).
  void defer(const Waiting& w);
  // The early test of a tet's step at p (StepRules::defers_at); none for other steps, or
  // when the rules never defer early.
  CavitySearch::Reject reject(const Point& p, bool tet_step);
  std::uint8_t early_reason_ = 0;  // reject()'s last verdict
  void finish();
  TetId any_real_tet();
  void send(int to, Bytes b);
  // Relink notices (Submesh::relink), one message per recipient; reorders `notes`.
  void send_relinks(std::vector<Relink>& notes);
  void want(TetId t);  // refinement: queue t when the rules want it
  bool start(Waiting w);  // false: a tet that has left
  // Refinement, while the search waits for replies: the step of w's tet when its cavity
  // is complete here and touches no locked tet (latency hiding); otherwise w is parked
  // until the search ends, or, when it needs other ranks, goes to remote_ (a search of
  // its own, once none waits). A given point, and a step known to need other ranks (set
  // back meanwhile), go to remote_ at once, unlooked at (Skipped); Gone: w's tet has left
  // (nothing done).
  enum class Local { Done, Skipped, Gone };
  Local local_step(const Waiting& w);
  // A complete cavity at this rank for step w: the rules accept it (commit, queue the new
  // tets they want), defer it (mark w's tet; a step on ∂Ω is dropped), or ask for a step
  // on ∂Ω first (queued in w's place; w's tet is tried again once it ends).
  bool complete(const Cavity& c, const Waiting& w);  // true: committed
  // A step on ∂Ω has ended (committed, dropped, or its point a vertex already): its
  // origin tet is queued again if it is here and still wanted.
  void requeue_origin(const Waiting& w);
  // Adds `seconds` to the active search's time; when it has ended (end_), moves its time
  // to the bucket of its outcome.
  void charge_search(double seconds);

  Transport& t_;
  Submesh sub_;
  TerminationDetector td_;
  CavitySearch search_;
  std::mt19937_64 rng_;
  std::uint64_t tick_ = 0, next_search_ = 1;
  bool active_ = false, again_ = false;  // again_: run the round on the next step
  bool worked_ = false;
  Search s_;
  SlotSet locked_;
  // Points, steps on ∂Ω, steps parked or set back: rings that grow (room()), so that the
  // parked steps going back at every search cost no allocation (a deque's blocks did:
  // about 2% of a rank's time in malloc and free).
  using Ring = boost::circular_buffer<Waiting>;
  Ring ready_;
  // Steps found to need other ranks while a search waited (Waiting::parked): taken only
  // when no search waits, so that no wait goes over them again.
  Ring remote_;
  // `r` with room for n more.
  static Ring& room(Ring& r, std::size_t n = 1) {
    if (r.capacity() - r.size() < n)
      r.set_capacity(std::max<std::size_t>({64, 2 * r.capacity(), r.size() + n}));
    return r;
  }
  Ring& ready(std::size_t n = 1) { return room(ready_, n); }
  // The tets want() queued, by slot, in order; the first tets_head_ taken. A slot is not
  // checked to hold the same tet when its turn comes: whatever real tet it holds then is
  // stepped if it is wanted (in Ω, not deferred, bad: Fig. 2 allows any order), and every
  // wanted tet was queued when it was made or arrived. 4 bytes a tet queued, where a
  // slot and a global id took 16 (the queue holds up to a million tets at 3.7M).
  GrowingArray<TetId> tets_;
  std::size_t tets_head_ = 0;
  std::vector<Waiting> delayed_;
  std::vector<Waiting> parked_;  // local_step(): until the search ends
  std::vector<TetId> made_;
  TetId cursor_ = 0;
  InsertionStats stats_;
  StepRules* rules_ = nullptr;
  std::vector<Point> committed_;
  // Table 1's clocks: the active search's time so far, whether it asked other ranks, and
  // how it ended (set by finish(), setback() and a commit in round()).
  enum class End { None, Commit, Setback, Other };
  double search_s_ = 0;
  bool search_distributed_ = false;
  End end_ = End::None;
};

}  // namespace pdr::par
