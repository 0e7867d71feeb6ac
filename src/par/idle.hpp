// IdlePolicy: how an event loop waits when a poll finds nothing to do, so that a rank
// never spins hot, whether it has a core of its own or shares it with other ranks
// (mpirun --oversubscribe) or with other programs.
//   - a streak of empty iterations first polls without a pause for kSpin (200 µs): a reply
//     from a peer with a core of its own comes within that and is taken at once;
//   - then the rank sleeps between polls, starting at 10 µs and doubling up to 100 µs
//     while it waits for replies to its own requests (each sleep adds to a round trip) and
//     up to 1 ms when it has nothing of its own under way (e.g. waiting for the last ranks
//     to finish), so an idle rank costs almost no CPU; any work resets the streak.
// It never yields (sched_yield): a yielding rank stays runnable, and on a core shared with
// another busy program the scheduler hands that program a whole time slice (milliseconds)
// at each yield, so every round trip costs slices. Measured (cube-in-cube, V = 0.01, 2
// ranks, each sharing its core with a busy loop): with a yield every 16 empty polls the
// phase took 4.5-6.2 s, against 0.22 s without the loops; spinning 200 µs, then sleeping,
// 0.6 s (the loops take half of each core) and 0.23 s without them. A sleeping rank leaves
// its core to a peer that shares it. The thread's timer slack is set to 1 µs (Linux:
// PR_SET_TIMERSLACK), so that a 10 µs sleep is not 60 µs.
#pragma once

#if defined(__linux__)
#include <sys/prctl.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <thread>

namespace pdr::par {

class IdlePolicy {
 public:
  IdlePolicy() {
#if defined(__linux__) && defined(PR_SET_TIMERSLACK)
    prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
#endif
  }
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
    if (empty_ == 1) streak_ = Clock::now();
    if (Clock::now() - streak_ < kSpin) return;
    std::this_thread::sleep_for(std::chrono::microseconds(sleep_us_));
    sleep_us_ = std::min(sleep_us_ * 2, waiting ? kMaxWaitingSleepUs : kMaxSleepUs);
    ++sleeps_;
  }
  std::uint64_t empty_iterations() const { return empty_total_; }
  std::uint64_t sleeps() const { return sleeps_; }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::microseconds kSpin{200};
  Clock::time_point streak_{};
  static constexpr long kFirstSleepUs = 10, kMaxWaitingSleepUs = 100, kMaxSleepUs = 1000;
  std::uint64_t empty_ = 0, empty_total_ = 0, sleeps_ = 0;
  long sleep_us_ = kFirstSleepUs;
};

}  // namespace pdr::par
