// validity.overlap by the degree of the tets' chain: a proof of disjoint interiors that
// looks at the boundary surface only, used before the pairwise test of overlap.cpp.
//
// Theorem. Let C be tets that are all positive (validity.orientation) and such that a
// triangle is a face of at most two of them, of two only when they lie on its opposite
// sides (validity.face_sharing). Let S be the boundary faces (held by one tet), oriented
// outward. For a point x on no face plane, let N(x) be the number of tets whose interior
// holds x and w(S, x) the winding number of S about x. Then N(x) = w(S, x).
// Proof: a positive tet's outward boundary winds once about its interior points and zero
// times about points outside it, so N(x) = sum over tets of w(boundary of t, x); the
// winding number is linear in the surface, and an interior face appears in the two
// boundaries with opposite orientations (its tets lie on opposite sides), so the sum is
// w(S, x). []
//
// Corollary (what this file decides). If moreover
//   (a) S is a simplicial complex: two faces of S meet only in a common vertex or a common
//       edge (nothing else: no crossing, no touching, no coplanar overlap), and
//   (b) for every class of faces of S linked through edges held by exactly two faces of S,
//       N = 0 at a point just outside one face of the class,
// then N <= 1 off the face planes, so no two tets have intersecting interiors, and no two
// tets touch through partially overlapping coplanar faces.
// Proof: w(S, .) is constant on each component of R^3 \ |S|. By (a), near the relative
// interior of a face f of S no other face of S passes, so the points just outside f form a
// connected set in one component, and w just inside f is w just outside plus one. At an
// edge held by exactly f and g, consistently oriented (S is a cycle), the outer sides of f
// and g meet in the wedge between them, which holds no other face of S by (a): they are in
// one component. So by (b), w = 0 just outside every face of S and w = 1 just inside.
// Every bounded component of R^3 \ |S| has a face interior on its boundary (a set of
// segments does not separate space), so w is 0 or 1 on every component, and N <= 1. Two
// tets touching through partially overlapping coplanar faces s, t (s of tet A): if s is an
// interior face, its other tet and t's tet overlap; if s is in S, t's tet lies just
// outside s, where N = 0; both contradict N <= 1. []
// Conversely, if (b) fails while the premises and (a) hold, some point just outside a face
// of S is covered, and just inside it N >= 2: two tets overlap. The caller then runs the
// pairwise test to name them.
//
// Exactness. Every decision is a sign of orient3d or orient2d on input points (signs.hpp).
// The point of (b) is symbolic: x = a + e1 (b - a) + e2 (d - a) + e3 n for the outward face
// (a, b, d) with normal n, 1 >> e1 >> e2 >> e3 > 0: inside the face near a, pushed out. The
// sign of orient3d(u, v, w, x) is the first nonzero of orient3d(u, v, w, a), .. b, .. d
// (the coefficients of 1, e1, e2 once the earlier ones vanish) and, when (u, v, w) lies in
// the face's plane, sign(n_uvw . n) = orient2d(u, v, w, k) * orient2d(a, b, d, k) for an
// axis k where the face's projection is not degenerate. It is never zero: x lies on no
// plane through three mesh vertices, so "x in a tet" is decided without ties.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "check/checks.hpp"
#include "check/signs.hpp"
#include "mesh/union_find.hpp"

namespace pdr::check {
namespace {

using P = const Point&;

int sgn(Sign s) { return to_int(s); }

// Closed 2D segments pq and rs (coordinates other than `drop`) meet.
bool segments_meet_2d(P p, P q, P r, P s, int drop) {
  const int o1 = sgn(signs::orient2d(p, q, r, drop)), o2 = sgn(signs::orient2d(p, q, s, drop));
  const int o3 = sgn(signs::orient2d(r, s, p, drop)), o4 = sgn(signs::orient2d(r, s, q, drop));
  if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) {
    // Collinear: points of one line are ordered by their lexicographic 2D coordinates.
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    auto less = [&](P x, P y) { return x[i] < y[i] || (x[i] == y[i] && x[j] < y[j]); };
    const Point& lo1 = less(p, q) ? p : q;
    const Point& hi1 = less(p, q) ? q : p;
    const Point& lo2 = less(r, s) ? r : s;
    const Point& hi2 = less(r, s) ? s : r;
    return !less(hi1, lo2) && !less(hi2, lo1);
  }
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

// p in the closed 2D triangle abc (non-degenerate in this projection).
bool in_triangle_2d(P p, P a, P b, P c, int drop) {
  const int s = sgn(signs::orient2d(a, b, c, drop));
  return sgn(signs::orient2d(a, b, p, drop)) * s >= 0 && sgn(signs::orient2d(b, c, p, drop)) * s >= 0 &&
         sgn(signs::orient2d(c, a, p, drop)) * s >= 0;
}

// An axis along which triangle abc's projection is not degenerate: the normal's largest
// component in floating point, confirmed exactly (the filter decides it at once).
int projection_axis(P a, P b, P c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {std::fabs(u[1] * v[2] - u[2] * v[1]), std::fabs(u[2] * v[0] - u[0] * v[2]),
                       std::fabs(u[0] * v[1] - u[1] * v[0])};
  const int best = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
  if (signs::orient2d(a, b, c, best) != Sign::Zero) return best;
  for (int k = 0; k < 3; ++k)
    if (signs::orient2d(a, b, c, k) != Sign::Zero) return k;
  return 2;  // unreachable for a non-degenerate triangle
}

// Closed segment pq meets the closed, non-degenerate triangle abc.
bool segment_meets_triangle(P p, P q, P a, P b, P c) {
  const int sp = sgn(signs::orient3d(a, b, c, p)), sq = sgn(signs::orient3d(a, b, c, q));
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {
    const int k = projection_axis(a, b, c);
    return in_triangle_2d(p, a, b, c, k) || in_triangle_2d(q, a, b, c, k) ||
           segments_meet_2d(p, q, a, b, k) || segments_meet_2d(p, q, b, c, k) ||
           segments_meet_2d(p, q, c, a, k);
  }
  // The line pq pierces the plane once, within the segment; the piercing point is in the
  // closed triangle iff the line passes no edge on the wrong side (Plücker signs).
  const int s1 = sgn(signs::orient3d(p, q, a, b)), s2 = sgn(signs::orient3d(p, q, b, c)),
            s3 = sgn(signs::orient3d(p, q, c, a));
  const bool pos = s1 > 0 || s2 > 0 || s3 > 0, neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(pos && neg);
}

// A quick sufficient test that f and g meet only in their common vertices' hull, in the
// projection along axis k (f's projection there not degenerate): a line through an edge
// of one projected triangle has the other's vertices strictly on its far side, except
// shared vertices on it. Disjoint projections mean disjoint triangles; projections that
// meet only in a shared vertex or edge mean the same in space (a second common point would
// lie with it on a line along k, which is in no plane of f). Mostly decided by the
// floating-point filter, where the tests in space meet exact zeros (faces of one facet).
bool separated_in_projection(const Tri& f, const Tri& g, std::span<const Point> pts, int k) {
  auto side_test = [&](const Tri& x, const Tri& y) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = x[e], v = x[(e + 1) % 3], w = x[(e + 2) % 3];
      const int own = sgn(signs::orient2d(pts[u], pts[v], pts[w], k));
      if (own == 0) return false;
      bool apart = true;
      for (int i = 0; i < 3 && apart; ++i) {
        if (y[i] == u || y[i] == v) continue;
        apart = y[i] != w && sgn(signs::orient2d(pts[u], pts[v], pts[y[i]], k)) == -own;
      }
      if (apart) return true;
    }
    return false;
  };
  return side_test(f, g) || side_test(g, f);
}

// Faces f and g of S (outward vertex triples) meet in more than their common vertices'
// hull: condition (a) fails for the pair.
bool improper(const Tri& f, const Tri& g, std::span<const Point> pts) {
  if (separated_in_projection(f, g, pts, projection_axis(pts[f[0]], pts[f[1]], pts[f[2]])))
    return false;
  int fs[3], gs[3], n = 0;  // positions of shared vertices
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[j]) fs[n] = i, gs[n] = j, ++n;
  auto F = [&](int i) -> P { return pts[f[i]]; };
  auto G = [&](int j) -> P { return pts[g[j]]; };
  if (n >= 3) return true;  // one face twice: topology dedups faces, so not in S
  if (n == 2) {
    // Sharing edge uv: they overlap iff coplanar with the third vertices on one side.
    const int a = 3 - fs[0] - fs[1], c = 3 - gs[0] - gs[1];
    P u = F(fs[0]);
    P v = F(fs[1]);
    if (signs::orient3d(u, v, F(a), G(c)) != Sign::Zero) return false;
    const int k = projection_axis(F(0), F(1), F(2));
    return signs::orient2d(u, v, F(a), k) == signs::orient2d(u, v, G(c), k);
  }
  if (n == 1) {
    // Sharing v: f and g meet beyond v iff the edge of one opposite v meets the other (the
    // farthest common point from v along a common ray lies on such an edge).
    const int a = (fs[0] + 1) % 3, b = (fs[0] + 2) % 3, c = (gs[0] + 1) % 3, d = (gs[0] + 2) % 3;
    return segment_meets_triangle(F(a), F(b), G(0), G(1), G(2)) ||
           segment_meets_triangle(G(c), G(d), F(0), F(1), F(2));
  }
  // Disjoint vertex sets: closed triangles meet iff an edge of one meets the other.
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(F(i), F((i + 1) % 3), G(0), G(1), G(2))) return true;
    if (segment_meets_triangle(G(i), G((i + 1) % 3), F(0), F(1), F(2))) return true;
  }
  return false;
}

// The symbolic point just outside outward face (a, b, d) (see the header), against the
// plane of the outward face (u, v, w): the sign of orient3d(u, v, w, x), never Zero.
Sign side_of_pushed_point(P u, P v, P w, P a, P b, P d, int k_face) {
  const signs::Plane plane(u, v, w);
  for (const Point* q : {&a, &b, &d})
    if (const Sign s = plane.orient(*q); s != Sign::Zero) return s;
  return sgn(signs::orient2d(u, v, w, k_face)) * sgn(signs::orient2d(a, b, d, k_face)) > 0
             ? Sign::Positive
             : Sign::Negative;
}

}  // namespace

DegreeVerdict overlap_by_degree(const Context& c, CheckResult& r) {
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  const Topology& topo = c.topology;
  // The premises: positive tets; faces held once, or twice with opposite orientations.
  for (Sign s : c.orientation)
    if (s != Sign::Positive) return DegreeVerdict::PremisesFail;
  for (std::size_t f = 0; f < topo.faces.size(); ++f) {
    const auto h = topo.holders(f);
    if (h.size() > 2) return DegreeVerdict::PremisesFail;
    // Opposite orientations: one holder lists the face as an odd permutation of the
    // other's (FaceRef::odd; every tet here has distinct vertices, being positive).
    if (h.size() == 2 && h[0].odd == h[1].odd) return DegreeVerdict::PremisesFail;
  }
  const std::size_t m = topo.boundary.size();
  std::vector<Tri> S(m);
  std::vector<Box> boxes(m);
  for (std::size_t i = 0; i < m; ++i) {
    const FaceRef& h = topo.holders(topo.boundary[i])[0];
    S[i] = face_of(tets[h.tet], h.local);
    boxes[i] = box_of<3>(pts, S[i]);
  }
  // (a): candidate pairs from a grid over the faces' boxes, each pair examined once
  // (grid.hpp).
  std::uint64_t pairs = 0;
  bool improper_pair = false;
  auto sequential = [](std::size_t n, auto&& body) { body(0u, 0, n); };
  for_each_box_pair(boxes, 4, sequential, [&](unsigned, std::uint32_t i, std::uint32_t j) {
    if (improper_pair) return;
    ++pairs;
    improper_pair = improper(S[i], S[j], pts);
  });
  if (improper_pair) {
    r.counts["degree.boundary_pairs_examined"] = pairs;
    r.counts["degree.boundary_not_a_complex"] = 1;
    return DegreeVerdict::PremisesFail;
  }
  r.counts["degree.boundary_pairs_examined"] = pairs;
  // (b): classes of S linked through edges held by exactly two faces of S.
  UnionFind classes(m);
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> uses;  // (edge, face)
    uses.reserve(3 * m);
    for (std::uint32_t i = 0; i < m; ++i)
      for (int k = 0; k < 3; ++k) uses.emplace_back(edge_key(S[i][k], S[i][(k + 1) % 3]), i);
    std::sort(uses.begin(), uses.end());
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i;
      while (j < uses.size() && uses[j].first == uses[i].first) ++j;
      if (j - i == 2) classes.join(uses[i].second, uses[i + 1].second);
      i = j;
    }
  }
  struct Probe {
    std::uint32_t face;  // index into S
    int axis;            // a projection axis of the face
  };
  std::vector<Probe> probes;
  for (std::uint32_t i = 0; i < m; ++i)
    if (classes.find(i) == i) probes.push_back({i, 0});
  for (Probe& p : probes) p.axis = projection_axis(pts[S[p.face][0]], pts[S[p.face][1]], pts[S[p.face][2]]);
  // Probes by the x coordinate of their vertex a: a tet's box selects them by binary search.
  std::sort(probes.begin(), probes.end(),
            [&](const Probe& x, const Probe& y) { return pts[S[x.face][0]][0] < pts[S[y.face][0]][0]; });
  std::uint64_t covered = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& k = tets[t];
    const Box b = box_of<4>(pts, k);
    auto it = std::lower_bound(probes.begin(), probes.end(), b.lo[0],
                               [&](const Probe& p, double x) { return pts[S[p.face][0]][0] < x; });
    for (; it != probes.end() && pts[S[it->face][0]][0] <= b.hi[0]; ++it) {
      const Tri& f = S[it->face];
      P a = pts[f[0]];
      if (a[1] < b.lo[1] || a[1] > b.hi[1] || a[2] < b.lo[2] || a[2] > b.hi[2]) continue;
      bool inside = true;
      for (int g = 0; g < 4 && inside; ++g) {
        const Tri o = face_of(k, g);
        inside = side_of_pushed_point(pts[o[0]], pts[o[1]], pts[o[2]], a, pts[f[1]], pts[f[2]], it->axis) ==
                 Sign::Negative;
      }
      if (inside) ++covered;
    }
  }
  r.counts["degree.outer_cells_probed"] = probes.size();
  if (covered > 0) r.counts["degree.covered_probes"] = covered;
  return covered == 0 ? DegreeVerdict::Disjoint : DegreeVerdict::Overlap;
}

}  // namespace pdr::check
