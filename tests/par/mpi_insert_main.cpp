// Distributed Delaunay insertion (par/insertion_actor.hpp) under mpirun: every rank builds
// the same refined cube-in-cube and METIS partition (deterministic), keeps its own part,
// and inserts its share of seeded random points (spread over the box, or with "ball" all
// in one small ball that every rank fills at once) with the Open MPI transport, until
// termination is detected. The ranks then send their finite tets (as point quadruples) to
// rank 0, which compares them with the sequential kernel's Delaunay tetrahedralization
// of the same points. Exit 0 when they are the same.
//   par_mpi_insert [POINTS [ball]]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>

#include "delaunay/delaunay.hpp"
#include "par/idle.hpp"
#include "par/insertion_actor.hpp"
#include "par/mpi_transport.hpp"
#include "par/par_meshes.hpp"
#include "par/partition.hpp"
#include "par/point_tets.hpp"

int main(int argc, char** argv) {
  using namespace pdr;
  using namespace pdr::par;
  MpiSession session(&argc, &argv);
  const int points = argc > 1 ? std::atoi(argv[1]) : 400;
  const bool ball = argc > 2 && std::strcmp(argv[2], "ball") == 0;
  const int rank = session.rank(), size = session.size();
  std::vector<test::PointTet> mine;
  std::vector<Point> all_points;
  InsertionStats st;
  try {
    const refine::VolumeMesh& vm = test::cube_in_cube();
    const Partition part = partition_tets(vm.dt.store(), vm.inside, static_cast<std::uint32_t>(size), 7);
    MpiTransport t;
    InsertionActor actor(t, Submesh::extract(static_cast<ActorId>(rank), vm.dt.store(), vm.dt.points(), vm.inside, part), 7);
    std::mt19937_64 rng(99);
    for (int i = 0; i < points; ++i) {
      Point p;
      for (int k = 0; k < 3; ++k)
        p[static_cast<std::size_t>(k)] = ball ? 2.5 + 0.6 * static_cast<double>(rng() % 1000003) / 1000003.0
                                              : 10.0 * static_cast<double>(rng() % 1000003) / 1000003.0;
      all_points.push_back(p);
      if (i % size == rank) actor.add_point(p);
    }
    IdlePolicy idle;
    InsertionStats before;
    while (!actor.step()) {
      const InsertionStats& now = actor.stats();
      idle.after_iteration(now.rounds != before.rounds || now.fetches_served != before.fetches_served,
                           !actor.idle());
      before = now;
    }
    test::add_finite_tets(actor.submesh().store(), actor.submesh().points(), mine);
    st = actor.stats();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rank %d: %s\n", rank, e.what());
    MpiSession::abort(1);
  }
  // Gather the tets at rank 0.
  const int count = static_cast<int>(mine.size() * 12);
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < size; ++r) offsets[static_cast<std::size_t>(r)] = total, total += counts[static_cast<std::size_t>(r)];
  std::vector<double> gathered(rank == 0 ? static_cast<std::size_t>(total) : 0);
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, gathered.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  std::uint64_t local[3] = {st.commits, st.setbacks, st.tets_sent}, sums[3] = {0, 0, 0};
  MPI_Reduce(local, sums, 3, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank != 0) return 0;
  std::vector<test::PointTet> got(static_cast<std::size_t>(total / 12));
  std::memcpy(got.data(), gathered.data(), gathered.size() * sizeof(double));
  Delaunay reference = test::cube_in_cube().dt;
  for (const Point& p : all_points) reference.insert(p);
  std::vector<test::PointTet> want;
  test::add_finite_tets(reference.store(), reference.points(), want);
  got = test::sorted(std::move(got));
  want = test::sorted(std::move(want));
  const bool same = got == want;
  std::printf("ranks %d, %d points%s: %llu commits, %llu setbacks, %llu tets migrated; %zu tets, "
              "%s the sequential Delaunay tetrahedralization (%zu tets)\n",
              size, points, ball ? " in one ball" : "", static_cast<unsigned long long>(sums[0]),
              static_cast<unsigned long long>(sums[1]), static_cast<unsigned long long>(sums[2]),
              got.size(), same ? "equal to" : "NOT equal to", want.size());
  return same && sums[0] == static_cast<std::uint64_t>(points) ? 0 : 1;
}
