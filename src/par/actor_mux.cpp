// Several actors per rank over one rank transport: par/actor_mux.hpp.
#include "par/actor_mux.hpp"

#include <cstring>
#include <span>
#include <stdexcept>
#include <string>

namespace pdr::par {

namespace {

// A message between ranks carries its receiving and sending actor after its bytes.
constexpr std::size_t kTrailer = 2 * sizeof(std::uint32_t);

}  // namespace

class ActorMux::Port final : public Transport {
 public:
  Port(ActorMux& mux, int actor) : mux_(mux), actor_(actor) {}
  int rank() const override { return actor_; }
  int size() const override { return mux_.actors_; }
  void start_reduction(const Reduction& mine) override {
    if (read_ != rounds_) throw std::logic_error("ActorMux: a round started before the last one was read");
    mux_.contribute(rounds_++, mine);
  }
  std::optional<Reduction> reduction_done() override {
    if (rounds_ == 0 || read_ == rounds_) return std::nullopt;
    const std::optional<Reduction> r = mux_.result(rounds_ - 1);
    if (r) read_ = rounds_;
    return r;
  }

 private:
  void do_send(int to, Bytes message) override {
    if (to < 0 || to >= mux_.actors_ || to == actor_)
      throw std::logic_error("ActorMux: a message to actor " + std::to_string(to));
    if (mux_.host(to) == mux_.rank_.rank()) {
      mux_.post(actor_, to, std::move(message));
      return;
    }
    const std::uint32_t ids[2] = {static_cast<std::uint32_t>(to),
                                  static_cast<std::uint32_t>(actor_)};
    const std::size_t n = message.size();
    message.resize(n + kTrailer);
    std::memcpy(message.data() + n, ids, kTrailer);
    mux_.rank_.send(mux_.host(to), std::move(message));
  }
  std::size_t do_poll(const Deliver& deliver, std::size_t max) override {
    mux_.pump();
    auto& in = mux_.inbox_[static_cast<std::size_t>(mux_.slot(actor_))];
    std::size_t n = 0;
    for (; n < max && !in.empty(); ++n) {
      const std::pair<int, Bytes> m = std::move(in.front());
      in.pop_front();
      deliver(m.first, m.second);
    }
    return n;
  }

  ActorMux& mux_;
  int actor_;
  std::uint64_t rounds_ = 0, read_ = 0;  // rounds started; the last one whose result was read
};

ActorMux::ActorMux(Transport& rank, int actors) : rank_(rank), actors_(actors) {
  if (actors < rank.size())
    throw std::invalid_argument("--submeshes " + std::to_string(actors) + ": at least one per rank (" +
                                std::to_string(rank.size()) + " ranks)");
  for (int k = rank.rank(); k < actors; k += rank.size()) {
    local_.push_back(k);
    ports_.push_back(std::make_unique<Port>(*this, k));
    inbox_.emplace_back();
  }
}

ActorMux::~ActorMux() = default;

Transport& ActorMux::port(int actor) {
  if (host(actor) != rank_.rank()) throw std::logic_error("ActorMux: actor hosted elsewhere");
  return *ports_[static_cast<std::size_t>(slot(actor))];
}

std::size_t ActorMux::queued() const {
  std::size_t n = 0;
  for (const auto& in : inbox_) n += in.size();
  return n;
}

void ActorMux::post(int from, int to, Bytes message) {
  inbox_[static_cast<std::size_t>(slot(to))].emplace_back(from, std::move(message));
}

void ActorMux::pump() {
  rank_.poll(
      [this](int from_rank, std::span<const std::byte> m) {
        if (m.size() < kTrailer) throw std::logic_error("ActorMux: a message without its actors");
        std::uint32_t ids[2];
        std::memcpy(ids, m.data() + (m.size() - kTrailer), kTrailer);
        if (ids[0] >= static_cast<std::uint32_t>(actors_) || ids[1] >= static_cast<std::uint32_t>(actors_) ||
            host(static_cast<int>(ids[0])) != rank_.rank() || host(static_cast<int>(ids[1])) != from_rank)
          throw std::logic_error("ActorMux: a message for actor " + std::to_string(ids[0]) +
                                 " from actor " + std::to_string(ids[1]) + " came from rank " +
                                 std::to_string(from_rank));
        post(static_cast<int>(ids[1]), static_cast<int>(ids[0]),
             Bytes(m.begin(), m.end() - static_cast<std::ptrdiff_t>(kTrailer)));
      },
      64);
  if (real_open_)
    if (const auto r = rank_.reduction_done()) {
      rounds_[next_real_ - 1].result = r;
      real_open_ = false;
      start_ready_round();
    }
}

void ActorMux::contribute(std::uint64_t round, const Reduction& mine) {
  Round& r = rounds_[round];
  for (std::size_t i = 0; i < mine.size(); ++i) r.sum[i] += mine[i];
  ++r.contributed;
  start_ready_round();
}

void ActorMux::start_ready_round() {
  if (real_open_) return;
  const auto it = rounds_.find(next_real_);
  if (it == rounds_.end() || it->second.contributed < static_cast<int>(local_.size())) return;
  rank_.start_reduction(it->second.sum);
  real_open_ = true;
  ++next_real_;
}

std::optional<Reduction> ActorMux::result(std::uint64_t round) {
  pump();
  const auto it = rounds_.find(round);
  if (it == rounds_.end() || !it->second.result) return std::nullopt;
  const Reduction r = *it->second.result;
  if (++it->second.read == static_cast<int>(local_.size())) rounds_.erase(it);
  return r;
}

}  // namespace pdr::par
