// Files written by every rank at once: each rank's bytes of a file follow those of the
// ranks before it (a mesh file whose lines each rank lists for its own part: the ranks'
// TetGen files, app/parallel.cpp). Nothing is gathered at rank 0.
//
// How: rank 0 creates each file's temporary beside it (io::AtomicFile) and tells the
// others its name; every rank opens it (without creating it: on hosts that do not share
// rank 0's file system the open fails, and the run says so instead of writing a file with
// holes) and writes its bytes at its offset, the sum of the sizes of the ranks before it;
// once every rank reports its writes done, rank 0 renames the temporaries onto the files,
// all or none (io::commit_all). A failure anywhere leaves no file changed and no
// temporary behind: rank 0 then throws std::system_error with the reason (which rank,
// which error), so the run reports it once, as the sequential command reports a file it
// cannot write, and the other ranks return false (rank 0 ends the run).
//
// Collective: every rank calls it, with the same paths in the same order. The ranks wait
// for each other asleep (par/mpi_collect.hpp).
#pragma once

#include <span>
#include <string>

namespace pdr::par {

// Writes file k as the concatenation of every rank's bytes[k], in rank order. True when
// written; false on the ranks other than 0 when not (above).
bool write_in_rank_order(std::span<const std::string> paths, std::span<const std::string> bytes);

}  // namespace pdr::par
