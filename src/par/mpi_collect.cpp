// Gathering at rank 0 and the polled broadcast; see par/mpi_collect.hpp.
#include "par/mpi_collect.hpp"

#include <mpi.h>

#include <chrono>
#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

namespace pdr::par {
namespace {

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("mpi: ") + what + " failed");
}

// Waits for request r, testing it and sleeping in between (20 µs doubling to 1 ms).
void wait_asleep(MPI_Request& r) {
  auto pause = std::chrono::microseconds(20);
  for (;;) {
    int done = 0;
    check(MPI_Test(&r, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done != 0) return;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

// Gathers `mine` (bytes) from every rank at rank 0, in rank order.
std::vector<std::byte> gather_bytes(const std::byte* data, std::size_t size) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("mpi: a rank's part of a gather exceeds MPI's int count");
  const int count = static_cast<int>(size);
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks));
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Igather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD, &r),
        "MPI_Igather");
  wait_asleep(r);
  std::size_t total = 0;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    if (total > static_cast<std::size_t>(std::numeric_limits<int>::max()) - static_cast<std::size_t>(counts[k]))
      throw std::runtime_error("mpi: a gather exceeds MPI's int count");
    offsets[k] = static_cast<int>(total);
    total += static_cast<std::size_t>(counts[k]);
  }
  std::vector<std::byte> all(rank == 0 ? total : 0);
  check(MPI_Igatherv(data, count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                     0, MPI_COMM_WORLD, &r),
        "MPI_Igatherv");
  wait_asleep(r);
  return all;
}

template <class T>
std::vector<T> gather_values(const std::vector<T>& mine) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::vector<std::byte> b =
      gather_bytes(reinterpret_cast<const std::byte*>(mine.data()), mine.size() * sizeof(T));
  std::vector<T> out(b.size() / sizeof(T));
  if (!b.empty()) std::memcpy(out.data(), b.data(), b.size());
  return out;
}

}  // namespace

std::vector<Point> gather_points(const std::vector<Point>& mine) { return gather_values(mine); }

std::vector<std::byte> gather_bytes(const std::vector<std::byte>& mine) {
  return gather_values(mine);
}

std::vector<RankFigures> gather_figures(const RankFigures& mine) {
  return gather_values(std::vector<RankFigures>{mine});
}

int broadcast_from_root(int value) {
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &r), "MPI_Ibcast");
  wait_asleep(r);
  return value;
}

std::array<int, 2> max_over_ranks(std::array<int, 2> values) {
  std::array<int, 2> out{};
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallreduce(values.data(), out.data(), 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &r),
        "MPI_Iallreduce");
  wait_asleep(r);
  return out;
}

}  // namespace pdr::par
