// ActorMux: several submeshes per rank (over-decomposition, paper §4 footnote 3:
// `--submeshes N`, N >= P). Submesh k of N lives on rank k % P; each is an actor
// (par/insertion_actor.hpp) that sees a Transport of its own in which the N actors are the
// ranks. The protocol, its proof and its tests are unchanged: an actor cannot tell whether
// its peer shares its process.
//
// How each guarantee of par/transport.hpp is kept over the rank's own transport:
//   - FIFO per pair of actors: a message to an actor on this rank goes straight to its
//     inbox; one to another rank travels on the rank transport (FIFO per pair of ranks)
//     with the two actor ids appended, and joins its receiver's inbox in arrival order; an
//     inbox is one queue, so each pair's messages stay in order;
//   - counting: each actor's transport counts its own messages; a message is in flight
//     from its send until its receiver polls it (local ones too);
//   - reductions: round r of the rank transport starts once every actor of this rank has
//     started its own round r, with the sum of their contributions; its result is every
//     actor's result of round r. Rounds therefore sum over all N actors, and the round
//     starts only after every actor of every rank has contributed: the condition the
//     termination argument (par/termination.hpp) needs of a round.
// Single-threaded: the rank's loop steps its actors in turn.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "par/transport.hpp"

namespace pdr::par {

class ActorMux {
 public:
  // `actors` N >= rank.size(); rank's transport must outlive the mux.
  ActorMux(Transport& rank, int actors);
  ~ActorMux();
  ActorMux(const ActorMux&) = delete;
  ActorMux& operator=(const ActorMux&) = delete;

  int actors() const { return actors_; }
  int host(int actor) const { return actor % rank_.size(); }
  // The actors this rank hosts, ascending.
  const std::vector<int>& local() const { return local_; }
  // Actor k's transport. Precondition: host(k) == this rank.
  Transport& port(int actor);
  // Messages in this rank's inboxes, not yet polled by their actor.
  std::size_t queued() const;

 private:
  class Port;
  struct Round {
    Reduction sum{};
    int contributed = 0, read = 0;
    std::optional<Reduction> result;
  };

  int slot(int actor) const { return actor / rank_.size(); }
  void post(int from, int to, Bytes message);  // to an actor of this rank
  void pump();                                 // moves arrivals and reduction results
  void contribute(std::uint64_t round, const Reduction& mine);
  std::optional<Reduction> result(std::uint64_t round);
  void start_ready_round();

  Transport& rank_;
  int actors_;
  std::vector<int> local_;
  std::vector<std::unique_ptr<Port>> ports_;                 // by slot
  std::vector<std::deque<std::pair<int, Bytes>>> inbox_;     // by slot
  std::map<std::uint64_t, Round> rounds_;
  std::uint64_t next_real_ = 0;   // the next round to start on the rank transport
  bool real_open_ = false;
};

}  // namespace pdr::par
