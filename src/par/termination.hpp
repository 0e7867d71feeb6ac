// Termination detection for the asynchronous refinement loop (paper Fig. 7: "if |Q| = 0,
// |L| = 0, and all PEs are done then Exit"): every rank learns, without a blocking call,
// that no rank has work left and no message is in flight, so none ever will.
//
// The rule (counting plus a dirty flag, in two reduction rounds):
//   a rank that is idle (no queued work, no timer, no live search of its own, nothing
//   unsent) and has no round open starts round 1 with (sent, received) and clears its
//   dirty flag; any work it does afterwards (a message handled, a task started, a timer
//   fired) sets the flag, and so does any change of its own counts since the snapshot
//   (so a send the caller forgot to report still counts). When round 1 completes it
//   starts round 2 at once with (dirty or busy); when round 2 completes, the run has terminated iff round 2 summed to
//   zero and round 1's sums of sent and received are equal; otherwise the rank waits until
//   it is idle again and starts the next pair.
// Why it is sound: let T be the moment the last rank started round 1. Round 1 completes on
// no rank before T, and every rank starts round 2 after its round 1 completes, so a clean
// round 2 means every rank did nothing from its round-1 snapshot until after T: each was
// idle at T and had sent nothing since its snapshot. The snapshots then count every
// message sent before T, and every message received before T; a message is received
// after it is sent, so equal sums mean none was in flight at T. Idle ranks with nothing in
// flight stay idle: the run is over. Conversely, once the run is over, the next pair of
// rounds succeeds, so detection is never late by more than two rounds.
// The transport counts messages (par/transport.hpp); the caller reports work and idleness.
#pragma once

#include <cstdint>

#include "par/transport.hpp"

namespace pdr::par {

class TerminationDetector {
 public:
  explicit TerminationDetector(Transport& t) : t_(t) {}

  // Some work was done since the last call to step() (sets the dirty flag).
  void activity() { dirty_ = true; }
  // Advances the rounds; call once per loop iteration with whether this rank is idle now.
  // True once the run has terminated (then for ever).
  bool step(bool idle);

  bool terminated() const { return state_ == State::Done; }
  std::uint64_t rounds() const { return rounds_; }  // reduction rounds started

 private:
  enum class State { Quiet, Counting, Confirming, Done };
  Transport& t_;
  State state_ = State::Quiet;
  bool dirty_ = false;
  bool balanced_ = false;  // round 1: sent == received over all ranks
  std::uint64_t sent_at_snapshot_ = 0, received_at_snapshot_ = 0;
  std::uint64_t rounds_ = 0;
};

}  // namespace pdr::par
