// Semi-static floating-point filters for the two hot predicates of the kernel: orient3d
// (the walk) and insphere (the cavity search). A stage-1 filter in the sense of
// geom/filter.hpp -- it returns the exact sign or Unsure, never a wrong sign -- but its
// error bound is computed from the largest coordinate differences instead of the
// permanent, which saves about a third of the work. Callers fall back to the full
// adaptive predicates (geom/predicates.hpp) on Unsure.
//
// Proof. Let u = 2^-53. The determinant is evaluated exactly as in geom/filter.hpp (same
// expression tree), whose proof gives |det_fl - det| <= g_K * S, S = sum_j |t_j| over the
// monomials t_j of the determinant in the exact coordinate differences, g_K = K u/(1-K u),
// K = 8 for orient3d and 16 for insphere. Bounding S: every exact difference is at most
// its rounded value over (1 - u); write mx, my, mz for the largest rounded |difference| per
// axis and L for the largest computed lifted norm x^2+y^2+z^2 (3 roundings, so an exact
// lift is <= L/(1-u)^5).
//   orient3d: det[u,v,w] has 6 monomials, each |x y z| <= mx my mz / (1-u)^3, so
//             S <= 6 mx my mz / (1-u)^3.
//   insphere: det = sum over 4 rows of +-lift * (3x3 minor of 6 monomials |x y z|), so
//             S <= 24 L mx my mz / (1-u)^8.
// The bound is computed as B = fl(((C * L) * mx) * my) * mz) >= C L mx my mz (1-u)^4 with
// C = (K+1) u (1 + 2^-40) * {6 | 24} (exact in binary). Then B >= g_K S whenever
// (K+1)(1 + 2^-40)(1-u)^12 (1-Ku) >= K, which holds with room to spare; so |det_fl| > B
// implies sign(det_fl) = sign(det). If an axis has no nonzero difference, every monomial
// and det_fl are 0 and the filter answers Unsure (the adaptive predicate then says Zero).
// Range: as in filter.hpp (no underflow for coordinates 0 or of magnitude in
// [2^-130, 2^130]); overflow gives inf or NaN, every comparison fails: Unsure.
// Tested against the GMP predicates in tests/delaunay/semistatic_test.cpp.
#pragma once

#include <algorithm>
#include <cmath>

#include "geom/filter.hpp"

namespace pdr::semistatic {

inline constexpr double kOrient3dBound = 9.0 * 6.0 * (1.0 + 0x1p-40) * 0x1p-53;
inline constexpr double kInsphereBound = 17.0 * 24.0 * (1.0 + 0x1p-40) * 0x1p-53;

inline Filtered decide(double det, double bound) {
  if (det > bound) return Filtered::Positive;
  if (det < -bound) return Filtered::Negative;
  return Filtered::Unsure;
}

// orient3d(a,b,c,d) = sign det[b-a, c-a, d-a].
inline Filtered orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double det = (ux * (vy * wz - vz * wy) + uy * (vz * wx - vx * wz)) +
                     uz * (vx * wy - vy * wx);
  const double mx = std::max(std::max(std::fabs(ux), std::fabs(vx)), std::fabs(wx));
  const double my = std::max(std::max(std::fabs(uy), std::fabs(vy)), std::fabs(wy));
  const double mz = std::max(std::max(std::fabs(uz), std::fabs(vz)), std::fabs(wz));
  return decide(det, ((kOrient3dBound * mx) * my) * mz);
}

// insphere(a,b,c,d,e) > 0: e inside the sphere of the positive tet abcd.
inline Filtered insphere(const double* a, const double* b, const double* c, const double* d,
                         const double* e) {
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  const double ab = ax * by - ay * bx, ac = ax * cy - ay * cx, ad = ax * dy - ay * dx;
  const double bc = bx * cy - by * cx, bd = bx * dy - by * dx, cd = cx * dy - cy * dx;
  const double ma = (bz * cd - cz * bd) + dz * bc;
  const double mb = (az * cd - cz * ad) + dz * ac;
  const double mc = (az * bd - bz * ad) + dz * ab;
  const double md = (az * bc - bz * ac) + cz * ab;
  const double al = (ax * ax + ay * ay) + az * az, bl = (bx * bx + by * by) + bz * bz;
  const double cl = (cx * cx + cy * cy) + cz * cz, dl = (dx * dx + dy * dy) + dz * dz;
  const double det = (al * ma - bl * mb) + (cl * mc - dl * md);
  const double mx = std::max(std::max(std::fabs(ax), std::fabs(bx)),
                             std::max(std::fabs(cx), std::fabs(dx)));
  const double my = std::max(std::max(std::fabs(ay), std::fabs(by)),
                             std::max(std::fabs(cy), std::fabs(dy)));
  const double mz = std::max(std::max(std::fabs(az), std::fabs(bz)),
                             std::max(std::fabs(cz), std::fabs(dz)));
  const double l = std::max(std::max(al, bl), std::max(cl, dl));
  return decide(det, (((kInsphereBound * l) * mx) * my) * mz);
}

}  // namespace pdr::semistatic
