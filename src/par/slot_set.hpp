// SlotSet: a set of tet slots with O(1) insert, lookup and clear, and no allocation once
// it has grown to the store's size. A slot is in the set when its stamp equals the
// current epoch; clear() starts a new epoch. The event loop locks a search's closure and
// the tets that arrive for it (par/insertion_actor.hpp) and clears the lock at every
// round: a hash set there allocated a node per tet and freed them all again, round after
// round (about 5% of a rank's time in malloc and free, docs/parallel.md).
#pragma once

#include <algorithm>
#include <cstdint>

#include "mesh/growing_array.hpp"
#include "mesh/tet_store.hpp"

namespace pdr::par {

class SlotSet {
 public:
  bool contains(TetId t) const { return t < stamp_.size() && stamp_[t] == epoch_; }
  void insert(TetId t) {
    if (t >= stamp_.size()) stamp_.resize(std::max<std::size_t>(std::size_t{t} + 1, 2 * stamp_.size()), 0);
    stamp_[t] = epoch_;
  }
  template <class It>
  void insert(It first, It last) {
    for (; first != last; ++first) insert(*first);
  }
  void clear() {
    if (++epoch_ == 0) {  // after 2^32 - 1 epochs: old stamps could match again
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      epoch_ = 1;
    }
  }

 private:
  GrowingArray<std::uint32_t> stamp_;  // 0: in no epoch
  std::uint32_t epoch_ = 1;
};

}  // namespace pdr::par
