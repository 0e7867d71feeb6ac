// AtomicFile; see atomic_file.hpp.
#include "io/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <sys/stat.h>
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

// A descriptor of the file that a rename onto `path` would replace, when freeing it could
// cost anything: a regular file with no other link (a link elsewhere keeps it alive
// anyway). -1 otherwise. Never blocks (O_NONBLOCK: a FIFO there) and never follows a
// symbolic link (the rename replaces the link itself).
int hold_replaced(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return -1;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1 && st.st_size > 0)
    return fd;
  ::close(fd);
  return -1;
}

// Closes the held files on a detached thread (there the kernel frees them), or here when
// no thread can be started. The thread makes no call but close(2): it may still run when
// the process exits, which then frees what is left.
void release(std::vector<int> held) {
  if (held.empty()) return;
  try {
    std::thread([held] {
      for (const int fd : held) ::close(fd);
    }).detach();
  } catch (const std::system_error&) {
    for (const int fd : held) ::close(fd);
  }
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

void AtomicFile::commit() {
  std::vector<int> held;
  commit(held);
  release(std::move(held));
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
  if (old >= 0) held.push_back(old);
}

void commit_all(std::span<AtomicFile* const> files) {
  for (AtomicFile* f : files) f->close();
  std::vector<int> held;
  try {
    for (AtomicFile* f : files) f->commit(held);
  } catch (...) {
    release(std::move(held));
    throw;
  }
  release(std::move(held));
}

}  // namespace pdr::io
