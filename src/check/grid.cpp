// Grids adapted to density (see grid.hpp for the monotonicity argument that makes queries
// complete and reports pairs once).
#include "check/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdr::check {

Box bounding_box(std::span<const Point> points) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const Point& p : points)
    for (int i = 0; i < 3; ++i) {
      b.lo[i] = std::min(b.lo[i], p[i]);
      b.hi[i] = std::max(b.hi[i], p[i]);
    }
  if (points.empty()) b = Box{{0, 0, 0}, {0, 0, 0}};
  return b;
}

GridFrame::GridFrame(const Box& extent, double cells) {
  cells = std::max(1.0, cells);
  std::array<double, 3> len{};
  double volume = 1;
  int spread = 0;
  for (int i = 0; i < 3; ++i) {
    origin_[i] = std::isfinite(extent.lo[i]) ? extent.lo[i] : 0.0;
    len[i] = extent.hi[i] - extent.lo[i];
    if (!std::isfinite(len[i]) || len[i] > 1e300) len[i] = 0;  // degenerate: one slab
    if (len[i] > 0) {
      volume *= len[i];
      ++spread;
    }
  }
  if (spread == 0) return;
  const double side = std::pow(volume / cells, 1.0 / spread);
  side_ = side;
  for (int i = 0; i < 3; ++i) {
    if (len[i] > 0 && side > 0) {
      const double d = std::ceil(len[i] / side);
      dims_[i] = static_cast<int>(std::clamp(d, 1.0, double(1 << 20)));
    }
  }
  // Keep the cell count near `cells` (ceil may overshoot on thin boxes).
  while (static_cast<double>(size()) > 4 * cells + 64) {
    int widest = 0;
    for (int i = 1; i < 3; ++i)
      if (dims_[i] > dims_[widest]) widest = i;
    dims_[widest] = std::max(1, dims_[widest] / 2);
  }
  for (int i = 0; i < 3; ++i) inv_[i] = len[i] > 0 ? dims_[i] / len[i] : 0.0;
}

int GridFrame::cell(double x, int axis) const {
  const double t = std::floor((x - origin_[axis]) * inv_[axis]);
  if (!(t > 0)) return 0;  // also NaN
  const double top = dims_[axis] - 1;
  if (t >= top) return dims_[axis] - 1;
  return static_cast<int>(t);
}

Box GridFrame::region(const std::array<int, 3>& c) const {
  Box b{origin_, origin_};
  for (int i = 0; i < 3; ++i) {
    if (inv_[i] == 0) continue;
    b.lo[i] = origin_[i] + c[i] / inv_[i];
    b.hi[i] = origin_[i] + (c[i] + 1) / inv_[i];
  }
  return b;
}

double GridFrame::gap(int k, int axis, double lo, double hi) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (inv_[axis] == 0) return 0;  // one slab holds every x
  const Interval o(origin_[axis]), inv(inv_[axis]);
  const double widen = 0x1p-48;
  const double slab_lo =
      k <= 0 ? -inf : (o + Interval(k) / inv * Interval(1 - widen)).lo - 0x1p-1000;
  const double slab_hi =
      k >= dims_[axis] - 1 ? inf : (o + Interval(k + 1) / inv * Interval(1 + widen)).hi + 0x1p-1000;
  if (slab_lo > hi) return interval_detail::down(slab_lo - hi);
  if (slab_hi < lo) return interval_detail::down(lo - slab_hi);
  return 0;
}

PointGrid::PointGrid(std::span<const Point> points, double per_cell) {
  const std::size_t n = points.size();
  ids_.resize(n);
  for (std::size_t i = 0; i < n; ++i) ids_[i] = static_cast<std::uint32_t>(i);
  build(points, bounding_box(points), 0, static_cast<std::uint32_t>(n), per_cell, 0);
  sorted_.resize(n);
  for (std::size_t s = 0; s < n; ++s) sorted_[s] = points[ids_[s]];
}

// Node over ids_[b, e): its cells, the ids sorted into them, and nested nodes for crowded
// cells (over the bounding box of their points).
void PointGrid::build(std::span<const Point> points, const Box& extent, std::uint32_t b,
                      std::uint32_t e, double per_cell, int depth) {
  depth_ = std::max(depth_, depth);
  const GridFrame frame(extent, (e - b) / per_cell);
  const std::size_t cells = frame.size(), first = begin_.size();
  nodes_.push_back({frame, static_cast<std::uint32_t>(first)});
  begin_.resize(first + cells + 1, 0);
  child_.resize(first + cells + 1, -1);
  std::vector<std::uint32_t> count(cells + 1, 0);
  {  // the temporaries end before the nested nodes are built
    std::vector<std::uint32_t> cell(e - b);
    for (std::uint32_t s = b; s < e; ++s) {
      cell[s - b] = static_cast<std::uint32_t>(frame.index(frame.cell_of(points[ids_[s]])));
      ++count[cell[s - b] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    std::vector<std::uint32_t> sorted(e - b);
    std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
    for (std::uint32_t s = b; s < e; ++s) sorted[fill[cell[s - b]]++] = ids_[s];
    std::copy(sorted.begin(), sorted.end(), ids_.begin() + b);
  }
  for (std::size_t c = 0; c <= cells; ++c) begin_[first + c] = b + count[c];
  if (depth >= kMaxDepth) return;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::uint32_t cb = b + count[c], ce = b + count[c + 1];
    if (ce - cb <= kLeafPoints) continue;
    Box box{points[ids_[cb]], points[ids_[cb]]};
    for (std::uint32_t s = cb; s < ce; ++s)
      for (int a = 0; a < 3; ++a) {
        box.lo[a] = std::min(box.lo[a], points[ids_[s]][a]);
        box.hi[a] = std::max(box.hi[a], points[ids_[s]][a]);
      }
    if (box.lo == box.hi) continue;  // coincident points: nothing to separate
    const auto nested = static_cast<std::int32_t>(nodes_.size());
    build(points, box, cb, ce, per_cell, depth + 1);
    child_[first + c] = nested;
  }
}

BoxCells::BoxCells(const GridFrame& frame, std::vector<Box> boxes)
    : frame_(frame), boxes_(std::move(boxes)) {
  std::vector<std::uint32_t> all(boxes_.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
  grid_detail::Buckets b = grid_detail::bucket(frame_, boxes_, all);
  start_ = std::move(b.start);
  ids_ = std::move(b.ids);
  clear_.resize(frame_.size());
  for (std::size_t c = 0; c < clear_.size(); ++c) clear_[c] = start_[c + 1] > start_[c] ? 0 : kClear;
  const auto& dims = frame_.dims();
  std::vector<std::uint8_t> line;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto n = static_cast<std::size_t>(dims[axis]);
    const std::size_t stride = axis == 0 ? 1
                               : axis == 1 ? static_cast<std::size_t>(dims[0])
                                           : static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]);
    line.resize(n);
    for (std::size_t first = 0; first < clear_.size(); ++first) {
      if ((first / stride) % n != 0) continue;  // not the start of a line along the axis
      for (std::size_t x = 0; x < n; ++x) line[x] = clear_[first + x * stride];
      for (std::size_t x = 0; x < n; ++x) {
        int d = line[x];
        for (int k = 1; k < d; ++k) {  // a neighbour k cells away offers max(k, its d) >= k
          const auto uk = static_cast<std::size_t>(k);
          if (x >= uk) d = std::min(d, std::max<int>(k, line[x - uk]));
          if (x + uk < n) d = std::min(d, std::max<int>(k, line[x + uk]));
        }
        clear_[first + x * stride] = static_cast<std::uint8_t>(d);
      }
    }
  }
}

bool BoxCells::meets(const Box& box) const {
  const auto a = frame_.cell_of(box.lo), z = frame_.cell_of(box.hi);
  const int span = std::max({z[0] - a[0], z[1] - a[1], z[2] - a[2]});
  if (clear_[frame_.index(a)] > span) return false;
  for (int k = a[2]; k <= z[2]; ++k)
    for (int j = a[1]; j <= z[1]; ++j)
      for (int i = a[0]; i <= z[0]; ++i) {
        const std::size_t cell = frame_.index(i, j, k);
        for (std::size_t s = start_[cell]; s < start_[cell + 1]; ++s)
          if (boxes_meet(box, boxes_[ids_[s]])) return true;
      }
  return false;
}

namespace grid_detail {

Buckets bucket(const GridFrame& frame, std::span<const Box> boxes, std::span<const std::uint32_t> ids,
               bool separating) {
  Buckets out;
  out.start.assign(frame.size() + 1, 0);
  auto each_cell = [&](const Box& b, auto&& f) {
    const auto a = frame.cell_of(b.lo), z = frame.cell_of(b.hi);
    for (int k = a[2]; k <= z[2]; ++k)
      for (int j = a[1]; j <= z[1]; ++j)
        for (int i = a[0]; i <= z[0]; ++i) f(frame.index(i, j, k));
  };
  for (std::uint32_t t : ids) each_cell(boxes[t], [&](std::size_t c) { ++out.start[c + 1]; });
  if (separating) {
    std::size_t total = 0, largest = 0;
    for (std::size_t c = 1; c < out.start.size(); ++c)
      total += out.start[c], largest = std::max(largest, out.start[c]);
    if (largest >= ids.size() || total > 4 * ids.size()) {
      out.ok = false;
      return out;
    }
  }
  for (std::size_t c = 0; c + 1 < out.start.size(); ++c) out.start[c + 1] += out.start[c];
  out.ids.resize(out.start.back());
  std::vector<std::size_t> fill(out.start.begin(), out.start.end() - 1);
  for (std::uint32_t t : ids) each_cell(boxes[t], [&](std::size_t c) { out.ids[fill[c]++] = t; });
  return out;
}

Box extent_of(std::span<const Box> boxes, std::span<const std::uint32_t> ids) {
  Box all = ids.empty() ? Box{} : boxes[ids[0]];
  for (std::uint32_t t : ids)
    for (int i = 0; i < 3; ++i) {
      const Box& b = boxes[t];
      all.lo[i] = std::min(all.lo[i], b.lo[i]);
      all.hi[i] = std::max(all.hi[i], b.hi[i]);
    }
  return all;
}

}  // namespace grid_detail

}  // namespace pdr::check
