// Facet charts (paper §2.1 step 2): construction, exact chart orientation, placement on
// the facet's plane, and the facet in-circle test; see surface/chart.hpp.
//
// The in-circle test (paper §2.1 step 2, §3 subfacet cavities) is the plane-centred
// lifted determinant of surface/chart.hpp, evaluated exactly, with symbolic perturbation.
//
// Notation: t0, t1, t2 the facet's defining triple (exact doubles), e1 = t1 - t0,
// e2 = t2 - t0 (exact differences), and for the rows q = a, b, c
//     x_q = e1 . (q - d),   y_q = e2 . (q - d),   w_q = sum_k (q_k - d_k)((q_k - t0_k) + (d_k - t0_k))
// (w_q = |q - t0|^2 - |d - t0|^2). The determinant is
//     x_a (y_b w_c - y_c w_b) + x_b (y_c w_a - y_a w_c) + x_c (y_a w_b - y_b w_a).
// Its sign is evaluated in three stages:
//   1. Filter: filter::chart_incircle (geom/filter_kit.hpp: K = 21, coefficient 22u, with
//      its range precondition); plane_orient's filter is filter::chart_orient (K = 12, 13u).
//   2. Coplanar shortcut. If orient3d(a, b, c, d) == 0 and o = plane_orient(a, b, c) != 0,
//      the sign is incircle3(a, b, c, d) * o: every sphere through a, b, c meets their plane
//      in their circle (the adaptive kernel decides cocircular grids without GMP).
//   3. GMP rationals, the same determinant with exact e1, e2 and lifts.
// Perturbation: the incircle_sos cofactor table (predicates.hpp) with plane_orient as the
// cofactors, in the dominance order of the 3D points (lex-largest first), as incircle3_sos
// does: the perturbation of the lift |p - t0|^2 that insphere_sos applies in 3D.

#include "surface/chart.hpp"

#include <gmpxx.h>

#include <cmath>

#include "geom/filter_kit.hpp"
#include "geom/predicates.hpp"
#include "geom/sos_order.hpp"

namespace pdr::surface {

FacetChart make_chart(const domain::FacetPlane& plane, const std::vector<Point>& pts) {
  FacetChart ch;
  ch.projection = plane.projection;
  const Point& t0 = pts[plane.triple[0]];
  const Point& t1 = pts[plane.triple[1]];
  const Point& t2 = pts[plane.triple[2]];
  ch.origin = t0;
  ch.t1 = t1;
  ch.t2 = t2;
  const Point u{t1[0] - t0[0], t1[1] - t0[1], t1[2] - t0[2]};
  const Point v{t2[0] - t0[0], t2[1] - t0[1], t2[2] - t0[2]};
  ch.normal = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return ch;
}

Sign chart_orient(const FacetChart& ch, const Point& a, const Point& b, const Point& c) {
  return domain::orient2d(ch(a), ch(b), ch(c));
}

Point place_on_facet(const FacetChart& ch, Point p) {
  const int k = ch.projection.drop, i = (k + 1) % 3, j = (k + 2) % 3;
  const Point& o = ch.origin;
  const Point& n = ch.normal;
  // n[k] != 0: the chart drops the largest normal component, nonzero for a proper triple
  // (a rounded cross product of a proper triple could still vanish for extreme inputs;
  // then p stays as constructed).
  if (n[k] == 0) return p;
  p[k] = o[k] - (n[i] * (p[i] - o[i]) + n[j] * (p[j] - o[j])) / n[k];
  return p;
}

namespace {

mpq_class dot_exact(const FacetChart& ch, const Point& t, const Point& q, const Point& d) {
  mpq_class s = 0;
  for (int k = 0; k < 3; ++k)
    s += (mpq_class(t[k]) - ch.origin[k]) * (mpq_class(q[k]) - d[k]);
  return s;
}

Sign raw_gmp(const FacetChart& ch, const Point* p[4]) {
  const Point& d = *p[3];
  mpq_class x[3], y[3], w[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = dot_exact(ch, ch.t1, *p[i], d);
    y[i] = dot_exact(ch, ch.t2, *p[i], d);
    w[i] = 0;
    for (int k = 0; k < 3; ++k) {
      const mpq_class sq = mpq_class((*p[i])[k]) - ch.origin[k];
      const mpq_class sd = mpq_class(d[k]) - ch.origin[k];
      w[i] += sq * sq - sd * sd;
    }
  }
  const mpq_class det = x[0] * (y[1] * w[2] - y[2] * w[1]) + x[1] * (y[2] * w[0] - y[0] * w[2]) +
                        x[2] * (y[0] * w[1] - y[1] * w[0]);
  return sign_of(sgn(det));
}

}  // namespace

Sign plane_orient(const FacetChart& ch, const Point& a, const Point& b, const Point& c) {
  // det [e1.(b-a) e1.(c-a); e2.(b-a) e2.(c-a)]
  const Filtered f = filter::chart_orient(ch.origin, ch.t1, ch.t2, a, b, c);
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
  const mpq_class det = dot_exact(ch, ch.t1, b, a) * dot_exact(ch, ch.t2, c, a) -
                        dot_exact(ch, ch.t1, c, a) * dot_exact(ch, ch.t2, b, a);
  return sign_of(sgn(det));
}

Sign chart_incircle_raw(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                        const Point& d) {
  const Filtered f = filter::chart_incircle(ch.origin, ch.t1, ch.t2, a, b, c, d);
  if (f != Filtered::Unsure) return static_cast<Sign>(f);
  if (orient3d(a, b, c, d) == Sign::Zero) {
    const Sign o = plane_orient(ch, a, b, c);
    if (o != Sign::Zero) return incircle3(a, b, c, d) * o;
  }
  const Point* p[4] = {&a, &b, &c, &d};
  return raw_gmp(ch, p);
}

Sign chart_incircle(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                    const Point& d) {
  Sign s = chart_incircle_raw(ch, a, b, c, d);
  if (s == Sign::Zero) {
    for (const int i : sos::dominance_order<4>({&a, &b, &c, &d})) {
      switch (i) {
        case 0: s = plane_orient(ch, b, c, d); break;
        case 1: s = -plane_orient(ch, a, c, d); break;
        case 2: s = plane_orient(ch, a, b, d); break;
        default: s = -plane_orient(ch, a, b, c); break;
      }
      if (s != Sign::Zero) break;
    }
  }
  // s is "inside" relative to the orientation of a, b, c in the plane chart; the caller's
  // orientation is the projection chart's (they differ only on near-degenerate triangles).
  const Sign op = plane_orient(ch, a, b, c), oc = chart_orient(ch, a, b, c);
  return op != Sign::Zero && oc != Sign::Zero && op != oc ? -s : s;
}

}  // namespace pdr::surface
