// audit_surface (paper §1.1, §2.1; Lemma 1 invariant 1 on the surface): the structural
// half, then the encroachment half; see surface/audit.hpp.
//
// Encroachment candidates: the surface's vertices sorted by x; for a ball of center c and radius r,
// those with x in [c_x - h, c_x + h] and y, z likewise, h = r (1 + 2^-40) + 2^-40 max|c_i|.
// The center and radius come from doubles within a few ulps of the exact values (the
// midpoint rounded once, the subfacet's exact rational circumcenter and radius converted
// with relative error 2^-52, one rounded square root), so the box holds the closed ball;
// the box only prunes. Each candidate is then decided exactly (geom/encroach.hpp).

#include "surface/audit.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "geom/encroach.hpp"
#include "geom/predicates.hpp"
#include "surface/encroach.hpp"

namespace pdr::surface {

namespace {

std::string edge_str(std::uint32_t u, std::uint32_t w) {
  std::string s = "(";  // appended: GCC 12 warns (-Wrestrict) on "(" + std::string&&
  s += std::to_string(u);
  s += ", ";
  s += std::to_string(w);
  s += ")";
  return s;
}

std::string tri_str(const Subfacet& t) {
  return "subfacet (" + std::to_string(t.v[0]) + ", " + std::to_string(t.v[1]) + ", " +
         std::to_string(t.v[2]) + ")";
}

// sign of (q - p).(b - a), exact.
Sign advance(const Point& p, const Point& q, const Point& a, const Point& b) {
  mpq_class s = 0;
  for (int k = 0; k < 3; ++k) s += (mpq_class(q[k]) - p[k]) * (mpq_class(b[k]) - a[k]);
  return sign_of(sgn(s));
}

mpq_class cross2(const domain::P2& p, const domain::P2& q) { return mpq_class(p[0]) * q[1] - mpq_class(p[1]) * q[0]; }

void check_incidences(const SurfaceMesh& m, SurfaceAudit& out) {
  const std::size_t n = m.vertex_count();
  std::vector<std::vector<std::uint32_t>> segs(n), tris(n);
  for (std::uint32_t s = 0; s < m.subsegments().size(); ++s)
    for (const std::uint32_t v : m.subsegment(s).v) segs[v].push_back(s);
  for (std::uint32_t t = 0; t < m.subfacets().size(); ++t)
    if (m.subfacet(t).alive)
      for (const std::uint32_t v : m.subfacet(t).v) tris[v].push_back(t);
  std::vector<std::vector<std::uint32_t>> of(m.facets.size());
  for (std::uint32_t t = 0; t < m.subfacets().size(); ++t)
    if (m.subfacet(t).alive && m.subfacet(t).facet < of.size()) of[m.subfacet(t).facet].push_back(t);
  for (std::uint32_t f = 0; f < of.size(); ++f)
    if (m.facet_subfacets(f) != of[f])
      out.add("surface.homes: the subfacet list of " + m.facet_name(f) +
              " differs from the live subfacets of that facet");
  for (std::uint32_t v = 0; v < n; ++v) {
    std::vector<std::uint32_t> a = m.vertex_subsegments(v), b = m.vertex_subfacets(v);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != segs[v] || b != tris[v])
      out.add("surface.homes: the incidence lists of vertex " + std::to_string(v) +
              " differ from the subsegments and live subfacets that contain it");
    const Home h = m.home(v);
    const std::string who = "vertex " + std::to_string(v);
    switch (h.kind) {
      case HomeKind::Input:
        if (h.id != v) out.add("surface.homes: input " + who + " has home id " + std::to_string(h.id));
        break;
      case HomeKind::Segment:
        if (h.id >= m.segments.size() || segs[v].size() != 2 ||
            m.subsegment(segs[v][0]).segment != h.id || m.subsegment(segs[v][1]).segment != h.id) {
          out.add("surface.homes: " + who + " with segment home " + std::to_string(h.id) +
                  " is not inside exactly one chain of that segment");
          break;
        }
        for (const std::uint32_t t : tris[v]) {
          const auto& fs = m.segments[h.id].facets;
          if (!std::binary_search(fs.begin(), fs.end(), m.subfacet(t).facet))
            out.add("surface.homes: " + who + " on " + m.segment_name(h.id) + " is in " +
                    tri_str(m.subfacet(t)) + " of " + m.facet_name(m.subfacet(t).facet) +
                    ", which does not contain the segment");
        }
        break;
      case HomeKind::Facet:
        if (h.id >= m.facets.size() || tris[v].empty() || !segs[v].empty()) {
          out.add("surface.homes: facet " + who + " is in no subfacet of its facet, or on a subsegment");
          break;
        }
        for (const std::uint32_t t : tris[v])
          if (m.subfacet(t).facet != h.id)
            out.add("surface.homes: " + who + " of " + m.facet_name(h.id) + " is in " +
                    tri_str(m.subfacet(t)) + " of " + m.facet_name(m.subfacet(t).facet));
        break;
    }
  }
}

void check_chains(const SurfaceMesh& m, SurfaceAudit& out) {
  std::vector<std::size_t> count(m.segments.size(), 0);
  for (const Subsegment& g : m.subsegments()) ++count[g.segment];
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) {
    const SurfaceSegment& S = m.segments[s];
    const std::vector<std::uint32_t> ch = m.chain(s);
    if (ch.back() != S.b || ch.size() != count[s] + 1) {
      out.add("surface.chains: the subsegments of " + m.segment_name(s) +
              " do not form one chain from a to b");
      continue;
    }
    for (std::size_t i = 0; i + 1 < ch.size(); ++i) {
      if (i > 0 && (m.home(ch[i]).kind != HomeKind::Segment || m.home(ch[i]).id != s))
        out.add("surface.chains: vertex " + std::to_string(ch[i]) + " inside " +
                m.segment_name(s) + " does not have the segment as its home");
      if (advance(m.point(ch[i]), m.point(ch[i + 1]), m.point(S.a), m.point(S.b)) != Sign::Positive)
        out.add("surface.chains: subsegment " + edge_str(ch[i], ch[i + 1]) + " of " +
                m.segment_name(s) + " does not advance from a to b");
    }
  }
}

// Orientation, adjacency, conformity, area and local Delaunay of facet f.
void check_facet(const SurfaceMesh& m, std::uint32_t f, const std::vector<std::uint32_t>& tris,
                 SurfaceAudit& out) {
  const SurfaceFacet& F = m.facets[f];
  const FacetChart& ch = F.chart;
  const std::string fn = m.facet_name(f);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  mpq_class area2 = 0;
  for (const std::uint32_t t : tris) {
    const Subfacet& T = m.subfacet(t);
    const Point &a = m.point(T.v[0]), &b = m.point(T.v[1]), &c = m.point(T.v[2]);
    if (chart_orient(ch, a, b, c) != Sign::Positive)
      out.add("surface.orientation: " + tri_str(T) + " of " + fn + " is not counter-clockwise in the chart");
    const domain::P2 A = ch(a), B = ch(b), C = ch(c);
    area2 += (mpq_class(B[0]) - A[0]) * (mpq_class(C[1]) - A[1]) -
             (mpq_class(B[1]) - A[1]) * (mpq_class(C[0]) - A[0]);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = T.v[(i + 1) % 3], w = T.v[(i + 2) % 3];
      ++directed[{u, w}];
      const auto g = m.find_subsegment(u, w);
      const bool sub = g && std::binary_search(F.segments.begin(), F.segments.end(),
                                               m.subsegment(*g).segment);
      if (sub != T.constrained[i])
        out.add("surface.conformity: edge " + edge_str(u, w) + " of " + tri_str(T) + " in " + fn +
                (sub ? " is a subsegment but not marked" : " is marked but not a subsegment of the facet"));
      const std::int32_t nb = T.nbr[i];
      if (nb < 0) {
        if (!sub) out.add("surface.adjacency: edge " + edge_str(u, w) + " of " + tri_str(T) + " in " + fn +
                          " has no neighbour and is not a subsegment");
        continue;
      }
      const Subfacet& N = m.subfacet(static_cast<std::uint32_t>(nb));
      const int j = N.alive && N.facet == f ? edge_index(N, u, w) : -1;
      if (j < 0 || N.nbr[j] != static_cast<std::int32_t>(t)) {
        out.add("surface.adjacency: the neighbour of " + tri_str(T) + " across " + edge_str(u, w) +
                " in " + fn + " does not share the edge or does not point back");
        continue;
      }
      if (nb < static_cast<std::int32_t>(t)) continue;  // each interior edge once
      const Point& d = m.point(N.v[j]);
      if (chart_incircle(ch, a, b, c, d) != Sign::Negative)
        out.add("surface.delaunay: edge " + edge_str(u, w) + " of " + fn +
                " is not locally Delaunay: vertex " + std::to_string(N.v[j]) + " is inside the circle of " +
                tri_str(T));
      if (orient3d(a, b, c, d) == Sign::Zero) {
        ++out.coplanar_edges;
        if (incircle3_sos(a, b, c, d) != Sign::Negative)
          out.add("surface.delaunay: at edge " + edge_str(u, w) + " of " + fn +
                  ", incircle3_sos disagrees with the facet's in-circle test");
      } else {
        ++out.off_plane_edges;
      }
    }
  }
  // Boundary chains once in their direction; interior segments once each way; the rest
  // of the directed edges paired.
  mpq_class bound2 = 0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> expected;
  std::vector<bool> on_boundary(m.segments.size(), false);
  for (const BoundarySide& side : F.boundary) {
    on_boundary[side.segment] = true;
    std::vector<std::uint32_t> c = m.chain(side.segment);
    if (!side.forward) std::reverse(c.begin(), c.end());
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
      ++expected[{c[i], c[i + 1]}];
      bound2 += cross2(ch(m.point(c[i])), ch(m.point(c[i + 1])));
    }
  }
  for (const std::uint32_t s : F.segments) {
    if (on_boundary[s]) continue;
    const std::vector<std::uint32_t> c = m.chain(s);
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
      ++expected[{c[i], c[i + 1]}];
      ++expected[{c[i + 1], c[i]}];
    }
  }
  for (const auto& [e, k] : expected)
    if (directed.count(e) == 0 || directed[e] != k)
      out.add("surface.conformity: subsegment " + edge_str(e.first, e.second) + " of " + fn +
              " is not an edge of exactly one subfacet on each of its facet sides");
  for (const auto& [e, k] : directed) {
    const bool rev = directed.count({e.second, e.first}) != 0;
    if (k != 1 || (!rev && expected.count(e) == 0))
      out.add("surface.conformity: directed edge " + edge_str(e.first, e.second) + " of " + fn +
              (k != 1 ? " is used by two subfacets (overlap)" : " is unmatched and not on the boundary"));
  }
  // Shoelace over the boundary chains (each counter-clockwise around the region).
  if (area2 != bound2)
    out.add("surface.area: the subfacets of " + fn + " cover " + std::to_string(area2.get_d() / 2) +
            " of chart area, the facet's boundary chains enclose " + std::to_string(bound2.get_d() / 2));
}

void check_sizes(const SurfaceMesh& m, SurfaceAudit& out) {
  if (!(m.d > 0) || !std::isfinite(m.d)) return;
  // Graded meshes: each element against the d it was refined for (at its position).
  for (std::uint32_t s = 0; s < m.subsegments().size(); ++s)
    if (subsegment_too_long(m, s, m.subsegment_size(s)))
      out.add("surface.size: subsegment " + edge_str(m.subsegment(s).v[0], m.subsegment(s).v[1]) +
              " of " + m.segment_name(m.subsegment(s).segment) + " is at least 2d long");
  for (std::uint32_t t = 0; t < m.subfacets().size(); ++t)
    if (m.subfacet(t).alive && subfacet_too_large(m, t, m.subfacet_size(t)))
      out.add("surface.size: " + tri_str(m.subfacet(t)) + " of " + m.facet_name(m.subfacet(t).facet) +
              " has circumradius at least d√2");
}

}  // namespace

void audit_surface_structure(const SurfaceMesh& m, SurfaceAudit& out) {
  check_incidences(m, out);
  check_chains(m, out);
  std::vector<std::vector<std::uint32_t>> by_facet(m.facets.size());
  for (std::uint32_t t = 0; t < m.subfacets().size(); ++t) {
    const Subfacet& T = m.subfacet(t);
    if (!T.alive) continue;
    if (T.facet >= m.facets.size() || !m.facets[T.facet].is_face)
      out.add("surface.homes: " + tri_str(T) + " belongs to no face");
    else
      by_facet[T.facet].push_back(t);
  }
  for (std::uint32_t f = 0; f < m.facets.size(); ++f)
    if (m.facets[f].is_face) check_facet(m, f, by_facet[f], out);
  check_sizes(m, out);
}

SurfaceAudit audit_surface(const SurfaceMesh& m, std::size_t max_reported) {
  SurfaceAudit out;
  out.max_reported = max_reported;
  audit_surface_structure(m, out);
  audit_surface_balls(m, out);
  return out;
}

namespace {

constexpr double kMargin = 0x1p-40;

class SortedVertices {
 public:
  explicit SortedVertices(const SurfaceMesh& m) : m_(m) {
    for (std::uint32_t v = 0; v < m.vertex_count(); ++v) order_.push_back(v);
    std::sort(order_.begin(), order_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return m.point(a)[0] < m.point(b)[0]; });
  }

  // Calls f(v) for every vertex in the box of center c and half-width h.
  template <class F>
  void query(const Point& c, double h, F&& f) const {
    const auto lo = std::lower_bound(order_.begin(), order_.end(), c[0] - h,
                                     [&](std::uint32_t v, double x) { return m_.point(v)[0] < x; });
    for (auto it = lo; it != order_.end() && m_.point(*it)[0] <= c[0] + h; ++it) {
      const Point& p = m_.point(*it);
      if (std::fabs(p[1] - c[1]) <= h && std::fabs(p[2] - c[2]) <= h) f(*it);
    }
  }

 private:
  const SurfaceMesh& m_;
  std::vector<std::uint32_t> order_;
};

double half_width(const Point& c, double r) {
  const double big = std::max({std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2])});
  return r * (1 + kMargin) + kMargin * big + 0x1p-1000;
}

}  // namespace

void audit_surface_balls(const SurfaceMesh& m, SurfaceAudit& out) {
  const SortedVertices sorted(m);
  for (std::uint32_t s = 0; s < m.subsegments().size(); ++s) {
    const Subsegment& g = m.subsegment(s);
    const Point &a = m.point(g.v[0]), &b = m.point(g.v[1]);
    Point c;
    double r2 = 0;
    for (int k = 0; k < 3; ++k) {
      c[k] = 0.5 * a[k] + 0.5 * b[k];
      r2 += (b[k] - a[k]) * (b[k] - a[k]);
    }
    sorted.query(c, half_width(c, 0.5 * std::sqrt(r2)), [&](std::uint32_t v) {
      if (v == g.v[0] || v == g.v[1] || in_diametral_ball(a, b, m.point(v)) == Sign::Negative) return;
      out.add("surface.encroachment: vertex " + std::to_string(v) +
              " is in the closed diametral ball of subsegment " + edge_str(g.v[0], g.v[1]) + " of " +
              m.segment_name(g.segment));
    });
  }
  // The vertices of each facet, for the cocircular case.
  std::vector<std::vector<std::uint32_t>> facet_vertices(m.facets.size());
  for (const Subfacet& t : m.subfacets())
    if (t.alive) facet_vertices[t.facet].insert(facet_vertices[t.facet].end(), t.v.begin(), t.v.end());
  for (auto& fv : facet_vertices) {
    std::sort(fv.begin(), fv.end());
    fv.erase(std::unique(fv.begin(), fv.end()), fv.end());
  }
  for (std::uint32_t t = 0; t < m.subfacets().size(); ++t) {
    const Subfacet& T = m.subfacet(t);
    if (!T.alive) continue;
    const Point &a = m.point(T.v[0]), &b = m.point(T.v[1]), &c = m.point(T.v[2]);
    const auto qc = exact::triangle_circumcenter(a, b, c);
    const Point center{qc[0].get_d(), qc[1].get_d(), qc[2].get_d()};
    const double r = std::sqrt(exact::triangle_circumradius2(a, b, c).get_d());
    const auto& fv = facet_vertices[T.facet];
    sorted.query(center, half_width(center, r), [&](std::uint32_t v) {
      if (v == T.v[0] || v == T.v[1] || v == T.v[2]) return;
      const Sign s = in_equatorial_ball(a, b, c, m.point(v));
      if (s == Sign::Negative) return;
      if (s == Sign::Zero && std::binary_search(fv.begin(), fv.end(), v)) {
        ++out.cocircular;
        return;
      }
      const bool off_plane = std::binary_search(fv.begin(), fv.end(), v) &&
                             orient3d(a, b, c, m.point(v)) != Sign::Zero;
      out.off_plane_balls += off_plane;
      out.add("surface.encroachment: vertex " + std::to_string(v) +
              (s == Sign::Positive ? " is strictly inside" : " is on") +
              " the equatorial ball of subfacet (" + std::to_string(T.v[0]) + ", " +
              std::to_string(T.v[1]) + ", " + std::to_string(T.v[2]) + ") of " +
              m.facet_name(T.facet) +
              (off_plane ? " (a vertex of the same facet off the subfacet's plane)" : ""));
    });
  }
}

}  // namespace pdr::surface
