// Exact helpers for the domain analysis of paper §1.1 that the kernel predicates
// (geom/predicates.hpp) do not provide: projections onto coordinate planes, collinearity,
// signs of dot products, and rational points for rays that start inside a triangle.
//
// Every function returns the exact answer for the input doubles taken as rationals: the
// classification of angles at exactly 90° (a dot product of zero) and every incidence
// decision of the validation rely on this. Floating point only filters (with a bound).
#pragma once

#include <gmpxx.h>

#include <array>

#include "geom/point.hpp"

namespace pdr::domain {

using P2 = std::array<double, 2>;

// The projection that drops coordinate `drop` and keeps ((drop+1)%3, (drop+2)%3), in that
// order (the convention of stage2::plane_axis): orient2d of the projections of a, b, c has
// the sign of the `drop` component of (b-a)x(c-a). `swap` exchanges the kept coordinates,
// which mirrors every projected orientation.
struct Projection {
  int drop = 2;
  bool swap = false;
  P2 operator()(const Point& p) const {
    const double u = p[(drop + 1) % 3], v = p[(drop + 2) % 3];
    return swap ? P2{v, u} : P2{u, v};
  }
};

Sign orient2d(const P2& a, const P2& b, const P2& c);
// orient2d of a, b, c under the projection dropping `drop` (no swap).
Sign orient2d_dropping(int drop, const Point& a, const Point& b, const Point& c);
// A coordinate whose projection keeps a, b, c a proper triangle (the largest |normal
// component| is preferred); -1 when a, b, c are collinear (or coincide).
int nondegenerate_drop(const Point& a, const Point& b, const Point& c);
bool collinear(const Point& a, const Point& b, const Point& c);
// Precondition: collinear(a, b, c) and a != b. True when c lies in the open segment ab.
bool strictly_between(const Point& a, const Point& b, const Point& c);
// Precondition: a, b, c collinear in the plane. True when c lies in the closed segment ab.
bool on_closed_segment(const P2& a, const P2& b, const P2& c);

// sign of (a - o) . (b - o): Positive iff the angle aob is below 90°.
Sign dot_sign(const Point& o, const Point& a, const Point& b);
// sign of (u x (a - p)) . (u x (b - p)) with u = q - p: the sign of the cosine of the
// angle between the half-planes bounded by line pq through a and through b (Lagrange's
// identity: |u|^2 (a.b) - (u.a)(u.b) for a, b taken relative to p).
Sign dihedral_cos_sign(const Point& p, const Point& q, const Point& a, const Point& b);

// Rational points, for rays cast from inside a triangle (plc_orient.cpp).
using QPoint = std::array<mpq_class, 3>;
QPoint to_q(const Point& p);
// Same convention as orient3d: sign det[b-a, c-a, d-a].
Sign orient3d_q(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d);

// A rational point with a floating-point shadow: |q[k] - d[k]| <= err for every k. The
// predicates below are exact for the rational point; they decide in floating point when
// the shadow's error and the rounding provably cannot change the sign, else in GMP.
struct RatPoint {
  QPoint q;
  Point d{};
  double err = 0;
};
RatPoint make_rat(const QPoint& q);
RatPoint make_rat(const Point& p);  // err = 0
// orient3d(a, b, c, o) for the rational o.
Sign orient3d_rat(const Point& a, const Point& b, const Point& c, const RatPoint& o);
// orient2d of the projections (dropping `drop`, no swap) of a, b and the rational o.
Sign orient2d_rat(int drop, const Point& a, const Point& b, const RatPoint& o);

}  // namespace pdr::domain
