// SimNetwork: P virtual ranks in one process, for tests (docs/parallel.md, "testing the
// protocol"). Each rank gets a Transport endpoint; a message sent is held in flight on its
// (sender, receiver) channel until the network delivers it, one at a time, choosing among
// the channels that hold one with a seeded random draw, so a seed names one interleaving
// and replays it exactly. Within a channel the order is FIFO, as MPI's.
// Reductions complete once every rank has contributed to the round; ranks then read the
// result whenever they next ask.
// A test may hold a channel (hold()): nothing on it is delivered until release(), which is
// how a "last message still in flight while everyone looks idle" case is staged.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "par/transport.hpp"

namespace pdr::par {

class SimNetwork {
 public:
  SimNetwork(int ranks, std::uint64_t seed);
  ~SimNetwork();
  SimNetwork(const SimNetwork&) = delete;
  SimNetwork& operator=(const SimNetwork&) = delete;

  int size() const { return ranks_; }
  Transport& endpoint(int rank);

  // Delivers one in-flight message from a channel that is not held (a seeded choice);
  // false when there is none.
  bool deliver_one();
  std::size_t in_flight() const;  // held channels and delivered, unpolled messages included

  void hold(int from, int to) { channel(from, to).held = true; }
  void release(int from, int to) { channel(from, to).held = false; }

  std::mt19937_64& rng() { return rng_; }

 private:
  class Endpoint;
  struct Channel {
    std::deque<Bytes> messages;
    bool held = false;
  };
  struct Round {
    Reduction sum{};
    int contributed = 0;
  };

  Channel& channel(int from, int to) { return channels_[static_cast<std::size_t>(from * ranks_ + to)]; }
  void post(int from, int to, Bytes message) { channel(from, to).messages.push_back(std::move(message)); }
  void contribute(std::size_t round, const Reduction& mine);
  std::optional<Reduction> result(std::size_t round) const;

  int ranks_;
  std::mt19937_64 rng_;
  std::vector<Channel> channels_;
  std::vector<std::deque<std::pair<int, Bytes>>> inbox_;  // delivered, not yet polled
  std::vector<Round> rounds_;
  std::vector<std::unique_ptr<Endpoint>> endpoints_;
};

}  // namespace pdr::par
