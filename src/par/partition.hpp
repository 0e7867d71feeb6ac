// Element-wise partition of the initial mesh M_o into N submeshes (paper §4, item 1:
// "M_o has been elementwise partitioned into N submeshes", with sequential Metis as in §5).
//
// The graph is T's dual over its finite tets: one node per finite live tet, one edge per
// face two finite tets share. Tets inside Ω weigh kInsideWeight, the others (outside Ω but
// inside the hull: the kernel keeps them, and some submesh must own them) weigh 1, so the
// parts balance the refinement work. METIS k-way with contiguous parts (every submesh is
// face-connected) when the graph is connected (METIS refuses contiguity otherwise),
// seeded, so a seed gives the same partition on every run. Ghost tets are not
// partitioned: each goes with the finite tet across its hull face; proxy tets are left
// out. A part METIS leaves empty is an error (fewer parts are needed).
// Interface faces: the faces whose two tets lie in different parts.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/tet_store.hpp"

namespace pdr::par {

inline constexpr std::uint32_t kNoPart = 0xFFFFFFFFu;
inline constexpr std::int32_t kInsideWeight = 8;

struct Partition {
  std::uint32_t parts = 0;
  std::vector<std::uint32_t> part;         // per tet slot; kNoPart for dead slots
  std::vector<std::uint64_t> tets;         // per part: finite tets
  std::vector<std::uint64_t> weight;       // per part: summed weights
  std::uint64_t interface_faces = 0;       // finite faces between two parts
  bool contiguous = true;                  // every part face-connected (connected input)
};

// Precondition: 1 <= parts <= the number of finite tets, else std::invalid_argument, as
// when METIS leaves a part empty; `inside` is indexed by tet slot (shorter: the rest are
// outside).
Partition partition_tets(const TetStore& s, std::span<const std::uint8_t> inside,
                         std::uint32_t parts, std::uint64_t seed);

}  // namespace pdr::par
