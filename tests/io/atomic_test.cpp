// Atomic output: a write that fails (by an exception in the writer, a bad MeshData, a file
// size limit hit midway, a missing directory) leaves no target and no temporary; an older
// file of the same name survives a failed write; multi-file sets appear all or none.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <thread>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>
#include <filesystem>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/mesh_io.hpp"
#include "io/tasks.hpp"
#include "io/tetgen.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

using Names = std::vector<std::string>;

TEST(Atomic, CommitLeavesOnlyTheTarget) {
  ScratchDir dir;
  {
    AtomicFile f(dir / "out.txt");
    f.write("hello ");
    f.write("world");
    EXPECT_EQ(dir.entries().size(), 1u);  // the temporary
    EXPECT_NE(dir.entries()[0], "out.txt");
    f.commit();
  }
  EXPECT_EQ(dir.entries(), Names{"out.txt"});
  EXPECT_EQ(read_text(dir / "out.txt"), "hello world");
}

TEST(Atomic, ThrowMidwayLeavesNothing) {
  ScratchDir dir;
  try {
    AtomicFile f(dir / "out.txt");
    f.write("partial");
    throw std::runtime_error("writer failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Atomic, FailedWriteKeepsTheOldFile) {
  ScratchDir dir;
  write_text(dir / "out.txt", "old");
  try {
    AtomicFile f(dir / "out.txt");
    f.write("new but unfinished");
    throw std::runtime_error("writer failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_text(dir / "out.txt"), "old");
  EXPECT_EQ(dir.entries(), Names{"out.txt"});
  {
    AtomicFile f(dir / "out.txt");
    f.write("new");
    f.commit();
  }
  EXPECT_EQ(read_text(dir / "out.txt"), "new");
}

TEST(Atomic, GroupCommitsAllOrNone) {
  ScratchDir dir;
  try {
    AtomicFile a(dir / "x.node"), b(dir / "x.ele"), c(dir / "x.face");
    a.write("1");
    b.write("2");
    throw std::runtime_error("third file failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(dir.entries().empty());
  {
    AtomicFile a(dir / "x.node"), b(dir / "x.ele");
    a.write("1");
    b.write("2");
    AtomicFile* both[] = {&a, &b};
    commit_all(both);
  }
  EXPECT_EQ(dir.entries(), (Names{"x.ele", "x.node"}));
}

// The descriptors open in this process on files under `dir` (a replaced file shows as
// "<path> (deleted)"), from /proc; -1 where there is no /proc.
int descriptors_under(const std::string& dir) {
  std::error_code ec;
  int n = 0;
  for (auto it = std::filesystem::directory_iterator("/proc/self/fd", ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    std::error_code link_ec;
    const std::string target = std::filesystem::read_symlink(it->path(), link_ec).string();
    if (!link_ec && target.rfind(dir + "/", 0) == 0) ++n;
  }
  return ec ? -1 : n;
}

bool on_local_file_system(const std::string& dir) {
  struct statfs fs {};
  return ::statfs(dir.c_str(), &fs) == 0 && local_file_system(static_cast<std::uint64_t>(fs.f_type));
}

// A commit over an older large file holds it across the rename and closes it on a thread
// of its own: the target is replaced as before, and no descriptor is left open.
TEST(Atomic, ReplacedFileIsReleased) {
  ScratchDir dir;
  const std::string big(2 << 20, 'a');
  write_text(dir / "x.node", big);
  write_text(dir / "x.ele", big);
  if (on_local_file_system(dir.str())) {
    EXPECT_TRUE(replaced_file_is_held(dir / "x.node"));
    EXPECT_TRUE(replaced_file_is_held(dir / "x.ele"));
  }
  {
    AtomicFile a(dir / "x.node"), b(dir / "x.ele");
    a.write("new node");
    b.write("new ele");
    AtomicFile* both[] = {&a, &b};
    commit_all(both);
  }
  write_text(dir / "y", big);
  {
    AtomicFile c(dir / "y");
    c.write("new y");
    c.commit();
  }
  EXPECT_EQ(read_text(dir / "x.node"), "new node");
  EXPECT_EQ(read_text(dir / "x.ele"), "new ele");
  EXPECT_EQ(read_text(dir / "y"), "new y");
  EXPECT_EQ(dir.entries(), (Names{"x.ele", "x.node", "y"}));
  if (descriptors_under(dir.str()) < 0) GTEST_SKIP() << "no /proc/self/fd";
  // The closing thread runs on its own: wait for it (a leak fails after 10 s).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (descriptors_under(dir.str()) > 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(descriptors_under(dir.str()), 0);
}

// Held only where holding is harmless and worth a thread: a lone regular file of at
// least 1 MiB on a local file system; not a small file, a file with another link, a
// symbolic link (replaced itself), a FIFO or a directory.
TEST(Atomic, OnlyALoneLargeLocalFileIsHeld) {
  ScratchDir dir;
  const std::string big(2 << 20, 'b');
  write_text(dir / "small", "small");
  write_text(dir / "shared", big);
  ASSERT_EQ(::link((dir / "shared").c_str(), (dir / "other").c_str()), 0);
  write_text(dir / "real", big);
  ASSERT_EQ(::symlink("real", (dir / "link").c_str()), 0);
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  std::filesystem::create_directory(dir / "sub");
  for (const char* name : {"small", "shared", "link", "fifo", "sub", "missing"})
    EXPECT_FALSE(replaced_file_is_held(dir / name)) << name;
  EXPECT_EQ(replaced_file_is_held(dir / "real"), on_local_file_system(dir.str()));
  EXPECT_TRUE(local_file_system(0xEF53));                 // ext4
  EXPECT_FALSE(local_file_system(0x6969));                // NFS
  EXPECT_FALSE(local_file_system(0x65735546));            // FUSE
}

// What is not a lone regular file is replaced without being held: a FIFO (opening it
// must not wait for a writer), a symbolic link (replaced itself; its target untouched),
// and a file with another link (which keeps the old contents).
TEST(Atomic, ReplacesFifoLinkAndHardLinkedFile) {
  ScratchDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  write_text(dir / "real", "real");
  ASSERT_EQ(::symlink("real", (dir / "link").c_str()), 0);
  write_text(dir / "shared", "shared");
  ASSERT_EQ(::link((dir / "shared").c_str(), (dir / "other").c_str()), 0);
  for (const char* name : {"fifo", "link", "shared"}) {
    AtomicFile f(dir / name);
    f.write(std::string("new ") + name);
    f.commit();
    struct stat st {};
    ASSERT_EQ(::lstat((dir / name).c_str(), &st), 0);
    EXPECT_TRUE(S_ISREG(st.st_mode)) << name;
    EXPECT_EQ(read_text(dir / name), std::string("new ") + name);
  }
  EXPECT_EQ(read_text(dir / "real"), "real");
  EXPECT_EQ(read_text(dir / "other"), "shared");
}

TEST(Atomic, InvalidMeshIsRejectedBeforeAnyFile) {
  ScratchDir dir;
  MeshData bad = cube_mesh();
  bad.tets[2][1] = 99;
  EXPECT_THROW(write_tetgen_mesh(bad, dir / "b"), std::invalid_argument);
  const MeshFormat all[] = {MeshFormat::TetGen, MeshFormat::Vtu, MeshFormat::Msh,
                            MeshFormat::Medit};
  EXPECT_THROW(write_mesh(bad, dir / "b", all), std::invalid_argument);
  MeshData short_markers = cube_mesh();
  short_markers.face_markers.pop_back();
  EXPECT_THROW(write_mesh(short_markers, dir / "c", all), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Atomic, MissingDirectoryFailsCleanly) {
  ScratchDir dir;
  EXPECT_THROW(write_mesh(cube_mesh(), dir / "no/such/dir/x",
                          std::vector<MeshFormat>{MeshFormat::Vtu}),
               std::system_error);
  EXPECT_TRUE(dir.entries().empty());
}

// Lowers the file size limit so that writes fail with EFBIG part way through a file.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &old_);
    rlimit lim = old_;
    lim.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &lim);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit old_{};
  void (*old_handler_)(int);
};

MeshData few_points_many_tets() {
  MeshData m = cube_mesh();
  m.tets.assign(200000, Tet{0, 1, 2, 6});
  m.tet_regions.clear();
  return m;
}

TEST(Atomic, WriterFailingMidwayLeavesNoFileAndNoTemp) {
  ScratchDir dir;
  const MeshData m = few_points_many_tets();
  for (MeshFormat f : {MeshFormat::TetGen, MeshFormat::Vtu, MeshFormat::Msh,
                       MeshFormat::Medit}) {
    SCOPED_TRACE(static_cast<int>(f));
    FileSizeLimit limit(64 * 1024);  // .node fits, the tets do not
    EXPECT_THROW(write_mesh(m, dir / "big", std::vector<MeshFormat>{f}), std::system_error);
    EXPECT_TRUE(dir.entries().empty());
  }
  // Every format at once (each on a thread of its own): all fail, nothing is left.
  {
    FileSizeLimit limit(64 * 1024);
    EXPECT_THROW(write_mesh(m, dir / "big",
                            std::vector<MeshFormat>{MeshFormat::TetGen, MeshFormat::Vtu,
                                                    MeshFormat::Msh, MeshFormat::Medit}),
                 std::system_error);
    EXPECT_TRUE(dir.entries().empty());
  }
  // Without the limit the same writes succeed.
  write_mesh(m, dir / "big", std::vector<MeshFormat>{MeshFormat::TetGen});
  EXPECT_EQ(dir.entries(), (Names{"big.ele", "big.face", "big.node"}));
}

// run_tasks: every task runs to its end, and the first failure in task order is rethrown
// after all of them, whichever failed first in time.
TEST(Atomic, RunTasksRunsEveryTaskAndRethrowsTheFirstInOrder) {
  std::atomic<int> ran{0};
  std::vector<std::function<void()>> tasks;
  for (int i = 0; i < 4; ++i)
    tasks.emplace_back([&ran, i] {
      if (i == 1) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      ++ran;
      if (i == 1) throw std::runtime_error("task 1");
      if (i == 3) throw std::runtime_error("task 3");
    });
  try {
    run_tasks(tasks);
    FAIL() << "nothing was rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 1");
  }
  EXPECT_EQ(ran.load(), 4);
  run_tasks({});
}

}  // namespace
}  // namespace pdr::io::test
