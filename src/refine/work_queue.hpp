// The work queue of SeqRefinement (paper §3, Fig. 2: "while there is a tet t with
// ratio(t) >= B"): the bad tets waiting to be refined, first in, first out.
//
// An entry is a tet id with the four vertices it had when queued. Tet ids are slots that a
// cavity commit frees and reuses (docs/design.md §3), so an entry is current only while its
// slot is alive and still holds those vertices; a stale entry is skipped. Fig. 2 allows any
// order (Remark 1); FIFO keeps the refinement breadth-first, which keeps the cavities small.
// The consumed prefix is dropped once it is over half of the storage (amortised O(1)).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "mesh/tet_store.hpp"

namespace pdr::refine {

struct QueuedTet {
  TetId t = kNoTet;
  std::array<VertexId, 4> v{};
};

class WorkQueue {
 public:
  void push(const TetStore& s, TetId t) {
    const VertexId* v = s.vertices(t);
    items_.push_back({t, {v[0], v[1], v[2], v[3]}});
  }
  void push(const QueuedTet& e) { items_.push_back(e); }

  // The next entry, current or not; false when the queue is empty.
  bool pop(QueuedTet& e) {
    if (head_ >= items_.size()) return false;
    e = items_[head_++];
    if (head_ > 4096 && head_ * 2 > items_.size()) {
      items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
    }
    return true;
  }

  // True while e's slot is alive and holds the vertices it was queued with.
  static bool current(const TetStore& s, const QueuedTet& e) {
    if (e.t >= s.slots() || !s.is_alive(e.t)) return false;
    const VertexId* v = s.vertices(e.t);
    return v[0] == e.v[0] && v[1] == e.v[1] && v[2] == e.v[2] && v[3] == e.v[3];
  }

  std::size_t pending() const { return items_.size() - head_; }

 private:
  std::vector<QueuedTet> items_;
  std::size_t head_ = 0;
};

}  // namespace pdr::refine
