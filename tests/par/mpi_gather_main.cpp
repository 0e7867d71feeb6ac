// gather_bytes and gather_append (par/mpi_collect.hpp) under mpirun: ranks of different
// sizes (rank 1 sends nothing), gathered in rounds much smaller than the parts (7 bytes,
// 1000 bytes) and in one round; rank 0 checks that it got every rank's bytes, in rank
// order (appended to its own, which gather_append must not read from where they were, so
// its vector is given no spare capacity and moves when it grows). Exit 0 on success; a
// failing check aborts the job.
#include <mpi.h>

#include <cstdio>
#include <vector>

#include "par/mpi_collect.hpp"
#include "par/mpi_transport.hpp"

namespace {

std::byte byte_of(int rank, std::size_t i) { return static_cast<std::byte>((rank * 37 + i * 11) & 0xFF); }

std::size_t size_of(int rank) { return rank == 1 ? 0 : 1000 * static_cast<std::size_t>(rank) + 13; }

}  // namespace

int main(int argc, char** argv) {
  using namespace pdr::par;
  MpiSession session(&argc, &argv);
  const int rank = session.rank(), ranks = session.size();
  std::vector<std::byte> mine(size_of(rank));
  for (std::size_t i = 0; i < mine.size(); ++i) mine[i] = byte_of(rank, i);
  for (const std::size_t round : {std::size_t{7}, std::size_t{1000}, std::size_t{1} << 30})
    for (const bool append : {false, true}) {
      std::vector<std::byte> all;
      if (append) {
        all = mine;
        all.shrink_to_fit();
        gather_append(all, round);
      } else {
        all = gather_bytes(mine, round);
      }
      if (rank != 0) {
        if (append ? all != mine : !all.empty()) MpiSession::abort(1);
        continue;
      }
      std::size_t at = 0;
      for (int r = 0; r < ranks; ++r)
        for (std::size_t i = 0; i < size_of(r); ++i, ++at)
          if (at >= all.size() || all[at] != byte_of(r, i)) {
            std::fprintf(stderr, "rounds of %zu bytes%s: byte %zu of rank %d is wrong\n", round,
                         append ? " (appended)" : "", i, r);
            MpiSession::abort(1);
          }
      if (at != all.size()) {
        std::fprintf(stderr, "rounds of %zu bytes%s: %zu bytes, %zu expected\n", round,
                     append ? " (appended)" : "", all.size(), at);
        MpiSession::abort(1);
      }
    }
  return 0;
}
