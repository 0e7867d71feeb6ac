// The facet in-circle test (paper §2.1 step 2, §3 subfacet cavities): the lifted chart
// determinant of surface_chart.hpp, evaluated exactly, with symbolic perturbation.
//
// Evaluation of the unperturbed sign, in three stages:
//   1. Filter. With x_q, y_q the chart differences q - d, e_k = q_k - d_k and
//      s_k = (q_k - t0_k) + (d_k - t0_k), the lift difference is w_q = sum_k e_k s_k and the
//      determinant x_a (y_b w_c - y_c w_b) + x_b (y_c w_a - y_a w_c) + x_c (y_a w_b - y_b w_a).
//      Each leaf difference is rounded once; the longest chain of roundings has 10
//      operations, so |error| <= gamma_10 * (the same program on absolute values) (Higham,
//      straight-line programs), below 11u of that bound as computed; we use 16u. Used only
//      when every difference is 0 or in [2^-150, 2^150] (no underflow, no overflow in a
//      product of four). Valid with or without fused multiply-add.
//   2. Coplanar shortcut. If orient3d(a, b, c, d) == 0 and o = chart_orient(a, b, c) != 0,
//      the sign is incircle3(a, b, c, d) * o (surface_chart.hpp: for coplanar points the
//      lifted test is the 3D circle test); the adaptive kernel decides without GMP, which
//      matters for cocircular grids (every test on them reaches this stage).
//   3. GMP rationals, the same determinant with exact lifts.
// Perturbation: the incircle_sos cofactor table (predicates.hpp) with chart orientations,
// in the dominance order of the 3D points (lex-largest first), as incircle3_sos does.
#include <gmpxx.h>

#include <cmath>

#include "geom/predicates.hpp"
#include "geom/sos_order.hpp"
#include "refine/surface_chart.hpp"

namespace pdr::refine {
namespace {

bool in_range(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m >= 0x1p-150 && m <= 0x1p150);
}

// One row of the filter: chart differences, lift difference and its absolute bound.
struct Row {
  double x, y, w, xa, ya, wa;
  bool ok;
};

Row filter_row(const FacetChart& ch, const Point& q, const P2& Q, const Point& d, const P2& D) {
  Row r{};
  r.x = Q[0] - D[0];
  r.y = Q[1] - D[1];
  r.ok = in_range(r.x) && in_range(r.y);
  double w = 0, wa = 0;
  for (int k = 0; k < 3; ++k) {
    const double e = q[k] - d[k], sq = q[k] - ch.origin[k], sd = d[k] - ch.origin[k];
    r.ok = r.ok && in_range(e) && in_range(sq) && in_range(sd);
    w += e * (sq + sd);
    wa += std::fabs(e) * (std::fabs(sq) + std::fabs(sd));
  }
  r.w = w;
  r.wa = wa;
  r.xa = std::fabs(r.x);
  r.ya = std::fabs(r.y);
  return r;
}

Sign raw_gmp(const FacetChart& ch, const Point* p[4]) {
  const P2 D = ch(*p[3]);
  mpq_class x[3], y[3], w[3];
  for (int i = 0; i < 3; ++i) {
    const P2 Q = ch(*p[i]);
    x[i] = mpq_class(Q[0]) - D[0];
    y[i] = mpq_class(Q[1]) - D[1];
    w[i] = 0;
    for (int k = 0; k < 3; ++k) {
      const mpq_class sq = mpq_class((*p[i])[k]) - ch.origin[k];
      const mpq_class sd = mpq_class((*p[3])[k]) - ch.origin[k];
      w[i] += sq * sq - sd * sd;
    }
  }
  const mpq_class det = x[0] * (y[1] * w[2] - y[2] * w[1]) + x[1] * (y[2] * w[0] - y[0] * w[2]) +
                        x[2] * (y[0] * w[1] - y[1] * w[0]);
  return sign_of(sgn(det));
}

}  // namespace

Sign chart_incircle_raw(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                        const Point& d) {
  const P2 A = ch(a), B = ch(b), C = ch(c), D = ch(d);
  const Row ra = filter_row(ch, a, A, d, D), rb = filter_row(ch, b, B, d, D),
            rc = filter_row(ch, c, C, d, D);
  if (ra.ok && rb.ok && rc.ok) {
    const double det = ra.x * (rb.y * rc.w - rc.y * rb.w) + rb.x * (rc.y * ra.w - ra.y * rc.w) +
                       rc.x * (ra.y * rb.w - rb.y * ra.w);
    const double bar = ra.xa * (rb.ya * rc.wa + rc.ya * rb.wa) +
                       rb.xa * (rc.ya * ra.wa + ra.ya * rc.wa) +
                       rc.xa * (ra.ya * rb.wa + rb.ya * ra.wa);
    const double bound = 16 * 0x1p-53 * bar;
    if (det > bound) return Sign::Positive;
    if (det < -bound) return Sign::Negative;
  }
  if (orient3d(a, b, c, d) == Sign::Zero) {
    const Sign o = orient2d(A, B, C);
    if (o != Sign::Zero) return incircle3(a, b, c, d) * o;
  }
  const Point* p[4] = {&a, &b, &c, &d};
  return raw_gmp(ch, p);
}

Sign chart_incircle(const FacetChart& ch, const Point& a, const Point& b, const Point& c,
                    const Point& d) {
  const Sign s = chart_incircle_raw(ch, a, b, c, d);
  if (s != Sign::Zero) return s;
  const P2 A = ch(a), B = ch(b), C = ch(c), D = ch(d);
  for (const int i : sos::dominance_order<4>({&a, &b, &c, &d})) {
    Sign t = Sign::Zero;
    switch (i) {
      case 0: t = orient2d(B, C, D); break;
      case 1: t = -orient2d(A, C, D); break;
      case 2: t = orient2d(A, B, D); break;
      default: t = -orient2d(A, B, C); break;
    }
    if (t != Sign::Zero) return t;
  }
  return Sign::Zero;
}

}  // namespace pdr::refine
