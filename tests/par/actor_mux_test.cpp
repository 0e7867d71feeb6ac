// Several submeshes per rank (par/actor_mux.hpp) on the simulator: P simulated ranks, each
// hosting its share of N > P actors through an ActorMux over its endpoint; random points
// given to the actors; every actor's loop stepped and every message delivered in a seeded
// random order. When termination is detected, no message is in flight, in the network or
// in a mux's inbox; every point was inserted once; every store is valid; and the actors
// together hold exactly the sequential kernel's Delaunay tetrahedralization.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <optional>
#include <random>
#include <span>

#include "delaunay/delaunay.hpp"
#include "par/actor_mux.hpp"
#include "par/insertion_actor.hpp"
#include "par/par_meshes.hpp"
#include "par/partition.hpp"
#include "par/point_tets.hpp"
#include "par/sim_network.hpp"
#include "par/sim_run.hpp"

namespace pdr::par {
namespace {

TEST(ActorMux, SubmeshesSharingRanksBuildTheSequentialDelaunayMesh) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const int ranks = 2 + static_cast<int>(seed % 2);
    const int actors = ranks + 1 + static_cast<int>(seed % 4);  // N > P, not a multiple
    const Partition part =
        partition_tets(vm.dt.store(), vm.inside, static_cast<std::uint32_t>(actors), seed);
    SimNetwork net(ranks, seed);
    std::vector<std::unique_ptr<ActorMux>> muxes;
    for (int r = 0; r < ranks; ++r) muxes.push_back(std::make_unique<ActorMux>(net.endpoint(r), actors));
    std::vector<std::unique_ptr<InsertionActor>> all;
    std::vector<Transport*> ports;
    for (int k = 0; k < actors; ++k) {
      ActorMux& mux = *muxes[static_cast<std::size_t>(k % ranks)];
      ASSERT_EQ(mux.host(k), k % ranks);
      ports.push_back(&mux.port(k));
      all.push_back(std::make_unique<InsertionActor>(
          *ports.back(),
          Submesh::extract(static_cast<ActorId>(k), vm.dt.store(), vm.dt.points(), vm.inside, part),
          seed));
    }
    Delaunay reference = vm.dt;
    std::mt19937_64 rng(seed);
    const int points = 250;
    for (int i = 0; i < points; ++i) {
      Point p;
      for (int k = 0; k < 3; ++k) p[k] = 10.0 * static_cast<double>(rng() % 1000003) / 1000003.0;
      all[rng() % static_cast<std::size_t>(actors)]->add_point(p);
      ASSERT_EQ(reference.insert(p).outcome, Outcome::Inserted);
    }
    const auto unread = [&] {
      std::size_t n = 0;
      for (const auto& m : muxes) n += m->queued();
      return n;
    };
    ASSERT_GT(test::run_to_termination(net, all, seed, 20'000'000u, unread), 0u);
    std::uint64_t sent = 0, received = 0, commits = 0;
    for (const Transport* t : ports) sent += t->sent(), received += t->received();
    EXPECT_EQ(sent, received) << "seed " << seed << ": a message left in a mux's inbox";
    std::vector<test::PointTet> got;
    for (const auto& a : all) {
      const auto problems = a->submesh().check();
      ASSERT_TRUE(problems.empty()) << "seed " << seed << ": " << problems.front();
      EXPECT_EQ(a->submesh().waiting_relinks(), 0u);
      test::add_finite_tets(a->submesh().store(), a->submesh().points(), got);
      commits += a->stats().commits;
    }
    EXPECT_EQ(commits, static_cast<std::uint64_t>(points)) << "seed " << seed;
    std::vector<test::PointTet> want;
    test::add_finite_tets(reference.store(), reference.points(), want);
    EXPECT_TRUE(test::sorted(std::move(got)) == test::sorted(std::move(want)))
        << "seed " << seed << ", " << ranks << " ranks, " << actors
        << " submeshes: not the Delaunay tetrahedralization";
  }
}

// The guarantees of par/transport.hpp, for the actors' transports: every message delivered
// once, FIFO per pair of actors (local and remote pairs alike), counts that balance, and
// reductions that sum over all N actors with every actor reading the same result.
TEST(ActorMux, PortsKeepFifoCountsAndReductions) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const int ranks = 2 + static_cast<int>(seed % 3), actors = ranks + static_cast<int>(seed % 5);
    SimNetwork net(ranks, seed);
    std::vector<std::unique_ptr<ActorMux>> muxes;
    for (int r = 0; r < ranks; ++r) muxes.push_back(std::make_unique<ActorMux>(net.endpoint(r), actors));
    auto port = [&](int k) -> Transport& { return muxes[static_cast<std::size_t>(k % ranks)]->port(k); };
    std::mt19937_64 rng(seed);
    std::vector<std::uint32_t> next_sent(static_cast<std::size_t>(actors * actors), 0),
        next_seen(static_cast<std::size_t>(actors * actors), 0);
    std::size_t delivered = 0, total = 0;
    auto poll_all = [&] {
      for (int k = 0; k < actors; ++k)
        port(k).poll(
            [&](int from, std::span<const std::byte> m) {
              std::uint32_t n = 0;
              ASSERT_EQ(m.size(), sizeof n + static_cast<std::size_t>(from));  // length kept
              std::memcpy(&n, m.data(), sizeof n);
              EXPECT_EQ(n, next_seen[static_cast<std::size_t>(from * actors + k)]++)
                  << "seed " << seed << ": " << from << " -> " << k << " out of order";
              ++delivered;
            },
            1 + rng() % 4);
    };
    for (int i = 0; i < 2000; ++i) {
      const int from = static_cast<int>(rng() % static_cast<unsigned>(actors));
      int to = static_cast<int>(rng() % static_cast<unsigned>(actors - 1));
      if (to >= from) ++to;
      const std::uint32_t n = next_sent[static_cast<std::size_t>(from * actors + to)]++;
      Bytes b(sizeof n + static_cast<std::size_t>(from));
      std::memcpy(b.data(), &n, sizeof n);
      port(from).send(to, std::move(b));
      ++total;
      if (rng() % 3 == 0) net.deliver_one();
      if (rng() % 5 == 0) poll_all();
    }
    while (net.deliver_one()) {}
    for (int i = 0; i < 10000 && delivered < total; ++i) poll_all();
    EXPECT_EQ(delivered, total) << "seed " << seed;
    std::uint64_t sent = 0, received = 0;
    for (int k = 0; k < actors; ++k) sent += port(k).sent(), received += port(k).received();
    EXPECT_EQ(sent, total);
    EXPECT_EQ(received, total);
    // Two reduction rounds: actor k contributes (k, 1, sent); each actor reads the sum.
    for (int round = 0; round < 2; ++round) {
      for (int k = 0; k < actors; ++k)
        port(k).start_reduction({static_cast<std::uint64_t>(k), 1, port(k).sent()});
      std::vector<std::optional<Reduction>> got(static_cast<std::size_t>(actors));
      for (int spins = 0; spins < 1000; ++spins) {
        for (int k = 0; k < actors; ++k)
          if (!got[static_cast<std::size_t>(k)]) got[static_cast<std::size_t>(k)] = port(k).reduction_done();
        net.deliver_one();
      }
      for (int k = 0; k < actors; ++k) {
        ASSERT_TRUE(got[static_cast<std::size_t>(k)].has_value()) << "seed " << seed;
        const Reduction want{static_cast<std::uint64_t>(actors * (actors - 1) / 2),
                             static_cast<std::uint64_t>(actors), total};
        EXPECT_EQ(*got[static_cast<std::size_t>(k)], want) << "seed " << seed;
      }
    }
  }
}

// Reduction rounds with the actors of a rank at different rounds: each actor starts its
// round, reads its result whenever it is next picked, and starts the next round at once
// (as termination detection does), in a random order across actors and ranks. Every actor
// reads every round's sum over all N actors.
TEST(ActorMux, InterleavedRoundsEachSumOverAllActors) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const int ranks = 2 + static_cast<int>(seed % 3), actors = ranks + static_cast<int>(seed % 5);
    const int rounds = 6;
    SimNetwork net(ranks, seed);
    std::vector<std::unique_ptr<ActorMux>> muxes;
    for (int r = 0; r < ranks; ++r) muxes.push_back(std::make_unique<ActorMux>(net.endpoint(r), actors));
    auto port = [&](int k) -> Transport& { return muxes[static_cast<std::size_t>(k % ranks)]->port(k); };
    std::mt19937_64 rng(seed);
    std::vector<int> round(static_cast<std::size_t>(actors), -1);  // started, not yet read
    int finished = 0;
    for (int spins = 0; spins < 200000 && finished < actors; ++spins) {
      const int k = static_cast<int>(rng() % static_cast<unsigned>(actors));
      int& r = round[static_cast<std::size_t>(k)];
      if (r == rounds) continue;
      if (r >= 0) {
        const std::optional<Reduction> got = port(k).reduction_done();
        if (!got) continue;
        const std::uint64_t n = static_cast<std::uint64_t>(actors);
        EXPECT_EQ(*got, (Reduction{n * (n - 1) / 2, n * static_cast<std::uint64_t>(r), n}))
            << "seed " << seed << ", actor " << k << ", round " << r;
      }
      if (++r == rounds) {
        ++finished;
        continue;
      }
      port(k).start_reduction({static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(r), 1});
      EXPECT_THROW(port(k).start_reduction({0, 0, 0}), std::logic_error);  // unread round
    }
    EXPECT_EQ(finished, actors) << "seed " << seed << ": rounds stuck";
  }
}

TEST(ActorMux, FewerSubmeshesThanRanksIsRefused) {
  SimNetwork net(3, 1);
  EXPECT_THROW(ActorMux(net.endpoint(0), 2), std::invalid_argument);
}

}  // namespace
}  // namespace pdr::par
