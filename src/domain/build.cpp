// build_domain: validation of a PLC as a polyhedral domain and construction of its related
// components (paper §1.1). Steps 1, 2 and 6 and the segment structure live here; the other
// steps have their own files (domain/steps.hpp).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "domain/steps.hpp"
#include "domain/validate.hpp"
#include "io/error.hpp"

namespace pdr::domain {

namespace detail {

std::string vertex_name(const Plc& plc, std::uint32_t v) {
  std::string s = "vertex " + std::to_string(v);
  if (v < plc.point_lines.size() && plc.point_lines[v] != 0)
    s += " (line " + std::to_string(plc.point_lines[v]) + ")";
  return s;
}

std::string facet_name(const Plc& plc, std::size_t f) {
  std::string s = "facet " + std::to_string(f);
  if (f < plc.facets.size() && plc.facets[f].line != 0)
    s += " (line " + std::to_string(plc.facets[f].line) + ")";
  return s;
}

void fail(const Plc& plc, std::size_t line, const std::string& message) {
  throw InputError(plc.source, line, message);
}

namespace {

std::size_t point_line(const Plc& plc, std::uint32_t v) {
  return v < plc.point_lines.size() ? plc.point_lines[v] : 0;
}

}  // namespace

void check_points(const Plc& plc) {
  const auto n = static_cast<std::uint32_t>(plc.points.size());
  for (std::uint32_t v = 0; v < n; ++v)
    for (double x : plc.points[v])
      if (!std::isfinite(x))
        fail(plc, point_line(plc, v),
             "finite coordinates: " + vertex_name(plc, v) +
                 " has a coordinate that is not a finite number; fix the coordinate");
  std::vector<std::uint32_t> ord(n);
  std::iota(ord.begin(), ord.end(), 0u);
  std::sort(ord.begin(), ord.end(), [&](std::uint32_t a, std::uint32_t b) {
    return plc.points[a] < plc.points[b] || (plc.points[a] == plc.points[b] && a < b);
  });
  for (std::uint32_t i = 1; i < n; ++i)
    if (plc.points[ord[i - 1]] == plc.points[ord[i]])
      fail(plc, point_line(plc, ord[i]),
           "distinct vertices: " + vertex_name(plc, ord[i]) + " has the same coordinates as " +
               vertex_name(plc, ord[i - 1]) +
               "; remove one of them and renumber the polygons that use it");
}

std::vector<FacetPolys> check_polygons(const Plc& plc) {
  std::vector<FacetPolys> out(plc.facets.size());
  const std::size_t n = plc.points.size();
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    const PlcFacet& facet = plc.facets[f];
    auto here = [&](const std::string& m) { fail(plc, facet.line, m); };
    if (facet.polygons.empty()) here("non-empty facet: this facet has no polygon; remove it");
    for (std::size_t k = 0; k < facet.polygons.size(); ++k) {
      const auto& poly = facet.polygons[k];
      const std::string which = "polygon " + std::to_string(k + 1) + " of this facet";
      if (poly.empty()) here("non-empty polygon: " + which + " has no vertex; remove it");
      for (std::uint32_t v : poly)
        if (v >= n)
          here("index in range: " + which + " uses vertex index " + std::to_string(v) +
               " (0-based) but there are " + std::to_string(n) +
               " vertices; fix the index (the first vertex's number in the file sets the "
               "index base)");
      const std::size_t m = poly.size();
      for (std::size_t i = 0; i < m && m >= 2; ++i) {
        if (m == 2 && i == 1) break;
        if (poly[i] == poly[(i + 1) % m])
          here("non-degenerate polygon: " + which + " repeats " + vertex_name(plc, poly[i]) +
               " consecutively; remove the repetition");
      }
      if (m == 1) {
        out[f].points.push_back(poly[0]);
        continue;
      }
      if (m == 2) {
        out[f].segs.push_back({poly[0], poly[1]});
        continue;
      }
      std::vector<std::uint32_t> sorted(poly);
      std::sort(sorted.begin(), sorted.end());
      if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
        here("simple polygon: " + which + " visits " + vertex_name(plc, *it) +
             " twice, so it touches itself; split it into simple polygons");
      bool flat = true;
      for (std::size_t i = 2; i < m && flat; ++i)
        flat = collinear(plc.points[poly[0]], plc.points[poly[1]], plc.points[poly[i]]);
      if (flat)
        here("non-degenerate polygon: " + which + " has zero area (its " + std::to_string(m) +
             " vertices are collinear); remove it, or list it as 2-vertex segments");
      out[f].loops.push_back(poly);
      out[f].loop_index.push_back(k);
    }
  }
  return out;
}

void build_structure(const std::vector<FacetPolys>& polys, PlcDomain& dom) {
  const Plc& plc = dom.plc;
  std::vector<std::array<std::uint32_t, 2>> keys;
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return std::array<std::uint32_t, 2>{std::min(a, b), std::max(a, b)};
  };
  for (std::size_t f = 0; f < dom.facets.size(); ++f) {
    for (const FacetTri& t : dom.facets[f].tris)
      for (int i = 0; i < 3; ++i)
        if (t.on_segment[i]) keys.push_back(key(t.v[(i + 1) % 3], t.v[(i + 2) % 3]));
    if (!dom.facets[f].is_face)
      for (const auto& s : polys[f].segs) keys.push_back(key(s[0], s[1]));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  dom.segments.resize(keys.size());
  for (std::size_t s = 0; s < keys.size(); ++s) {
    dom.segments[s].a = keys[s][0];
    dom.segments[s].b = keys[s][1];
  }
  const std::size_t nv = plc.points.size();
  dom.vertex_segments.assign(nv, {});
  dom.vertex_facets.assign(nv, {});
  for (std::size_t f = 0; f < dom.facets.size(); ++f) {
    DomainFacet& F = dom.facets[f];
    const auto fid = static_cast<std::uint32_t>(f);
    std::vector<std::uint32_t> verts(polys[f].points);
    for (std::uint32_t t = 0; t < F.tris.size(); ++t) {
      const FacetTri& T = F.tris[t];
      for (int i = 0; i < 3; ++i) {
        verts.push_back(T.v[i]);
        if (!T.on_segment[i]) continue;
        const std::uint32_t p = T.v[(i + 1) % 3], q = T.v[(i + 2) % 3];
        const std::uint32_t s = *dom.find_segment(p, q);
        HalfFacet h;
        h.facet = fid;
        h.tri = t;
        h.apex = T.v[i];
        h.dir = p == dom.segments[s].a ? 1 : -1;
        dom.segments[s].sides.push_back(h);
        F.segments.push_back(s);
      }
    }
    if (!F.is_face)
      for (const auto& sg : polys[f].segs) {
        verts.push_back(sg[0]);
        verts.push_back(sg[1]);
      }
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    F.vertices = verts;
    std::sort(F.segments.begin(), F.segments.end());
    F.segments.erase(std::unique(F.segments.begin(), F.segments.end()), F.segments.end());
    if (F.is_face)
      for (std::uint32_t v : verts) dom.vertex_facets[v].push_back(fid);
  }
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    DomainSegment& S = dom.segments[s];
    dom.vertex_segments[S.a].push_back(s);
    dom.vertex_segments[S.b].push_back(s);
    for (const HalfFacet& h : S.sides) S.facets.push_back(h.facet);
    std::sort(S.facets.begin(), S.facets.end());
    S.facets.erase(std::unique(S.facets.begin(), S.facets.end()), S.facets.end());
  }
}

void check_closed(PlcDomain& dom) {
  const Plc& plc = dom.plc;
  if (plc.enclosure == Enclosure::HolePoints) return;  // open edges: domain/orient.cpp
  bool walls = false;
  for (const DomainSegment& s : dom.segments) {
    walls = walls || s.sides.size() > 2;
    if (s.sides.size() != 1) continue;
    const std::string seg = "the segment from " + vertex_name(plc, s.a) + " to " +
                            vertex_name(plc, s.b);
    fail(plc, plc.facets[s.sides[0].facet].line,
         "closed boundary: " + seg + " bounds only one facet side (this facet); every "
         "segment must be shared by two or more facet sides (two for a manifold "
         "surface). Add the missing facet; if a vertex of a neighbouring facet should "
         "split this edge, it must lie on it (within the coordinates' rounding)");
  }
  // A surface with walls (an edge of three or more faces: an assembly's shared face, a wall
  // splitting a body, bodies touching along an edge) is no 2-manifold, and parity misreads
  // it (the middle one of five tets filling a cube is enclosed twice): every bounded cell
  // is a region, as TetGen reads any surface.
  if (walls) {
    dom.plc.enclosure = Enclosure::HolePoints;
    dom.surface_walls = true;
  }
}

}  // namespace detail

std::optional<std::uint32_t> PlcDomain::find_segment(std::uint32_t a, std::uint32_t b) const {
  if (a > b) std::swap(a, b);
  auto it = std::lower_bound(segments.begin(), segments.end(), std::pair{a, b},
                             [](const DomainSegment& s, const std::pair<std::uint32_t, std::uint32_t>& k) {
                               return s.a < k.first || (s.a == k.first && s.b < k.second);
                             });
  if (it == segments.end() || it->a != a || it->b != b) return std::nullopt;
  return static_cast<std::uint32_t>(it - segments.begin());
}

std::size_t PlcDomain::face_count() const {
  return static_cast<std::size_t>(
      std::count_if(facets.begin(), facets.end(), [](const DomainFacet& f) { return f.is_face; }));
}

PlcDomain build_domain(const Plc& plc, const PlcOptions& options) {
  PlcDomain dom;
  dom.plc = plc;
  dom.options = options;
  dom.tolerance = io::planarity_tolerance_of(dom.plc, options.planarity_tolerance);
  dom.facets.resize(plc.facets.size());
  detail::check_points(plc);
  std::vector<detail::FacetPolys> polys = detail::check_polygons(plc);
  detail::split_edges(plc, dom.tolerance.uncertainty(), polys);
  detail::fit_planes(polys, dom);
  detail::triangulate_faces(polys, dom);
  detail::build_structure(polys, dom);
  detail::check_crossings(dom);
  detail::check_closed(dom);
  detail::orient_boundary(dom);
  return dom;
}

}  // namespace pdr::domain
