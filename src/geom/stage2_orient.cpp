// Stage 2, orientation predicates: exact orient2d and orient3d by expansion arithmetic.
//
// orient2d(a,b,c) = det[b-a, c-a]; translated by a when the four differences are exact
// (2 products, at most 4 components), else the untranslated form
//   xy(a,b) + xy(b,c) + xy(c,a),  xy(p,q) = p_x q_y - p_y q_x   (at most 12 components).
// orient3d(a,b,c,d) = det[b-a, c-a, d-a]; translated by a when exact (at most 24
// components), else -det[p 1] expanded along the constant column,
//   det3(b,c,d) - det3(a,c,d) + det3(a,b,d) - det3(a,b,c)     (at most 96 components),
// with det3(p,q,r) = p_z xy(q,r) - q_z xy(p,r) + r_z xy(p,q).
// Reference: Shewchuk 1997, §4 (method only). Invariant: exact within filter.hpp's range.
#include "geom/expansion.hpp"
#include "geom/stage2.hpp"

namespace pdr::stage2 {

using expansion::cross_difference;
using expansion::Expansion;
using expansion::two_diff;

namespace {

// p_x q_y - p_y q_x on the coordinates (i, j).
Expansion<4> xy(const double* p, const double* q, int i = 0, int j = 1) {
  return cross_difference(p[i], q[j], p[j], q[i]);
}

// det3(p, q, r) of untranslated rows.
Expansion<24> det3(const double* p, const double* q, const double* r) {
  return (xy(q, r) * p[2] - xy(p, r) * q[2]) + xy(p, q) * r[2];
}

// out[i] = p[i] - o[i] for i < n; false if any difference is inexact.
bool exact_differences(const double* p, const double* o, int n, double* out) {
  for (int i = 0; i < n; ++i) {
    double err;
    two_diff(p[i], o[i], out[i], err);
    if (err != 0) return false;
  }
  return true;
}

}  // namespace

Sign orient2d(const double* a, const double* b, const double* c) {
  double u[2], v[2];
  if (exact_differences(b, a, 2, u) && exact_differences(c, a, 2, v)) return xy(u, v).sign();
  return ((xy(a, b) + xy(b, c)) + xy(c, a)).sign();
}

Sign orient2d_projected(int k, const Point& a, const Point& b, const Point& c) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
  return orient2d(pa, pb, pc);
}

int plane_axis(const Point& a, const Point& b, const Point& c) {
  // Try the axes by decreasing approximate |n_k|; the choice only affects conditioning.
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double n[3] = {std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz),
                       std::fabs(ux * vy - uy * vx)};
  int order[3] = {0, 1, 2};
  for (int s = 0; s < 2; ++s)
    for (int t = 0; t + 1 < 3 - s; ++t)
      if (n[order[t + 1]] > n[order[t]]) {
        const int x = order[t];
        order[t] = order[t + 1];
        order[t + 1] = x;
      }
  for (const int k : order)
    if (orient2d_projected(k, a, b, c) != Sign::Zero) return k;
  return -1;
}

Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  double u[3], v[3], w[3];
  if (exact_differences(b.data(), a.data(), 3, u) &&
      exact_differences(c.data(), a.data(), 3, v) &&
      exact_differences(d.data(), a.data(), 3, w))
    return det3(u, v, w).sign();
  const Expansion<48> bcd_acd = det3(b.data(), c.data(), d.data()) -
                                det3(a.data(), c.data(), d.data());
  const Expansion<48> abd_abc = det3(a.data(), b.data(), d.data()) -
                                det3(a.data(), b.data(), c.data());
  return (bcd_acd + abd_abc).sign();
}

}  // namespace pdr::stage2
