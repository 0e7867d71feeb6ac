// Stage 1 of the adaptive predicates: floating-point filters with proven error bounds.
//
// Each filter evaluates its determinant in double precision on translated coordinates (as
// in Shewchuk 1997, §4.3) together with its "permanent" P (the same expression with every
// product replaced by its absolute value), and returns the sign when |det| > c*P, Zero when
// P == 0, and Unsure otherwise. Callable alone; predicates.hpp falls back to stage 2
// (stage2.hpp, exact expansion arithmetic) on Unsure.
//
// Error bound (proof; u = 2^-53 is the unit roundoff). Write the exact determinant as
// det = sum_j s_j t_j, t_j monomials in the exact coordinate differences. Each t_j reaches
// the computed det_fl through at most K roundings (counted below per filter: the rounded
// differences, products and sums on its path), so det_fl = sum_j s_j t_j (1 + th_j) with
// |th_j| <= g_K = K u / (1 - K u) (Higham, Accuracy and Stability, Lemma 3.1). Hence
// |det_fl - det| <= g_K * sum_j |t_j|. The permanent is computed with the same tree and the
// same rounded products, so P_fl >= (1 - u)^K * sum_j |t_j|, and fl(c * P_fl) >= (1-u) c P_fl.
// With c = (K + 1) u: (K + 1)(1 - u)^(K+1)(1 - K u) >= K whenever (K + 1)(2K + 1) u <= 1,
// so the computed bound exceeds the error and |det_fl| > bound implies sign(det_fl) =
// sign(det). If P_fl == 0, every t_j has a zero factor (a rounded difference is 0 only if
// the difference is), so det = 0. A fused multiply-add only removes roundings from a path,
// so the bound also holds if the compiler contracts (this header may be inlined anywhere).
// Overflow makes det or P infinite or NaN; every comparison then fails: Unsure.
//
// Range (no underflow, no overflow; tested in tests/geom): if every coordinate is an
// integer multiple of l = 2^(-E-52) of magnitude at most 2^E (so 0 and every double in
// [2^-E, 2^E] qualify), every nonzero intermediate of the filters is a normal double, and
// stage 2 is exact too: E = 450 for orient2d, 270 for orient3d, 190 for incircle and
// incircle3, 130 for insphere. Proof sketch: differences are multiples of l, so a nonzero
// rounded difference is >= l; a rounded product of such values is >= their product; a
// cancelling sum of doubles >= x is >= 2^-53 x. Insphere: lift >= l^2, 3x3 minor >=
// 2^-106 l^3, so the smallest product is >= 2^-106 l^5 >= 2^-1022 for E <= 131; its
// permanent is <= 2^(5E+12) < 2^1023. Stage 2's components are multiples of l^degree
// (>= 2^-1074) and its split arguments stay below 2^995. Likewise orient2d: l^2;
// orient3d: 2^-53 l^3; incircle(3): 2^-53 l^4.
#pragma once

#include <cmath>
#include <cstdint>

#include "geom/point.hpp"

namespace pdr {

enum class Filtered : std::int8_t { Negative = -1, Zero = 0, Positive = 1, Unsure = 2 };

namespace filter {

inline constexpr double unit_roundoff = 0x1p-53;

// The decision shared by all filters; coefficient = (K + 1) * unit_roundoff.
// Written without data-dependent branches on the sign (a random sign mispredicts a branch).
inline Filtered decide(double det, double permanent, double coefficient) {
  const double bound = coefficient * permanent;
  const int sign = static_cast<int>(det > bound) - static_cast<int>(det < -bound);
  const int unsure = static_cast<int>(sign == 0) & static_cast<int>(permanent != 0);
  return static_cast<Filtered>(sign + 2 * unsure);
}

// det[b - a, c - a]. K = 4: two differences, one product, one sum.
inline Filtered orient2d(const double* a, const double* b, const double* c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double vx = c[0] - a[0], vy = c[1] - a[1];
  const double l = ux * vy, r = uy * vx;
  return decide(l - r, std::fabs(l) + std::fabs(r), 5 * unit_roundoff);
}

// det[b - a, c - a, d - a] = u . (v x w). K = 8: the 2x2 minor of v, w (2 differences,
// product, sum), times a difference of u (2), and two sums.
inline Filtered orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double vywz = vy * wz, vzwy = vz * wy;
  const double vzwx = vz * wx, vxwz = vx * wz;
  const double vxwy = vx * wy, vywx = vy * wx;
  const double det = (ux * (vywz - vzwy) + uy * (vzwx - vxwz)) + uz * (vxwy - vywx);
  const double perm = (std::fabs(ux) * (std::fabs(vywz) + std::fabs(vzwy)) +
                       std::fabs(uy) * (std::fabs(vzwx) + std::fabs(vxwz))) +
                      std::fabs(uz) * (std::fabs(vxwy) + std::fabs(vywx));
  return decide(det, perm, 9 * unit_roundoff);
}

// det[(p - d, |p - d|^2)] for p = a, b, c. K = 11: lift (2 differences, product, sum),
// minor (4), their product, two sums.
inline Filtered incircle(const double* a, const double* b, const double* c, const double* d) {
  const double ax = a[0] - d[0], ay = a[1] - d[1];
  const double bx = b[0] - d[0], by = b[1] - d[1];
  const double cx = c[0] - d[0], cy = c[1] - d[1];
  const double bxcy = bx * cy, cxby = cx * by;
  const double cxay = cx * ay, axcy = ax * cy;
  const double axby = ax * by, bxay = bx * ay;
  const double al = ax * ax + ay * ay, bl = bx * bx + by * by, cl = cx * cx + cy * cy;
  const double det = (al * (bxcy - cxby) + bl * (cxay - axcy)) + cl * (axby - bxay);
  const double perm = (al * (std::fabs(bxcy) + std::fabs(cxby)) +
                       bl * (std::fabs(cxay) + std::fabs(axcy))) +
                      cl * (std::fabs(axby) + std::fabs(bxay));
  return decide(det, perm, 12 * unit_roundoff);
}

// sum_i (-1)^i |p_i - e|^2 det3[the other three of p - e], p = a, b, c, d (the 3x3 minors
// expanded along z). K = 16: lift (2 differences, product, 2 sums), 3x3 minor (2x2 minor 4,
// difference, product, 2 sums), their product, 2 sums.
inline Filtered insphere(const double* a, const double* b, const double* c, const double* d,
                         const double* e) {
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  // xy(p, q) = p_x q_y - p_y q_x, kept as its two rounded products.
  const double ab1 = ax * by, ab2 = ay * bx, ac1 = ax * cy, ac2 = ay * cx;
  const double ad1 = ax * dy, ad2 = ay * dx, bc1 = bx * cy, bc2 = by * cx;
  const double bd1 = bx * dy, bd2 = by * dx, cd1 = cx * dy, cd2 = cy * dx;
  const double ab = ab1 - ab2, ac = ac1 - ac2, ad = ad1 - ad2;
  const double bc = bc1 - bc2, bd = bd1 - bd2, cd = cd1 - cd2;
  const double pab = std::fabs(ab1) + std::fabs(ab2), pac = std::fabs(ac1) + std::fabs(ac2);
  const double pad = std::fabs(ad1) + std::fabs(ad2), pbc = std::fabs(bc1) + std::fabs(bc2);
  const double pbd = std::fabs(bd1) + std::fabs(bd2), pcd = std::fabs(cd1) + std::fabs(cd2);
  const double fax = std::fabs(az), fbz = std::fabs(bz), fcz = std::fabs(cz);
  const double fdz = std::fabs(dz);
  // det3(p, q, r) = p_z xy(q, r) - q_z xy(p, r) + r_z xy(p, q).
  const double ma = (bz * cd - cz * bd) + dz * bc, pa = (fbz * pcd + fcz * pbd) + fdz * pbc;
  const double mb = (az * cd - cz * ad) + dz * ac, pb = (fax * pcd + fcz * pad) + fdz * pac;
  const double mc = (az * bd - bz * ad) + dz * ab, pc = (fax * pbd + fbz * pad) + fdz * pab;
  const double md = (az * bc - bz * ac) + cz * ab, pd = (fax * pbc + fbz * pac) + fcz * pab;
  const double al = (ax * ax + ay * ay) + az * az, bl = (bx * bx + by * by) + bz * bz;
  const double cl = (cx * cx + cy * cy) + cz * cz, dl = (dx * dx + dy * dy) + dz * dz;
  const double det = (al * ma - bl * mb) + (cl * mc - dl * md);
  const double perm = (al * pa + bl * pb) + (cl * pc + dl * pd);
  return decide(det, perm, 17 * unit_roundoff);
}

// The coordinate plane for incircle3: the axis k maximising |n_k| of n = (b-a)x(c-a), and
// the certified sign of n_k (Unsure if even the largest component is not certain). The
// projection onto the coordinates (k+1, k+2) mod 3 has orient2d(a,b,c) = n_k.
struct PlaneAxis {
  int axis;
  Filtered sign;
};
inline PlaneAxis plane_axis(const double* a, const double* b, const double* c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double l[3] = {uy * vz, uz * vx, ux * vy};
  const double r[3] = {uz * vy, ux * vz, uy * vx};
  const double n[3] = {l[0] - r[0], l[1] - r[1], l[2] - r[2]};
  int k = 0;
  if (std::fabs(n[1]) > std::fabs(n[k])) k = 1;
  if (std::fabs(n[2]) > std::fabs(n[k])) k = 2;
  return {k, decide(n[k], std::fabs(l[k]) + std::fabs(r[k]), 5 * unit_roundoff)};
}

// incircle on the plane of coplanar a, b, c, d: the 2D incircle of the projection along
// `axis`, with lifts |p - d|^2 in 3D (equal to the 2D lifted determinant because p - d is
// in the plane), times the sign of n_k. K = 12: as incircle, with one more sum per lift.
inline Filtered incircle3(const double* a, const double* b, const double* c, const double* d) {
  const PlaneAxis pl = plane_axis(a, b, c);
  if (pl.sign == Filtered::Unsure || pl.sign == Filtered::Zero) return Filtered::Unsure;
  const int i = (pl.axis + 1) % 3, j = (pl.axis + 2) % 3, k = pl.axis;
  const double ax = a[i] - d[i], ay = a[j] - d[j], az = a[k] - d[k];
  const double bx = b[i] - d[i], by = b[j] - d[j], bz = b[k] - d[k];
  const double cx = c[i] - d[i], cy = c[j] - d[j], cz = c[k] - d[k];
  const double bxcy = bx * cy, cxby = cx * by;
  const double cxay = cx * ay, axcy = ax * cy;
  const double axby = ax * by, bxay = bx * ay;
  const double al = (ax * ax + ay * ay) + az * az, bl = (bx * bx + by * by) + bz * bz;
  const double cl = (cx * cx + cy * cy) + cz * cz;
  const double det = (al * (bxcy - cxby) + bl * (cxay - axcy)) + cl * (axby - bxay);
  const double perm = (al * (std::fabs(bxcy) + std::fabs(cxby)) +
                       bl * (std::fabs(cxay) + std::fabs(axcy))) +
                      cl * (std::fabs(axby) + std::fabs(bxay));
  const Filtered s = decide(det, perm, 13 * unit_roundoff);
  if (s == Filtered::Unsure || pl.sign == Filtered::Positive) return s;
  return static_cast<Filtered>(-static_cast<int>(s));
}

}  // namespace filter
}  // namespace pdr
