// SlotSet: a small set of tet slots with O(1) insert, lookup and clear, and no allocation
// once it has grown to the largest set it held. The event loop locks a search's closure
// and the tets that arrive for it (par/insertion_actor.hpp) and clears the lock at every
// round; a fetch collects its tets in one (par/cavity_search.hpp). Such a set holds tens of
// tets, a few thousand at most, out of millions of slots:
//   - a node-based hash set allocated a node per tet and freed them all again, round after
//     round (about 5% of a rank's time in malloc and free, docs/parallel.md);
//   - a stamp per slot of the store (4 bytes a slot, for each set) made every rank fault in
//     memory along the whole store for sets that small.
// So it is an open-addressing table (linear probing) whose entries carry the epoch they
// were written in. An entry belongs to the set when its epoch is the current one; clear()
// starts a new epoch, which empties every entry at once. No entry is ever removed within
// an epoch, so a probe run ends at the first entry of an older epoch.
// Invariants: the capacity is a power of two, at least twice the size; every slot in the
// set is found by probing from its home entry without meeting an entry of an older epoch.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "mesh/tet_store.hpp"

namespace pdr::par {

// Tet ids count up from 0: Fibonacci hashing spreads them over a table's low bits (the
// high bits of their product). For SlotSet, and FlatHashMaps keyed by slot.
struct SlotHash {
  std::size_t operator()(TetId t) const {
    return static_cast<std::size_t>((std::uint64_t{t} * 0x9E3779B97F4A7C15ull) >> 32);
  }
};

class SlotSet {
 public:
  bool contains(TetId t) const {
    if (size_ == 0) return false;
    for (std::size_t i = home(t);; i = (i + 1) & mask_) {
      const Entry& e = table_[i];
      if (e.epoch != epoch_) return false;
      if (e.slot == t) return true;
    }
  }
  void insert(TetId t) {
    if (2 * (size_ + 1) > table_.size()) grow();
    put(t);
  }
  template <class It>
  void insert(It first, It last) {
    for (; first != last; ++first) insert(*first);
  }
  void clear() {
    size_ = 0;
    if (++epoch_ == 0) {  // after 2^32 - 1 epochs: old entries could match again
      for (Entry& e : table_) e.epoch = 0;
      epoch_ = 1;
    }
  }
  std::size_t size() const { return size_; }
  // Tests only: clear() as if it had been called until the epoch was `epoch` (> 0), to
  // reach the wrap without 2^32 calls.
  void clear_to_epoch_for_tests(std::uint32_t epoch) {
    size_ = 0;
    epoch_ = epoch;
  }

 private:
  struct Entry {
    TetId slot = 0;
    std::uint32_t epoch = 0;  // 0: in no epoch
  };
  std::size_t home(TetId t) const { return SlotHash{}(t) & mask_; }
  void put(TetId t) {
    for (std::size_t i = home(t);; i = (i + 1) & mask_) {
      Entry& e = table_[i];
      if (e.epoch != epoch_) {
        e = Entry{t, epoch_};
        ++size_;
        return;
      }
      if (e.slot == t) return;
    }
  }
  void grow() {
    std::vector<Entry> old = std::move(table_);
    table_.assign(std::max<std::size_t>(64, 2 * old.size()), Entry{});
    mask_ = table_.size() - 1;
    size_ = 0;
    for (const Entry& e : old)
      if (e.epoch == epoch_) put(e.slot);
  }

  std::vector<Entry> table_;
  std::size_t size_ = 0, mask_ = 0;
  std::uint32_t epoch_ = 1;
};

}  // namespace pdr::par
