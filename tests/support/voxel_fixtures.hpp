// Voxel solids as PLCs, test domains for the mesher (paper §1.1 admissible domains): a set
// of unit cells on a small integer grid (a union of grid boxes), made well-composed (no
// two cells, nor two empty cells, meet only along an edge or at a vertex, so the boundary
// is a closed 2-manifold), its boundary merged per plane and side into polygonal facets
// (non-convex, with holes marked by facet hole points; the corners of every facet are
// vertices of the PLC, so no vertex of one facet lies inside an edge of another), and
// enclosed voids marked by volume hole points. Every angle is 90, 180 or 270 degrees.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/plc.hpp"

namespace pdr::test {

struct GridBox {
  std::array<int, 3> lo{}, hi{};  // cells lo[a] <= c[a] < hi[a]
};

class VoxelSet {
 public:
  explicit VoxelSet(std::array<int, 3> n) : n_(n), cells_(std::size_t(n[0]) * n[1] * n[2], 0) {}
  const std::array<int, 3>& size() const { return n_; }
  bool inside_grid(std::array<int, 3> c) const;
  bool at(std::array<int, 3> c) const;  // false outside the grid
  void set(std::array<int, 3> c, bool v = true);
  std::size_t count() const;

 private:
  std::size_t index(std::array<int, 3> c) const {
    return std::size_t(c[0]) + std::size_t(n_[0]) * (std::size_t(c[1]) + std::size_t(n_[1]) * c[2]);
  }
  std::array<int, 3> n_;
  std::vector<std::uint8_t> cells_;
};

// The union of the boxes (clipped to the grid).
VoxelSet voxels_of(std::array<int, 3> n, const std::vector<GridBox>& boxes);

// Adds cells until no critical configuration remains (a 2x2 square of cells with exactly
// one diagonal occupied; a 2x2x2 block with exactly two, or exactly six, cells occupied
// and the two odd ones antipodal). Terminates: cells are only added.
void make_well_composed(VoxelSet& s);

// One point in each empty region that the set encloses (cell centres, in grid units).
std::vector<std::array<double, 3>> enclosed_voids(const VoxelSet& s);

// The boundary of a well-composed set as a PLC: grid point g maps to origin + unit * g;
// the volume holes are the enclosed voids' points. Precondition: s is not empty.
Plc voxel_plc(const VoxelSet& s, double unit, const Point& origin = {0, 0, 0});

}  // namespace pdr::test
