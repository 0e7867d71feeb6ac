// Helpers shared by the mesh readers and writers (internal to pdr_io):
//   - PointRoles: which points are used as element corners and which only as high-order
//     (mid-edge, face, ...) nodes; the latter are removed after reading, since MeshData is
//     linear. Points referenced by nothing are kept: the checker must see them.
//   - drop_if_all_zero: formats that always carry a reference number (Gmsh physical tags,
//     medit refs) report markers only when one is non-zero, so empty == all zero.
//   - check_writable: a writer refuses a MeshData whose indices or marker arrays are
//     inconsistent, before any file is created.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh_data.hpp"

namespace pdr::io {

class PointRoles {
 public:
  explicit PointRoles(std::size_t n) : role_(n, kUnused) {}
  void corner(std::uint32_t i) { role_[i] = kCorner; }
  void high_order(std::uint32_t i) {
    if (role_[i] == kUnused) role_[i] = kHighOrder;
    any_high_order_ = true;
  }
  // Removes points used only as high-order nodes from `mesh`, renumbering tets, faces and
  // point markers. Returns how many were removed. Call after every element is read.
  std::size_t drop_high_order_only(MeshData& mesh) const;

 private:
  enum : std::uint8_t { kUnused = 0, kCorner = 1, kHighOrder = 2 };
  std::vector<std::uint8_t> role_;
  bool any_high_order_ = false;
};

void drop_if_all_zero(std::vector<int>& markers);

// Throws std::invalid_argument (naming `target`) unless every tet/face index is below
// points.size() and each marker array is empty or of the matching size.
void check_writable(const MeshData& mesh, const std::string& target);

}  // namespace pdr::io
