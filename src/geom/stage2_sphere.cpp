// Stage 2, sphere predicates: exact incircle, insphere and incircle3 by expansion
// arithmetic. Each lifted determinant is expanded along its lift column into orientation
// minors (the same cofactors that symbolic perturbation uses, sos.cpp):
//   incircle  = sign sum_i (-1)^i     w_i orient2d(others),  w = x^2 + y^2, rows a,b,c,d
//   insphere  = sign sum_i (-1)^(i+1) w_i orient3d(others),  w = |p|^2,     rows a,b,c,d,e
//   incircle3 = sign(n_k) sign sum_i (-1)^i w_i orient2d_k(others), w = |p|^2 (3D), where
//               orient2d_k is orient2d of the projection dropping axis k, n_k != 0.
// Translated by the last point when every difference is exact (its row then vanishes and
// the orientation minors become 2x2 / 3x3 determinants of the differences); this is an
// identity for incircle and insphere, and for incircle3 it holds on coplanar input
// (the dropped coordinate of p - d is then a linear combination of the other two).
// Worst-case sizes: insphere untranslated 5 x 1152 components (about 100 KB of stack);
// compression (expansion::compress) keeps the actual lengths short.
// Reference: Shewchuk 1997, §4.4 (method only). Invariant: exact for all finite doubles
// (outside filter.hpp's range the GMP reference decides, stage2_range.hpp).
#include "geom/exact.hpp"
#include "geom/stage2.hpp"
#include "geom/stage2_range.hpp"
#include "geom/stage2_terms.hpp"

namespace pdr::stage2 {

using namespace terms;

Sign incircle(const double* a, const double* b, const double* c, const double* d) {
  if (!in_range<190>({a, b, c, d}, 2)) return exact::incircle(a, b, c, d);
  double ta[2], tb[2], tc[2];
  if (exact_differences(a, d, 2, ta) && exact_differences(b, d, 2, tb) &&
      exact_differences(c, d, 2, tc))
    return ((lift2(ta) * xy(tb, tc) + lift2(tb) * xy(tc, ta)) + lift2(tc) * xy(ta, tb)).sign();
  const Expansion<192> ab = lift2(a) * compressed(orient2(b, c, d)) -
                            lift2(b) * compressed(orient2(a, c, d));
  const Expansion<192> cd = lift2(c) * compressed(orient2(a, b, d)) -
                            lift2(d) * compressed(orient2(a, b, c));
  return (ab + cd).sign();
}

Sign insphere(const Point& pa, const Point& pb, const Point& pc, const Point& pd,
              const Point& pe) {
  if (!in_range<130>({pa.data(), pb.data(), pc.data(), pd.data(), pe.data()}, 3))
    return exact::insphere(pa, pb, pc, pd, pe);
  const double* p[5] = {pa.data(), pb.data(), pc.data(), pd.data(), pe.data()};
  double t[4][3];
  bool translated = true;
  for (int i = 0; i < 4 && translated; ++i)
    translated = exact_differences(p[i], p[4], 3, t[i]);
  if (translated) {
    const Expansion<576> ab = lift3(t[0]) * compressed(det3(t[1], t[2], t[3])) -
                              lift3(t[1]) * compressed(det3(t[0], t[2], t[3]));
    const Expansion<576> cd = lift3(t[2]) * compressed(det3(t[0], t[1], t[3])) -
                              lift3(t[3]) * compressed(det3(t[0], t[1], t[2]));
    return (ab + cd).sign();
  }
  // The ten untranslated 3x3 minors det3(p_i, p_j, p_k), i < j < k, computed once.
  Expansion<24> m[5][5][5];
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j)
      for (int k = j + 1; k < 5; ++k) m[i][j][k] = det3(p[i], p[j], p[k]);
  // orient3d of the four points other than p_i (in order q < r < s < t).
  const auto orient_without = [&](int i) {
    int o[4], n = 0;
    for (int k = 0; k < 5; ++k)
      if (k != i) o[n++] = k;
    return compressed((m[o[1]][o[2]][o[3]] - m[o[0]][o[2]][o[3]]) +
                      (m[o[0]][o[1]][o[3]] - m[o[0]][o[1]][o[2]]));
  };
  Expansion<4608> sum;
  {
    const Expansion<2304> ab = lift3(p[1]) * orient_without(1) - lift3(p[0]) * orient_without(0);
    const Expansion<2304> cd = lift3(p[3]) * orient_without(3) - lift3(p[2]) * orient_without(2);
    sum.n = expansion::sum(ab.c, ab.n, cd.c, cd.n, sum.c);
  }
  return (sum - lift3(p[4]) * orient_without(4)).sign();
}

Sign incircle3(const Point& pa, const Point& pb, const Point& pc, const Point& pd) {
  if (!in_range<190>({pa.data(), pb.data(), pc.data(), pd.data()}, 3))
    return exact::incircle3(pa, pb, pc, pd);
  const int k = plane_axis(pa, pb, pc);
  if (k < 0) return Sign::Zero;
  const Sign nk = orient2d_projected(k, pa, pb, pc);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double *a = pa.data(), *b = pb.data(), *c = pc.data(), *d = pd.data();
  double ta[3], tb[3], tc[3];
  if (exact_differences(a, d, 3, ta) && exact_differences(b, d, 3, tb) &&
      exact_differences(c, d, 3, tc)) {
    const Expansion<144> v = (lift3(ta) * xy(tb, tc, i, j) + lift3(tb) * xy(tc, ta, i, j)) +
                             lift3(tc) * xy(ta, tb, i, j);
    return v.sign() * nk;
  }
  const Expansion<288> ab = lift3(a) * compressed(orient2(b, c, d, i, j)) -
                            lift3(b) * compressed(orient2(a, c, d, i, j));
  const Expansion<288> cd = lift3(c) * compressed(orient2(a, b, d, i, j)) -
                            lift3(d) * compressed(orient2(a, b, c, i, j));
  return (ab + cd).sign() * nk;
}

}  // namespace pdr::stage2
