// A workload for the transport and termination tests: a chain reaction of tokens. Handling
// a token with ttl > 0 makes 0..2 children (a hash of its id says how many and where they
// go), so work spreads over the ranks at random, ranks fall idle and wake up again, and
// messages are in flight while others look idle: what termination detection must see
// through. The total number of tokens handled is known in advance (expected_tokens), so
// a run that stops early or loses a token is caught.
#pragma once

#include <cstdint>
#include <cstring>
#include <deque>
#include <stdexcept>
#include <vector>

#include "par/termination.hpp"
#include "par/transport.hpp"

namespace pdr::par::test {

inline std::uint64_t mix(std::uint64_t x) {  // SplitMix64's finaliser
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

struct Token {
  std::uint64_t id = 0;
  std::uint32_t ttl = 0;
};

inline int children(const Token& t) { return t.ttl == 0 ? 0 : static_cast<int>(mix(t.id) % 3); }
inline Token child(const Token& t, int k) { return {mix(t.id * 4 + static_cast<std::uint64_t>(k) + 1), t.ttl - 1}; }
inline int home(const Token& t, int ranks) { return static_cast<int>(mix(t.id ^ 0xA5A5) % static_cast<std::uint64_t>(ranks)); }

inline std::uint64_t expected_tokens(const Token& t) {
  std::uint64_t n = 1;
  for (int k = 0; k < children(t); ++k) n += expected_tokens(child(t, k));
  return n;
}

// The tokens rank r starts with.
inline std::vector<Token> initial_tokens(int rank, int per_rank, std::uint32_t ttl) {
  std::vector<Token> v;
  for (int i = 0; i < per_rank; ++i)
    v.push_back({mix(static_cast<std::uint64_t>(rank) * 1000003u + static_cast<std::uint64_t>(i)), ttl});
  return v;
}

inline std::uint64_t expected_total(int ranks, int per_rank, std::uint32_t ttl) {
  std::uint64_t n = 0;
  for (int r = 0; r < ranks; ++r)
    for (const Token& t : initial_tokens(r, per_rank, ttl)) n += expected_tokens(t);
  return n;
}

// One rank's event loop, one iteration per step().
class ChainRank {
 public:
  // `pad`: bytes appended to every message, a pattern of the token's id that the
  // receiver checks (large messages take MPI's rendezvous path).
  ChainRank(Transport& t, int per_rank, std::uint32_t ttl, std::size_t pad = 0)
      : t_(t), td_(t), pad_(pad) {
    for (const Token& k : initial_tokens(t.rank(), per_rank, ttl)) work_.push_back(k);
  }
  // One iteration; true once the run has terminated.
  bool step() {
    bool worked = t_.poll([&](int, std::span<const std::byte> m) { receive(m); }, 8) > 0;
    if (!work_.empty()) {
      const Token k = work_.front();
      work_.pop_front();
      ++handled_;
      for (int i = 0; i < children(k); ++i) {
        const Token c = child(k, i);
        const int to = home(c, t_.size());
        if (to == t_.rank()) {
          work_.push_back(c);
        } else {
          Bytes b(sizeof c + pad_);
          std::memcpy(b.data(), &c, sizeof c);
          for (std::size_t i = 0; i < pad_; ++i) b[sizeof c + i] = pattern(c, i);
          t_.send(to, std::move(b));
        }
      }
      worked = true;
    }
    if (worked) td_.activity();
    return td_.step(work_.empty());
  }
  std::uint64_t handled() const { return handled_; }
  std::uint64_t rounds() const { return td_.rounds(); }
  bool idle() const { return work_.empty(); }

 private:
  static std::byte pattern(const Token& k, std::size_t i) {
    return static_cast<std::byte>((k.id >> (i % 8)) + i);
  }
  void receive(std::span<const std::byte> m) {
    Token k;
    if (m.size() != sizeof k + pad_) throw std::runtime_error("chain: a message of the wrong size");
    std::memcpy(&k, m.data(), sizeof k);
    for (std::size_t i = 0; i < pad_; ++i)
      if (m[sizeof k + i] != pattern(k, i)) throw std::runtime_error("chain: a corrupted message");
    work_.push_back(k);
  }
  Transport& t_;
  TerminationDetector td_;
  std::size_t pad_ = 0;
  std::deque<Token> work_;
  std::uint64_t handled_ = 0;
};

}  // namespace pdr::par::test
