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

// The least-squares plane of points: their centroid, and the unit normal spanned by the
// scatter matrix C = sum (p - c)(p - c)^T. Its rows span the directions along the points'
// spread, so the largest cross product of two rows is the direction of least spread (the
// eigenvector of C's smallest eigenvalue, to within the ratio of the smallest eigenvalue to
// the others: the square of the facet's deviation). The mesher finds the same plane by
// Jacobi rotations (domain/plane.cpp); this is a separate computation.
struct FittedPlane {
  Point centroid{};
  Vec normal{};
};
FittedPlane least_squares_plane(const std::vector<Point>& pts) {
  FittedPlane f;
  for (const Point& p : pts)
    for (int k = 0; k < 3; ++k) f.centroid[k] += p[k] / static_cast<double>(pts.size());
  std::array<Vec, 3> c{};
  for (const Point& p : pts) {
    const Vec d = sub(p, f.centroid);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[i][j] += d[i] * d[j];
  }
  double best = -1;
  for (const auto& [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
    const Vec x = cross(c[i], c[j]);
    if (const double l = norm(x); l > best) {
      best = l;
      f.normal = {x[0] / l, x[1] / l, x[2] / l};
    }
  }
  return f;
}

bool exactly_collinear(const Point& a, const Point& b, const Point& p) {
  for (int drop = 0; drop < 3; ++drop)
    if (signs::orient2d(a, b, p, drop) != Sign::Zero) return false;
  return true;
}

// The mesh vertices on the straight piece from mesh vertex ma to mb (both included), in
// order; false when the piece is degenerate. tolerance_vertices counts those not exactly
// on it.
bool map_piece(std::uint32_t ma, std::uint32_t mb, const MeshView& mesh, const PointGrid& grid,
               double tol, std::vector<std::uint32_t>& out, std::uint64_t& tolerance_vertices) {
  const Point& A = mesh.points[ma];
  const Point& B = mesh.points[mb];
  const Vec ab = sub(B, A);
  const double len = norm(ab);
  if (A == B) return false;
  // Relative to |AB|, plus the rounding of a vertex computed at this magnitude (a unit
  // segment far from the origin: its midpoint rounds farther off the line than tol |AB|).
  const double dist = tol > 0 ? tol * len + 4 * kEps * std::max(max_abs(A), max_abs(B)) : 0;
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
  std::vector<std::uint32_t> on;
  for (std::uint32_t id : cand) {
    const Point& p = mesh.points[id];
    bool tolerance = false;
    if (!exactly_collinear(A, B, p)) {
      if (!(norm(cross(ab, sub(p, A))) <= dist * len)) continue;
      tolerance = true;
    }
    if (signs::dot(p, A, B, A) == Sign::Negative || signs::dot(p, B, A, B) == Sign::Negative)
      continue;
    on.push_back(id);
    if (tolerance) ++tolerance_vertices;
  }
  // Order from A to B: p before q iff (q - p) . (B - A) > 0; ties by id (duplicates).
  std::sort(on.begin(), on.end(), [&](std::uint32_t p, std::uint32_t q) {
    const Sign o = signs::dot(mesh.points[q], mesh.points[p], B, A);
    return o == Sign::Positive || (o == Sign::Zero && p < q);
  });
  // Joined to the previous piece at its last vertex (this piece's first).
  if (!out.empty() && !on.empty() && on.front() == out.back()) on.erase(on.begin());
  out.insert(out.end(), on.begin(), on.end());
  return true;
}

// Segment ab of the input through the input vertices `pivots` (in order from a to b) that
// lie on it within the coordinates' rounding (tolerance_pivots): the mesh vertices on each
// straight piece between them.
SegmentMap map_segment(std::uint32_t a, std::uint32_t b, const std::vector<std::uint32_t>& pivots,
                       const DomainMap& m, const MeshView& mesh, const PointGrid& grid,
                       double tol) {
  SegmentMap s;
  s.a = a;
  s.b = b;
  std::vector<std::uint32_t> ends{a};
  ends.insert(ends.end(), pivots.begin(), pivots.end());
  ends.push_back(b);
  for (std::uint32_t v : ends)
    if (!m.mesh_vertex[v]) {
      s.status = ItemStatus::MissingVertex;
      return s;
    }
  for (std::size_t i = 0; i + 1 < ends.size(); ++i)
    if (!map_piece(*m.mesh_vertex[ends[i]], *m.mesh_vertex[ends[i + 1]], mesh, grid, tol,
                   s.vertices, s.tolerance_vertices)) {
      s.status = ItemStatus::Degenerate;
      s.vertices.clear();
      return s;
    }
  s.tolerance_vertices += ends.size() - 2;
  return s;
}

// Options::coordinate_uncertainty u > 0 (rounded input): input vertex v lies on the edge
// from input vertex a to b (a < b) within the rounding. A vertex exactly on a segment is
// read back off it by up to 2u (each of the three points moved by at most u), so one within
// 2u of the edge's line with its foot farther than 2u from both ends does, unless a polygon
// with the edge has it (a polygon narrower than the rounding does not touch itself) or it
// is within the rounding of another edge too (near a corner: the coordinates do not say
// which it is on); map_domain applies those two. pdr mesh classifies T-junctions of rounded
// input alike (the mesh then holds the pieces); the same floating-point expression, from
// the lower-numbered end, so that both agree at the threshold.
bool within_rounding(const Point& a, const Point& b, const Point& v, double reach) {
  const Vec ab = sub(b, a), av = sub(v, a);
  const double len = norm(ab);
  if (!(len > 2 * reach)) return false;
  const double t = (ab[0] * av[0] + ab[1] * av[1] + ab[2] * av[2]) / (len * len);
  if (!(t * len > reach && (1 - t) * len > reach)) return false;
  return norm(cross(ab, av)) <= reach * len;
}

// Rounded input (Options::coordinate_uncertainty u > 0): for each edge (a < b) the input
// vertices it is mapped through (map_segment's pivots), ordered from a to b: none unless some
// vertex lies on it within the rounding (within_rounding: not a vertex of a polygon with the
// edge, and near no other edge), and then every vertex on it, exact ones too, since the
// mesh holds the straight pieces between them; ordered along the dominant coordinate, ties
// by id, as pdr mesh orders them.
std::vector<std::vector<std::uint32_t>> edge_pivots(
    const Plc& domain, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
    const DomainMap& m, const PointGrid& grid, std::size_t mesh_points, double uncertainty) {
  std::vector<std::vector<std::uint32_t>> pivots(edges.size());
  if (!(uncertainty > 0)) return pivots;
  const double reach = 2 * uncertainty;
  // The input vertices used by the polygons, by mesh vertex; which polygons have which
  // edges (those of 3 or more vertices) and vertices.
  std::vector<std::int64_t> input_of(mesh_points, -1);
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>> edge_polys;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> poly_vertices;
  std::uint32_t id = 0;
  for (const PlcFacet& f : domain.facets)
    for (const auto& poly : f.polygons) {
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const std::uint32_t x = poly[i], y = poly[(i + 1) % poly.size()];
        if (x >= domain.points.size() || y >= domain.points.size()) continue;
        if (m.mesh_vertex[x]) input_of[*m.mesh_vertex[x]] = x;
        poly_vertices.push_back({id, x});
        if (poly.size() >= 3) edge_polys.push_back({{std::min(x, y), std::max(x, y)}, id});
      }
      ++id;
    }
  std::sort(edge_polys.begin(), edge_polys.end());
  std::sort(poly_vertices.begin(), poly_vertices.end());
  // The input vertices in box b, each once.
  const auto inputs_in = [&](const Box& b) {
    std::vector<std::uint32_t> found;
    grid.query(b, [&](std::uint32_t mv, const Point&) {
      if (input_of[mv] >= 0) found.push_back(static_cast<std::uint32_t>(input_of[mv]));
    });
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  };
  const auto box_of = [&](const Point& a, const Point& b, double pad) {
    Box box{a, a};
    for (int c = 0; c < 3; ++c) {
      box.lo[c] = std::min(a[c], b[c]) - pad;
      box.hi[c] = std::max(a[c], b[c]) + pad;
    }
    return box;
  };
  // (vertex, edge) within the rounding, then those of vertices near one edge only.
  std::vector<std::pair<std::uint32_t, std::size_t>> rounded;
  for (std::size_t ei = 0; ei < edges.size(); ++ei) {
    const auto& e = edges[ei];
    const Point& a = domain.points[e.first];
    const Point& b = domain.points[e.second];
    for (const std::uint32_t w : inputs_in(box_of(a, b, reach))) {
      if (w == e.first || w == e.second || exactly_collinear(a, b, domain.points[w]) ||
          !within_rounding(a, b, domain.points[w], reach))
        continue;
      bool with_edge = false;
      auto it = std::lower_bound(edge_polys.begin(), edge_polys.end(), std::pair{e, 0u});
      for (; it != edge_polys.end() && it->first == e && !with_edge; ++it)
        with_edge = std::binary_search(poly_vertices.begin(), poly_vertices.end(),
                                       std::pair{it->second, w});
      if (!with_edge) rounded.push_back({w, ei});
    }
  }
  std::sort(rounded.begin(), rounded.end());
  for (std::size_t i = 0; i < rounded.size();) {
    std::size_t j = i;
    while (j < rounded.size() && rounded[j].first == rounded[i].first) ++j;
    if (j == i + 1) pivots[rounded[i].second].push_back(rounded[i].first);
    i = j;
  }
  for (std::size_t ei = 0; ei < edges.size(); ++ei) {
    std::vector<std::uint32_t>& p = pivots[ei];
    if (p.empty()) continue;
    const Point& a = domain.points[edges[ei].first];
    const Point& b = domain.points[edges[ei].second];
    for (const std::uint32_t w : inputs_in(box_of(a, b, 0))) {
      const Point& q = domain.points[w];
      if (w != edges[ei].first && w != edges[ei].second && exactly_collinear(a, b, q) &&
          signs::dot(q, a, b, a) == Sign::Positive && signs::dot(q, b, a, b) == Sign::Positive)
        p.push_back(w);
    }
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (std::fabs(b[j] - a[j]) > std::fabs(b[k] - a[k])) k = j;
    const bool up = a[k] < b[k];
    std::sort(p.begin(), p.end(), [&](std::uint32_t x, std::uint32_t y) {
      const double px = domain.points[x][k], py = domain.points[y][k];
      if (px != py) return up ? px < py : px > py;
      return x < y;
    });
  }
  return pivots;
}

using SegmentIndex = std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t>;

// Options::coordinate_uncertainty u: a facet planar within 4u (pdr mesh's classification,
// io/precision.hpp) has its new vertices within 7 * 4u of its least-squares plane.
constexpr double kUncertaintyShare = 32;

FacetMap map_facet(const PlcFacet& f, const std::vector<Point>& input, const DomainMap& m,
                   const SegmentIndex& seg_index, const MeshView& mesh, const PointGrid& grid,
                   double tol, double inexact_tol, double uncertainty,
                   const std::vector<std::uint8_t>& dropped_vertex) {
  FacetMap fm;
  // The facet's vertices: equal to their mesh vertices, which a mesher may leave out where
  // they lie only on dropped pieces (Options::dropped_vertices).
  std::vector<Point> pts;
  bool has_polygon = false;
  for (const auto& poly : f.polygons) {
    has_polygon = has_polygon || poly.size() >= 3;
    for (std::uint32_t v : poly) {
      if (v >= m.mesh_vertex.size() || (!m.mesh_vertex[v] && !dropped_vertex[v])) {
        fm.status = ItemStatus::MissingVertex;
        return fm;
      }
      pts.push_back(input[v]);
    }
  }
  if (!has_polygon) {
    fm.status = ItemStatus::Degenerate;
    return fm;
  }
  // Spanning triple: a, the farthest b, the c maximizing |(b-a) x (c-a)|.
  const Point& a = pts[0];
  Point b = a, c = a;
  double best = -1;
  for (const Point& v : pts) {
    const double d = norm(sub(v, a));
    if (d > best) best = d, b = v;
  }
  best = -1;
  for (const Point& v : pts) {
    const double d = norm(cross(sub(b, a), sub(v, a)));
    if (d > best) best = d, c = v;
  }
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
  const Box fbox = bounding_box(pts);
  const double diam = norm(sub(fbox.hi, fbox.lo));
  // Exactly planar (every input vertex on plane abc): the plane abc, with `tol`. Planar only
  // within tolerance: the least-squares plane of the distinct input vertices, with
  // `inexact_tol`, and no exact shortcut (plane abc may lie several times the deviation off
  // other vertices).
  const bool exact = std::all_of(pts.begin(), pts.end(), [&](const Point& v) {
    return signs::orient3d(a, b, c, v) == Sign::Zero;
  });
  const double t = exact ? tol : inexact_tol;
  const double admitted = exact ? t * diam : std::max(t * diam, kUncertaintyShare * uncertainty);
  const double dist = t > 0 ? admitted + 4 * kEps * std::max(max_abs(fbox.lo), max_abs(fbox.hi)) : 0,
               nn = norm(n);
  FittedPlane fit;
  if (!exact) {
    std::vector<Point> distinct = pts;
    std::sort(distinct.begin(), distinct.end(), lex_less);
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    fit = least_squares_plane(distinct);
  }
  fm.plane_origin = exact ? a : fit.centroid;
  fm.plane_normal = exact ? Vec{n[0] / nn, n[1] / nn, n[2] / nn} : fit.normal;
  auto on_plane = [&](const Point& p, bool& tolerance) {
    tolerance = false;
    if (exact) {
      if (signs::orient3d(a, b, c, p) == Sign::Zero) return true;
      const Vec w = sub(p, a);
      tolerance = std::fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) <= dist * nn;
      return tolerance;
    }
    const Vec w = sub(p, fit.centroid);
    tolerance = std::fabs(fit.normal[0] * w[0] + fit.normal[1] * w[1] + fit.normal[2] * w[2]) <= dist;
    return tolerance;
  };
  for (const Point& v : pts) {
    bool tolerance = false;
    if (!on_plane(v, tolerance)) {
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
      q.push_back(project(input[u], drop));
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

// The pieces the domain analysis dropped (Options::dropped_*): the pairs of consecutive
// mesh vertices of a segment between the ends of a dropped segment, and each facet's
// dropped triangles, projected, through the mesh vertices on their edges where those lie
// on a segment (as the region polygons are built: the areas then still compare exactly).
void mark_dropped(DomainMap& m, const std::vector<Point>& input, const MeshView& mesh,
                  const Options& options) {
  if (options.dropped_segments.empty() && options.dropped_tris.empty()) return;
  // Where each input vertex's mesh vertex lies on the segment chains: (segment, position).
  std::vector<std::int64_t> input_of(mesh.points.size(), -1);
  for (std::size_t v = 0; v < m.mesh_vertex.size(); ++v)
    if (m.mesh_vertex[v]) input_of[*m.mesh_vertex[v]] = static_cast<std::int64_t>(v);
  std::multimap<std::uint32_t, std::pair<std::size_t, std::size_t>> on_chain;
  for (std::size_t i = 0; i < m.segments.size(); ++i) {
    const SegmentMap& s = m.segments[i];
    if (s.status != ItemStatus::Ok) continue;
    for (std::size_t k = 0; k < s.vertices.size(); ++k)
      if (input_of[s.vertices[k]] >= 0) on_chain.emplace(static_cast<std::uint32_t>(input_of[s.vertices[k]]), std::pair{i, k});
  }
  // The segments whose chains hold input vertices u and v: (segment, position of u, of v).
  const auto chains = [&](std::uint32_t u, std::uint32_t v) {
    std::vector<std::array<std::size_t, 3>> out;
    const auto [ub, ue] = on_chain.equal_range(u);
    const auto [vb, ve] = on_chain.equal_range(v);
    for (auto x = ub; x != ue; ++x)
      for (auto y = vb; y != ve; ++y)
        if (x->second.first == y->second.first)
          out.push_back({x->second.first, x->second.second, y->second.second});
    return out;
  };
  for (const auto& d : options.dropped_segments) {
    if (d[0] >= m.mesh_vertex.size() || d[1] >= m.mesh_vertex.size()) continue;
    if (!m.mesh_vertex[d[0]] || !m.mesh_vertex[d[1]]) {
      for (SegmentMap& s : m.segments)
        if (std::minmax(s.a, s.b) == std::minmax(d[0], d[1])) s.status = ItemStatus::Dropped;
      continue;
    }
    for (const auto& [i, pu, pv] : chains(d[0], d[1])) {
      SegmentMap& s = m.segments[i];
      s.dropped.resize(s.vertices.size() - 1, 0);
      for (auto k = std::min(pu, pv); k < std::max(pu, pv); ++k) s.dropped[k] = 1;
    }
  }
  for (const Options::DroppedTri& t : options.dropped_tris) {
    if (t.facet >= m.facets.size() || m.facets[t.facet].status != ItemStatus::Ok) continue;
    if (std::any_of(t.v.begin(), t.v.end(), [&](std::uint32_t v) { return v >= input.size(); }))
      continue;
    FacetMap& f = m.facets[t.facet];
    std::vector<P2> q;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = t.v[e], v = t.v[(e + 1) % 3];
      q.push_back(project(input[u], f.drop));
      const auto on = chains(u, v);
      if (on.empty()) continue;
      const auto& [i, pu, pv] = on.front();
      const std::vector<std::uint32_t>& chain = m.segments[i].vertices;
      if (pu < pv)
        for (std::size_t k = pu + 1; k < pv; ++k) q.push_back(project(mesh.points[chain[k]], f.drop));
      else
        for (std::size_t k = pu - 1; k > pv; --k) q.push_back(project(mesh.points[chain[k]], f.drop));
    }
    f.dropped.push_back(std::move(q));
  }
}

// Mesh faces in each facet: all three vertices on the facet's plane and in its closed
// region, the centroid inside it.
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
  // The facets of a PLC meet only along their boundaries, so a mesh face lies in at most
  // one: where several take it (two facets at a thin notch, each within the other's
  // tolerance near their common segment), it goes to the one whose plane its corners lie
  // nearest.
  const auto signed_distance = [&](const FacetMap& f, std::uint32_t v) {
    const Vec w = sub(mesh.points[v], f.plane_origin);
    return f.plane_normal[0] * w[0] + f.plane_normal[1] * w[1] + f.plane_normal[2] * w[2];
  };
  const auto distance = [&](const FacetMap& f, const Tri& t) {
    double d = 0;
    for (const std::uint32_t v : t) d = std::max(d, std::fabs(signed_distance(f, v)));
    return d;
  };
  // A facet given within the planarity tolerance is a slab, not a plane, and a face
  // between two tets can have its corners in it without lying in the facet: the upper
  // faces of a flat tet on the facet (all four corners in the slab, next to an input vertex
  // off the plane), stacked over its lower face, or a small face tilted across the slab
  // with both its tets on the same side. Where the facet bounds the mesh (a face in it
  // belongs to one tet alone), its subfacets are such faces, and a face in it between two
  // tets is in it only when the two tets lie on opposite sides: each one's fourth corner
  // off the slab, on opposite sides of the facet's plane. Between two regions every face
  // in the slab is held by two tets, and a flat tet (its fourth corner in the slab and
  // not outside the facet's region) stacks two layers of them; each covers the facet, so
  // one is kept: the one the mesher made the facet's, from the faces it lists (a mesher
  // lists a facet between regions: TetGen's and pdr's .face files do); a mesh that lists
  // none gets the lower one: a face of a flat tet is then in the facet only where the tet's
  // outward normal points down the chart's dropped axis (the projected face, in the tet's
  // outward order, turns clockwise: exact), and in a stack of flat tets only the faces
  // under the lowest one remain (encroachment.subfacets may then fail where the mesher
  // took the upper layer: list the faces to say which).
  // (A thin tet whose fourth corner lies in the slab outside the region, on a neighbour a
  // hair from coplanar, is no flat tet: its face on the facet is a subfacet.)
  struct Candidate {
    std::uint32_t face, facet;
    double distance;
  };
  std::vector<Candidate> candidates;
  std::vector<std::uint8_t> bounds_mesh(m.facets.size(), 0);
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
      // A face with a corner outside the region is not in the facet, whatever its centroid:
      // the faces of a sliver across a segment between two facets a hair from coplanar have
      // their corners within tolerance of both planes, and would stack on the subfacets.
      if (std::any_of(t.begin(), t.end(), [&](std::uint32_t v) {
            return f.region->locate(Q2::at(project(mesh.points[v], d))) == Where::Outside;
          }))
        continue;
      if (std::any_of(f.dropped.begin(), f.dropped.end(), [&](const std::vector<P2>& tri) {
            return locate_in_polygon(tri, q) != Where::Outside;
          }))
        continue;
      candidates.push_back({static_cast<std::uint32_t>(fid), fi, distance(f, t)});
      if (topo.holders(fid).size() == 1) bounds_mesh[fi] = 1;
    }
  }
  // The side of f's plane of the corner of tet `r` opposite its face: 0 in the slab.
  const auto side = [&](const FacetMap& f, const FaceRef& r) {
    const std::uint32_t v = mesh.tets[r.tet][r.local];
    if (std::binary_search(f.on_plane.begin(), f.on_plane.end(), v)) return 0;
    const double d = signed_distance(f, v);
    return d > 0 ? 1 : d < 0 ? -1 : 0;
  };
  // Tet r.tet lies flat on f: its corner opposite face r.local in f's slab and region.
  const auto flat_on = [&](const FacetMap& f, const FaceRef& r) {
    const std::uint32_t v = mesh.tets[r.tet][r.local];
    return std::binary_search(f.on_plane.begin(), f.on_plane.end(), v) &&
           f.region->locate(Q2::at(project(mesh.points[v], f.drop))) != Where::Outside;
  };
  // The face r.local of tet r.tet, in the tet's outward order, projected by f's chart.
  const auto outward_turn = [&](const FacetMap& f, const FaceRef& r) {
    const Tet& t = mesh.tets[r.tet];
    const auto& k = kFaceVertices[r.local];
    return signs::orient2d(mesh.points[t[k[0]]], mesh.points[t[k[1]]], mesh.points[t[k[2]]],
                           f.drop);
  };
  // Whether the mesh lists face t (its vertex ids sorted, as the topology's): built on
  // first use.
  std::vector<Tri> listed_faces;
  const auto listed = [&](const Tri& t) {
    if (listed_faces.empty()) {
      listed_faces.assign(mesh.faces.begin(), mesh.faces.end());
      for (Tri& x : listed_faces) std::sort(x.begin(), x.end());
      std::sort(listed_faces.begin(), listed_faces.end());
    }
    return std::binary_search(listed_faces.begin(), listed_faces.end(), t);
  };
  for (std::size_t i = 0; i < candidates.size();) {
    const std::uint32_t fid = candidates[i].face;
    std::optional<std::uint32_t> in;
    double nearest = 0;
    for (; i < candidates.size() && candidates[i].face == fid; ++i) {
      const Candidate& c = candidates[i];
      const FacetMap& f = m.facets[c.facet];
      const auto holders = topo.holders(fid);
      if (f.tolerance_vertices > 0 && bounds_mesh[c.facet] && holders.size() == 2) {
        const int a = side(f, holders[0]), b = side(f, holders[1]);
        if (a == 0 || b == 0 || a == b) continue;
      } else if (f.tolerance_vertices > 0 && holders.size() == 2 &&
                 (flat_on(f, holders[0]) || flat_on(f, holders[1]))) {
        // Which layer the mesher made the facet's: the faces it lists, if it lists any;
        // else the lower one.
        const auto upper = [&](const FaceRef& r) {
          return flat_on(f, r) && outward_turn(f, r) != Sign::Negative;
        };
        if (!mesh.faces.empty() ? !listed(topo.faces[fid])
                                : std::any_of(holders.begin(), holders.end(), upper))
          continue;
      }
      if (!in || c.distance < nearest) in = c.facet, nearest = c.distance;
    }
    if (!in) continue;
    m.facets[*in].faces.push_back(fid);
    m.subfacets.push_back(fid);
    m.face_in_facet[fid] = 1;
  }
  std::sort(m.subfacets.begin(), m.subfacets.end());
}

}  // namespace

DomainMap map_domain(const Plc& domain, const MeshView& mesh, const Topology& topo,
                     const PointGrid& grid, const Options& options) {
  DomainMap m;
  // Input vertices are matched by exactly equal coordinates: the smallest mesh vertex id at
  // p, found through the grid (a query of the box [p, p] visits every stored point equal
  // to p).
  m.mesh_vertex.resize(domain.points.size());
  for (std::size_t i = 0; i < domain.points.size(); ++i) {
    const Point& p = domain.points[i];
    grid.query(Box{p, p}, [&](std::uint32_t v, const Point& q) {
      if (q == p && (!m.mesh_vertex[i] || v < *m.mesh_vertex[i])) m.mesh_vertex[i] = v;
    });
  }
  const double tol = options.relative_tolerance;
  SegmentIndex seg_index;
  using Edge = std::pair<std::uint32_t, std::uint32_t>;  // input ids, first < second
  std::vector<Edge> edges;                                // in first-seen order
  for (const PlcFacet& f : domain.facets)
    for (const auto& poly : f.polygons) {
      if (poly.size() < 2) continue;
      const std::size_t n_edges = poly.size() == 2 ? 1 : poly.size();
      for (std::size_t i = 0; i < n_edges; ++i) {
        const std::uint32_t u = poly[i], v = poly[(i + 1) % poly.size()];
        if (u == v || u >= domain.points.size() || v >= domain.points.size()) continue;
        if (seg_index.emplace(std::pair{std::min(u, v), std::max(u, v)}, edges.size()).second)
          edges.push_back({std::min(u, v), std::max(u, v)});
      }
    }
  const std::vector<std::vector<std::uint32_t>> pivots =
      edge_pivots(domain, edges, m, grid, mesh.points.size(), options.coordinate_uncertainty);
  for (std::size_t ei = 0; ei < edges.size(); ++ei)
    m.segments.push_back(
        map_segment(edges[ei].first, edges[ei].second, pivots[ei], m, mesh, grid, tol));
  std::vector<std::uint8_t> dropped_vertex(domain.points.size(), 0);
  for (const std::uint32_t v : options.dropped_vertices)
    if (v < dropped_vertex.size()) dropped_vertex[v] = 1;
  for (const PlcFacet& f : domain.facets)
    m.facets.push_back(map_facet(f, domain.points, m, seg_index, mesh, grid, tol,
                                 options.inexact_facet_tolerance,
                                 options.coordinate_uncertainty, dropped_vertex));
  mark_dropped(m, domain.points, mesh, options);
  assign_faces(m, mesh, topo);
  return m;
}

}  // namespace pdr::check
