// Gathering at rank 0 and the polled broadcast; see par/mpi_collect.hpp.
#include "par/mpi_collect.hpp"

#include <mpi.h>

#include <chrono>
#include <algorithm>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

namespace pdr::par {
namespace {

constexpr auto kIntMax = static_cast<std::size_t>(std::numeric_limits<int>::max());

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

}  // namespace

std::vector<std::byte> gather_bytes(std::span<const std::byte> mine, std::size_t round_bytes) {
  std::vector<std::byte> all;
  gather_into(
      mine,
      [&](std::size_t total) {
        all.resize(total);
        return all.data();
      },
      round_bytes);
  return all;
}

void gather_into(std::span<const std::byte> mine, const std::function<std::byte*(std::size_t)>& out,
                 std::size_t round_bytes, bool root_in_place) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const auto n = static_cast<std::size_t>(ranks);
  // Every rank learns every size, so all agree on the rounds.
  const std::uint64_t size = mine.size();
  std::vector<std::uint64_t> sizes(n);
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallgather(&size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD, &r),
        "MPI_Iallgather");
  wait_asleep(r);
  std::vector<std::size_t> start(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k) start[k + 1] = start[k] + sizes[k];
  const std::size_t total = start[n];
  const std::size_t most = *std::max_element(sizes.begin(), sizes.end());
  std::byte* const all = rank == 0 ? out(total) : nullptr;
  // Rank 0's own bytes, read from its buffer when they are already there.
  const bool in_place = root_in_place && rank == 0;
  const std::byte* const own = in_place ? all : mine.data();
  // One round when it fits (the counts and offsets are ints), straight into `all`; else
  // rounds of at most `chunk` bytes per rank, n * chunk <= INT_MAX, through a buffer.
  const std::size_t chunk =
      total <= kIntMax && most <= round_bytes ? std::max<std::size_t>(most, 1)
                                              : std::max<std::size_t>(1, std::min(round_bytes, kIntMax / n));
  const bool one_round = most <= chunk;
  std::vector<std::byte> buffer;
  std::vector<int> counts(n), offsets(n);
  for (std::size_t lo = 0; lo < most; lo += chunk) {
    int at = 0;
    for (std::size_t k = 0; k < n; ++k) {
      counts[k] = sizes[k] > lo ? static_cast<int>(std::min<std::uint64_t>(chunk, sizes[k] - lo)) : 0;
      offsets[k] = one_round ? static_cast<int>(start[k]) : at;
      at += counts[k];
    }
    const int now = size > lo ? static_cast<int>(std::min<std::uint64_t>(chunk, size - lo)) : 0;
    if (rank == 0 && !one_round) buffer.resize(static_cast<std::size_t>(at));
    check(MPI_Igatherv(in_place && one_round ? MPI_IN_PLACE : own + (now > 0 ? lo : 0), now, MPI_BYTE,
                       one_round ? all : buffer.data(), counts.data(), offsets.data(),
                       MPI_BYTE, 0, MPI_COMM_WORLD, &r),
          "MPI_Igatherv");
    wait_asleep(r);
    if (rank == 0 && !one_round)
      for (std::size_t k = in_place ? 1 : 0; k < n; ++k)
        if (counts[k] > 0)
          std::memcpy(all + start[k] + lo, buffer.data() + offsets[k],
                      static_cast<std::size_t>(counts[k]));
  }
}

std::vector<Point> gather_points(const std::vector<Point>& mine) { return gather_values(mine); }

std::vector<RankFigures> gather_figures(const RankFigures& mine) {
  return gather_values(std::vector<RankFigures>{mine});
}

int broadcast_from_root(int value) {
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &r), "MPI_Ibcast");
  wait_asleep(r);
  return value;
}

std::string broadcast_from_root(const std::string& text) {
  int rank = 0;
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
  if (text.size() > kIntMax) throw std::length_error("broadcast_from_root: text too long");
  const int size = broadcast_from_root(static_cast<int>(text.size()));
  std::string out = rank == 0 ? text : std::string(static_cast<std::size_t>(size), '\0');
  if (size == 0) return out;
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Ibcast(out.data(), size, MPI_CHAR, 0, MPI_COMM_WORLD, &r), "MPI_Ibcast");
  wait_asleep(r);
  return out;
}

std::vector<std::uint64_t> all_values(const std::vector<std::uint64_t>& mine) {
  int ranks = 1;
  check(MPI_Comm_size(MPI_COMM_WORLD, &ranks), "MPI_Comm_size");
  if (mine.size() * static_cast<std::size_t>(ranks) > kIntMax)
    throw std::length_error("all_values: too many values");
  std::vector<std::uint64_t> out(mine.size() * static_cast<std::size_t>(ranks));
  if (mine.empty()) return out;
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallgather(mine.data(), static_cast<int>(mine.size()), MPI_UINT64_T, out.data(),
                       static_cast<int>(mine.size()), MPI_UINT64_T, MPI_COMM_WORLD, &r),
        "MPI_Iallgather");
  wait_asleep(r);
  return out;
}

std::vector<std::uint64_t> sum_over_ranks(const std::vector<std::uint64_t>& values) {
  std::vector<std::uint64_t> out(values.size());
  if (values.empty()) return out;
  if (values.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("sum_over_ranks: too many values");
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallreduce(values.data(), out.data(), static_cast<int>(values.size()), MPI_UINT64_T,
                       MPI_SUM, MPI_COMM_WORLD, &r),
        "MPI_Iallreduce");
  wait_asleep(r);
  return out;
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
