// SimNetwork: the in-process simulator of par/sim_network.hpp.
#include "par/sim_network.hpp"

#include <stdexcept>

namespace pdr::par {

class SimNetwork::Endpoint final : public Transport {
 public:
  Endpoint(SimNetwork& net, int rank) : net_(net), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return net_.ranks_; }

  void start_reduction(const Reduction& mine) override {
    if (open_) throw std::logic_error("sim: a reduction round is already open on this rank");
    net_.contribute(next_round_, mine);
    open_ = true;
  }
  std::optional<Reduction> reduction_done() override {
    if (!open_) return std::nullopt;
    auto r = net_.result(next_round_);
    if (r) {
      open_ = false;
      ++next_round_;
    }
    return r;
  }

 private:
  void do_send(int to, Bytes message) override {
    if (to < 0 || to >= net_.ranks_ || to == rank_)
      throw std::logic_error("sim: a message to rank " + std::to_string(to) + " from rank " +
                             std::to_string(rank_));
    net_.post(rank_, to, std::move(message));
  }
  std::size_t do_poll(const Deliver& deliver, std::size_t max) override {
    auto& box = net_.inbox_[static_cast<std::size_t>(rank_)];
    std::size_t n = 0;
    while (n < max && !box.empty()) {
      auto [from, message] = std::move(box.front());
      box.pop_front();
      deliver(from, message);
      ++n;
    }
    return n;
  }

  SimNetwork& net_;
  int rank_;
  std::size_t next_round_ = 0;
  bool open_ = false;
};

SimNetwork::SimNetwork(int ranks, std::uint64_t seed)
    : ranks_(ranks),
      rng_(seed),
      channels_(static_cast<std::size_t>(ranks) * static_cast<std::size_t>(ranks)),
      inbox_(static_cast<std::size_t>(ranks)) {
  if (ranks < 1) throw std::invalid_argument("sim: at least one rank");
  for (int r = 0; r < ranks; ++r) endpoints_.push_back(std::make_unique<Endpoint>(*this, r));
}

SimNetwork::~SimNetwork() = default;

Transport& SimNetwork::endpoint(int rank) { return *endpoints_.at(static_cast<std::size_t>(rank)); }

bool SimNetwork::deliver_one() {
  std::vector<std::size_t> ready;
  for (std::size_t c = 0; c < channels_.size(); ++c)
    if (!channels_[c].held && !channels_[c].messages.empty()) ready.push_back(c);
  if (ready.empty()) return false;
  const std::size_t c = ready[std::uniform_int_distribution<std::size_t>(0, ready.size() - 1)(rng_)];
  Channel& ch = channels_[c];
  const int from = static_cast<int>(c / static_cast<std::size_t>(ranks_));
  const int to = static_cast<int>(c % static_cast<std::size_t>(ranks_));
  inbox_[static_cast<std::size_t>(to)].emplace_back(from, std::move(ch.messages.front()));
  ch.messages.pop_front();
  return true;
}

std::size_t SimNetwork::in_flight() const {
  std::size_t n = 0;
  for (const Channel& ch : channels_) n += ch.messages.size();
  for (const auto& box : inbox_) n += box.size();  // delivered, not yet polled
  return n;
}

void SimNetwork::contribute(std::size_t round, const Reduction& mine) {
  if (rounds_.size() <= round) rounds_.resize(round + 1);
  Round& r = rounds_[round];
  for (std::size_t i = 0; i < mine.size(); ++i) r.sum[i] += mine[i];
  ++r.contributed;
}

std::optional<Reduction> SimNetwork::result(std::size_t round) const {
  if (round >= rounds_.size() || rounds_[round].contributed < ranks_) return std::nullopt;
  return rounds_[round].sum;
}

}  // namespace pdr::par
