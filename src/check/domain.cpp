// DomainMap: input vertices, segments and facets located in the mesh (see domain.hpp).
#include "check/domain.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <map>
#include <utility>

#include "check/signs.hpp"

namespace pdr::check {
namespace {

constexpr double kEps = 0x1p-52;

using Vec = std::array<double, 3>;
Vec sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& u, const Vec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double norm(const Vec& u) { return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); }
double max_abs(const Point& p) { return std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])}); }

Box padded(Box b, double pad) {
  for (int i = 0; i < 3; ++i) {
    b.lo[i] -= pad;
    b.hi[i] += pad;
  }
  return b;
}

bool exactly_collinear(const Point& a, const Point& b, const Point& p) {
  for (int drop = 0; drop < 3; ++drop)
    if (signs::orient2d(a, b, p, drop) != Sign::Zero) return false;
  return true;
}

SegmentMap map_segment(std::uint32_t a, std::uint32_t b, const DomainMap& m, const MeshView& mesh,
                       const PointGrid& grid, double tol) {
  SegmentMap s;
  s.a = a;
  s.b = b;
  if (!m.mesh_vertex[a] || !m.mesh_vertex[b]) {
    s.status = ItemStatus::MissingVertex;
    return s;
  }
  const std::uint32_t ma = *m.mesh_vertex[a], mb = *m.mesh_vertex[b];
  const Point& A = mesh.points[ma];
  const Point& B = mesh.points[mb];
  const Vec ab = sub(B, A);
  const double len = norm(ab);
  if (A == B) {
    s.status = ItemStatus::Degenerate;
    return s;
  }
  const double dist = tol * len;
  // Piecewise boxes along AB; the pad covers the rounding of the pieces' ends.
  const double pad = dist * (1 + 1e-9) + 8 * kEps * std::max(max_abs(A), max_abs(B)) + 0x1p-1000;
  const double side = grid.frame().side();
  const double pieces = side > 0 ? std::clamp(std::ceil(len / side), 1.0, 65536.0) : 1.0;
  std::vector<std::uint32_t> cand;
  Point prev = A;
  for (int i = 1; i <= static_cast<int>(pieces); ++i) {
    const double t = i / pieces;
    Point next = i == static_cast<int>(pieces) ? B
                                               : Point{A[0] + ab[0] * t, A[1] + ab[1] * t, A[2] + ab[2] * t};
    Box box{prev, prev};
    for (int c = 0; c < 3; ++c) {
      box.lo[c] = std::min(prev[c], next[c]);
      box.hi[c] = std::max(prev[c], next[c]);
    }
    grid.query(padded(box, pad), [&](std::uint32_t id, const Point&) { cand.push_back(id); });
    prev = next;
  }
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  for (std::uint32_t id : cand) {
    const Point& p = mesh.points[id];
    bool tolerance = false;
    if (!exactly_collinear(A, B, p)) {
      if (!(norm(cross(ab, sub(p, A))) <= dist * len)) continue;
      tolerance = true;
    }
    if (signs::dot(p, A, B, A) == Sign::Negative || signs::dot(p, B, A, B) == Sign::Negative)
      continue;
    s.vertices.push_back(id);
    if (tolerance) ++s.tolerance_vertices;
  }
  // Order from A to B: p before q iff (q - p) . (B - A) > 0; ties by id (duplicates).
  std::sort(s.vertices.begin(), s.vertices.end(), [&](std::uint32_t p, std::uint32_t q) {
    const Sign o = signs::dot(mesh.points[q], mesh.points[p], B, A);
    return o == Sign::Positive || (o == Sign::Zero && p < q);
  });
  return s;
}

using SegmentIndex = std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t>;

FacetMap map_facet(const PlcFacet& f, const DomainMap& m, const SegmentIndex& seg_index,
                   const MeshView& mesh, const PointGrid& grid, double tol) {
  FacetMap fm;
  std::vector<std::uint32_t> ids;  // mesh ids of the facet's vertices
  bool has_polygon = false;
  for (const auto& poly : f.polygons) {
    has_polygon = has_polygon || poly.size() >= 3;
    for (std::uint32_t v : poly) {
      if (v >= m.mesh_vertex.size() || !m.mesh_vertex[v]) {
        fm.status = ItemStatus::MissingVertex;
        return fm;
      }
      ids.push_back(*m.mesh_vertex[v]);
    }
  }
  if (!has_polygon) {
    fm.status = ItemStatus::Degenerate;
    return fm;
  }
  // Spanning triple: a, the farthest b, the c maximizing |(b-a) x (c-a)|.
  const Point& a = mesh.points[ids[0]];
  std::uint32_t bi = ids[0], ci = ids[0];
  double best = -1;
  for (std::uint32_t v : ids) {
    const double d = norm(sub(mesh.points[v], a));
    if (d > best) best = d, bi = v;
  }
  const Point& b = mesh.points[bi];
  best = -1;
  for (std::uint32_t v : ids) {
    const double d = norm(cross(sub(b, a), sub(mesh.points[v], a)));
    if (d > best) best = d, ci = v;
  }
  const Point& c = mesh.points[ci];
  const Vec n = cross(sub(b, a), sub(c, a));
  int drop = -1;
  for (int k = 0; k < 3; ++k)
    if (signs::orient2d(a, b, c, k) != Sign::Zero &&
        (drop < 0 || std::fabs(n[k]) > std::fabs(n[drop])))
      drop = k;
  if (drop < 0) {
    fm.status = ItemStatus::Degenerate;
    return fm;
  }
  fm.drop = drop;
  const Box fbox = bounding_box([&] {
    std::vector<Point> pts;
    for (std::uint32_t v : ids) pts.push_back(mesh.points[v]);
    return pts;
  }());
  const double diam = norm(sub(fbox.hi, fbox.lo));
  const double dist = tol * diam, nn = norm(n);
  auto on_plane = [&](const Point& p, bool& tolerance) {
    tolerance = false;
    if (signs::orient3d(a, b, c, p) == Sign::Zero) return true;
    const Vec w = sub(p, a);
    tolerance = std::fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) <= dist * nn;
    return tolerance;
  };
  for (std::uint32_t v : ids) {
    bool tolerance = false;
    if (!on_plane(mesh.points[v], tolerance)) {
      fm.status = ItemStatus::NonPlanar;
      return fm;
    }
  }
  // Region polygons through the mesh vertices on their edges (the subsegment chains): with
  // tolerance-classified vertices the mesh faces tile this polygon exactly, not the input
  // one; with exact vertices both have the same area and the same interior.
  std::vector<std::vector<P2>> polygons;
  for (const auto& poly : f.polygons) {
    if (poly.size() < 3) continue;
    std::vector<P2> q;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::uint32_t u = poly[i], v = poly[(i + 1) % poly.size()];
      q.push_back(project(mesh.points[*m.mesh_vertex[u]], drop));
      const auto it = seg_index.find({std::min(u, v), std::max(u, v)});
      if (u == v || it == seg_index.end()) continue;
      const SegmentMap& s = m.segments[it->second];
      if (s.status != ItemStatus::Ok || s.vertices.size() < 3) continue;
      std::vector<std::uint32_t> inner(s.vertices.begin() + 1, s.vertices.end() - 1);
      if (s.a != u) std::reverse(inner.begin(), inner.end());
      for (std::uint32_t w : inner) q.push_back(project(mesh.points[w], drop));
    }
    polygons.push_back(std::move(q));
  }
  std::vector<P2> holes;
  for (const Point& h : f.holes) holes.push_back(project(h, drop));
  fm.region.emplace(std::move(polygons), holes);
  if (!fm.region->supported()) {
    fm.status = ItemStatus::Unsupported;
    return fm;
  }
  const double pad = dist * (1 + 1e-9) + 0x1p-1000;
  grid.query(padded(fbox, pad), [&](std::uint32_t id, const Point& p) {
    bool tolerance = false;
    if (!on_plane(p, tolerance)) return;
    fm.on_plane.push_back(id);
    if (tolerance) ++fm.tolerance_vertices;
  });
  std::sort(fm.on_plane.begin(), fm.on_plane.end());
  return fm;
}

// Mesh faces in each facet: all three vertices on the facet's plane, centroid in its region.
void assign_faces(DomainMap& m, const MeshView& mesh, const Topology& topo) {
  std::vector<std::uint32_t> start(mesh.points.size() + 1, 0), list;
  for (const FacetMap& f : m.facets)
    for (std::uint32_t v : f.on_plane) ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  list.resize(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t fi = 0; fi < m.facets.size(); ++fi)
    for (std::uint32_t v : m.facets[fi].on_plane) list[fill[v]++] = fi;
  auto facets_of = [&](std::uint32_t v) {
    return std::span<const std::uint32_t>(list.data() + start[v], list.data() + start[v + 1]);
  };
  m.face_in_facet.assign(topo.faces.size(), 0);
  for (std::size_t fid = 0; fid < topo.faces.size(); ++fid) {
    const Tri& t = topo.faces[fid];
    const auto l0 = facets_of(t[0]), l1 = facets_of(t[1]), l2 = facets_of(t[2]);
    if (l0.empty() || l1.empty() || l2.empty()) continue;
    for (std::uint32_t fi : l0) {
      if (!std::binary_search(l1.begin(), l1.end(), fi) ||
          !std::binary_search(l2.begin(), l2.end(), fi))
        continue;
      FacetMap& f = m.facets[fi];
      const int d = f.drop;
      const Q2 q = Q2::centroid(project(mesh.points[t[0]], d), project(mesh.points[t[1]], d),
                                project(mesh.points[t[2]], d));
      const Where w = f.region->locate(q);
      if (w == Where::Boundary) ++f.ambiguous_faces;
      if (w != Where::Inside) continue;
      f.faces.push_back(static_cast<std::uint32_t>(fid));
      if (!m.face_in_facet[fid]) m.subfacets.push_back(static_cast<std::uint32_t>(fid));
      m.face_in_facet[fid] = 1;
    }
  }
  std::sort(m.subfacets.begin(), m.subfacets.end());
}

}  // namespace

DomainMap map_domain(const Plc& domain, const MeshView& mesh, const Topology& topo,
                     const PointGrid& grid, const Options& options) {
  DomainMap m;
  // Input vertices are matched by exactly equal coordinates.
  std::vector<std::uint32_t> order(mesh.points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    return lex_less(mesh.points[x], mesh.points[y]) ||
           (!lex_less(mesh.points[y], mesh.points[x]) && x < y);
  });
  m.mesh_vertex.resize(domain.points.size());
  for (std::size_t i = 0; i < domain.points.size(); ++i) {
    const Point& p = domain.points[i];
    const auto it = std::lower_bound(order.begin(), order.end(), p, [&](std::uint32_t v, const Point& q) {
      return lex_less(mesh.points[v], q);
    });
    if (it != order.end() && !lex_less(p, mesh.points[*it])) m.mesh_vertex[i] = *it;
  }
  const double tol = options.relative_tolerance;
  SegmentIndex seg_index;
  for (const PlcFacet& f : domain.facets)
    for (const auto& poly : f.polygons) {
      if (poly.size() < 2) continue;
      const std::size_t edges = poly.size() == 2 ? 1 : poly.size();
      for (std::size_t i = 0; i < edges; ++i) {
        std::uint32_t u = poly[i], v = poly[(i + 1) % poly.size()];
        if (u == v || u >= domain.points.size() || v >= domain.points.size()) continue;
        if (!seg_index.emplace(std::pair{std::min(u, v), std::max(u, v)}, m.segments.size()).second)
          continue;
        m.segments.push_back(map_segment(u, v, m, mesh, grid, tol));
      }
    }
  for (const PlcFacet& f : domain.facets)
    m.facets.push_back(map_facet(f, m, seg_index, mesh, grid, tol));
  assign_faces(m, mesh, topo);
  return m;
}

}  // namespace pdr::check
