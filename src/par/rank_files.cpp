// Files written by every rank at once; see par/rank_files.hpp.
#include "par/rank_files.hpp"

#include <fcntl.h>
#include <mpi.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/atomic_file.hpp"
#include "par/mpi_collect.hpp"

namespace pdr::par {
namespace {

// Writes `part` from `offset` on, each piece by put(piece, at) (0, or an errno); 0, or
// the errno of the first failure (the pieces after it are made and dropped).
using PutAt = std::function<int(std::string_view, std::uint64_t)>;
int write_part(const PutAt& put, const StreamedPart& part, std::uint64_t offset) {
  int err = 0;
  std::uint64_t done = 0;
  part.fill([&](std::string_view piece) {
    if (done + piece.size() > part.size)  // before it reaches the next rank's bytes
      throw std::logic_error("write_in_rank_order: a part longer than its announced " +
                             std::to_string(part.size) + " bytes");
    if (err == 0) err = put(piece, offset + done);
    done += piece.size();
  });
  if (done != part.size)
    throw std::logic_error("write_in_rank_order: a part of " + std::to_string(done) +
                           " bytes announced as " + std::to_string(part.size));
  return err;
}

// Writes `part` into the existing file `path` from `offset` on; 0, or the errno of the
// failure.
int write_at(const std::string& path, const StreamedPart& part, std::uint64_t offset) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);  // never creates it
  if (fd < 0) return errno;
  int err = 0;
  try {
    err = write_part([fd](std::string_view piece, std::uint64_t at) { return io::write_all_at(fd, piece, at); },
                     part, offset);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0 && err == 0) err = errno;
  return err;
}

}  // namespace

bool write_in_rank_order(std::span<const std::string> paths, std::span<const std::string> bytes) {
  std::vector<StreamedPart> parts;
  for (const std::string& b : bytes)
    parts.push_back({b.size(), [&b](const std::function<void(std::string_view)>& out) { out(b); }});
  return write_in_rank_order(paths, std::span<const StreamedPart>(parts));
}

bool write_in_rank_order(std::span<const std::string> paths, std::span<const StreamedPart> parts) {
  if (paths.size() != parts.size())
    throw std::logic_error("write_in_rank_order: a part for every file");
  int rank = 0;
  if (MPI_Comm_rank(MPI_COMM_WORLD, &rank) != MPI_SUCCESS)
    throw std::runtime_error("mpi: MPI_Comm_rank failed");
  // Rank 0's temporaries, removed unless committed.
  std::vector<std::unique_ptr<io::AtomicFile>> files;
  std::string names;  // rank 0: the temporaries' names
  std::optional<std::system_error> not_created;
  if (rank == 0) {
    try {
      for (const std::string& p : paths) {
        files.push_back(std::make_unique<io::AtomicFile>(p));
        names += files.back()->temp_path();
        names.push_back('\0');
      }
    } catch (const std::system_error& e) {
      not_created = e;
      files.clear();
    }
  }
  if (broadcast_from_root(not_created ? 1 : 0) != 0) {
    if (rank == 0) throw RankFilesError(*not_created);
    return false;
  }
  names = broadcast_from_root(names);
  // Where this rank's bytes go: after the ranks' before it, file by file.
  std::vector<std::uint64_t> sizes;
  for (const StreamedPart& part : parts) sizes.push_back(part.size);
  const std::vector<std::uint64_t> all = all_values(sizes);
  int err = 0;
  std::size_t at = 0, failed_file = 0;
  for (std::size_t k = 0; k < paths.size() && err == 0; ++k) {
    const std::size_t end = names.find('\0', at);
    const std::string temp = names.substr(at, end - at);
    at = end + 1;
    std::uint64_t offset = 0;
    for (int r = 0; r < rank; ++r) offset += all[static_cast<std::size_t>(r) * paths.size() + k];
    failed_file = k;
    if (rank != 0) {
      err = write_at(temp, parts[k], offset);
      continue;
    }
    // Rank 0 through its own descriptor (the temporary may be read-only by mode).
    io::AtomicFile& file = *files[k];
    err = write_part(
        [&file](std::string_view piece, std::uint64_t at) {
          try {
            file.write_at(piece, at);
            return 0;
          } catch (const std::system_error& e) {
            return e.code().value();
          }
        },
        parts[k], offset);
  }
  // The last rank that failed, then its errno (every rank learns both).
  const int failed = max_over_ranks({err != 0 ? rank + 1 : 0, 0})[0];
  if (failed == 0) {
    if (rank == 0) {
      std::vector<io::AtomicFile*> raw;
      for (auto& f : files) raw.push_back(f.get());
      io::commit_all(raw);
    }
    return true;
  }
  const int failed_errno = max_over_ranks({rank + 1 == failed ? err : 0, 0})[0];
  if (rank != 0) return false;
  const int who = failed - 1;
  throw RankFilesError(std::error_code(failed_errno, std::generic_category()),
                       who == 0 ? "cannot write '" + paths[failed_file] + "'"
                                : "rank " + std::to_string(who) +
                                      " cannot write its part of the output files");
}

}  // namespace pdr::par
