// Uniform grids for candidate queries: points (Delaunay emptiness, encroachment,
// conformity) and boxes (overlap of tets).
//
// Correctness argument. A coordinate's cell is floor((x - origin) * inv), computed in double
// and clamped to [0, dims-1] (clamping is done in double, so infinities and NaN are safe).
// Every step (rounded subtraction, multiplication by a positive constant, floor, clamp) is
// monotone non-decreasing in x, so lo <= x <= hi implies cell(lo) <= cell(x) <= cell(hi):
// a query over the cells of a box [lo, hi] returns every stored point inside the box, and
// a box stored over the cells of its [lo, hi] is met by every query box it intersects. The
// grid only proposes candidates; exact predicates decide.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geom/point.hpp"

namespace pdr::check {

struct Box {
  Point lo, hi;
};

class GridFrame {
 public:
  GridFrame() = default;
  // Cells over the bounding box of `extent`, about `cells` of them in all.
  GridFrame(const Box& extent, double cells);
  int cell(double x, int axis) const;
  std::array<int, 3> cell_of(const Point& p) const {
    return {cell(p[0], 0), cell(p[1], 1), cell(p[2], 2)};
  }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims_[1] + static_cast<std::size_t>(j)) * dims_[0] +
           static_cast<std::size_t>(i);
  }
  std::size_t size() const {
    return static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  }
  const std::array<int, 3>& dims() const { return dims_; }
  double side() const { return side_; }  // typical cell side (0 if all points coincide)

 private:
  Point origin_{};
  double side_ = 0;
  std::array<double, 3> inv_{0, 0, 0};
  std::array<int, 3> dims_{1, 1, 1};
};

// Points bucketed by cell; ~per_cell points per cell on average.
class PointGrid {
 public:
  PointGrid() = default;
  explicit PointGrid(std::span<const Point> points, double per_cell = 1.5);
  const GridFrame& frame() const { return frame_; }

  // f(id, point) for every stored point whose cell meets the box [lo, hi]; all points in
  // the closed box are visited (and some outside it).
  template <class F>
  void query(const Box& box, F&& f) const {
    if (ids_.empty()) return;
    const auto a = frame_.cell_of(box.lo), b = frame_.cell_of(box.hi);
    for (int k = a[2]; k <= b[2]; ++k)
      for (int j = a[1]; j <= b[1]; ++j) {
        const std::size_t row = frame_.index(0, j, k);
        for (std::size_t c = row + a[0]; c <= row + b[0]; ++c)
          for (std::uint32_t s = start_[c]; s < start_[c + 1]; ++s) f(ids_[s], sorted_[s]);
      }
  }

 private:
  GridFrame frame_;
  std::vector<std::uint32_t> start_;  // cells + 1
  std::vector<std::uint32_t> ids_;    // point ids in cell order
  std::vector<Point> sorted_;         // their coordinates, for locality
};

// Boxes (by id) bucketed by every cell their [lo, hi] meets.
class BoxGrid {
 public:
  BoxGrid(std::span<const Box> boxes, double cells);
  const GridFrame& frame() const { return frame_; }
  std::size_t cells() const { return start_.size() - 1; }
  std::span<const std::uint32_t> in_cell(std::size_t c) const {
    return {ids_.data() + start_[c], ids_.data() + start_[c + 1]};
  }

 private:
  GridFrame frame_;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> ids_;
};

Box bounding_box(std::span<const Point> points);

// The box of the points `ids` (a tet's four, a triangle's three) index.
template <std::size_t N>
Box box_of(std::span<const Point> points, const std::array<std::uint32_t, N>& ids) {
  Box b{points[ids[0]], points[ids[0]]};
  for (std::size_t k = 1; k < N; ++k)
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = std::min(b.lo[a], points[ids[k]][a]);
      b.hi[a] = std::max(b.hi[a], points[ids[k]][a]);
    }
  return b;
}

}  // namespace pdr::check
