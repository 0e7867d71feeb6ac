// The dominance order of symbolic perturbation (SoS), shared by sos.cpp and exact.cpp.
//
// Following Devillers & Teillaud (2011), "Perturbations for Delaunay and weighted Delaunay
// 3D triangulations", the lifted coordinate |p|^2 of each point of one predicate call is
// raised by a positive infinitesimal eps(p), and eps(p) >> eps(q) whenever p is
// lexicographically *larger* than q (lex_less on (x, y, z); (x, y) for planar points).
// The perturbed determinant is affine in the lift column, D0 + sum_p eps(p) * C(p), so its
// sign is that of D0, else that of the first nonzero C(p) with p taken in this order:
// lex-largest point first. Equal points (a precondition violation) are ranked by argument
// position, the later argument counting as larger, so the result is still a function of
// the arguments alone. The order never depends on indices or addresses (docs/design.md §5).
#pragma once

#include <array>
#include <cstddef>

#include "geom/point.hpp"

namespace pdr::sos {

// Lexicographic order of planar points by (x, y).
constexpr bool lex_less2(const double* a, const double* b) {
  if (a[0] != b[0]) return a[0] < b[0];
  return a[1] < b[1];
}

// Argument positions 0..N-1 sorted so that the dominant (lex-largest) point comes first.
// `less(i, j)` must say whether argument i is lexicographically smaller than argument j.
template <std::size_t N, class Less>
constexpr std::array<int, N> dominance_order(Less less) {
  std::array<int, N> order{};
  for (std::size_t i = 0; i < N; ++i) order[i] = static_cast<int>(i);
  // Insertion sort, descending: i before j iff j is smaller, or equal and j earlier.
  for (std::size_t i = 1; i < N; ++i) {
    const int x = order[i];
    std::size_t k = i;
    while (k > 0) {
      const int y = order[k - 1];
      const bool x_dominates = less(y, x) || (!less(x, y) && x > y);
      if (!x_dominates) break;
      order[k] = y;
      --k;
    }
    order[k] = x;
  }
  return order;
}

template <std::size_t N>
constexpr std::array<int, N> dominance_order(const std::array<const Point*, N>& p) {
  return dominance_order<N>([&](int i, int j) { return lex_less(*p[i], *p[j]); });
}

template <std::size_t N>
constexpr std::array<int, N> dominance_order2(const std::array<const double*, N>& p) {
  return dominance_order<N>([&](int i, int j) { return lex_less2(p[i], p[j]); });
}

}  // namespace pdr::sos
