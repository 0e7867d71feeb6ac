// Points and signs: the two value types every geometric decision in pdr speaks.
//
// A Point is three doubles, exactly as read from input or constructed; predicates treat
// them as exact rationals. Sign is what every predicate returns (STYLE §4).
#pragma once

#include <array>
#include <cstdint>

namespace pdr {

using Point = std::array<double, 3>;

enum class Sign : std::int8_t { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}
constexpr int to_int(Sign s) { return static_cast<int>(s); }
template <class T>
constexpr Sign sign_of(T x) {
  return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero);
}

// The lexicographic order of points by (x, y, z). Symbolic perturbation ranks points by
// this order, never by index or address, so every insertion order agrees (STYLE §5).
constexpr bool lex_less(const Point& a, const Point& b) {
  if (a[0] != b[0]) return a[0] < b[0];
  if (a[1] != b[1]) return a[1] < b[1];
  return a[2] < b[2];
}

}  // namespace pdr
