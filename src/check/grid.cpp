// Uniform grids (see grid.hpp for the monotonicity argument that makes queries complete).
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

PointGrid::PointGrid(std::span<const Point> points, double per_cell)
    : frame_(bounding_box(points), static_cast<double>(points.size()) / per_cell) {
  const std::size_t n = points.size();
  std::vector<std::uint32_t> cell(n);
  start_.assign(frame_.size() + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = frame_.cell_of(points[i]);
    cell[i] = static_cast<std::uint32_t>(frame_.index(c[0], c[1], c[2]));
    ++start_[cell[i] + 1];
  }
  for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
  ids_.resize(n);
  sorted_.resize(n);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t s = fill[cell[i]]++;
    ids_[s] = static_cast<std::uint32_t>(i);
    sorted_[s] = points[i];
  }
}

BoxGrid::BoxGrid(std::span<const Box> boxes, double cells) {
  Box all = boxes.empty() ? Box{} : boxes[0];
  for (const Box& b : boxes)
    for (int i = 0; i < 3; ++i) {
      all.lo[i] = std::min(all.lo[i], b.lo[i]);
      all.hi[i] = std::max(all.hi[i], b.hi[i]);
    }
  frame_ = GridFrame(all, cells);
  start_.assign(frame_.size() + 1, 0);
  auto each_cell = [&](const Box& b, auto&& f) {
    const auto a = frame_.cell_of(b.lo), z = frame_.cell_of(b.hi);
    for (int k = a[2]; k <= z[2]; ++k)
      for (int j = a[1]; j <= z[1]; ++j)
        for (int i = a[0]; i <= z[0]; ++i) f(frame_.index(i, j, k));
  };
  for (const Box& b : boxes) each_cell(b, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
  ids_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t t = 0; t < boxes.size(); ++t)
    each_cell(boxes[t], [&](std::size_t c) { ids_[fill[c]++] = static_cast<std::uint32_t>(t); });
}

}  // namespace pdr::check
