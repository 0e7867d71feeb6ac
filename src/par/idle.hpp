// IdlePolicy: how an event loop waits when a poll finds nothing to do, so that a rank
// never spins hot, whether it has a core of its own or shares it with other ranks
// (mpirun --oversubscribe).
//   - every 16th empty iteration in a row yields the core (sched_yield): an oversubscribed
//     peer that holds the message we wait for gets to run; MPI progresses on our next poll;
//   - after 4096 empty iterations in a row of a rank with nothing of its own under way
//     (e.g. waiting for the last ranks to finish), it sleeps, starting at 20 µs and
//     doubling up to 1 ms, so an idle rank costs almost no CPU; any work resets the
//     streak. A rank waiting for replies to its own requests only yields: a sleep there
//     would add to every round trip.
// A 1 ms sleep delays a reply by at most 1 ms, against a refinement phase of seconds.
#pragma once

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <thread>

namespace pdr::par {

class IdlePolicy {
 public:
  // Called once per loop iteration; `worked`: the iteration did something; `waiting`: the
  // rank waits for replies to its own requests.
  void after_iteration(bool worked, bool waiting = false) {
    if (worked) {
      empty_ = 0;
      sleep_us_ = kFirstSleepUs;
      return;
    }
    ++empty_;
    ++empty_total_;
    if (empty_ >= kSleepAfter && !waiting) {
      std::this_thread::sleep_for(std::chrono::microseconds(sleep_us_));
      sleep_us_ = std::min(sleep_us_ * 2, kMaxSleepUs);
      ++sleeps_;
    } else if (empty_ % kYieldEvery == 0) {
      sched_yield();
    }
  }
  std::uint64_t empty_iterations() const { return empty_total_; }
  std::uint64_t sleeps() const { return sleeps_; }

 private:
  static constexpr std::uint64_t kYieldEvery = 16, kSleepAfter = 4096;
  static constexpr long kFirstSleepUs = 20, kMaxSleepUs = 1000;
  std::uint64_t empty_ = 0, empty_total_ = 0, sleeps_ = 0;
  long sleep_us_ = kFirstSleepUs;
};

}  // namespace pdr::par
