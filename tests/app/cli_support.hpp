// Helpers of the end-to-end CLI tests: run the built `pdr` binary (PDR_BINARY) through a
// shell and capture its exit code and output; a fixture with a fresh temporary directory
// per test.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace pdr::cli_test {

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string out;  // stdout (and stderr, unless asked otherwise)
};

// Runs the shell command `cmd`, capturing what it prints on stdout.
inline Outcome capture(const std::string& cmd) {
  Outcome r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), p)) r.out += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// with_stderr: capture stderr too (false: stdout only, e.g. to parse --json).
inline Outcome run(const std::string& args, bool with_stderr = true) {
  return capture(std::string(PDR_BINARY) + " " + args + (with_stderr ? " 2>&1" : ""));
}

// Runs a shell command (not pdr) in `dir`, capturing stdout and stderr.
inline Outcome shell(const std::string& dir, const std::string& command) {
  return capture("cd '" + dir + "' && " + command + " 2>&1");
}

inline bool on_path(const std::string& tool) {
  return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pdr-cli-" + std::string(::testing::UnitTest::GetInstance()
                                         ->current_test_info()->name()) + "-" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
  }
  // A .node file of n seeded random points in the unit cube plus the cube's corners.
  void write_points(const std::string& name, int n) const {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    std::ostringstream s;
    s.precision(17);
    s << n + 8 << " 3 0 0\n";
    int id = 1;
    for (int c = 0; c < 8; ++c) s << id++ << ' ' << (c & 1) << ' ' << (c >> 1 & 1) << ' ' << (c >> 2) << '\n';
    for (int i = 0; i < n; ++i) s << id++ << ' ' << u(rng) << ' ' << u(rng) << ' ' << u(rng) << '\n';
    write(name, s.str());
  }
  // The entries of the test directory whose names start with `stem`.
  std::vector<std::string> left_behind(const std::string& stem) const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename().string().rfind(stem, 0) == 0) out.push_back(e.path().string());
    return out;
  }
  fs::path dir_;
};

}  // namespace pdr::cli_test
