// ReadInfo: what a mesh reader left out, for the caller to report. Readers never drop data
// silently: elements that are not tetrahedra or boundary triangles are counted here, and so
// are the mid-edge nodes of quadratic elements (kept out of MeshData, which is linear).
#pragma once

#include <cstddef>

namespace pdr::io {

struct ReadInfo {
  std::size_t skipped_elements = 0;        // lines, quads, prisms, hexes, ... (not read)
  std::size_t dropped_high_order_nodes = 0;  // nodes used only as non-corner nodes
};

}  // namespace pdr::io
