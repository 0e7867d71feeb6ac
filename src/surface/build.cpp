// The unrefined surface mesh (paper §2.1), and the Lawson flips that make each facet's
// triangulation constrained Delaunay; see surface/build.hpp.
//
// Flips (paper §2.1 step 2: "let D be a Delaunay triangulation of the vertices of F").
// Start: the domain analysis' triangulation of the facet's region (any triangulation
// with the input vertices as corners, conforming to the segments). An unconstrained
// interior edge whose opposite vertex is inside the circle of the other side
// (chart_incircle > 0) is flipped. chart_incircle is one lifting map plus one perturbation
// (surface/chart.hpp), so every flip lowers the lifted surface and no triangulation comes
// back: the flips stop, at the constrained regular (for coplanar points: constrained
// Delaunay under incircle3_sos) triangulation. For such a lift a non-locally-Delaunay edge
// always has a convex quadrilateral when no vertex is redundant, which a near-paraboloid
// lift excludes; a non-convex one is reported (SurfaceError), as is the flip cap
// (a safety net: n(n-1)/2 flips bound Lawson's algorithm for n vertices).

#include "surface/build.hpp"

#include <algorithm>
#include <cmath>
#include <vector>


namespace pdr::surface {

SurfaceMesh build_surface(const domain::PlcDomain& dom) {
  const Plc& plc = dom.plc;
  SurfaceMesh m;
  m.source = plc.source;
  for (std::uint32_t v = 0; v < plc.points.size(); ++v)
    m.add_vertex(plc.points[v], {HomeKind::Input, v});
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    const domain::DomainSegment& S = dom.segments[s];
    m.segments.push_back({S.a, S.b, S.facets});
    m.add_subsegment(S.a, S.b, s);
  }
  m.facets.resize(dom.facets.size());
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    const domain::DomainFacet& F = dom.facets[f];
    SurfaceFacet& sf = m.facets[f];
    sf.is_face = F.is_face;
    sf.segments = F.segments;
    sf.line = plc.facets[f].line;
    sf.separates = dom.facets[f].separates;
    sf.plane_group = F.plane_group;
    if (!F.is_face) continue;
    sf.chart = make_chart(F.plane, plc.points);
    if (!F.plane.exact) {
      const Point& o = sf.chart.origin;
      const Point& n = sf.chart.normal;
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (const std::uint32_t v : F.vertices) {
        const Point& p = plc.points[v];
        const double h = n[0] * (p[0] - o[0]) + n[1] * (p[1] - o[1]) + n[2] * (p[2] - o[2]);
        sf.gap = std::max(sf.gap, std::abs(h) / len);
      }
    }
    const auto base = static_cast<std::int32_t>(m.subfacets().size());
    for (const domain::FacetTri& T : F.tris) {
      Subfacet t;
      t.v = T.v;
      t.facet = f;
      for (int i = 0; i < 3; ++i) {
        t.nbr[i] = T.nbr[i] >= 0 ? base + T.nbr[i] : -1;
        t.constrained[i] = T.on_segment[i];
        if (T.nbr[i] >= 0) continue;
        const std::uint32_t u = T.v[(i + 1) % 3], w = T.v[(i + 2) % 3];
        const std::uint32_t s = *dom.find_segment(u, w);
        sf.boundary.push_back({s, u == dom.segments[s].a});
      }
      m.add_subfacet(t);
    }
    make_facet_delaunay(m, f);
  }
  return m;
}

void make_facet_delaunay(SurfaceMesh& m, std::uint32_t f) {
  const FacetChart& ch = m.facets[f].chart;
  std::vector<std::pair<std::uint32_t, int>> stack;
  std::vector<std::uint32_t> verts;
  for (const std::uint32_t t : m.facet_subfacets(f))
    for (int i = 0; i < 3; ++i) {
      stack.emplace_back(t, i);
      verts.push_back(m.subfacet(t).v[i]);
    }
  const std::size_t n = verts.size();  // at least the vertex count
  const std::size_t cap = n * n / 2 + 16;
  std::size_t flips = 0;
  while (!stack.empty()) {
    const auto [t, i] = stack.back();
    stack.pop_back();
    const Subfacet T = m.subfacet(t);
    if (!T.alive || T.nbr[i] < 0 || T.constrained[i]) continue;
    const auto nb = static_cast<std::uint32_t>(T.nbr[i]);
    const Subfacet N = m.subfacet(nb);
    const std::uint32_t a = T.v[i], b = T.v[(i + 1) % 3], c = T.v[(i + 2) % 3];
    const int j = edge_index(N, b, c);
    const std::uint32_t d = N.v[j];
    if (chart_incircle(ch, m.point(a), m.point(b), m.point(c), m.point(d)) != Sign::Positive)
      continue;
    if (chart_orient(ch, m.point(a), m.point(b), m.point(d)) != Sign::Positive ||
        chart_orient(ch, m.point(a), m.point(d), m.point(c)) != Sign::Positive)
      throw SurfaceError("surface.delaunay: " + m.facet_name(f) + ": the edge (" +
                         std::to_string(b) + ", " + std::to_string(c) +
                         ") is not locally Delaunay but its quadrilateral is not convex");
    if (++flips > cap)
      throw SurfaceError("surface.delaunay: " + m.facet_name(f) + ": more than " +
                         std::to_string(cap) + " Lawson flips");
    // N = (d, c, b) in counter-clockwise order: N.nbr[(j+1)%3] is across (b, d), N.nbr[(j+2)%3]
    // across (d, c); T.nbr[(i+1)%3] is across (c, a), T.nbr[(i+2)%3] across (a, b).
    const int ib = (i + 1) % 3, ic = (i + 2) % 3, jc = (j + 1) % 3, jb = (j + 2) % 3;
    Subfacet P, Q;  // P = (a, b, d), Q = (a, d, c)
    P.facet = Q.facet = f;
    P.v = {a, b, d};
    P.nbr = {N.nbr[jc], -1, T.nbr[ic]};
    P.constrained = {N.constrained[jc], false, T.constrained[ic]};
    Q.v = {a, d, c};
    Q.nbr = {N.nbr[jb], T.nbr[ib], -1};
    Q.constrained = {N.constrained[jb], T.constrained[ib], false};
    m.kill_subfacet(t);
    m.kill_subfacet(nb);
    const std::uint32_t p = m.add_subfacet(P), q = m.add_subfacet(Q);
    m.subfacet_mut(p).nbr[1] = static_cast<std::int32_t>(q);
    m.subfacet_mut(q).nbr[2] = static_cast<std::int32_t>(p);
    for (const std::uint32_t x : {p, q}) {
      const Subfacet& X = m.subfacet(x);
      for (const int k : {0, x == p ? 2 : 1}) {
        if (X.nbr[k] >= 0) {
          Subfacet& O = m.subfacet_mut(static_cast<std::uint32_t>(X.nbr[k]));
          O.nbr[edge_index(O, X.v[(k + 1) % 3], X.v[(k + 2) % 3])] = static_cast<std::int32_t>(x);
        }
        stack.emplace_back(x, k);
      }
    }
  }
}

}  // namespace pdr::surface
