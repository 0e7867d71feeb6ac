// Summary printing, phase timing and the peak-memory probe (summary.hpp).
#include "app/summary.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <iostream>

namespace pdr::app {

nlohmann::json Summary::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : items_) j[k] = v;
  return j;
}

std::string Summary::to_text() const {
  std::string out;
  for (const auto& [k, v] : items_) {
    out += k;
    out += ": ";
    out += v.is_string() ? v.get<std::string>() : v.dump();
    out += '\n';
  }
  return out;
}

void Summary::print(bool json) const {
  if (json)
    std::cout << to_json().dump(2) << '\n';
  else
    std::cout << to_text();
  std::cout.flush();
}

double PhaseTimer::lap(const std::string& phase) {
  const auto now = Clock::now();
  const double s = std::chrono::duration<double>(now - last_).count();
  last_ = now;
  phases_[phase] = s;
  return s;
}

double PhaseTimer::total() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

std::uint64_t peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<std::uint64_t>(u.ru_maxrss) * 1024u;  // Linux reports KiB
}

}  // namespace pdr::app
