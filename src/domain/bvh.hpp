// A bounding-volume hierarchy over axis-aligned boxes: the spatial index of the domain
// analysis (crossing facets, vertices on segments, rays, and the distance d of paper §2.1),
// so that none of them loops over all pairs of components.
//
// Boxes are closed and built from input doubles, so box overlap tests are exact. The
// hierarchy is a binary tree split at the median of the longest axis of the box centres,
// with at most 4 items per leaf: depth O(log n), build O(n log n).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "geom/point.hpp"

namespace pdr::domain {

struct Box {
  Point lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Point hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};
  void add(const Point& p);
  void add(const Box& b);
  bool overlaps(const Box& b) const;
  bool empty() const { return lo[0] > hi[0]; }
};

// Squared distance between two boxes in floating point (0 when they overlap). A lower
// bound of the distance between anything inside them, up to rounding.
double box_gap2(const Box& a, const Box& b);

class Bvh {
 public:
  Bvh() = default;
  explicit Bvh(std::vector<Box> boxes);

  std::size_t size() const { return boxes_.size(); }
  const Box& box(std::uint32_t item) const { return boxes_[item]; }

  // Calls f(item) for every item whose box overlaps q.
  template <class F>
  void for_overlapping(const Box& q, F&& f) const {
    if (nodes_.empty()) return;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const Node& n = nodes_[stack.back()];
      stack.pop_back();
      if (!n.box.overlaps(q)) continue;
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
          if (boxes_[order_[i]].overlaps(q)) f(order_[i]);
      } else {
        stack.push_back(n.first);
        stack.push_back(n.first + 1);
      }
    }
  }

  // Calls f(item) for every item whose box passes `keep(box)`; `keep` must hold for a node
  // box whenever it holds for a box inside it (a monotone filter, such as "meets a ray").
  template <class Keep, class F>
  void for_each_kept(Keep&& keep, F&& f) const {
    if (nodes_.empty()) return;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const Node& n = nodes_[stack.back()];
      stack.pop_back();
      if (!keep(n.box)) continue;
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
          if (keep(boxes_[order_[i]])) f(order_[i]);
      } else {
        stack.push_back(n.first);
        stack.push_back(n.first + 1);
      }
    }
  }

  // Branch and bound: visits nodes nearest-first by key(box) (a lower bound of whatever
  // leaf(item) can find in that box) and skips those with key >= bound(), which leaf may
  // lower as it goes.
  template <class Key, class Bound, class Leaf>
  void branch_and_bound(Key&& key, Bound&& bound, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    struct Entry {
      std::uint32_t node;
      double key;
    };
    std::vector<Entry> stack{{0, key(nodes_[0].box)}};
    while (!stack.empty()) {
      const Entry e = stack.back();
      stack.pop_back();
      if (e.key >= bound()) continue;
      const Node& n = nodes_[e.node];
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
          if (key(boxes_[order_[i]]) < bound()) leaf(order_[i]);
        continue;
      }
      const double k0 = key(nodes_[n.first].box), k1 = key(nodes_[n.first + 1].box);
      // Push the farther child first so that the nearer one is explored first.
      if (k0 <= k1) {
        stack.push_back({n.first + 1, k1});
        stack.push_back({n.first, k0});
      } else {
        stack.push_back({n.first, k0});
        stack.push_back({n.first + 1, k1});
      }
    }
  }

 private:
  struct Node {
    Box box;
    std::uint32_t first = 0;  // leaf: first index into order_; inner: index of left child
    std::uint32_t count = 0;  // leaf: number of items; inner: 0
  };
  void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end);

  std::vector<Box> boxes_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace pdr::domain
