// The progress line (see progress.hpp).
#include "app/progress.hpp"

#include <unistd.h>

#include <cstdlib>

namespace pdr::app {

Progress::Progress(bool enabled, std::FILE* out)
    : enabled_(enabled), out_(out), start_(Clock::now()), phase_start_(start_) {
  // PDR_PROGRESS_MS: the redraw period (tests shorten it to see short phases).
  if (const char* ms = std::getenv("PDR_PROGRESS_MS"); ms && std::atoi(ms) > 0) period_ms_ = std::atoi(ms);
  if (enabled_) ticker_ = std::jthread([this](std::stop_token stop) { tick(stop); });
}

bool Progress::wanted(bool json) { return !json && isatty(STDERR_FILENO) == 1; }

void Progress::phase(std::string_view name) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  phase_start_ = Clock::now();
  phase_ = name;
  text_ = phase_ + " ...";
  dirty_ = true;
}

void Progress::count(std::size_t n, std::string_view unit) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  const double s = std::chrono::duration<double>(Clock::now() - phase_start_).count();
  char rate[48] = "";
  if (s > 0) std::snprintf(rate, sizeof rate, ", %.0f/s", static_cast<double>(n) / s);
  text_ = phase_ + ": " + std::to_string(n) + " " + std::string(unit) + rate;
  dirty_ = true;
}

void Progress::tick(std::stop_token stop) {
  std::unique_lock lock(mutex_);
  while (!stop.stop_requested()) {
    if (dirty_) {
      const double s = std::chrono::duration<double>(Clock::now() - start_).count();
      // \r, then "erase to end of line" (ECMA-48 EL): the line is redrawn in place.
      std::fprintf(out_, "\r\033[K[pdr %.1f s] %s", s, text_.c_str());
      std::fflush(out_);
      dirty_ = false;
      drawn_ = true;
    }
    wake_.wait_for(lock, stop, std::chrono::milliseconds(period_ms_), [] { return false; });
  }
}

void Progress::finish() {
  if (!enabled_) return;
  ticker_.request_stop();
  if (ticker_.joinable()) ticker_.join();
  if (drawn_) {
    std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
  }
  enabled_ = false;
}

}  // namespace pdr::app
