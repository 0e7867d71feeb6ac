// The collective steps of `mpirun pdr mesh` around the parallel phase, on MPI_COMM_WORLD:
// gathering at rank 0, and the run's end, which every rank must reach without spinning
// (a rank waiting for rank 0's completion and output sleeps between tests of a
// non-blocking collective: par/idle.hpp's reasoning, with ranks that may share cores).
// Preconditions: MPI is initialised (par/mpi_transport.hpp MpiSession); every rank calls
// each function in the same order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "geom/point.hpp"
#include "par/par_refinement.hpp"

namespace pdr::par {

// Every rank's points, concatenated in rank order, at rank 0 (empty elsewhere).
std::vector<Point> gather_points(const std::vector<Point>& mine);

// Every rank's bytes, concatenated in rank order, at rank 0 (empty elsewhere). Any size:
// in rounds of at most `round_bytes` per rank (and at most INT_MAX bytes in all, MPI's
// counts being ints), every rank taking part in every round.
std::vector<std::byte> gather_bytes(std::span<const std::byte> mine,
                                    std::size_t round_bytes = std::size_t{1} << 30);

// The same, received where out(total) says at rank 0 (called there once, with the
// total size, before anything is received; never elsewhere). With `root_in_place`, the
// buffer out(total) returns at rank 0 already begins with rank 0's bytes (`mine` may be
// gone by then: they are not read there).
void gather_into(std::span<const std::byte> mine, const std::function<std::byte*(std::size_t)>& out,
                 std::size_t round_bytes = std::size_t{1} << 30, bool root_in_place = false);

// Every rank's values, concatenated in rank order, at rank 0 (empty elsewhere), received
// in place (no second copy).
template <class T>
std::vector<T> gather_values(const std::vector<T>& mine) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<T> out;
  gather_into(std::as_bytes(std::span(mine.data(), mine.size())), [&](std::size_t total) {
    if (total % sizeof(T) != 0) throw std::logic_error("gather_values: a rank sent part of a value");
    out.resize(total / sizeof(T));
    return reinterpret_cast<std::byte*>(out.data());
  });
  return out;
}

// Every rank's values appended, in rank order, to rank 0's own `mine` (unchanged
// elsewhere): rank 0's values are not copied, and nothing is moved when mine's capacity
// already holds the total.
template <class T>
void gather_append(std::vector<T>& mine, std::size_t round_bytes = std::size_t{1} << 30) {
  static_assert(std::is_trivially_copyable_v<T>);
  gather_into(
      std::as_bytes(std::span(mine.data(), mine.size())),
      [&](std::size_t total) {
        if (total % sizeof(T) != 0) throw std::logic_error("gather_append: a rank sent part of a value");
        mine.resize(total / sizeof(T));
        return reinterpret_cast<std::byte*>(mine.data());
      },
      round_bytes, true);
}

// Every rank's figures, in rank order, at rank 0 (empty elsewhere).
std::vector<RankFigures> gather_figures(const RankFigures& mine);

// Rank 0's value on every rank; the other ranks wait for it asleep (at most 1 ms late).
int broadcast_from_root(int value);

// Rank 0's text on every rank (the others' `text` is ignored), waiting asleep.
std::string broadcast_from_root(const std::string& text);

// Every rank's values, concatenated in rank order, on every rank (the same count on every
// rank), waiting asleep.
std::vector<std::uint64_t> all_values(const std::vector<std::uint64_t>& mine);

// The element-wise maximum of `values` over the ranks, on every rank (waiting asleep).
std::array<int, 2> max_over_ranks(std::array<int, 2> values);

// The element-wise sum of `values` over the ranks (the same length on every rank), on
// every rank (waiting asleep).
std::vector<std::uint64_t> sum_over_ranks(const std::vector<std::uint64_t>& values);

}  // namespace pdr::par
