// Files written by every rank at once: each rank's bytes of a file follow those of the
// ranks before it (a mesh file whose lines each rank lists for its own part: the ranks'
// TetGen files, app/parallel.cpp). Nothing is gathered at rank 0.
//
// How: rank 0 creates each file's temporary beside it (io::AtomicFile) and tells the
// others its name; every other rank opens it (without creating it: on hosts that do not
// share rank 0's file system the open fails, and the run says so instead of writing a
// file with holes) and writes its bytes at its offset, the sum of the sizes of the ranks
// before it, as rank 0 does through its own descriptor; once every rank reports its
// writes done, rank 0 renames the temporaries onto the files (io::commit_all: all are
// closed before any is renamed). When a rank cannot write its part, no file is renamed
// and rank 0's temporaries are removed; rank 0 then throws RankFilesError with the
// reason (which rank, which error), so the run reports it once and ends with exit 2, as
// the sequential command does for a file it cannot write, and the other ranks return
// false. (A run aborted meanwhile, by a rank that fails otherwise, may leave the
// temporaries.)
//
// Collective: every rank calls it, with the same paths in the same order. The ranks wait
// for each other asleep (par/mpi_collect.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>

namespace pdr::par {

// The output could not be written (rank 0 only; the user's to mend, not an internal error).
class RankFilesError : public std::system_error {
 public:
  using std::system_error::system_error;
  explicit RankFilesError(const std::system_error& e) : std::system_error(e) {}
};

// Writes file k as the concatenation of every rank's bytes[k], in rank order. True when
// written; false on the ranks other than 0 when not (above).
bool write_in_rank_order(std::span<const std::string> paths, std::span<const std::string> bytes);

// A rank's part of a file, made as it is written: exactly `size` bytes, which `fill`
// hands to the function it is given, in order and in pieces (a large part then never
// stands whole in memory). A part whose pieces do not add up to `size` is an internal
// error (std::logic_error, on that rank: the run is aborted).
struct StreamedPart {
  std::uint64_t size = 0;
  std::function<void(const std::function<void(std::string_view)>&)> fill;
};
bool write_in_rank_order(std::span<const std::string> paths, std::span<const StreamedPart> parts);

}  // namespace pdr::par
