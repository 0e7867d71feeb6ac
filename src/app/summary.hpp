// Summary: what a command reports at its end, as ordered key/value pairs, printed either as
// "key: value" lines for people or as one JSON object (--json) for programs. Also the
// wall-clock phase timer and the peak-memory probe the summaries quote.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace pdr::app {

class Summary {
 public:
  template <class T>
  void set(const std::string& key, T&& value) {
    for (auto& kv : items_)
      if (kv.first == key) {
        kv.second = std::forward<T>(value);
        return;
      }
    items_.emplace_back(key, nlohmann::json(std::forward<T>(value)));
  }
  // The value under `key` (null if none).
  nlohmann::json get(const std::string& key) const {
    for (const auto& kv : items_)
      if (kv.first == key) return kv.second;
    return nullptr;
  }
  nlohmann::json to_json() const;
  std::string to_text() const;
  void print(bool json) const;  // to stdout

 private:
  std::vector<std::pair<std::string, nlohmann::json>> items_;
};

class PhaseTimer {
 public:
  PhaseTimer() : start_(Clock::now()), last_(start_) {}
  // Seconds since the previous lap (or construction); records it under `phase`.
  double lap(const std::string& phase);
  double total() const;
  const nlohmann::json& phases() const { return phases_; }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_, last_;
  nlohmann::json phases_ = nlohmann::json::object();
};

// Peak resident set size of this process, in bytes (getrusage).
std::uint64_t peak_rss_bytes();

}  // namespace pdr::app
