// The simulator's main loop for the actor tests: every rank's loop stepped and every
// message delivered in the seeded random order of `net`, until every rank has concluded
// termination. When the first one concludes, nothing may be in flight and every actor must
// be idle (termination detection that messages in flight cannot fool).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "par/insertion_actor.hpp"
#include "par/sim_network.hpp"

namespace pdr::par::test {

// The number of simulator steps taken; 0 (and a test failure) when `limit` was reached.
// An actor that concluded is not stepped again (as in the real loop), and `unread` counts
// messages held elsewhere (a mux's inboxes) that must be gone when the first one concludes.
inline std::uint64_t run_to_termination(
    SimNetwork& net, const std::vector<std::unique_ptr<InsertionActor>>& actors,
    std::uint64_t seed, std::uint64_t limit,
    const std::function<std::size_t()>& unread = [] { return std::size_t(0); }) {
  const int ranks = static_cast<int>(actors.size());
  std::vector<bool> done(actors.size(), false);
  const auto all = [&] { return std::all_of(done.begin(), done.end(), [](bool d) { return d; }); };
  const auto none = [&] { return std::none_of(done.begin(), done.end(), [](bool d) { return d; }); };
  std::uniform_int_distribution<int> pick(0, ranks - 1);
  std::bernoulli_distribution deliver(0.5);
  std::uint64_t steps = 0;
  while (!all()) {
    if (++steps > limit) {
      ADD_FAILURE() << "seed " << seed << ": no termination in " << limit << " steps";
      return 0;
    }
    if (deliver(net.rng()) && net.deliver_one()) continue;
    const auto r = static_cast<std::size_t>(pick(net.rng()));
    if (done[r]) continue;
    if (actors[r]->step()) {
      if (none()) {
        EXPECT_EQ(net.in_flight(), 0u) << "seed " << seed << ": concluded with messages in flight";
        EXPECT_EQ(unread(), 0u) << "seed " << seed << ": concluded with messages unread";
        for (const auto& a : actors) EXPECT_TRUE(a->idle()) << "seed " << seed;
      }
      done[r] = true;
    }
  }
  return steps;
}

}  // namespace pdr::par::test
