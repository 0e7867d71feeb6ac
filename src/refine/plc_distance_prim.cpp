// Distances between points, segments and triangles (paper §2.1's d); see the header.
#include "refine/plc_distance_prim.hpp"

#include <algorithm>
#include <array>

namespace pdr::refine {

namespace {

using Vec = std::array<double, 3>;
Vec sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

double dist2_point_point(const Point& p, const Point& q) {
  const Vec d = sub(p, q);
  return dot(d, d);
}

double dist2_point_segment(const Point& p, const Point& a, const Point& b) {
  const Vec ab = sub(b, a), ap = sub(p, a);
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(ap, ab) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec d{ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
  return dot(d, d);
}

double dist2_point_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  // The foot of the perpendicular lies in the triangle iff p is on the inner side of all
  // three edge planes; otherwise the nearest point is on an edge.
  const Vec n = cross(sub(b, a), sub(c, a));
  const double nn = dot(n, n);
  if (nn > 0) {
    const bool in = dot(cross(sub(b, a), sub(p, a)), n) >= 0 &&
                    dot(cross(sub(c, b), sub(p, b)), n) >= 0 &&
                    dot(cross(sub(a, c), sub(p, c)), n) >= 0;
    if (in) {
      const double h = dot(sub(p, a), n);
      return h * h / nn;
    }
  }
  return std::min({dist2_point_segment(p, a, b), dist2_point_segment(p, b, c),
                   dist2_point_segment(p, c, a)});
}

double dist2_segment_segment(const Point& p, const Point& q, const Point& r, const Point& s) {
  // The squared distance between p + x(q-p) and r + y(s-r) is convex on [0,1]^2: its
  // minimum is at the interior critical point (the closest points of the two lines, when
  // not parallel) or on the boundary of the square (an endpoint against a segment).
  double best = std::min({dist2_point_segment(p, r, s), dist2_point_segment(q, r, s),
                          dist2_point_segment(r, p, q), dist2_point_segment(s, p, q)});
  const Vec d1 = sub(q, p), d2 = sub(s, r), r0 = sub(p, r);
  const double a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2);
  const double c = dot(d1, r0), f = dot(d2, r0);
  const double denom = a * e - b * b;
  if (denom > 1e-14 * a * e) {
    const double x = (b * f - c * e) / denom, y = (a * f - b * c) / denom;
    if (x > 0 && x < 1 && y > 0 && y < 1) {
      const Vec d{r0[0] + x * d1[0] - y * d2[0], r0[1] + x * d1[1] - y * d2[1],
                  r0[2] + x * d1[2] - y * d2[2]};
      best = std::min(best, dot(d, d));
    }
  }
  return best;
}

double dist2_segment_triangle(const Point& p, const Point& q, const Point& a, const Point& b,
                              const Point& c) {
  return std::min({dist2_point_triangle(p, a, b, c), dist2_point_triangle(q, a, b, c),
                   dist2_segment_segment(p, q, a, b), dist2_segment_segment(p, q, b, c),
                   dist2_segment_segment(p, q, c, a)});
}

double dist2_triangle_triangle(const Point& a, const Point& b, const Point& c, const Point& d,
                               const Point& e, const Point& f) {
  return std::min({dist2_segment_triangle(a, b, d, e, f), dist2_segment_triangle(b, c, d, e, f),
                   dist2_segment_triangle(c, a, d, e, f), dist2_segment_triangle(d, e, a, b, c),
                   dist2_segment_triangle(e, f, a, b, c), dist2_segment_triangle(f, d, a, b, c)});
}

}  // namespace pdr::refine
