// Which side of the boundary is the domain (paper §1.1: "a closed polyhedral domain,
// possibly having holes and voids"), and the volume hole and region point checks (step 7
// of build_domain).
//
// The facets cut space into cells (domain/cells.hpp). Which cells form Ω depends on
// plc.enclosure: by parity, the points from which a ray crosses the boundary an odd number
// of times (the boundary is then closed mod 2); by hole points (TetGen's reading of a
// .poly), every bounded cell in which no volume hole point lies. Before the cells, the
// facet sides around each segment are sorted by angle about a->b (exact: orient3d against
// a reference side, then pairwise).
#include <algorithm>
#include <optional>
#include <stdexcept>

#include "domain/cells.hpp"
#include "domain/exact.hpp"
#include "domain/intersect.hpp"
#include "domain/steps.hpp"
#include "geom/predicates.hpp"
#include "mesh/union_find.hpp"

namespace pdr::domain::detail {

namespace {

void sort_sides(const std::vector<Point>& pts, DomainSegment& s) {
  if (s.sides.size() < 2) return;
  const Point &p = pts[s.a], &q = pts[s.b], &w0 = pts[s.sides[0].apex];
  const int drop = nondegenerate_drop(p, q, w0);
  auto half = [&](const HalfFacet& h) {
    if (h.apex == s.sides[0].apex) return 0;
    const Sign o = orient3d(p, q, w0, pts[h.apex]);
    if (o != Sign::Zero) return o == Sign::Positive ? 0 : 1;
    if (orient2d_dropping(drop, p, q, w0) == orient2d_dropping(drop, p, q, pts[h.apex]))
      throw std::logic_error("plc_orient: two facet sides overlap along a segment");
    return 1;  // the opposite half-plane: angle pi
  };
  std::stable_sort(s.sides.begin() + 1, s.sides.end(), [&](const HalfFacet& x, const HalfFacet& y) {
    const int hx = half(x), hy = half(y);
    if (hx != hy) return hx < hy;
    return orient3d(p, q, pts[x.apex], pts[y.apex]) == Sign::Positive;
  });
}

// A point given to mark a cell (a hole or region point) must lie off every facet (a ray
// cast from it needs that): else fail(line, what + " lies on <facet>" + advice).
void check_off_facets(const Plc& plc, const RayCaster& rays, const Point& p, std::size_t line,
                      const std::string& what, const std::string& advice) {
  Box q;
  q.add(p);
  rays.bvh().for_overlapping(q, [&](std::uint32_t k) {
    const FacetTri& t = rays.tri(rays.tris()[k]);
    if (point_in_triangle(plc.points[t.v[0]], plc.points[t.v[1]], plc.points[t.v[2]], p))
      fail(plc, line, what + " lies on " + facet_name(plc, rays.tris()[k].facet) + advice);
  });
}

void check_hole_off_facets(const PlcDomain& dom, const RayCaster& rays, std::size_t i) {
  const Plc& plc = dom.plc;
  check_off_facets(plc, rays, plc.holes[i], i < plc.hole_lines.size() ? plc.hole_lines[i] : 0,
                   "volume hole off facets: volume hole point " + std::to_string(i + 1),
                   "; move it into the void it marks");
}

// Shells: the connected components of the boundary surface (triangles joined within their
// facet and at segments), a figure of the domain report.
void number_shells(PlcDomain& dom) {
  UnionFind joins(dom.facets.size());
  for (const DomainSegment& s : dom.segments)
    for (const HalfFacet& h : s.sides) joins.join(h.facet, s.sides[0].facet);
  std::vector<int> id(dom.facets.size(), -1);
  dom.shells = 0;
  for (std::size_t f = 0; f < dom.facets.size(); ++f) {
    if (dom.facets[f].tris.empty()) continue;
    int& c = id[joins.find(static_cast<std::uint32_t>(f))];
    if (c < 0) c = static_cast<int>(dom.shells++);
    dom.facets[f].shell = c;
  }
}

// Volume hole points: each lies off the facets and in a bounded cell, and (by parity) in
// a void. Counts them per cell.
void locate_holes(PlcDomain& dom, const Cells& cells) {
  const Plc& plc = dom.plc;
  dom.cell_holes.assign(cells.count(), 0);
  for (std::size_t i = 0; i < plc.holes.size(); ++i) {
    const std::size_t line = i < plc.hole_lines.size() ? plc.hole_lines[i] : 0;
    const std::string which = "volume hole point " + std::to_string(i + 1);
    check_hole_off_facets(dom, cells.rays(), i);
    int total = 0;
    const int cell = cells.locate(make_rat(plc.holes[i]), &total);
    if (cell < 0)
      fail(plc, line,
           "volume hole in a void: " + which +
               " lies outside the domain's closed boundary; a volume hole point must mark "
               "a void enclosed by the boundary. Move it into the void or remove it");
    if (plc.enclosure == Enclosure::Parity && total % 2 == 1)
      fail(plc, line,
           "volume hole in a void: " + which +
               " lies inside the domain (it is enclosed by an odd number of closed boundary "
               "surfaces), not in a void; pdr's domain is what the closed boundary encloses, "
               "so a hole point can only mark a void. Move it into the void or remove it");
    std::uint8_t& n = dom.cell_holes[static_cast<std::size_t>(cell)];
    if (n < 255) ++n;
  }
}

// Which cells are in Ω, which facets separate, which triangle sides and wedges face Ω.
// Returns the facets (or parts) with no domain on either side.
std::vector<std::uint32_t> mark_inside(PlcDomain& dom, const Cells& cells) {
  dom.cells = cells.count();
  dom.cell_inside.assign(dom.cells, 0);
  for (std::size_t c = 0; c < dom.cells; ++c)
    dom.cell_inside[c] = dom.plc.enclosure == Enclosure::Parity ? cells.seed_parity(static_cast<int>(c))
                                                                : dom.cell_holes[c] == 0;
  const auto inside = [&](int c) { return c >= 0 && dom.cell_inside[static_cast<std::size_t>(c)] != 0; };
  std::vector<std::uint32_t> gone;
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    DomainFacet& F = dom.facets[f];
    if (F.tris.empty()) continue;
    F.cells = {cells.cell_of_side(f, 0, +1), cells.cell_of_side(f, 0, -1)};
    const bool front = inside(F.cells[0]), back = inside(F.cells[1]);
    if (!front && !back) gone.push_back(f);
    F.separates = front != back;
    for (FacetTri& t : F.tris) t.inward = static_cast<std::int8_t>(front ? 1 : -1);
  }
  for (DomainSegment& s : dom.segments)
    for (HalfFacet& h : s.sides)
      h.inside_after = static_cast<std::int8_t>(inside(cells.cell_of_side(h.facet, h.tri, h.dir)) ? 1 : -1);
  return gone;
}

// Facets (or parts) with no domain on either side: between two voids, or a void and the
// outside. TetGen drops them; so does pdr (PlcDomain::dropped), unless one has a free edge
// (an open surface: the boundary is open there) or the domain would be empty (the facets
// enclose no volume, or every region is a void): then the input is refused.
void drop_facets(PlcDomain& dom, const std::vector<std::uint32_t>& gone) {
  if (gone.empty()) return;
  // A dropped facet with a free edge (one facet side) is an open surface, not a wall
  // between voids: the boundary is open there.
  for (const std::uint32_t f : gone)
    for (const std::uint32_t sg : dom.facets[f].segments)
      if (dom.segments[sg].sides.size() == 1)
        fail(dom.plc, dom.plc.facets[f].line,
             "closed boundary: the segment from " + vertex_name(dom.plc, dom.segments[sg].a) +
                 " to " + vertex_name(dom.plc, dom.segments[sg].b) +
                 " bounds only one facet side (this facet) and no side of it is in the "
                 "domain; every segment must be shared by two or more facet sides, except "
                 "the free edges of a facet inside the domain. Add the missing facet; if a "
                 "vertex of a neighbouring facet should split this edge, it must lie "
                 "exactly on it");
  std::size_t faces = 0;
  for (const DomainFacet& F : dom.facets) faces += F.tris.empty() ? 0 : 1;
  if (gone.size() == faces) {
    const std::uint32_t f = gone.front();
    if (dom.plc.holes.empty())
      fail(dom.plc, dom.plc.facets[f].line,
           "closed boundary: the facets enclose no volume (" + facet_name(dom.plc, f) +
               " and every other one has the outside on both sides); a domain is the "
               "volume its facets enclose");
    fail(dom.plc, dom.plc.facets[f].line,
         "volume holes: every region is a void (volume hole points mark them all), so "
         "the domain is empty; remove the hole point of a region to mesh it");
  }
  std::vector<std::uint8_t> is_gone(dom.facets.size(), 0);
  for (const std::uint32_t f : gone) {
    DomainFacet& F = dom.facets[f];
    is_gone[f] = 1;
    PlcDomain::Dropped d{F.part_of >= 0 ? static_cast<std::uint32_t>(F.part_of) : f, {}};
    for (const FacetTri& t : F.tris) d.tris.push_back(t.v);
    dom.dropped.push_back(std::move(d));
    F.is_face = false;
    F.tris.clear();
    F.vertices.clear();
    F.segments.clear();
  }
  std::vector<std::int64_t> id(dom.segments.size(), -1);
  std::vector<DomainSegment> kept;
  for (std::size_t i = 0; i < dom.segments.size(); ++i) {
    DomainSegment& s = dom.segments[i];
    // Only a segment that loses every facet to dropped ones goes (a standalone segment,
    // on no facet side, stays).
    const std::size_t lost =
        std::erase_if(s.sides, [&](const HalfFacet& h) { return is_gone[h.facet] != 0; }) +
        std::erase_if(s.facets, [&](std::uint32_t f) { return is_gone[f] != 0; });
    if (lost > 0 && s.sides.empty() && s.facets.empty()) {
      dom.dropped_segments.push_back({s.a, s.b});
      continue;
    }
    id[i] = static_cast<std::int64_t>(kept.size());
    kept.push_back(std::move(s));
  }
  dom.segments = std::move(kept);
  const auto renumber = [&](std::vector<std::uint32_t>& list) {
    std::vector<std::uint32_t> out;
    for (const std::uint32_t sg : list)
      if (id[sg] >= 0) out.push_back(static_cast<std::uint32_t>(id[sg]));
    list = std::move(out);
  };
  for (DomainFacet& F : dom.facets) renumber(F.segments);
  for (auto& list : dom.vertex_segments) renumber(list);
  for (auto& list : dom.vertex_facets)
    std::erase_if(list, [&](std::uint32_t f) { return is_gone[f] != 0; });
  std::erase_if(dom.tolerance_facets, [&](std::uint32_t f) { return is_gone[f] != 0; });
}

void check_region_points(const PlcDomain& dom, const Cells& cells) {
  const Plc& plc = dom.plc;
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    const Point& p = plc.regions[i].point;
    const std::size_t line = plc.regions[i].line;
    const std::string which = "region point " + std::to_string(i + 1);
    check_off_facets(plc, cells.rays(), p, line, "region point in the domain: " + which,
                     "; move it into the region it names");
    const int cell = cells.locate(make_rat(p));
    if (cell < 0 || !dom.cell_inside[static_cast<std::size_t>(cell)])
      fail(plc, line,
           "region point in the domain: " + which +
               " lies outside the domain (outside its closed boundary, or in a void); a region "
               "point must lie inside the region it names. Move it there or remove it");
  }
}


// A facet whose triangles bound different pairs of cells (two polygons in different
// regions, or a face crossed by a wall's foot) is split into one facet per pair, so that
// every facet separates or is internal as a whole: the first part keeps its index, the
// others are appended, copies of its record without polygons (same marker and line).
// Returns whether any facet was split.
bool split_mixed_facets(PlcDomain& dom, const Cells& cells) {
  bool any = false;
  const std::size_t count = dom.facets.size();
  for (std::uint32_t f = 0; f < count; ++f) {
    const std::size_t n = dom.facets[f].tris.size();
    std::vector<std::pair<int, int>> pairs;
    std::vector<std::uint32_t> part(n), local(n);
    for (std::uint32_t t = 0; t < n; ++t) {
      const std::pair<int, int> key{cells.cell_of_side(f, t, +1), cells.cell_of_side(f, t, -1)};
      const auto it = std::find(pairs.begin(), pairs.end(), key);
      part[t] = static_cast<std::uint32_t>(it - pairs.begin());
      if (it == pairs.end()) pairs.push_back(key);
    }
    if (pairs.size() < 2) continue;
    any = true;
    const DomainFacet whole = dom.facets[f];
    std::vector<std::uint32_t> id(pairs.size(), f);
    for (std::size_t k = 1; k < pairs.size(); ++k) {
      id[k] = static_cast<std::uint32_t>(dom.facets.size());
      dom.facets.push_back({});
      PlcFacet copy = dom.plc.facets[f];
      copy.polygons.clear();
      copy.holes.clear();
      dom.plc.facets.push_back(std::move(copy));
      if (std::binary_search(dom.tolerance_facets.begin(), dom.tolerance_facets.end(), f))
        dom.tolerance_facets.push_back(id[k]);
    }
    std::vector<std::uint32_t> size(pairs.size(), 0);
    for (std::uint32_t t = 0; t < n; ++t) local[t] = size[part[t]]++;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      DomainFacet& F = dom.facets[id[k]];
      F = whole;
      F.part_of = f;
      F.tris.clear();
      F.vertices.clear();
      F.segments.clear();
      for (std::uint32_t t = 0; t < n; ++t) {
        if (part[t] != k) continue;
        FacetTri x = whole.tris[t];
        for (int e = 0; e < 3; ++e) {
          if (x.nbr[e] >= 0)
            x.nbr[e] = part[x.nbr[e]] == k ? static_cast<std::int32_t>(local[x.nbr[e]]) : -1;
          if (x.on_segment[e])
            if (const auto sg = dom.find_segment(x.v[(e + 1) % 3], x.v[(e + 2) % 3])) F.segments.push_back(*sg);
        }
        F.vertices.insert(F.vertices.end(), x.v.begin(), x.v.end());
        F.tris.push_back(x);
      }
      if (k == 0)  // 1-vertex polygons, and any segment no triangle holds, stay with the first part
        for (const std::uint32_t v : whole.vertices) F.vertices.push_back(v);
      std::sort(F.vertices.begin(), F.vertices.end());
      F.vertices.erase(std::unique(F.vertices.begin(), F.vertices.end()), F.vertices.end());
      if (k == 0)
        for (const std::uint32_t sg : whole.segments) {
          const DomainSegment& S = dom.segments[sg];
          bool held = false;
          for (const HalfFacet& h : S.sides) held = held || h.facet == f;
          if (!held) F.segments.push_back(sg);
        }
      std::sort(F.segments.begin(), F.segments.end());
      F.segments.erase(std::unique(F.segments.begin(), F.segments.end()), F.segments.end());
    }
    for (const std::uint32_t sg : whole.segments) {
      DomainSegment& S = dom.segments[sg];
      S.facets.clear();
      for (HalfFacet& h : S.sides) {
        if (h.facet == f) {
          const std::uint32_t t = h.tri;
          h.facet = id[part[t]];
          h.tri = local[t];
        }
        S.facets.push_back(h.facet);
      }
      std::sort(S.facets.begin(), S.facets.end());
      S.facets.erase(std::unique(S.facets.begin(), S.facets.end()), S.facets.end());
    }
    for (const std::uint32_t v : whole.vertices) {
      std::vector<std::uint32_t>& vf = dom.vertex_facets[v];
      vf.erase(std::remove(vf.begin(), vf.end(), f), vf.end());
      for (std::size_t k = 0; k < pairs.size(); ++k)
        if (std::binary_search(dom.facets[id[k]].vertices.begin(), dom.facets[id[k]].vertices.end(), v))
          vf.push_back(id[k]);
      std::sort(vf.begin(), vf.end());
    }
  }
  std::sort(dom.tolerance_facets.begin(), dom.tolerance_facets.end());
  return any;
}

}  // namespace

void orient_boundary(PlcDomain& dom) {
  for (DomainSegment& s : dom.segments) sort_sides(dom.plc.points, s);
  std::optional<Cells> cells(std::in_place, dom);
  if (split_mixed_facets(dom, *cells)) cells.emplace(dom);  // the same cells, renumbered triangles
  number_shells(dom);
  locate_holes(dom, *cells);
  const std::vector<std::uint32_t> gone = mark_inside(dom, *cells);
  check_region_points(dom, *cells);
  // Isolated vertices (off every facet, crossing.cpp) in a void or outside.
  for (std::uint32_t v = 0; v < dom.vertex_count(); ++v)
    if (dom.vertex_facets[v].empty() && dom.vertex_segments[v].empty())
      if (const int c = cells->locate(make_rat(dom.plc.points[v])); c < 0 || !dom.cell_inside[static_cast<std::size_t>(c)])
        dom.outside_vertices.push_back(v);
  drop_facets(dom, gone);  // after the last use of the cells, which point into the facets
}

}  // namespace pdr::domain::detail
