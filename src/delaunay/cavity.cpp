// CavityBuilder::build: breadth-first search of the conflict region (cavity.hpp).
#include "delaunay/cavity.hpp"

#include <cassert>

#include "delaunay/conflict.hpp"
#include "mesh/huge_pages.hpp"

namespace pdr {

template <class StopFn>
bool CavityBuilder::grow(const TetStore& s, std::span<const Point> pts, const Point& p,
                         TetId seed, Cavity& out, const StopFn& stop) {
  out.clear();
  out.point = p;
  out.seed = seed;
  if (mark_.size() < s.slots()) {
    mark_.reserve(s.slots() + s.slots() / 2 + 64);
    advise_huge_pages(mark_.data(), mark_.capacity());
    mark_.resize(mark_.capacity(), Mark::Unseen);
  }
  assert(in_conflict(s, pts, seed, p));
  mark_[seed] = Mark::Inside;
  out.conflict.push_back(seed);
  bool stopped = stop(kNoTet, -1, seed);
  // out.conflict doubles as the BFS queue: entries before i have been expanded.
  // Prefetching: a tet's four neighbours are requested from memory as soon as the tet
  // joins C_p, well before the search reads them (their loads would otherwise wait behind
  // the mispredicted branches of the conflict tests).
  for (int f = 0; f < 4; ++f) s.prefetch(s.neighbour(seed, f));
  for (std::size_t i = 0; i < out.conflict.size() && !stopped; ++i) {
    const TetId t = out.conflict[i];
    // Request the points of the neighbours still to be tested before testing any.
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (mark_[u] != Mark::Unseen || s.is_ghost(u)) continue;
      const VertexId* w = s.vertices(u);
      for (int k = 0; k < 4; ++k) __builtin_prefetch(&pts[w[k]]);
    }
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      const Mark m = mark_[u];
      if (m == Mark::Inside) continue;
      if (m == Mark::Unseen) {
        if (in_conflict(s, pts, u, p)) {
          mark_[u] = Mark::Inside;
          out.conflict.push_back(u);
          for (int g = 0; g < 4; ++g) s.prefetch(s.neighbour(u, g));
          if (stop(t, f, u)) {
            stopped = true;
            break;
          }
          continue;
        }
        mark_[u] = Mark::Outside;
        out.ring.push_back(u);
      }
      out.boundary.push_back(half_face(t, f));
    }
  }
  for (TetId t : out.conflict) mark_[t] = Mark::Unseen;
  for (TetId t : out.ring) mark_[t] = Mark::Unseen;
  return !stopped;
}

void CavityBuilder::build(const TetStore& s, std::span<const Point> pts, const Point& p,
                          TetId seed, Cavity& out) {
  grow(s, pts, p, seed, out, [](TetId, int, TetId) { return false; });
}

bool CavityBuilder::build_until(const TetStore& s, std::span<const Point> pts, const Point& p,
                                TetId seed, Cavity& out, const Stop& stop) {
  return grow(s, pts, p, seed, out, stop);
}

}  // namespace pdr
