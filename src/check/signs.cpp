// The checkers' exact signs: filter, 128-bit integers, GMP (see signs.hpp for the proofs).
#include "check/signs.hpp"

#include <gmpxx.h>

#include <array>
#include <bit>
#include <cmath>
#include <initializer_list>

#include "check/interval.hpp"
#include "check/qvec.hpp"
#include "geom/exact.hpp"

namespace pdr::check::signs {
namespace {

thread_local std::uint64_t g_exact = 0;

constexpr double kEps = 0x1p-53;
constexpr double kDet3Bound = (7.0 + 56.0 * kEps) * kEps;
constexpr double kLiftBound = (16.0 + 224.0 * kEps) * kEps;
constexpr double kOrient2Bound = (3.0 + 16.0 * kEps) * kEps;
constexpr double kMinEntry = 0x1p-150, kMaxEntry = 0x1p150;

bool in_range(double d) {
  const double a = std::fabs(d);
  return a == 0 || (a >= kMinEntry && a <= kMaxEntry);
}

}  // namespace

bool entry_in_range(double d) { return in_range(d); }

namespace {

std::optional<Sign> decide(double det, double bound) {
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  return std::nullopt;
}

using Vec = std::array<double, 3>;

Vec diff(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }

// det[u, v, w] for rounded differences u, v, w (Shewchuk's orient3d shape).
std::optional<Sign> det3_filter(const Vec& u, const Vec& v, const Vec& w) {
  for (const Vec* e : {&u, &v, &w})
    for (double x : *e)
      if (!in_range(x)) return std::nullopt;
  const double vywz = v[1] * w[2], vzwy = v[2] * w[1];
  const double wyuz = w[1] * u[2], wzuy = w[2] * u[1];
  const double uyvz = u[1] * v[2], uzvy = u[2] * v[1];
  const double det = u[0] * (vywz - vzwy) + v[0] * (wyuz - wzuy) + w[0] * (uyvz - uzvy);
  const double perm = std::fabs(u[0]) * (std::fabs(vywz) + std::fabs(vzwy)) +
                      std::fabs(v[0]) * (std::fabs(wyuz) + std::fabs(wzuy)) +
                      std::fabs(w[0]) * (std::fabs(uyvz) + std::fabs(uzvy));
  if (perm == 0) return Sign::Zero;  // every term has an exactly zero factor (signs.hpp)
  return decide(det, kDet3Bound * perm + 0x1p-1000);
}

// Common power-of-two scaling: x_i = X_i * 2^e with integers |X_i| < 2^bits, if possible.
// Reads the IEEE-754 fields directly: a finite nonzero double is m * 2^q with an integer
// m < 2^53 (m = fraction | 2^52 and q = exponent - 1075, or m = fraction and q = -1074 for
// subnormals).
template <std::size_t N>
bool to_ints(const std::array<double, N>& x, int bits, std::array<std::int64_t, N>& out) {
  std::array<std::uint64_t, N> mant{};
  std::array<int, N> q{};
  int low = 0, high = 0;
  bool any = false;
  for (std::size_t i = 0; i < N; ++i) {
    const auto u = std::bit_cast<std::uint64_t>(x[i]);
    const int e = static_cast<int>((u >> 52) & 0x7ff);
    const std::uint64_t f = u & ((std::uint64_t{1} << 52) - 1);
    if (e == 0x7ff) return false;  // inf, NaN
    if (e == 0 && f == 0) continue;  // +-0
    mant[i] = e == 0 ? f : (f | (std::uint64_t{1} << 52));
    q[i] = e == 0 ? -1074 : e - 1075;
    const int lo = q[i] + __builtin_ctzll(mant[i]);
    const int hi = q[i] + 64 - __builtin_clzll(mant[i]);  // |x| < 2^hi
    if (!any || lo < low) low = lo;
    if (!any || hi > high) high = hi;
    any = true;
  }
  if (any && high - low > bits) return false;
  for (std::size_t i = 0; i < N; ++i) {
    if (mant[i] == 0) {
      out[i] = 0;
      continue;
    }
    const int shift = q[i] - low;  // >= -ctz(mant): a right shift drops zero bits only
    const auto v = static_cast<std::int64_t>(shift >= 0 ? mant[i] << shift : mant[i] >> -shift);
    out[i] = std::signbit(x[i]) ? -v : v;
  }
  return true;
}

template <std::size_t K>
std::array<double, 3 * K> flatten(const std::array<const Point*, K>& p) {
  std::array<double, 3 * K> x{};
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t j = 0; j < 3; ++j) x[3 * i + j] = (*p[i])[j];
  return x;
}

using I128 = __int128;

I128 det3_i(const I128 u[3], const I128 v[3], const I128 w[3]) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) + v[0] * (w[1] * u[2] - w[2] * u[1]) +
         w[0] * (u[1] * v[2] - u[2] * v[1]);
}

Sign sign_i(I128 x) { return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero); }

// det[a1-a0, b1-b0, c1-c0] in integers, if the six points scale to 40-bit integers.
std::optional<Sign> det3_int(const std::array<const Point*, 6>& p) {
  std::array<std::int64_t, 18> X;
  if (!to_ints(flatten(p), 40, X)) return std::nullopt;
  I128 e[3][3];
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j < 3; ++j) e[r][j] = I128(X[3 * (2 * r + 1) + j]) - I128(X[3 * (2 * r) + j]);
  return sign_i(det3_i(e[0], e[1], e[2]));
}

using namespace qvec;
Sign qsign(const Q& x) { return pdr::sign_of(sgn(x)); }

}  // namespace

std::uint64_t exact_evaluations() { return g_exact; }

std::optional<Sign> orient3d_filter(const Point& a, const Point& b, const Point& c,
                                    const Point& d) {
  return det3_filter(diff(b, a), diff(c, a), diff(d, a));
}

std::optional<Sign> orient3d_int(const Point& a, const Point& b, const Point& c,
                                 const Point& d) {
  return det3_int({&a, &b, &a, &c, &a, &d});
}

Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (auto s = orient3d_filter(a, b, c, d)) return *s;
  if (auto s = orient3d_int(a, b, c, d)) return *s;
  ++g_exact;
  return exact::orient3d(a, b, c, d);
}

Plane::Plane(const Point& a, const Point& b, const Point& c) : a_(&a), b_(&b), c_(&c) {
  const Vec u = diff(b, a), v = diff(c, a);
  ok_ = true;
  for (int i = 0; i < 3; ++i) ok_ = ok_ && in_range(u[i]) && in_range(v[i]);
  const double p[6] = {u[1] * v[2], u[2] * v[1], u[2] * v[0], u[0] * v[2], u[0] * v[1], u[1] * v[0]};
  for (int i = 0; i < 3; ++i) {
    n_[i] = p[2 * i] - p[2 * i + 1];
    abs_[i] = std::fabs(p[2 * i]) + std::fabs(p[2 * i + 1]);
  }
}

Sign Plane::orient(const Point& q) const {
  if (ok_) {
    const Vec w = diff(q, *a_);
    if (in_range(w[0]) && in_range(w[1]) && in_range(w[2])) {
      const double det = w[0] * n_[0] + w[1] * n_[1] + w[2] * n_[2];
      const double perm = std::fabs(w[0]) * abs_[0] + std::fabs(w[1]) * abs_[1] + std::fabs(w[2]) * abs_[2];
      if (perm == 0) return Sign::Zero;  // as in det3_filter
      if (auto s = decide(det, kDet3Bound * perm + 0x1p-1000)) return *s;
    }
  }
  return orient3d(*a_, *b_, *c_, q);
}

Sign det3(const Point& a0, const Point& a1, const Point& b0, const Point& b1, const Point& c0,
          const Point& c1) {
  if (auto s = det3_filter(diff(a1, a0), diff(b1, b0), diff(c1, c0))) return *s;
  if (auto s = det3_int({&a0, &a1, &b0, &b1, &c0, &c1})) return *s;
  ++g_exact;
  const QVec u = qdiff(a1, a0), v = qdiff(b1, b0), w = qdiff(c1, c0);
  return qsign(qdot(u, qcross(v, w)));
}

// The lifted 4x4 determinant D = det[[p - e, |p - e|^2]] over rows p = a, b, c, d in
// Shewchuk's insphere shape; pdr's insphere is -sign(D) (see geom/exact.cpp).
std::optional<Sign> insphere_filter(const Point& a, const Point& b, const Point& c,
                                    const Point& d, const Point& e) {
  const Vec ae = diff(a, e), be = diff(b, e), ce = diff(c, e), de = diff(d, e);
  for (const Vec* v : {&ae, &be, &ce, &de})
    for (double x : *v)
      if (!in_range(x)) return std::nullopt;
  // 2x2 minors in (x, y); pq = p.x q.y - q.x p.y.
  const double aebe = ae[0] * be[1], beae = be[0] * ae[1], ab = aebe - beae;
  const double bece = be[0] * ce[1], cebe = ce[0] * be[1], bc = bece - cebe;
  const double cede = ce[0] * de[1], dece = de[0] * ce[1], cd = cede - dece;
  const double deae = de[0] * ae[1], aede = ae[0] * de[1], da = deae - aede;
  const double aece = ae[0] * ce[1], ceae = ce[0] * ae[1], ac = aece - ceae;
  const double bede = be[0] * de[1], debe = de[0] * be[1], bd = bede - debe;
  // 3x3 minors along z.
  const double abc = ae[2] * bc - be[2] * ac + ce[2] * ab;
  const double bcd = be[2] * cd - ce[2] * bd + de[2] * bc;
  const double cda = ce[2] * da + de[2] * ac + ae[2] * cd;
  const double dab = de[2] * ab + ae[2] * bd + be[2] * da;
  const double al = ae[0] * ae[0] + ae[1] * ae[1] + ae[2] * ae[2];
  const double bl = be[0] * be[0] + be[1] * be[1] + be[2] * be[2];
  const double cl = ce[0] * ce[0] + ce[1] * ce[1] + ce[2] * ce[2];
  const double dl = de[0] * de[0] + de[1] * de[1] + de[2] * de[2];
  const double det = (dl * abc - cl * dab) + (bl * cda - al * bcd);
  const double az = std::fabs(ae[2]), bz = std::fabs(be[2]), cz = std::fabs(ce[2]),
               dz = std::fabs(de[2]);
  const double pab = std::fabs(aebe) + std::fabs(beae), pbc = std::fabs(bece) + std::fabs(cebe);
  const double pcd = std::fabs(cede) + std::fabs(dece), pda = std::fabs(deae) + std::fabs(aede);
  const double pac = std::fabs(aece) + std::fabs(ceae), pbd = std::fabs(bede) + std::fabs(debe);
  const double perm = (pcd * bz + pbd * cz + pbc * dz) * al + (pda * cz + pac * dz + pcd * az) * bl +
                      (pab * dz + pbd * az + pda * bz) * cl + (pbc * az + pac * bz + pab * cz) * dl;
  const auto s = decide(det, kLiftBound * perm + 0x1p-700);
  if (!s) return std::nullopt;
  return -*s;
}

std::optional<Sign> insphere_int(const Point& a, const Point& b, const Point& c,
                                 const Point& d, const Point& e) {
  std::array<std::int64_t, 15> X;
  if (!to_ints(flatten<5>({&a, &b, &c, &d, &e}), 22, X)) return std::nullopt;
  I128 r[4][3], lift[4];
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) r[i][j] = I128(X[3 * i + j]) - I128(X[12 + j]);
    lift[i] = r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2];
  }
  // Laplace expansion along the lift column of det[[p - e, |p - e|^2]].
  const I128 D = -lift[0] * det3_i(r[1], r[2], r[3]) + lift[1] * det3_i(r[0], r[2], r[3]) -
                 lift[2] * det3_i(r[0], r[1], r[3]) + lift[3] * det3_i(r[0], r[1], r[2]);
  return -sign_i(D);
}

Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e) {
  if (auto s = insphere_filter(a, b, c, d, e)) return *s;
  if (auto s = insphere_int(a, b, c, d, e)) return *s;
  ++g_exact;
  return exact::insphere(a, b, c, d, e);
}

Sign dot(const Point& p, const Point& a, const Point& q, const Point& b) {
  const Interval v = check::dot(ivec(p) - ivec(a), ivec(q) - ivec(b));
  if (auto s = interval_sign(v)) return *s;
  ++g_exact;
  return qsign(qdot(qdiff(p, a), qdiff(q, b)));
}

// F = |n|^2 |w|^2 - w . m, with u = b-a, v = c-a, w = p-a, n = u x v and
// m = (|u|^2 v - |v|^2 u) x n = 2 |n|^2 (o - a), o the circumcenter of abc. Then
// |n|^2 (|p - o|^2 - r^2) = F, so p is strictly inside the equatorial sphere iff F < 0.
Sign equatorial(const Point& a, const Point& b, const Point& c, const Point& p) {
  {
    const IVec u = ivec(b) - ivec(a), v = ivec(c) - ivec(a), w = ivec(p) - ivec(a);
    const IVec n = cross(u, v);
    const IVec m = cross(norm2(u) * v - norm2(v) * u, n);
    const Interval nn = norm2(n);
    if (nn.lo > 0) {
      if (auto s = interval_sign(nn * norm2(w) - check::dot(w, m))) return -*s;
    }
  }
  ++g_exact;
  const QVec u = qdiff(b, a), v = qdiff(c, a), w = qdiff(p, a);
  const QVec n = qcross(u, v);
  const Q nn = qdot(n, n);
  if (sgn(nn) == 0) return Sign::Zero;
  const Q uu = qdot(u, u), vv = qdot(v, v);
  const QVec t = {uu * v[0] - vv * u[0], uu * v[1] - vv * u[1], uu * v[2] - vv * u[2]};
  return -qsign(nn * qdot(w, w) - qdot(w, qcross(t, n)));
}

Sign orient2d(const Point& a, const Point& b, const Point& c, int drop) {
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  const double acx = a[i] - c[i], acy = a[j] - c[j], bcx = b[i] - c[i], bcy = b[j] - c[j];
  if (in_range(acx) && in_range(acy) && in_range(bcx) && in_range(bcy)) {
    const double l = acx * bcy, r = acy * bcx;
    if (l == 0 && r == 0) return Sign::Zero;  // each product has an exactly zero factor
    if (auto s = decide(l - r, kOrient2Bound * (std::fabs(l) + std::fabs(r)) + 0x1p-1000))
      return *s;
  }
  std::array<std::int64_t, 6> X;
  if (to_ints(std::array<double, 6>{a[i], a[j], b[i], b[j], c[i], c[j]}, 60, X)) {
    const I128 ux = I128(X[2]) - X[0], uy = I128(X[3]) - X[1], vx = I128(X[4]) - X[0],
               vy = I128(X[5]) - X[1];
    return sign_i(ux * vy - uy * vx);  // |.| < 2 * 2^61 * 2^61
  }
  ++g_exact;
  const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
  return exact::orient2d(pa, pb, pc);
}

}  // namespace pdr::check::signs
