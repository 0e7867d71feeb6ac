// The input range within which stage 2 (expansion arithmetic) is exact, and the guard that
// sends inputs outside it to the GMP reference (exact.hpp), so that every predicate is
// exact for all finite doubles: fast within the range, slow but right outside it.
//
// A coordinate x is in range E when x == 0 or 2^-E <= |x| <= 2^E; such an x is a multiple
// of 2^(-E-52), which is what filter.hpp's underflow/overflow argument needs. E per
// predicate: 450 (orient2d), 270 (orient3d), 190 (incircle, incircle3), 130 (insphere).
#pragma once

#include <cmath>
#include <initializer_list>

namespace pdr::stage2 {

constexpr double pow2(int e) {
  double r = 1;
  for (; e > 0; --e) r *= 2;
  for (; e < 0; ++e) r /= 2;
  return r;
}

template <int E>
bool in_range(std::initializer_list<const double*> points, int dim) {
  constexpr double lo = pow2(-E), hi = pow2(E);
  for (const double* p : points)
    for (int k = 0; k < dim; ++k) {
      const double m = std::fabs(p[k]);
      if (m != 0 && !(m >= lo && m <= hi)) return false;
    }
  return true;
}

}  // namespace pdr::stage2
