// Stage 2, orientation predicates: exact orient2d and orient3d by expansion arithmetic.
//
// orient2d(a,b,c) = det[b-a, c-a]; translated by a when the four differences are exact
// (2 products, at most 4 components), else untranslated, xy(a,b) + xy(b,c) + xy(c,a)
// (at most 12 components). orient3d(a,b,c,d) = det[b-a, c-a, d-a]; translated by a when
// exact (at most 24 components), else -det[p 1] expanded along the constant column,
//   det3(b,c,d) - det3(a,c,d) + det3(a,b,d) - det3(a,b,c)     (at most 96 components).
// Reference: Shewchuk 1997, §4 (method only). Invariant: exact for all finite doubles
// (outside filter.hpp's range the GMP reference decides, stage2_range.hpp).
#include <cmath>

#include "geom/exact.hpp"
#include "geom/stage2.hpp"
#include "geom/stage2_range.hpp"
#include "geom/stage2_terms.hpp"

namespace pdr::stage2 {

using namespace terms;

Sign orient2d(const double* a, const double* b, const double* c) {
  if (!in_range<450>({a, b, c}, 2)) return exact::orient2d(a, b, c);
  double u[2], v[2];
  if (exact_differences(b, a, 2, u) && exact_differences(c, a, 2, v)) return xy(u, v).sign();
  return orient2(a, b, c).sign();
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
  const int first = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
  const int order[3] = {first, (first + 1) % 3, (first + 2) % 3};
  for (const int k : order)
    if (orient2d_projected(k, a, b, c) != Sign::Zero) return k;
  return -1;
}

Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (!in_range<270>({a.data(), b.data(), c.data(), d.data()}, 3))
    return exact::orient3d(a, b, c, d);
  double u[3], v[3], w[3];
  if (exact_differences(b.data(), a.data(), 3, u) &&
      exact_differences(c.data(), a.data(), 3, v) &&
      exact_differences(d.data(), a.data(), 3, w))
    return det3(u, v, w).sign();
  const double *pa = a.data(), *pb = b.data(), *pc = c.data(), *pd = d.data();
  return ((det3(pb, pc, pd) - det3(pa, pc, pd)) + (det3(pa, pb, pd) - det3(pa, pb, pc))).sign();
}

}  // namespace pdr::stage2
