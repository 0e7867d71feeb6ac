// IdlePolicy (par/idle.hpp): a streak of empty iterations polls without a pause for its
// spin, then sleeps between polls, waiting for replies or not; work ends the streak.
#include "par/idle.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace pdr::par {
namespace {

using Clock = std::chrono::steady_clock;

// Empty iterations for `span`; the number made.
std::uint64_t empty_for(IdlePolicy& p, Clock::duration span, bool waiting) {
  std::uint64_t n = 0;
  for (const auto end = Clock::now() + span; Clock::now() < end; ++n) p.after_iteration(false, waiting);
  return n;
}

TEST(IdlePolicy, AnEmptyStreakSleepsOnceItsSpinIsOver) {
  for (const bool waiting : {false, true}) {
    IdlePolicy p;
    const std::uint64_t n = empty_for(p, std::chrono::milliseconds(5), waiting);
    EXPECT_EQ(p.empty_iterations(), n);
    EXPECT_GT(p.sleeps(), 0u) << "waiting " << waiting << ": " << n << " polls without a pause";
  }
}

TEST(IdlePolicy, TheFirstSleepComesAfterTheSpin) {
  IdlePolicy p;
  const auto start = Clock::now();
  while (p.sleeps() == 0 && Clock::now() - start < std::chrono::seconds(1))
    p.after_iteration(false, true);
  ASSERT_GT(p.sleeps(), 0u) << "no sleep in a second of empty polls";
  // The streak began at the first call, after `start`: its spin lies within.
  EXPECT_GE(Clock::now() - start, std::chrono::microseconds(200));
  EXPECT_GT(p.empty_iterations(), 1u);
}

TEST(IdlePolicy, WorkEndsTheStreak) {
  IdlePolicy p;
  empty_for(p, std::chrono::milliseconds(2), true);
  const std::uint64_t slept = p.sleeps();
  ASSERT_GT(slept, 0u);
  p.after_iteration(true, true);
  // A new streak spins first: a few polls right after work do not sleep.
  for (int i = 0; i < 3; ++i) p.after_iteration(false, true);
  EXPECT_EQ(p.sleeps(), slept);
}

}  // namespace
}  // namespace pdr::par
