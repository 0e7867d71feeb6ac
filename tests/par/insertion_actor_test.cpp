// Distributed Delaunay insertion by concurrent ranks (par/insertion_actor.hpp) on the
// simulator: a refined cube-in-cube cut into one submesh per rank, random points given
// to the ranks, every rank's loop stepped and every message delivered in a seeded random
// order. When termination is detected, no message is in flight, every point was inserted
// once, every store is valid, and the ranks together hold exactly the tets of the
// sequential kernel's Delaunay tetrahedralization of the same points; setbacks happened
// (concurrent closures met) and were overcome.
#include <gtest/gtest.h>

#include <algorithm>

#include "delaunay/delaunay.hpp"
#include "par/insertion_actor.hpp"
#include "par/par_meshes.hpp"
#include "par/partition.hpp"
#include "par/point_tets.hpp"
#include "par/sim_network.hpp"
#include "par/sim_run.hpp"

namespace pdr::par {
namespace {

// Points spread over the box, or all in one small ball that every rank fills at once
// (the closures meet all the time: the livelock case of §4.3).
void run_ranks(bool clustered, std::uint64_t first_seed, std::uint64_t last_seed) {
  const refine::VolumeMesh& vm = test::cube_in_cube();
  InsertionStats total;
  for (std::uint64_t seed = first_seed; seed <= last_seed; ++seed) {
    const int ranks = 2 + static_cast<int>(seed % 4);
    const Partition part = partition_tets(vm.dt.store(), vm.inside, static_cast<std::uint32_t>(ranks), seed);
    SimNetwork net(ranks, seed);
    std::vector<std::unique_ptr<InsertionActor>> actors;
    for (int r = 0; r < ranks; ++r)
      actors.push_back(std::make_unique<InsertionActor>(
          net.endpoint(r),
          Submesh::extract(static_cast<ActorId>(r), vm.dt.store(), vm.dt.points(), vm.inside, part),
          seed));
    Delaunay reference = vm.dt;
    std::mt19937_64 rng(seed);
    const int points = 300;
    for (int i = 0; i < points; ++i) {
      Point p;
      for (int k = 0; k < 3; ++k)
        p[k] = clustered ? 2.5 + 0.6 * static_cast<double>(rng() % 1000003) / 1000003.0
                         : 10.0 * static_cast<double>(rng() % 1000003) / 1000003.0;
      actors[rng() % static_cast<std::size_t>(ranks)]->add_point(p);
      ASSERT_EQ(reference.insert(p).outcome, Outcome::Inserted);
    }
    const std::uint64_t steps = test::run_to_termination(net, actors, seed, 20'000'000u);
    ASSERT_GT(steps, 0u);
    std::vector<test::PointTet> got;
    InsertionStats run;
    for (const auto& a : actors) {
      const auto problems = a->submesh().check();
      ASSERT_TRUE(problems.empty()) << "seed " << seed << ": " << problems.front();
      EXPECT_EQ(a->submesh().waiting_relinks(), 0u);
      test::add_finite_tets(a->submesh().store(), a->submesh().points(), got);
      const InsertionStats& s = a->stats();
      run.commits += s.commits;
      run.setbacks += s.setbacks;
      run.rounds += s.rounds;
      run.duplicates += s.duplicates;
      run.refused += s.refused;
      run.tets_sent += s.tets_sent;
      run.points_passed += s.points_passed;
    }
    EXPECT_EQ(run.commits, static_cast<std::uint64_t>(points)) << "seed " << seed;
    EXPECT_EQ(run.duplicates, 0u);
    std::vector<test::PointTet> want;
    test::add_finite_tets(reference.store(), reference.points(), want);
    got = test::sorted(std::move(got));
    want = test::sorted(std::move(want));
    EXPECT_EQ(got.size(), want.size()) << "seed " << seed;
    EXPECT_TRUE(got == want) << "seed " << seed << ": not the Delaunay tetrahedralization";
    std::printf("%s seed %llu, %d ranks: %llu commits, %llu rounds, %llu setbacks, %llu refusals, "
                "%llu tets migrated, %llu sim steps\n",
                clustered ? "clustered" : "spread", static_cast<unsigned long long>(seed), ranks,
                static_cast<unsigned long long>(run.commits), static_cast<unsigned long long>(run.rounds),
                static_cast<unsigned long long>(run.setbacks), static_cast<unsigned long long>(run.refused),
                static_cast<unsigned long long>(run.tets_sent), static_cast<unsigned long long>(steps));
    total.setbacks += run.setbacks;
  }
  EXPECT_GT(total.setbacks, 0u);  // concurrent closures met, and the back-off resolved it
}

TEST(InsertionActor, ConcurrentRanksBuildTheSequentialDelaunayMesh) { run_ranks(false, 1, 6); }

TEST(InsertionActor, RanksFillingOneSmallBallAllFinish) { run_ranks(true, 11, 16); }

}  // namespace
}  // namespace pdr::par
