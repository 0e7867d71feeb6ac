// TetStore: the tetrahedra of a triangulation as flat arrays of 32-bit integers.
//
//   v(t,i)    vertex in slot i of tet t (local numbering: mesh/tables.hpp);
//   adj(t,f)  the half-face on the other side of face f of tet t, encoded 4t'+f': the
//             neighbour t' and its back face f' (accessors below; no bare shifts outside).
//
// 32 bytes per tet slot: the 4 vertices and 4 neighbours of tet t are interleaved in one
// 32-byte record, data[8t .. 8t+3] = v, data[8t+4 .. 8t+7] = adj, so a visit to a tet
// touches one cache line instead of two (this is the hot access of the cavity search).
// The store holds no points and makes no geometric decisions.
//
// Invariants of a valid store (check_topology() in topology_check.cpp reports breaks):
//   - every live tet has four distinct vertex ids; the ghost vertex may only be in slot 3;
//   - adjacency is an involution: adj[adj[h]] == h for every live half-face h, and the
//     two tets across a face are both live and share exactly the three face vertices, met
//     in opposite cyclic order (the faces are consistently oriented);
//   - no null neighbours: a ghost vertex (kGhostVertex, never a point index) closes the
//     convex hull with ghost tets (a,b,c,ghost), whose slots (0,1,2) are the hull face
//     oriented out of the hull;
//   - a proxy tet (a,b,c,kRemoteVertex) closes a face of a submesh whose other side lives
//     in another submesh (the parallel layer, src/par): slots (0,1,2) are that face,
//     oriented out of the submesh, face 3 is glued to the local tet, and faces 0-2 are
//     open (kNoHalfFace): a traversal stops at a proxy and never leaves it. Its face
//     vertices may include the ghost vertex (the face of a ghost tet). The sequential
//     mesher never makes one;
//   - dead slots have v(t,0) == kDeadVertex and are chained in a free list through
//     adj(t,0); create() reuses them last-in first-out (good cache locality after a
//     Bowyer-Watson commit, which frees and refills the same slots).
// Capacity: ids and half-faces are 32-bit, so a store holds at most kMaxTetSlots slots
// (half_face(t, 3) of the last one stays below kNoHalfFace); offsets into the records are
// computed in size_t (8 * t wraps 32 bits from t = 2^29). create() throws CapacityError
// instead of wrapping.
// Paper §1.2: the store is the T_i that a cavity commit turns into T_{i+1}.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/growing_array.hpp"

namespace pdr {

using TetId = std::uint32_t;
using VertexId = std::uint32_t;
using HalfFace = std::uint32_t;  // 4*tet + face; build and read it with the helpers below

inline constexpr VertexId kGhostVertex = 0xFFFFFFFFu;  // closes the hull; never a point
inline constexpr VertexId kDeadVertex = 0xFFFFFFFEu;   // marks a free slot in v[4t]
inline constexpr VertexId kNoVertex = 0xFFFFFFFDu;     // "none" in results
inline constexpr VertexId kRemoteVertex = 0xFFFFFFFCu; // slot 3 of a proxy tet; never a point
// Slot-3 ids of tets that are not finite (ghost, proxy): the smallest of them, so one
// compare tells a finite tet from the others.
inline constexpr VertexId kFirstSpecialVertex = kRemoteVertex;
inline constexpr TetId kNoTet = 0xFFFFFFFFu;
inline constexpr HalfFace kNoHalfFace = 0xFFFFFFFFu;

// The most tet slots a store may hold: tet ids 0 .. 2^30 - 2, whose half-faces 4t + f stay
// below kNoHalfFace (and the ids below kNoTet).
inline constexpr std::size_t kMaxTetSlots = (std::size_t{1} << 30) - 1;

// A store (or a vertex count) that would outgrow its 32-bit ids: a resource limit, reported
// like the vertex cap, never a silent wrap-around.
class CapacityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr HalfFace half_face(TetId t, int f) { return 4 * t + static_cast<std::uint32_t>(f); }
constexpr TetId tet_of(HalfFace h) { return h >> 2; }
constexpr int face_of(HalfFace h) { return static_cast<int>(h & 3u); }

class TetStore {
 public:
  // The offset of tet t's record in the flat array (size_t: no wrap-around for any id).
  static constexpr std::size_t record_offset(TetId t) { return kRecord * std::size_t{t}; }

  TetStore() = default;
  // A store refusing to grow beyond `max_slots` (at most kMaxTetSlots; tests use less).
  explicit TetStore(std::size_t max_slots)
      : max_slots_(max_slots < kMaxTetSlots ? max_slots : kMaxTetSlots) {}

  // ---- reading -----------------------------------------------------------------------
  VertexId vertex(TetId t, int slot) const { return data_[record_offset(t) + slot]; }
  const VertexId* vertices(TetId t) const { return &data_[record_offset(t)]; }
  // The half-face across face f of t (neighbour tet and its back face).
  HalfFace opposite(TetId t, int f) const { return data_[record_offset(t) + 4 + f]; }
  HalfFace opposite(HalfFace h) const { return opposite(tet_of(h), face_of(h)); }
  TetId neighbour(TetId t, int f) const { return tet_of(opposite(t, f)); }
  int back_face(TetId t, int f) const { return face_of(opposite(t, f)); }

  bool is_alive(TetId t) const { return data_[record_offset(t)] != kDeadVertex; }
  bool is_ghost(TetId t) const { return data_[record_offset(t) + 3] == kGhostVertex; }
  bool is_proxy(TetId t) const { return data_[record_offset(t) + 3] == kRemoteVertex; }

  // A hint to the cache: tet t's record will be read soon (no effect on the contents).
  void prefetch(TetId t) const { __builtin_prefetch(&data_[record_offset(t)]); }

  // Slots ever used (live + free); tet ids are < slots().
  std::size_t slots() const { return data_.size() / kRecord; }
  std::size_t live() const { return live_; }
  // Bytes of topology allocated (capacity), for reports.
  std::size_t bytes_allocated() const { return data_.capacity() * sizeof(std::uint32_t); }

  // ---- writing -----------------------------------------------------------------------
  // Capacity for `tets` slots; large stores also ask the OS for huge pages (fewer TLB
  // misses on the random-looking accesses of the cavity search).
  void reserve(std::size_t tets);
  void clear() {
    data_.clear();
    free_head_ = kNoTet;
    live_ = 0;
  }

  // A new live tet with the given vertices; its adjacency is kNoHalfFace until linked.
  // Precondition: the caller makes it positive (or a ghost with the ghost in slot 3).
  TetId create(VertexId a, VertexId b, VertexId c, VertexId d) {
    TetId t;
    if (free_head_ != kNoTet) {
      t = free_head_;
      free_head_ = data_[record_offset(t) + 4];
    } else {
      if (slots() >= max_slots_)
        throw CapacityError("tet_store.capacity: " + std::to_string(slots()) +
                            " tet slots is the most 32-bit ids allow (2^30 - 1); use a coarser "
                            "size, or split the domain across ranks");
      t = static_cast<TetId>(slots());
      data_.resize(data_.size() + kRecord);
    }
    set_vertices(t, a, b, c, d);
    for (int f = 0; f < 4; ++f) data_[record_offset(t) + 4 + f] = kNoHalfFace;
    ++live_;
    return t;
  }
  // n new live slots after the last one (no free slot is reused); returns the first. The
  // caller writes their records (set_vertices, set_opposite) before anything reads them;
  // distinct slots may be written from different threads.
  TetId append(std::size_t n) {
    if (n > max_slots_ || slots() > max_slots_ - n)
      throw CapacityError("tet_store.capacity: " + std::to_string(slots() + n) +
                          " tet slots is more than 32-bit ids allow (2^30 - 1); use a coarser "
                          "size, or split the domain across ranks");
    const auto t = static_cast<TetId>(slots());
    data_.resize(data_.size() + kRecord * n);
    live_ += n;
    return t;
  }
  void set_vertices(TetId t, VertexId a, VertexId b, VertexId c, VertexId d) {
    VertexId* p = &data_[record_offset(t)];
    p[0] = a;
    p[1] = b;
    p[2] = c;
    p[3] = d;
  }
  void set_vertex(TetId t, int slot, VertexId x) { data_[record_offset(t) + slot] = x; }
  // Glue two half-faces to each other (both directions).
  void link(HalfFace x, HalfFace y) {
    set_opposite(x, y);
    set_opposite(y, x);
  }
  // Set one direction only (the caller restores the involution before it reads again).
  void set_opposite(HalfFace x, HalfFace y) {
    data_[record_offset(tet_of(x)) + 4 + face_of(x)] = y;
  }

  // Free a live tet (its slot goes on the free list). Neighbours still pointing at it must
  // be relinked by the caller.
  void destroy(TetId t) {
    data_[record_offset(t)] = kDeadVertex;
    data_[record_offset(t) + 4] = free_head_;
    free_head_ = t;
    --live_;
  }

  // Topology invariants listed in the header comment. Returns one line per violation,
  // each starting with the invariant's name; empty means valid. O(slots).
  std::vector<std::string> check_topology() const;

 private:
  static constexpr std::size_t kRecord = 8;  // 4 vertices + 4 neighbours per tet
  GrowingArray<std::uint32_t> data_;
  std::size_t max_slots_ = kMaxTetSlots;
  TetId free_head_ = kNoTet;
  std::size_t live_ = 0;
};

}  // namespace pdr
