// AtomicFile: all-or-nothing output. A writer writes into a temporary file created next to
// the target (same directory, so rename(2) is atomic on POSIX file systems) and the target
// appears, whole, only on commit. If the writer throws, the destructor removes the
// temporary and the target is untouched (an older file of that name survives intact).
//
// Several files that belong together (TetGen .node/.ele/.face) are committed with
// commit_all: every temporary is written and closed first; only when all succeeded are
// they renamed, one after the other.
//
// Temporary names are "<dir>/.<name>.tmp-<pid>-<n>"; they are created with O_EXCL and mode
// 0666 (less the umask), so the final file has ordinary permissions.
//
// Replacing an older file: the kernel frees the old file's blocks and cached pages when
// its last link and its last descriptor are gone, which for a plain rename is inside
// rename(2) (measured: 0.06 s for a 180 MB .ele written a moment before, on top of the
// 0.08-0.11 s ext4 takes there to start writing back a file that replaces another). So a
// commit holds the file it replaces (an O_PATH descriptor) across the rename and closes
// it on a thread of its own: the freeing then runs beside whatever the process does next
// (the check, the summary), and what is left of it when the process exits, in the exit.
// Only a regular file of at least 1 MiB with no other link, on a local file system
// (ext2/3/4, xfs, btrfs, tmpfs, overlayfs) is held: a network or FUSE file system renames
// a target that is still open out of the way first (NFS's .nfsXXXX files), which would
// break the rename's atomicity. The rename itself is unchanged; a reader that opened the
// old file keeps reading it, as before.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pdr::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_; }

  // Appends bytes to the temporary file.
  void write(std::string_view bytes);
  // Writes bytes into the temporary file from `offset` on (other processes may write
  // other ranges of it: par/rank_files.hpp).
  void write_at(std::string_view bytes, std::uint64_t offset);
  // Closes the temporary file, reporting any deferred write error. Idempotent.
  void close();
  // close(), then renames the temporary onto the target.
  void commit();

 private:
  friend void commit_all(std::span<AtomicFile* const> files);
  // commit(), the replaced file's descriptor (if held) added to `held` for the caller to
  // release.
  void commit(std::vector<int>& held);
  std::string path_;
  std::string temp_;
  int fd_ = -1;
  bool committed_ = false;
};

// Writes all of `bytes` to descriptor fd from `offset` on (pwrite, again after a partial
// write or EINTR); 0, or the errno of the failure (EIO when nothing more can be written).
int write_all_at(int fd, std::string_view bytes, std::uint64_t offset);

// Closes every file, then renames every file; a failure before the renames leaves no target
// changed (the destructors remove the temporaries).
void commit_all(std::span<AtomicFile* const> files);

// Whether a file system (statfs's f_type) is one whose rename onto a file still open
// behaves as onto a closed one (above).
bool local_file_system(std::uint64_t magic);
// Whether a commit onto `path` would hold the file there (above). For tests.
bool replaced_file_is_held(const std::string& path);

}  // namespace pdr::io
