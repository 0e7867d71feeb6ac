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
// Worst-case sizes: insphere untranslated 5 x 1152 components (about 100 KB of stack).
// Reference: Shewchuk 1997, §4.4 (method only). Invariant: exact within filter.hpp's range.
#include "geom/expansion.hpp"
#include "geom/stage2.hpp"

namespace pdr::stage2 {

using expansion::cross_difference;
using expansion::Expansion;
using expansion::product;
using expansion::two_diff;

namespace {

Expansion<4> xy(const double* p, const double* q, int i = 0, int j = 1) {
  return cross_difference(p[i], q[j], p[j], q[i]);
}

Expansion<4> lift2(const double* p) { return product(p[0], p[0]) + product(p[1], p[1]); }
Expansion<6> lift3(const double* p) { return lift2(p) + product(p[2], p[2]); }

// Untranslated orient2d of (p, q, r) on coordinates (i, j).
Expansion<12> orient2(const double* p, const double* q, const double* r, int i, int j) {
  return (xy(p, q, i, j) + xy(q, r, i, j)) + xy(r, p, i, j);
}

Expansion<24> det3(const double* p, const double* q, const double* r) {
  return (xy(q, r) * p[2] - xy(p, r) * q[2]) + xy(p, q) * r[2];
}

// Untranslated orient3d(p, q, r, s) = det3(q,r,s) - det3(p,r,s) + det3(p,q,s) - det3(p,q,r).
Expansion<96> orient3(const double* p, const double* q, const double* r, const double* s) {
  return (det3(q, r, s) - det3(p, r, s)) + (det3(p, q, s) - det3(p, q, r));
}

bool exact_differences(const double* p, const double* o, int n, double* out) {
  for (int i = 0; i < n; ++i) {
    double err;
    two_diff(p[i], o[i], out[i], err);
    if (err != 0) return false;
  }
  return true;
}

}  // namespace

Sign incircle(const double* a, const double* b, const double* c, const double* d) {
  double ta[2], tb[2], tc[2];
  if (exact_differences(a, d, 2, ta) && exact_differences(b, d, 2, tb) &&
      exact_differences(c, d, 2, tc))
    return ((lift2(ta) * xy(tb, tc) + lift2(tb) * xy(tc, ta)) + lift2(tc) * xy(ta, tb)).sign();
  const Expansion<192> ab = lift2(a) * orient2(b, c, d, 0, 1) - lift2(b) * orient2(a, c, d, 0, 1);
  const Expansion<192> cd = lift2(c) * orient2(a, b, d, 0, 1) - lift2(d) * orient2(a, b, c, 0, 1);
  return (ab + cd).sign();
}

Sign insphere(const Point& pa, const Point& pb, const Point& pc, const Point& pd,
              const Point& pe) {
  const double *a = pa.data(), *b = pb.data(), *c = pc.data(), *d = pd.data(), *e = pe.data();
  double ta[3], tb[3], tc[3], td[3];
  if (exact_differences(a, e, 3, ta) && exact_differences(b, e, 3, tb) &&
      exact_differences(c, e, 3, tc) && exact_differences(d, e, 3, td)) {
    const Expansion<576> ab = lift3(ta) * det3(tb, tc, td) - lift3(tb) * det3(ta, tc, td);
    const Expansion<576> cd = lift3(tc) * det3(ta, tb, td) - lift3(td) * det3(ta, tb, tc);
    return (ab + cd).sign();
  }
  Expansion<4608> sum;
  {
    const Expansion<2304> ab = lift3(b) * orient3(a, c, d, e) - lift3(a) * orient3(b, c, d, e);
    const Expansion<2304> cd = lift3(d) * orient3(a, b, c, e) - lift3(c) * orient3(a, b, d, e);
    sum.n = expansion::sum(ab.c, ab.n, cd.c, cd.n, sum.c);
  }
  const Expansion<1152> ee = -(lift3(e) * orient3(a, b, c, d));
  return (sum + ee).sign();
}

Sign incircle3(const Point& pa, const Point& pb, const Point& pc, const Point& pd) {
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
  const Expansion<288> ab = lift3(a) * orient2(b, c, d, i, j) - lift3(b) * orient2(a, c, d, i, j);
  const Expansion<288> cd = lift3(c) * orient2(a, b, d, i, j) - lift3(d) * orient2(a, b, c, i, j);
  return (ab + cd).sign() * nk;
}

}  // namespace pdr::stage2
