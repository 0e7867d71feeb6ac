// Termination detection (par/termination.hpp) on the in-process simulator: under seeded
// random interleavings of rank steps and message deliveries, the detector fires on every
// rank, only after every token of the chain reaction (chain_workload.hpp) was handled and
// no message is in flight; a message held in flight while every rank is idle keeps it from
// firing however many rounds pass.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "par/chain_workload.hpp"
#include "par/sim_network.hpp"
#include "par/termination.hpp"

namespace pdr::par {
namespace {

using test::ChainRank;

struct Sim {
  SimNetwork net;
  std::vector<std::unique_ptr<ChainRank>> ranks;
  std::vector<bool> done;

  Sim(int p, std::uint64_t seed, int per_rank, std::uint32_t ttl) : net(p, seed), done(static_cast<std::size_t>(p)) {
    for (int r = 0; r < p; ++r) ranks.push_back(std::make_unique<ChainRank>(net.endpoint(r), per_rank, ttl));
  }
  // Random steps until every rank has terminated or `budget` steps passed; true if all did.
  // A rank that terminated keeps stepping (it must stay terminated, and nothing may reach
  // it). The moment the first rank concludes, the run must really be over: `expected`
  // tokens handled, nothing in flight, every rank idle (checked then, before a false
  // conclusion could heal).
  bool run(std::uint64_t budget, std::uint64_t expected) {
    std::bernoulli_distribution deliver(0.4);
    std::uniform_int_distribution<int> pick(0, net.size() - 1);
    for (std::uint64_t s = 0; s < budget; ++s) {
      if (deliver(net.rng()) && net.deliver_one()) continue;
      const int r = pick(net.rng());
      if (ranks[static_cast<std::size_t>(r)]->step() && !done[static_cast<std::size_t>(r)]) {
        if (std::none_of(done.begin(), done.end(), [](bool d) { return d; })) {
          EXPECT_EQ(handled(), expected) << "concluded with tokens unhandled";
          EXPECT_EQ(net.in_flight(), 0u) << "concluded with messages in flight";
          for (const auto& k : ranks) EXPECT_TRUE(k->idle()) << "concluded with a rank busy";
        }
        done[static_cast<std::size_t>(r)] = true;
      }
      if (std::all_of(done.begin(), done.end(), [](bool d) { return d; })) return true;
    }
    return false;
  }
  std::uint64_t handled() const {
    std::uint64_t n = 0;
    for (const auto& r : ranks) n += r->handled();
    return n;
  }
};

TEST(Termination, FiresOnlyWhenAllWorkIsDoneUnderRandomInterleavings) {
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    const int p = 1 + static_cast<int>(seed % 5);
    const int per_rank = 1 + static_cast<int>(seed % 4);
    const std::uint32_t ttl = 6 + static_cast<std::uint32_t>(seed % 6);
    Sim sim(p, seed, per_rank, ttl);
    ASSERT_TRUE(sim.run(2'000'000, test::expected_total(p, per_rank, ttl))) << "seed " << seed << ": no termination";
    for (const auto& r : sim.ranks) EXPECT_EQ(r->rounds(), sim.ranks[0]->rounds()) << "seed " << seed;
    EXPECT_EQ(sim.handled(), test::expected_total(p, per_rank, ttl)) << "seed " << seed;
    EXPECT_EQ(sim.net.in_flight(), 0u) << "seed " << seed;
    for (int r = 0; r < p; ++r) EXPECT_TRUE(sim.ranks[static_cast<std::size_t>(r)]->idle());
  }
}

TEST(Termination, AHeldMessageKeepsIdleRanksRunning) {
  // Rank 0 starts with all the work; its channel to rank 1 is held, so whatever it sends
  // there stays in flight while every rank runs out of work.
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Sim sim(3, seed, 0, 0);
    sim.ranks[0] = std::make_unique<ChainRank>(sim.net.endpoint(0), 40, 6);
    sim.net.hold(0, 1);
    std::uint64_t expected = 0;
    for (const auto& t : test::initial_tokens(0, 40, 6)) expected += test::expected_tokens(t);
    EXPECT_FALSE(sim.run(200'000, expected)) << "seed " << seed << ": terminated with a message held";
    ASSERT_GT(sim.net.in_flight(), 0u) << "seed " << seed << ": nothing was held";
    for (const auto& r : sim.ranks) {
      EXPECT_TRUE(r->idle()) << "seed " << seed;
      EXPECT_GT(r->rounds(), 4u) << "seed " << seed << ": rounds did not keep running";
    }
    sim.net.release(0, 1);
    ASSERT_TRUE(sim.run(2'000'000, expected)) << "seed " << seed;
    EXPECT_EQ(sim.handled(), expected) << "seed " << seed;
  }
}

// A scripted interleaving in which round 1's sums balance by coincidence: rank 0 takes its
// snapshot, then receives m1 (sent by rank 1 before its snapshot) and sends m2 to rank 2
// (received before rank 2's snapshot) and m4 to rank 1 (still in flight). Sent and
// received both sum to 1, yet m4 is in flight: only rank 0's dirty flag stops the run.
TEST(Termination, BalancedCountsWithAMessageInFlightDoNotEndTheRun) {
  SimNetwork net(3, 1);
  Transport &a = net.endpoint(0), &b = net.endpoint(1), &c = net.endpoint(2);
  TerminationDetector ta(a), tb(b), tc(c);
  const auto drain = [](Transport& t) { return t.poll([](int, std::span<const std::byte>) {}, 100); };
  const auto any_done = [&] { return ta.terminated() || tb.terminated() || tc.terminated(); };
  ta.step(true);                      // rank 0's snapshot: (0, 0)
  b.send(0, Bytes(1));                // m1
  ASSERT_TRUE(net.deliver_one());
  ASSERT_EQ(drain(a), 1u);
  ta.activity();
  net.hold(0, 1);
  a.send(2, Bytes(1));                // m2
  a.send(1, Bytes(1));                // m4, held
  ASSERT_TRUE(net.deliver_one());     // m2 (m4 is held)
  ASSERT_EQ(drain(c), 1u);
  tc.activity();
  for (int i = 0; i < 20; ++i) {
    ta.step(true);
    tb.step(true);
    tc.step(true);
    ASSERT_FALSE(any_done()) << "terminated with a message in flight, step " << i;
  }
  EXPECT_GE(ta.rounds(), 4u);
  net.release(0, 1);
  ASSERT_TRUE(net.deliver_one());
  ASSERT_EQ(drain(b), 1u);
  tb.activity();
  for (int i = 0; i < 20 && !(ta.terminated() && tb.terminated() && tc.terminated()); ++i) {
    ta.step(true);
    tb.step(true);
    tc.step(true);
  }
  EXPECT_TRUE(ta.terminated() && tb.terminated() && tc.terminated());
}

TEST(Termination, OneRankEndsAlone) {
  SimNetwork net(1, 7);
  ChainRank r(net.endpoint(0), 3, 5);
  int steps = 0;
  while (!r.step()) ASSERT_LT(++steps, 100000);
  EXPECT_EQ(r.handled(), test::expected_total(1, 3, 5));
}

}  // namespace
}  // namespace pdr::par
