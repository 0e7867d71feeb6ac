// Insertion order for bulk construction: BRIO rounds, each sorted along a Hilbert curve
// (Amenta, Choi & Rote 2003, "Incremental constructions con BRIO").
//
// The points are shuffled by a seeded generator; the last half of the shuffled list is
// the last round, the last half of the rest the round before it, and so on down to a first
// round of at most `min_round` points. Each round is sorted, by a radix sort, on the Hilbert
// index of the point's cell in a 2^b grid over the bounding box, b from 2 to 10 growing
// with the point count (the index by Skilling's transpose algorithm: J. Skilling,
// "Programming the Hilbert curve", AIP Conf. Proc. 707, 2004). Consecutive points
// are then close, so a walk from the last inserted tet is short, while the random rounds
// keep the expected total work optimal.
// The order is a heuristic only: the coordinates are rounded to the grid here, and no
// combinatorial decision depends on it (the triangulation is unique for any order).
// Deterministic for a given seed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geom/point.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

// Hilbert index of grid cell (x, y, z), each coordinate < 2^bits, 1 <= bits <= 10.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits);

// Sorts ids in place by the Hilbert index of pts[id] over the box [lo, hi].
void hilbert_sort(std::span<std::uint32_t> ids, std::span<const Point> pts, const Point& lo,
                  const Point& hi);

// The order of the given finite tets along a Hilbert curve through their centroids (over
// their bounding box): a permutation of 0..tets.size()-1. A work queue taken first in,
// first out keeps the order in its later generations (the tets each step makes), so
// consecutive steps touch nearby tets and points; a queue in slot order, which slot reuse
// scatters over space, fetches each cavity from memory afresh.
std::vector<std::uint32_t> hilbert_tet_order(const TetStore& s, std::span<const Point> pts,
                                             std::span<const TetId> tets);

// The BRIO order of the given ids (all of them, each once).
std::vector<std::uint32_t> brio_order(std::vector<std::uint32_t> ids,
                                      std::span<const Point> pts, std::uint64_t seed,
                                      std::size_t min_round = 1000);

}  // namespace pdr
