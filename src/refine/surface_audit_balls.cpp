// The encroachment half of audit_surface (paper §1.1 "encroached", Lemma 1 invariant 1 on
// the surface); see surface_audit.hpp.
//
// Candidates: the surface's vertices sorted by x; for a ball of center c and radius r,
// those with x in [c_x - h, c_x + h] and y, z likewise, h = r (1 + 2^-40) + 2^-40 max|c_i|.
// The center and radius come from doubles within a few ulps of the exact values (the
// midpoint rounded once, the subfacet's exact rational circumcenter and radius converted
// with relative error 2^-52, one rounded square root), so the box holds the closed ball;
// the box only prunes. Each candidate is then decided exactly (geom/encroach.hpp).
#include <algorithm>
#include <cmath>

#include "geom/encroach.hpp"
#include "geom/predicates.hpp"
#include "refine/surface_audit.hpp"

namespace pdr::refine {

namespace {

constexpr double kMargin = 0x1p-40;

class SortedVertices {
 public:
  explicit SortedVertices(const SurfaceMesh& m) : m_(m) {
    for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
      if (m.home(v).kind != HomeKind::Unused) order_.push_back(v);
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

std::string edge_str(std::uint32_t u, std::uint32_t w) {
  std::string s = "(";  // appended: GCC 12 warns (-Wrestrict) on "(" + std::string&&
  s += std::to_string(u);
  s += ", ";
  s += std::to_string(w);
  s += ")";
  return s;
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

}  // namespace pdr::refine
