// infer_precision and planarity_tolerance: see io/precision.hpp.
#include "io/precision.hpp"

#include <charconv>
#include <cmath>
#include <limits>

namespace pdr::io {

namespace {

// The significant digits of x's shortest round-trip decimal form (x != 0, finite).
int significant_digits(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific);
  int digits = 0;
  for (const char* p = buf; p != r.ptr && *p != 'e'; ++p)
    if (*p >= '0' && *p <= '9') ++digits;
  return digits;
}

// Whether x is a float's value. Through a volatile float: GCC 12's SLP vectorizer drops
// a double -> float -> double round trip written over an array's elements at -O2.
bool is_float(double x) {
  if (!(std::fabs(x) <= std::numeric_limits<float>::max())) return false;
  const volatile float f = static_cast<float>(x);
  return static_cast<double>(f) == x;
}

}  // namespace

CoordinatePrecision infer_precision(std::span<const Point> points) {
  CoordinatePrecision out;
  int digits = 0;
  bool floats = true, full = false;
  double largest = 0;
  Point lo{}, hi{};
  bool first = true;
  for (const Point& p : points) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
    for (int k = 0; k < 3; ++k) {
      lo[k] = first ? p[k] : std::min(lo[k], p[k]);
      hi[k] = first ? p[k] : std::max(hi[k], p[k]);
    }
    first = false;
    for (const double x : p) {
      if (x == 0) continue;
      largest = std::max(largest, std::fabs(x));
      if (full) continue;  // full double precision: only the magnitude is wanted now
      floats = floats && is_float(x);
      digits = std::max(digits, significant_digits(x));
      full = digits > 15 && !floats;
    }
  }
  // The rounding of the largest coordinate: half a unit in its last place, that is the
  // relative rounding times the place of its leading digit (a power of ten for decimals,
  // of two for floats); every smaller coordinate is rounded at that place or finer.
  double rounding = 0;
  if (full) {
    out.digits = 17;
    rounding = kComputedRounding * largest;
  } else {
    out.digits = digits;
    if (digits <= kExactDigits) return out;  // short decimals: exact values
    if (digits > 9 && floats) {
      out.float32 = true;
      rounding = std::ldexp(1.0, std::ilogb(largest) - 24);
    } else {
      rounding = 5 * std::pow(10.0, std::floor(std::log10(largest)) - digits);
    }
  }
  const double diameter = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  out.uncertainty = std::min(rounding * std::sqrt(3.0), kMaxUncertainty * diameter);
  return out;
}

PlanarityTolerance planarity_tolerance_of(std::span<const Point> points, double relative) {
  return {relative, relative > 0 ? infer_precision(points) : CoordinatePrecision{}};
}

PlanarityTolerance planarity_tolerance_of(const Plc& plc, double relative) {
  if (plc.precision.digits == 0) return planarity_tolerance_of(plc.points, relative);
  return {relative, relative > 0 ? plc.precision : CoordinatePrecision{}};
}

}  // namespace pdr::io
