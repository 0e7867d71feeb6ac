// Grids for candidate queries, adapted to the density of what they hold: points (Delaunay
// emptiness, encroachment, conformity) and pairs of intersecting boxes (overlap of tets,
// the boundary's self-intersection).
//
// A grid has cells of one size over its extent; a cell holding more than a leaf's worth is
// itself a grid over its own region, recursively (to a fixed depth). A mesh graded from
// coarse to fine (a surface patch refined to a small gap) then costs what a uniform one
// does: a query meets few points per leaf, however the points crowd.
//
// Correctness argument. A coordinate's cell in a frame is floor((x - origin) * inv),
// computed in double and clamped to [0, dims-1] (clamping is done in double, so infinities
// and NaN are safe). Every step (rounded subtraction, multiplication by a positive
// constant, floor, clamp) is monotone non-decreasing in x, whatever the frame's origin,
// scale or extent, so lo <= x <= hi implies cell(lo) <= cell(x) <= cell(hi) in every frame,
// a nested one included (points or boxes outside a frame's extent are clamped into it):
//   - points: a query visits, at every level, the cells of the query box's cell range, so
//     it reaches every stored point inside the box;
//   - box pairs: two intersecting boxes s, t have, in every frame, the cell of the low
//     corner of s ∩ t inside both boxes' cell ranges, and by monotonicity it is the
//     componentwise max of their low cells. The pair is reported in that cell of the top
//     frame, and inside it in that cell of each nested frame: exactly once.
// The grid only proposes candidates; exact predicates decide.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "check/interval.hpp"
#include "geom/point.hpp"

namespace pdr::check {

struct Box {
  Point lo, hi;
};

inline bool boxes_meet(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i)
    if (a.lo[i] > b.hi[i] || b.lo[i] > a.hi[i]) return false;
  return true;
}

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
  std::size_t index(const std::array<int, 3>& c) const { return index(c[0], c[1], c[2]); }
  std::array<int, 3> cell_at(std::size_t index) const {
    return {static_cast<int>(index % dims_[0]), static_cast<int>(index / dims_[0] % dims_[1]),
            static_cast<int>(index / dims_[0] / dims_[1])};
  }
  std::size_t size() const {
    return static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  }
  const std::array<int, 3>& dims() const { return dims_; }
  double side() const { return side_; }  // typical cell side (0 if all points coincide)
  // The region of a cell, approximately (rounded): the extent of a nested frame.
  Box region(const std::array<int, 3>& c) const;
  // A lower bound of |x - y| over every x whose cell on `axis` is k and every y in
  // [lo, hi]. The slab of cell k holds x only if fl(fl(x - origin) * inv) lies in [k, k + 1)
  // (or below, k = 0; or above, k = dims - 1): each rounding moves a value by at most
  // 2^-53 of itself (plus a subnormal ulp), so x - origin lies in [k, k + 1] / inv widened
  // by 2^-48 of itself and 2^-1000, which the interval arithmetic of interval.hpp then
  // encloses. The slack is far above the rounding's, and costs nothing measurable.
  double gap(int k, int axis, double lo, double hi) const;

 private:
  Point origin_{};
  double side_ = 0;
  std::array<double, 3> inv_{0, 0, 0};
  std::array<int, 3> dims_{1, 1, 1};
};

// Points bucketed by cell, ~per_cell points per cell on average; a cell holding more than
// kLeafPoints is a nested grid over its points.
class PointGrid {
 public:
  static constexpr std::size_t kLeafPoints = 32;
  static constexpr int kMaxDepth = 8;

  PointGrid() = default;
  explicit PointGrid(std::span<const Point> points, double per_cell = 1.5);
  const GridFrame& frame() const { return nodes_.front().frame; }  // the top level
  int depth() const { return depth_; }  // nesting levels below the top

  // f(id, point) for every stored point whose leaf cell meets the box [lo, hi]; all points
  // in the closed box are visited once (and some outside it).
  template <class F>
  void query(const Box& box, F&& f) const {
    if (!ids_.empty()) query_node(0, box, f);
  }
  // f(id, point) for every stored point in the closed ball whose centre lies in `center`
  // (per axis an interval) and whose squared radius is at most r2hi, once each, and some
  // outside it: the cells of the ball's box, less rows of cells that provably miss it (a
  // row (j, k) keeps the cells i whose x can be within sqrt(r2hi - gap_y^2 - gap_z^2) of
  // the centre, every step rounded outward). A flat tet's circumball covers much of the
  // mesh's box and little of the mesh: this visits what lies near the ball, not the box.
  template <class F>
  void query_ball(const IVec& center, double r2hi, F&& f) const {
    if (ids_.empty() || !(r2hi >= 0) || !std::isfinite(r2hi)) {
      if (!ids_.empty()) query(Box{{-kInf, -kInf, -kInf}, {kInf, kInf, kInf}}, f);
      return;
    }
    query_ball_node(0, center, r2hi, f);
  }

 private:
  struct Node {
    GridFrame frame;
    std::uint32_t first = 0;  // its cells are [first, first + frame.size())
  };
  template <class F>
  void query_node(std::uint32_t n, const Box& box, F& f) const {
    const Node& node = nodes_[n];
    const auto a = node.frame.cell_of(box.lo), b = node.frame.cell_of(box.hi);
    for (int k = a[2]; k <= b[2]; ++k)
      for (int j = a[1]; j <= b[1]; ++j) {
        const std::size_t row = node.first + node.frame.index(0, j, k);
        for (std::size_t c = row + a[0]; c <= row + b[0]; ++c) {
          if (child_[c] >= 0) {
            query_node(static_cast<std::uint32_t>(child_[c]), box, f);
            continue;
          }
          for (std::uint32_t s = begin_[c]; s < begin_[c + 1]; ++s) f(ids_[s], sorted_[s]);
        }
      }
  }
  template <class F>
  void query_ball_node(std::uint32_t n, const IVec& c, double r2hi, F& f) const {
    using interval_detail::down, interval_detail::up;
    const Node& node = nodes_[n];
    const GridFrame& fr = node.frame;
    const double r = up(std::sqrt(r2hi));
    std::array<int, 3> a{}, b{};
    for (int i = 0; i < 3; ++i) {
      a[i] = fr.cell(down(c[i].lo - r), i);
      b[i] = fr.cell(up(c[i].hi + r), i);
    }
    for (int k = a[2]; k <= b[2]; ++k) {
      const double gz = fr.gap(k, 2, c[2].lo, c[2].hi), rz = down(gz * gz);
      // (NaN only when the square overflows: then the row misses the ball too.)
      if (!(rz <= r2hi)) continue;
      for (int j = a[1]; j <= b[1]; ++j) {
        const double gy = fr.gap(j, 1, c[1].lo, c[1].hi), ryz = down(rz + down(gy * gy));
        if (!(ryz <= r2hi)) continue;
        const double sx = up(std::sqrt(std::max(0.0, up(r2hi - ryz))));
        const int ia = std::max(a[0], fr.cell(down(c[0].lo - sx), 0));
        const int ib = std::min(b[0], fr.cell(up(c[0].hi + sx), 0));
        if (ia > ib) continue;
        const std::size_t row = node.first + fr.index(0, j, k);
        for (std::size_t cell = row + ia; cell <= row + ib; ++cell) {
          if (child_[cell] >= 0) {
            query_ball_node(static_cast<std::uint32_t>(child_[cell]), c, r2hi, f);
            continue;
          }
          for (std::uint32_t s = begin_[cell]; s < begin_[cell + 1]; ++s) f(ids_[s], sorted_[s]);
        }
      }
    }
  }
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  void build(std::span<const Point> points, const Box& extent, std::uint32_t b, std::uint32_t e,
             double per_cell, int depth);

  std::vector<Node> nodes_;
  // Per cell (all levels): begin_[c]..begin_[c + 1] is its range of ids_ when child_[c] < 0
  // (a leaf). A nested node's cells are appended after a sentinel, so ranges stay adjacent.
  std::vector<std::uint32_t> begin_;
  std::vector<std::int32_t> child_;
  std::vector<std::uint32_t> ids_;  // point ids in cell order
  std::vector<Point> sorted_;       // their coordinates, for locality
  int depth_ = 0;
};

// Boxes bucketed by the cells of a frame their [lo, hi] meets, for "does this box meet any
// of them": two boxes that meet share the cell of a common point (monotone cells), which
// lies in both cell ranges. Per cell, also the Chebyshev distance in cells to the nearest
// cell holding a box, capped at kClear (three passes, one per axis: d(x) = min over |k| <=
// kClear of max(|k|, d(x + k e_axis)) computes min(kClear, that distance) because the
// Chebyshev norm is the max of the axes'), so a query box whose cell range lies within its
// low cell's clearance is answered in one lookup.
class BoxCells {
 public:
  static constexpr int kClear = 7;

  BoxCells(const GridFrame& frame, std::vector<Box> boxes);
  // Whether the closed box meets some stored closed box.
  bool meets(const Box& box) const;

 private:
  GridFrame frame_;
  std::vector<Box> boxes_;
  std::vector<std::size_t> start_;    // per cell: its boxes are ids_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> ids_;
  std::vector<std::uint8_t> clear_;   // per cell
};

// Every pair of boxes whose closed boxes intersect, once: f(worker, s, t) with s, t indices
// into `boxes` (in no particular order), from `threads` workers. Boxes with lo > hi on some
// axis (empty) are never reported. Cells hold about `per_cell` boxes; a cell holding more
// than kSweepBoxes is a nested grid.
struct BoxPairs {
  static constexpr std::size_t kSweepBoxes = 256;
  static constexpr int kMaxDepth = 6;
};

namespace grid_detail {

// Boxes `ids` bucketed by every cell of `frame` their [lo, hi] meets (CSR). With
// `separating`, nothing is filled (ok false) when that would list the boxes more than 4
// times over, or leave one cell holding them all: counted first, filled only then.
struct Buckets {
  bool ok = true;
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> ids;
};
Buckets bucket(const GridFrame& frame, std::span<const Box> boxes, std::span<const std::uint32_t> ids,
               bool separating = false);

struct Level {
  GridFrame frame;
  std::array<int, 3> cell;
};

// Whether the pair meeting in `meet` is owned by the cell of every level on the path.
inline bool owned(const std::vector<Level>& path, const Point& meet) {
  for (const Level& l : path)
    if (l.frame.cell_of(meet) != l.cell) return false;
  return true;
}

template <class F>
void sweep(std::span<const Box> boxes, std::span<const std::uint32_t> in, const std::vector<Level>& path,
           unsigned w, F& f) {
  std::vector<std::uint32_t> order(in.begin(), in.end());
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    return boxes[x].lo[0] < boxes[y].lo[0] || (boxes[x].lo[0] == boxes[y].lo[0] && x < y);
  });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Box& bs = boxes[order[i]];
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].lo[0] <= bs.hi[0]; ++j) {
      const Box& bt = boxes[order[j]];
      if (!boxes_meet(bs, bt)) continue;
      const Point meet{std::max(bs.lo[0], bt.lo[0]), std::max(bs.lo[1], bt.lo[1]),
                       std::max(bs.lo[2], bt.lo[2])};
      if (owned(path, meet)) f(w, order[i], order[j]);
    }
  }
}

template <class F>
void pairs_in_cell(std::span<const Box> boxes, std::span<const std::uint32_t> in, std::vector<Level>& path,
                   double per_cell, unsigned w, F& f) {
  if (in.size() > BoxPairs::kSweepBoxes && static_cast<int>(path.size()) <= BoxPairs::kMaxDepth) {
    const Level& here = path.back();
    const GridFrame sub(here.frame.region(here.cell), static_cast<double>(in.size()) / per_cell);
    // Nest only where it separates the boxes (not where they all share a point) and does
    // not multiply them by straddling.
    const Buckets b = bucket(sub, boxes, in, true);
    if (b.ok) {
      for (std::size_t c = 0; c + 1 < b.start.size(); ++c) {
        if (b.start[c + 1] - b.start[c] < 2) continue;
        path.push_back({sub, sub.cell_at(c)});
        pairs_in_cell(boxes, std::span(b.ids).subspan(b.start[c], b.start[c + 1] - b.start[c]), path,
                      per_cell, w, f);
        path.pop_back();
      }
      return;
    }
  }
  sweep(boxes, in, path, w, f);
}

Box extent_of(std::span<const Box> boxes, std::span<const std::uint32_t> ids);

}  // namespace grid_detail

// Runs parallel_blocks-style workers over the top cells (see parallel.hpp for the loop).
template <class Loop, class F>
void for_each_box_pair(std::span<const Box> boxes, double per_cell, Loop&& loop, F&& f) {
  std::vector<std::uint32_t> all;
  all.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (boxes[i].lo[0] <= boxes[i].hi[0] && boxes[i].lo[1] <= boxes[i].hi[1] &&
        boxes[i].lo[2] <= boxes[i].hi[2])
      all.push_back(static_cast<std::uint32_t>(i));
  if (all.size() < 2) return;
  const GridFrame top(grid_detail::extent_of(boxes, all), static_cast<double>(all.size()) / per_cell);
  const grid_detail::Buckets b = grid_detail::bucket(top, boxes, all);
  loop(top.size(), [&](unsigned w, std::size_t begin, std::size_t end) {
    std::vector<grid_detail::Level> path;
    for (std::size_t c = begin; c < end; ++c) {
      if (b.start[c + 1] - b.start[c] < 2) continue;
      path.assign(1, {top, top.cell_at(c)});
      grid_detail::pairs_in_cell(boxes, std::span(b.ids).subspan(b.start[c], b.start[c + 1] - b.start[c]),
                                 path, per_cell, w, f);
    }
  });
}

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
