// AtomicFile; see atomic_file.hpp.
#include "io/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <system_error>
#include <thread>
#include <unistd.h>
#include <vector>

namespace pdr::io {

namespace {

[[noreturn]] void throw_errno(int err, const std::string& what) {
  throw std::system_error(err, std::generic_category(), what);
}

std::string temp_name_for(const std::string& path, unsigned attempt) {
  static std::atomic<unsigned> counter{0};
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return dir + "." + name + ".tmp-" + std::to_string(::getpid()) + "-" +
         std::to_string(counter.fetch_add(1) + attempt);
}

// Holding a file smaller than this saves less than the thread costs.
constexpr std::uint64_t kHeldBytes = std::uint64_t{1} << 20;

// A descriptor of the file that a rename onto `path` would replace, when holding it is
// worth a thread and harmless (replaced_file_is_held). O_PATH: the file is not opened for
// reading (no device opened, no FIFO peer woken, no lease broken, no read permission
// needed); O_NOFOLLOW: a symbolic link is replaced itself. -1 otherwise.
int hold_replaced(const std::string& path) {
  const int fd = ::open(path.c_str(), O_PATH | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return -1;
  struct stat st {};
  struct statfs fs {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1 &&
      static_cast<std::uint64_t>(st.st_blocks) * 512 >= kHeldBytes && ::fstatfs(fd, &fs) == 0 &&
      local_file_system(static_cast<std::uint64_t>(fs.f_type)))
    return fd;
  ::close(fd);
  return -1;
}

// Closes the held files on a detached thread (there the kernel frees them), or here when
// no thread can be started. The thread closes descriptors and ends; the process's exit
// waits for a close in progress, and frees what is left.
void release(std::vector<int>& held) noexcept {
  if (held.empty()) return;
  try {
    std::thread([fds = held] {
      for (const int fd : fds) ::close(fd);
    }).detach();
  } catch (...) {  // no thread, or no memory for its copy
    for (const int fd : held) ::close(fd);
  }
  held.clear();
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty() || path_.back() == '/')
    throw std::system_error(std::make_error_code(std::errc::invalid_argument),
                            "cannot write '" + path_ + "': not a file name");
  for (unsigned attempt = 0; attempt < 100; ++attempt) {
    temp_ = temp_name_for(path_, attempt);
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) return;
    if (errno != EEXIST) throw_errno(errno, "cannot create a temporary file for '" + path_ + "'");
  }
  throw_errno(EEXIST, "cannot create a temporary file for '" + path_ + "'");
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlink(temp_.c_str());
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0)
    throw std::system_error(std::make_error_code(std::errc::bad_file_descriptor),
                            "write to closed file for '" + path_ + "'");
  while (!bytes.empty()) {
    const ::ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_errno(errno, "cannot write '" + path_ + "'");
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

int write_all_at(int fd, std::string_view bytes, std::uint64_t offset) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ::ssize_t n = ::pwrite(fd, bytes.data() + done, bytes.size() - done,
                                 static_cast<::off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

void AtomicFile::write_at(std::string_view bytes, std::uint64_t offset) {
  if (fd_ < 0)
    throw std::system_error(std::make_error_code(std::errc::bad_file_descriptor),
                            "write to closed file for '" + path_ + "'");
  if (const int err = write_all_at(fd_, bytes, offset); err != 0)
    throw_errno(err, "cannot write '" + path_ + "'");
}

void AtomicFile::close() {
  if (fd_ < 0) return;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw_errno(errno, "cannot finish writing '" + path_ + "'");
}

bool local_file_system(std::uint64_t magic) {
  switch (magic) {
    case EXT4_SUPER_MAGIC:  // ext2, ext3 and ext4
    case XFS_SUPER_MAGIC:
    case BTRFS_SUPER_MAGIC:
    case TMPFS_MAGIC:
    case OVERLAYFS_SUPER_MAGIC:  // containers: the upper layer is one of the above
      return true;
    default:
      return false;
  }
}

bool replaced_file_is_held(const std::string& path) {
  const int fd = hold_replaced(path);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

void AtomicFile::commit() {
  std::vector<int> held;
  held.reserve(1);
  try {
    commit(held);
  } catch (...) {
    release(held);
    throw;
  }
  release(held);
}

void AtomicFile::commit(std::vector<int>& held) {
  close();
  if (committed_) return;
  const int old = hold_replaced(path_);
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    if (old >= 0) ::close(old);
    throw_errno(err, "cannot rename the finished temporary file onto '" + path_ + "'");
  }
  committed_ = true;
  if (old >= 0) held.push_back(old);  // no allocation: the caller reserved room
}

void commit_all(std::span<AtomicFile* const> files) {
  for (AtomicFile* f : files) f->close();
  std::vector<int> held;
  held.reserve(files.size());
  try {
    for (AtomicFile* f : files) f->commit(held);
  } catch (...) {
    release(held);
    throw;
  }
  release(held);
}

}  // namespace pdr::io
