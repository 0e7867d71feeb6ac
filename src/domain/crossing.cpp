// Step 5 of build_domain: components meet only in the components they share (paper §1.1:
// Ω is a polyhedral domain whose boundary components are vertices, segments and facets).
//
// The items are the triangles of every face, the standalone segments (segments on no
// face) and the stray vertices (on no segment or face: 1-vertex polygons, and nodes that no
// facet lists, which TetGen inserts too). A bounding-volume
// hierarchy over their boxes enumerates the pairs whose boxes overlap (exact, closed
// boxes); each pair is decided by the exact tests of domain/intersect.hpp. Triangles of one
// face are not compared: a valid constrained triangulation of the face's chart does not
// overlap itself. Cost O(n log n + k) for n items and k overlapping pairs.
#include <string>

#include "domain/bvh.hpp"
#include "domain/intersect.hpp"
#include "domain/steps.hpp"

namespace pdr::domain::detail {

namespace {

struct Item {
  enum Kind : std::uint8_t { Triangle, Segment, Vertex } kind;
  std::uint32_t facet = 0;  // Triangle
  std::array<std::uint32_t, 3> v{};
};

bool has(const Item& it, std::uint32_t v) {
  const int n = it.kind == Item::Triangle ? 3 : (it.kind == Item::Segment ? 2 : 1);
  for (int i = 0; i < n; ++i)
    if (it.v[i] == v) return true;
  return false;
}

std::string describe(const PlcDomain& dom, const Item& it) {
  const Plc& plc = dom.plc;
  if (it.kind == Item::Triangle) return facet_name(plc, it.facet);
  if (it.kind == Item::Segment)
    return "the segment from " + vertex_name(plc, it.v[0]) + " to " + vertex_name(plc, it.v[1]);
  return "the isolated " + vertex_name(plc, it.v[0]);
}

std::size_t line_of(const PlcDomain& dom, const Item& it) {
  if (it.kind == Item::Triangle) return dom.plc.facets[it.facet].line;
  const auto& lines = dom.plc.point_lines;
  return it.v[0] < lines.size() ? lines[it.v[0]] : 0;
}

[[noreturn]] void report(const PlcDomain& dom, const Item& a, const Item& b) {
  const std::vector<Point>& pts = dom.plc.points;
  // A more specific diagnosis when a vertex of one lies on the other.
  const Item* pair[2] = {&a, &b};
  for (int k = 0; k < 2; ++k) {
    const Item& x = *pair[k];
    const Item& y = *pair[1 - k];
    if (y.kind != Item::Triangle) continue;
    const int n = x.kind == Item::Triangle ? 3 : (x.kind == Item::Segment ? 2 : 1);
    for (int i = 0; i < n; ++i)
      if (!has(y, x.v[i]) && point_in_triangle(pts[y.v[0]], pts[y.v[1]], pts[y.v[2]], pts[x.v[i]]))
        fail(dom.plc, line_of(dom, x),
             "non-crossing components: " +
                 (x.kind == Item::Vertex ? describe(dom, x)
                                         : vertex_name(dom.plc, x.v[i]) + " of " + describe(dom, x)) +
                 " lies on " + describe(dom, y) +
                 " but is not one of its vertices; list it in that facet (as a 1-vertex "
                 "polygon, or on its polygons) or fix the coordinates");
  }
  fail(dom.plc, line_of(dom, a),
       "non-crossing components: " + describe(dom, a) + " and " + describe(dom, b) +
           " intersect other than in shared vertices and segments; fix the geometry so "
           "that they meet only along common segments and vertices");
}

bool conflict(const Item& a, const Item& b, const std::vector<Point>& pts) {
  using K = Item::Kind;
  if (a.kind == K::Triangle && b.kind == K::Triangle)
    return a.facet != b.facet && triangles_conflict(a.v, b.v, pts);
  if (a.kind == K::Segment && b.kind == K::Triangle)  // along a triangle edge: see above
    return segment_triangle_conflict({a.v[0], a.v[1]}, b.v, pts);
  if (a.kind == K::Segment && b.kind == K::Segment)
    return segments_conflict({a.v[0], a.v[1]}, {b.v[0], b.v[1]}, pts);
  if (a.kind == K::Vertex && b.kind == K::Triangle)
    return point_in_triangle(pts[b.v[0]], pts[b.v[1]], pts[b.v[2]], pts[a.v[0]]);
  if (a.kind == K::Vertex && b.kind == K::Segment)
    return collinear(pts[b.v[0]], pts[b.v[1]], pts[a.v[0]]) &&
           strictly_between(pts[b.v[0]], pts[b.v[1]], pts[a.v[0]]);
  return false;
}

}  // namespace

void check_crossings(const PlcDomain& dom) {
  const std::vector<Point>& pts = dom.plc.points;
  // A segment along an edge of a face's triangulation that is not one of the face's
  // segments lies inside the face without being listed: the triangle tests below cannot
  // see it (triangles sharing an edge meet only in that edge), so it is checked here.
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
    for (const FacetTri& t : dom.facets[f].tris)
      for (int i = 0; i < 3; ++i) {
        if (t.on_segment[i]) continue;
        const std::uint32_t p = t.v[(i + 1) % 3], q = t.v[(i + 2) % 3];
        if (!dom.find_segment(p, q)) continue;
        fail(dom.plc, dom.plc.facets[f].line,
             "non-crossing components: the segment from " + vertex_name(dom.plc, p) + " to " +
                 vertex_name(dom.plc, q) + " of another facet lies inside " +
                 facet_name(dom.plc, f) +
                 " but is not one of its edges; add it to this facet as a 2-vertex polygon, or "
                 "fix the geometry so that the facets meet only along common segments");
      }
  std::vector<Item> items;
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
    for (const FacetTri& t : dom.facets[f].tris) items.push_back({Item::Triangle, f, t.v});
  for (const DomainSegment& s : dom.segments)
    if (s.sides.empty()) items.push_back({Item::Segment, 0, {s.a, s.b, 0}});
  for (std::uint32_t v = 0; v < pts.size(); ++v)
    if (dom.vertex_segments[v].empty() && dom.vertex_facets[v].empty())
      items.push_back({Item::Vertex, 0, {v, 0, 0}});
  std::vector<Box> boxes(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const int n = items[i].kind == Item::Triangle ? 3 : (items[i].kind == Item::Segment ? 2 : 1);
    for (int k = 0; k < n; ++k) boxes[i].add(pts[items[i].v[k]]);
  }
  const Bvh bvh(boxes);
  for (std::uint32_t i = 0; i < items.size(); ++i)
    bvh.for_overlapping(boxes[i], [&](std::uint32_t j) {
      if (j <= i) return;
      // Order the pair so that the lower kind comes second (Triangle < Segment < Vertex).
      const Item &a = items[i].kind >= items[j].kind ? items[i] : items[j];
      const Item &b = items[i].kind >= items[j].kind ? items[j] : items[i];
      if (conflict(a, b, pts)) report(dom, a, b);
    });
}

}  // namespace pdr::domain::detail
