// FlatHashMap: a hash map in two flat arrays (open addressing, linear probing), for the
// submesh's look-ups by global id and by face on every migration (par/submesh.hpp), where
// std::unordered_map spends an allocation per entry and a pointer chase per look-up.
//
// Invariants (capacity a power of two, at most half full):
//   (H1) every key is in at most one slot, and it is found by probing from its home slot
//        hash(key) & mask towards higher slots (cyclically) without meeting an empty slot;
//   (H2) erase() keeps H1 by shifting later entries of the same probe run back into the
//        hole (backward-shift deletion: no tombstones, so probe runs stay short).
// A pointer or reference returned by find() or operator[] is valid until the next
// operator[] (which may grow the table) or erase() (which may shift entries).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pdr::par {

template <class K, class V, class Hash>
class FlatHashMap {
 public:
  FlatHashMap() = default;
  FlatHashMap(const FlatHashMap&) = default;
  FlatHashMap& operator=(const FlatHashMap&) = default;
  // A moved-from map is empty and usable.
  FlatHashMap(FlatHashMap&& o) noexcept
      : slots_(std::move(o.slots_)), used_(std::move(o.used_)),
        size_(std::exchange(o.size_, 0)), mask_(std::exchange(o.mask_, 0)) {
    o.slots_.clear();
    o.used_.clear();
  }
  FlatHashMap& operator=(FlatHashMap&& o) noexcept {
    slots_ = std::move(o.slots_);
    used_ = std::move(o.used_);
    size_ = std::exchange(o.size_, 0);
    mask_ = std::exchange(o.mask_, 0);
    o.slots_.clear();
    o.used_.clear();
    return *this;
  }

  std::size_t size() const { return size_; }

  const V* find(const K& k) const {
    if (size_ == 0) return nullptr;
    for (std::size_t i = home(k);; i = (i + 1) & mask_) {
      if (!used_[i]) return nullptr;
      if (slots_[i].first == k) return &slots_[i].second;
    }
  }
  V* find(const K& k) { return const_cast<V*>(std::as_const(*this).find(k)); }

  // The value of k, inserted (value-initialised) if absent.
  V& operator[](const K& k) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t i = home(k);
    for (; used_[i]; i = (i + 1) & mask_)
      if (slots_[i].first == k) return slots_[i].second;
    used_[i] = 1;
    slots_[i] = {k, V{}};
    ++size_;
    return slots_[i].second;
  }

  // True when k was there.
  bool erase(const K& k) {
    if (size_ == 0) return false;
    std::size_t i = home(k);
    for (;; i = (i + 1) & mask_) {
      if (!used_[i]) return false;
      if (slots_[i].first == k) break;
    }
    // H2: move back each later entry of the run whose home is not cyclically in (i, j].
    for (std::size_t j = (i + 1) & mask_; used_[j]; j = (j + 1) & mask_) {
      const std::size_t h = home(slots_[j].first);
      const bool stays = i < j ? (h > i && h <= j) : (h > i || h <= j);
      if (stays) continue;
      slots_[i] = std::move(slots_[j]);
      i = j;
    }
    used_[i] = 0;
    --size_;
    return true;
  }

 private:
  std::size_t home(const K& k) const { return Hash{}(k) & mask_; }

  void grow() {
    std::vector<std::pair<K, V>> old = std::move(slots_);
    std::vector<std::uint8_t> was = std::move(used_);
    const std::size_t n = old.empty() ? 16 : 2 * old.size();
    slots_.assign(n, {});
    used_.assign(n, 0);
    mask_ = n - 1;
    size_ = 0;
    for (std::size_t i = 0; i < old.size(); ++i)
      if (was[i]) (*this)[old[i].first] = std::move(old[i].second);
  }

  std::vector<std::pair<K, V>> slots_;
  std::vector<std::uint8_t> used_;
  std::size_t size_ = 0, mask_ = 0;
};

}  // namespace pdr::par
