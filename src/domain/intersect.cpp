// Exact segment/triangle intersection tests (paper §1.1); see domain/intersect.hpp.
#include "domain/intersect.hpp"

#include "geom/predicates.hpp"

namespace pdr::domain {

namespace {

bool mixed(Sign a, Sign b, Sign c) {
  const bool neg = a == Sign::Negative || b == Sign::Negative || c == Sign::Negative;
  const bool pos = a == Sign::Positive || b == Sign::Positive || c == Sign::Positive;
  return neg && pos;
}

// Precondition: x, v, c, d coplanar is not assumed. True when the segment from the shared
// vertex v to x enters the closed triangle vcd anywhere but at v: x must be coplanar and
// the direction v->x inside the closed angle cvd.
bool ray_enters(const Point& v, const Point& x, const Point& c, const Point& d) {
  if (orient3d(v, c, d, x) != Sign::Zero) return false;
  const int drop = nondegenerate_drop(v, c, d);
  const Sign s = orient2d_dropping(drop, v, c, d);
  const Sign o1 = orient2d_dropping(drop, v, c, x) * s;
  const Sign o2 = orient2d_dropping(drop, v, x, d) * s;
  // Both zero is impossible (x would lie on two lines through v); one zero with the other
  // positive puts x on the ray of c or d; a negative means outside the angle (for the
  // opposite ray of c, the second sign is negative since cvd is below 180°).
  return o1 != Sign::Negative && o2 != Sign::Negative;
}

int shared_count(const std::uint32_t* s, int ns, const std::uint32_t* t, int nt) {
  int n = 0;
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < nt; ++j) n += s[i] == t[j];
  return n;
}

bool contains(const Tri3& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

}  // namespace

bool segments_meet_2d(const P2& a, const P2& b, const P2& c, const P2& d) {
  const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const Sign o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 == Sign::Negative && o3 * o4 == Sign::Negative) return true;
  if (o1 == Sign::Zero && on_closed_segment(a, b, c)) return true;
  if (o2 == Sign::Zero && on_closed_segment(a, b, d)) return true;
  if (o3 == Sign::Zero && on_closed_segment(c, d, a)) return true;
  if (o4 == Sign::Zero && on_closed_segment(c, d, b)) return true;
  return false;
}

bool point_in_triangle_2d(const P2& a, const P2& b, const P2& c, const P2& x) {
  return !mixed(orient2d(a, b, x), orient2d(b, c, x), orient2d(c, a, x));
}

bool segment_meets_triangle(const Point& p, const Point& q, const Point& a, const Point& b,
                            const Point& c) {
  const Sign sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp == sq && sp != Sign::Zero) return false;
  if (sp == Sign::Zero && sq == Sign::Zero) {
    const Projection pr{nondegenerate_drop(a, b, c), false};
    const P2 A = pr(a), B = pr(b), C = pr(c), P = pr(p), Q = pr(q);
    return point_in_triangle_2d(A, B, C, P) || point_in_triangle_2d(A, B, C, Q) ||
           segments_meet_2d(P, Q, A, B) || segments_meet_2d(P, Q, B, C) ||
           segments_meet_2d(P, Q, C, A);
  }
  // The line pq meets the plane in one point of the closed segment; it lies in the closed
  // triangle iff the line passes on the same side of (or through) all three edges.
  return !mixed(orient3d(p, q, a, b), orient3d(p, q, b, c), orient3d(p, q, c, a));
}

bool segments_meet(const Point& p, const Point& q, const Point& r, const Point& s) {
  if (orient3d(p, q, r, s) != Sign::Zero) return false;
  int drop = nondegenerate_drop(p, q, r);
  if (drop < 0) drop = nondegenerate_drop(p, q, s);
  if (drop < 0) {
    // All four collinear: keep a coordinate in which p and q differ.
    int k = 0;
    while (k < 3 && p[k] == q[k]) ++k;
    drop = (k + 2) % 3;
  }
  const Projection pr{drop, false};
  return segments_meet_2d(pr(p), pr(q), pr(r), pr(s));
}

bool point_in_triangle(const Point& a, const Point& b, const Point& c, const Point& x) {
  if (orient3d(a, b, c, x) != Sign::Zero) return false;
  const Projection pr{nondegenerate_drop(a, b, c), false};
  return point_in_triangle_2d(pr(a), pr(b), pr(c), pr(x));
}

bool triangles_conflict(const Tri3& s, const Tri3& t, const std::vector<Point>& pts) {
  const int shared = shared_count(s.data(), 3, t.data(), 3);
  if (shared == 3) return true;
  if (shared == 2) {
    std::uint32_t p = 0, q = 0, a = 0, b = 0;
    int found = 0;
    for (std::uint32_t v : s) {
      if (contains(t, v)) (found++ == 0 ? p : q) = v;
      else a = v;
    }
    for (std::uint32_t v : t)
      if (!contains(s, v)) b = v;
    if (orient3d(pts[p], pts[q], pts[a], pts[b]) != Sign::Zero) return false;
    // Coplanar: they overlap iff a and b lie on the same side of pq.
    const int drop = nondegenerate_drop(pts[p], pts[q], pts[a]);
    return orient2d_dropping(drop, pts[p], pts[q], pts[a]) ==
           orient2d_dropping(drop, pts[p], pts[q], pts[b]);
  }
  if (shared == 1) {
    std::uint32_t v = 0;
    for (std::uint32_t x : s)
      if (contains(t, x)) v = x;
    std::array<std::uint32_t, 2> so{}, to{};
    int i = 0, j = 0;
    for (std::uint32_t x : s)
      if (x != v) so[i++] = x;
    for (std::uint32_t x : t)
      if (x != v) to[j++] = x;
    const Point &V = pts[v], &A = pts[so[0]], &B = pts[so[1]], &C = pts[to[0]],
                &D = pts[to[1]];
    // The intersection is a convex set containing v; if it is more than v, one of its
    // extreme points lies on an edge of s or of t other than at v (see header).
    return segment_meets_triangle(A, B, V, C, D) || segment_meets_triangle(C, D, V, A, B) ||
           ray_enters(V, A, C, D) || ray_enters(V, B, C, D) || ray_enters(V, C, A, B) ||
           ray_enters(V, D, A, B);
  }
  const Point &A = pts[s[0]], &B = pts[s[1]], &C = pts[s[2]];
  const Point &D = pts[t[0]], &E = pts[t[1]], &F = pts[t[2]];
  return segment_meets_triangle(A, B, D, E, F) || segment_meets_triangle(B, C, D, E, F) ||
         segment_meets_triangle(C, A, D, E, F) || segment_meets_triangle(D, E, A, B, C) ||
         segment_meets_triangle(E, F, A, B, C) || segment_meets_triangle(F, D, A, B, C);
}

bool segment_triangle_conflict(const Seg2& s, const Tri3& t, const std::vector<Point>& pts) {
  const int shared = shared_count(s.data(), 2, t.data(), 3);
  if (shared == 2) return false;  // s is an edge of t
  if (shared == 1) {
    const std::uint32_t v = contains(t, s[0]) ? s[0] : s[1];
    const std::uint32_t x = v == s[0] ? s[1] : s[0];
    std::array<std::uint32_t, 2> o{};
    int j = 0;
    for (std::uint32_t y : t)
      if (y != v) o[j++] = y;
    return ray_enters(pts[v], pts[x], pts[o[0]], pts[o[1]]);
  }
  return segment_meets_triangle(pts[s[0]], pts[s[1]], pts[t[0]], pts[t[1]], pts[t[2]]);
}

bool segments_conflict(const Seg2& s, const Seg2& t, const std::vector<Point>& pts) {
  const int shared = shared_count(s.data(), 2, t.data(), 2);
  if (shared == 2) return true;
  if (shared == 1) {
    const std::uint32_t v = (s[0] == t[0] || s[0] == t[1]) ? s[0] : s[1];
    const std::uint32_t a = v == s[0] ? s[1] : s[0];
    const std::uint32_t b = v == t[0] ? t[1] : t[0];
    return collinear(pts[v], pts[a], pts[b]) && dot_sign(pts[v], pts[a], pts[b]) == Sign::Positive;
  }
  return segments_meet(pts[s[0]], pts[s[1]], pts[t[0]], pts[t[1]]);
}

}  // namespace pdr::domain
