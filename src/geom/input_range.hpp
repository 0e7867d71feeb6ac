// The coordinates pdr accepts as mesher input: finite, and 0 or of magnitude in
// [2^-100, 2^100] (about 7.9e-31 .. 1.3e30). Inside it, and for the points constructed
// from such input (midpoints, circumcenters inside the domain), the adaptive predicates'
// filters never underflow or overflow (predicates.hpp, filter.hpp: the tightest range is
// insphere's, 2^+-130), so their fast path is exact. Readers accept any finite doubles
// (the checker decides foreign meshes in GMP where needed); the mesher entry points reject
// input outside this range with a message that says to rescale.
#pragma once

#include <cmath>

#include "geom/point.hpp"

namespace pdr {

inline constexpr double kMinInputMagnitude = 0x1p-100;
inline constexpr double kMaxInputMagnitude = 0x1p+100;

inline bool in_input_range(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m >= kMinInputMagnitude && m <= kMaxInputMagnitude);
}

inline bool in_input_range(const Point& p) {
  return in_input_range(p[0]) && in_input_range(p[1]) && in_input_range(p[2]);
}

}  // namespace pdr
