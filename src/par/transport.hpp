// Transport: how the ranks of a parallel run exchange messages (paper §4: "one-sided,
// asynchronous remote procedure calls"; each rank's data is changed by that rank alone).
//
// Two implementations: MpiTransport (par/mpi_transport.hpp, Open MPI) and the in-process
// simulator (par/sim_network.hpp), which runs P virtual ranks in one process under a seeded
// scheduler, so every interleaving the protocol can meet is reproducible in a test.
//
// What every implementation guarantees, and the protocol may rely on:
//   - FIFO per pair: two messages from rank a to rank b are delivered in the order sent
//     (MPI's non-overtaking rule); nothing is ordered across pairs;
//   - reliable: every message sent is delivered exactly once, unless the run is torn down;
//   - reductions: rounds of an element-wise sum of three counters over all ranks, on a
//     channel of their own (never mixed with messages); every rank starts the same rounds
//     in the same order, and a round's result is the same on every rank;
//   - counting: sent() and received() count messages (not bytes), which termination
//     detection (par/termination.hpp) compares.
// Nothing here blocks: send() queues, poll() takes what has arrived.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace pdr::par {

using Bytes = std::vector<std::byte>;
using Reduction = std::array<std::uint64_t, 3>;  // summed element-wise over the ranks
using Deliver = std::function<void(int from, std::span<const std::byte> message)>;

class Transport {
 public:
  virtual ~Transport() = default;

  virtual int rank() const = 0;
  virtual int size() const = 0;

  // Sends `message` to rank `to` (another rank). Precondition: 0 <= to < size(), to != rank().
  void send(int to, Bytes message) {
    ++sent_;
    bytes_sent_ += message.size();
    do_send(to, std::move(message));
  }
  // Hands at most `max` arrived messages, oldest first per sender, to `deliver`; returns
  // how many. A message's bytes are valid during the call only.
  std::size_t poll(const Deliver& deliver, std::size_t max) {
    const std::size_t n = do_poll(deliver, max);
    received_ += n;
    return n;
  }
  // Starts the next reduction round with this rank's contribution. Precondition: the
  // previous round (if any) is done on this rank.
  virtual void start_reduction(const Reduction& mine) = 0;
  // The result of the round started last, once every rank has contributed (nullopt until
  // then; also nullopt when no round is open).
  virtual std::optional<Reduction> reduction_done() = 0;

  std::uint64_t sent() const { return sent_; }
  std::uint64_t received() const { return received_; }
  std::uint64_t bytes_sent() const { return bytes_sent_; }

 private:
  virtual void do_send(int to, Bytes message) = 0;
  virtual std::size_t do_poll(const Deliver& deliver, std::size_t max) = 0;

  std::uint64_t sent_ = 0, received_ = 0, bytes_sent_ = 0;
};

}  // namespace pdr::par
