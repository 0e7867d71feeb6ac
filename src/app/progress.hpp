// The progress line of long runs: on a terminal, `pdr mesh` and `pdr check` show one line on
// stderr (elapsed seconds, phase, count so far and rate), redrawn in place by a ticker
// thread at most four times a second (environment PDR_PROGRESS_MS: another period, for
// tests), and erased when done, so the summary that follows is
// unchanged. Off when stderr is not a terminal, with --json (programs read those runs), and
// under mpirun.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace pdr::app {

class Progress {
 public:
  // `enabled` false: every call does nothing and no thread starts. `out`: the terminal.
  explicit Progress(bool enabled, std::FILE* out = stderr);
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // True when stderr is a terminal and the command prints no JSON.
  static bool wanted(bool json);

  bool enabled() const { return enabled_; }
  // A new phase ("refine", "check: topology", ...).
  void phase(std::string_view name);
  // `n` `unit` so far in this phase; the line adds the rate per second.
  void count(std::size_t n, std::string_view unit);
  // Stops the ticker and erases the line; later calls do nothing.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void tick(std::stop_token stop);

  bool enabled_;
  std::FILE* out_;
  const Clock::time_point start_;
  int period_ms_ = 250;  // PDR_PROGRESS_MS overrides it (for tests)
  std::mutex mutex_;  // guards what follows
  std::condition_variable_any wake_;
  Clock::time_point phase_start_;
  std::string phase_, text_;
  bool dirty_ = false, drawn_ = false;
  std::jthread ticker_;  // last: started once the fields above exist
};

}  // namespace pdr::app
