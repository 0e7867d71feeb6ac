// Deterministic parallel loops and violation collectors for the per-element checks.
//
// parallel_blocks hands out blocks of [0, n) through an atomic counter. A Collector per
// worker keeps the `max` smallest keys (element ids) of its own stream; merging the workers'
// lists and keeping the `max` smallest gives exactly the first `max` violations of the
// whole loop, whatever the thread count or timing: reports are reproducible (docs/design.md §12).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "check/check.hpp"

namespace pdr::check {

// f(worker, begin, end) for consecutive blocks; workers in [0, threads).
template <class F>
void parallel_blocks(std::size_t n, unsigned threads, std::size_t block, F&& f) {
  threads = std::max(1u, threads);
  block = std::max<std::size_t>(1, block);
  if (threads == 1 || n <= block) {
    for (std::size_t b = 0; b < n; b += block) f(0u, b, std::min(n, b + block));
    return;
  }
  std::atomic<std::size_t> next{0};
  auto work = [&](unsigned w) {
    for (;;) {
      const std::size_t b = next.fetch_add(block);
      if (b >= n) return;
      f(w, b, std::min(n, b + block));
    }
  };
  std::vector<std::jthread> pool;
  for (unsigned w = 1; w < threads; ++w) pool.emplace_back(work, w);
  work(0);
}

// Violations of one check seen by one worker; keeps the `max` smallest keys (element ids)
// whatever order they arrive in.
struct Collector {
  std::size_t max = 0;
  std::uint64_t checked = 0, violations = 0;
  std::map<std::string, std::uint64_t> counts;
  std::vector<std::pair<std::uint64_t, Finding>> kept;  // (element id, finding)
  std::uint64_t threshold = std::numeric_limits<std::uint64_t>::max();

  explicit Collector(std::size_t max_reported = 0) : max(max_reported) {}
  // Whether a violation with this key would be kept (build its Finding only then).
  bool wants(std::uint64_t key) const { return max > 0 && (kept.size() < max || key < threshold); }
  void violation(std::uint64_t key, Finding f) {
    ++violations;
    if (!wants(key)) return;
    kept.emplace_back(key, std::move(f));
    if (kept.size() >= 2 * max) prune();
  }
  void violation(std::uint64_t) { ++violations; }
  void prune() {
    std::stable_sort(kept.begin(), kept.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    if (kept.size() > max) kept.resize(max);
    if (kept.size() == max && max > 0) threshold = kept.back().first;
  }
};

// Adds the workers' collectors into r (counts summed, findings: first max by id).
inline void merge_into(std::vector<Collector>& parts, CheckResult& r, std::size_t max) {
  std::vector<std::pair<std::uint64_t, Finding>> all;
  for (Collector& c : parts) {
    r.checked += c.checked;
    r.violations += c.violations;
    for (const auto& [k, v] : c.counts) r.counts[k] += v;
    for (auto& kf : c.kept) all.push_back(std::move(kf));
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < all.size() && r.findings.size() < max; ++i)
    r.findings.push_back(std::move(all[i].second));
}

}  // namespace pdr::check
