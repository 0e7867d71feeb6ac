// Bounding-volume hierarchy for the domain analysis (paper §1.1, §2.1); see domain/bvh.hpp.
#include "domain/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace pdr::domain {

void Box::add(const Point& p) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], p[k]);
    hi[k] = std::max(hi[k], p[k]);
  }
}

void Box::add(const Box& b) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], b.lo[k]);
    hi[k] = std::max(hi[k], b.hi[k]);
  }
}

bool Box::overlaps(const Box& b) const {
  for (int k = 0; k < 3; ++k)
    if (b.hi[k] < lo[k] || hi[k] < b.lo[k]) return false;
  return true;
}

double box_gap2(const Box& a, const Box& b) {
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    double g = 0;
    if (b.lo[k] > a.hi[k]) g = b.lo[k] - a.hi[k];
    else if (a.lo[k] > b.hi[k]) g = a.lo[k] - b.hi[k];
    s += g * g;
  }
  return s;
}

Bvh::Bvh(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
  if (boxes_.empty()) return;
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * boxes_.size());
  nodes_.emplace_back();
  build(0, 0, static_cast<std::uint32_t>(order_.size()));
}

void Bvh::build(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
  Box box, centres;
  for (std::uint32_t i = begin; i < end; ++i) {
    const Box& b = boxes_[order_[i]];
    box.add(b);
    centres.add(Point{0.5 * (b.lo[0] + b.hi[0]), 0.5 * (b.lo[1] + b.hi[1]),
                      0.5 * (b.lo[2] + b.hi[2])});
  }
  nodes_[node].box = box;
  if (end - begin <= 4) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (centres.hi[k] - centres.lo[k] > centres.hi[axis] - centres.lo[axis]) axis = k;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t x, std::uint32_t y) {
                     return boxes_[x].lo[axis] + boxes_[x].hi[axis] <
                            boxes_[y].lo[axis] + boxes_[y].hi[axis];
                   });
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build(left, begin, mid);
  build(left + 1, mid, end);
}

}  // namespace pdr::domain
