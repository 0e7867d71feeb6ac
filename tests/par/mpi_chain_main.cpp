// The Open MPI transport (par/mpi_transport.hpp) and termination detection under mpirun:
// every rank runs the chain reaction of chain_workload.hpp until the detector fires; then
// the ranks check, with blocking collectives outside the loop, that every token was handled
// exactly once and that as many messages were received as were sent. Exit 0 on success.
//   par_mpi_chain [PAD [TOKENS TTL]]   PAD bytes of checked padding per message (a large
//                                      PAD takes MPI's rendezvous protocol); TOKENS per
//                                      rank with TTL generations (default 6 and 9)
// A failing rank aborts the job (MPI_Abort) instead of leaving its peers waiting.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "par/chain_workload.hpp"
#include "par/idle.hpp"
#include "par/mpi_transport.hpp"

int main(int argc, char** argv) {
  using namespace pdr::par;
  MpiSession session(&argc, &argv);
  const std::size_t pad = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 0;
  const int per_rank = argc > 3 ? std::atoi(argv[2]) : 6;
  const auto ttl = static_cast<std::uint32_t>(argc > 3 ? std::atoi(argv[3]) : 9);
  std::uint64_t handled = 0, sent = 0, received = 0, rounds = 0;
  try {
    MpiTransport t;
    test::ChainRank rank(t, per_rank, ttl, pad);
    IdlePolicy idle;
    std::uint64_t before = 0;
    while (!rank.step()) {
      idle.after_iteration(rank.handled() != before);
      before = rank.handled();
    }
    handled = rank.handled();
    sent = t.sent();
    received = t.received();
    rounds = rank.rounds();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rank %d: %s\n", session.rank(), e.what());
    MpiSession::abort(1);
  }
  std::uint64_t local[3] = {handled, sent, received}, total[3] = {0, 0, 0};
  MPI_Allreduce(local, total, 3, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  const std::uint64_t expected = test::expected_total(session.size(), per_rank, ttl);
  if (session.rank() == 0)
    std::printf("ranks %d, %zu padding bytes: handled %llu of %llu tokens, %llu messages "
                "sent, %llu received, %llu reduction rounds on rank 0\n",
                session.size(), pad, static_cast<unsigned long long>(total[0]),
                static_cast<unsigned long long>(expected), static_cast<unsigned long long>(total[1]),
                static_cast<unsigned long long>(total[2]), static_cast<unsigned long long>(rounds));
  return total[0] == expected && total[1] == total[2] ? 0 : 1;
}
