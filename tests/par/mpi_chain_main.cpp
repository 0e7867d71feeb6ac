// The Open MPI transport (par/mpi_transport.hpp) and termination detection under mpirun:
// every rank runs the chain reaction of chain_workload.hpp until the detector fires; then
// the ranks check, with blocking collectives outside the loop, that every token was handled
// exactly once and that as many messages were received as were sent. Exit 0 on success.
#include <mpi.h>

#include <cstdio>

#include "par/chain_workload.hpp"
#include "par/idle.hpp"
#include "par/mpi_transport.hpp"

int main(int argc, char** argv) {
  using namespace pdr::par;
  MpiSession session(&argc, &argv);
  constexpr int kPerRank = 6;
  constexpr std::uint32_t kTtl = 9;
  std::uint64_t handled = 0, sent = 0, received = 0, rounds = 0;
  {
    MpiTransport t;
    test::ChainRank rank(t, kPerRank, kTtl);
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
  }
  std::uint64_t local[3] = {handled, sent, received}, total[3] = {0, 0, 0};
  MPI_Allreduce(local, total, 3, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  const std::uint64_t expected = test::expected_total(session.size(), kPerRank, kTtl);
  if (session.rank() == 0)
    std::printf("ranks %d: handled %llu of %llu tokens, %llu messages sent, %llu received, "
                "%llu reduction rounds on rank 0\n",
                session.size(), static_cast<unsigned long long>(total[0]),
                static_cast<unsigned long long>(expected), static_cast<unsigned long long>(total[1]),
                static_cast<unsigned long long>(total[2]), static_cast<unsigned long long>(rounds));
  return total[0] == expected && total[1] == total[2] ? 0 : 1;
}
