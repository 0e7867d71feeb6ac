// Step 3 of build_domain: split polygon edges at input vertices lying in their interior
// (paper §1.1: segments are "vertex-bounded"; a vertex inside an edge makes two segments).
//
// For every undirected edge of every polygon, the vertices used by any polygon that lie
// in its open interior (exact: collinear and strictly between) are found through a
// bounding-volume hierarchy over the vertices and inserted in order along the edge. Two
// collinear edges that overlap thus share the pieces they have in common, and a vertex of
// one facet inside another facet's edge (allowed by TetGen) splits that edge. A polygon
// whose edge passes through one of its own vertices touches itself: an input error.
//
// Rounded input (a coordinate uncertainty u > 0, io/precision.hpp) classifies too: a
// vertex within 2u of an edge's line (each of the three points moved by at most u, so a
// vertex exactly on the edge is read at most 2u off it), farther than 2u from both ends,
// lies on the edge, as the input means: a part turned and printed with 7 digits has its
// T-junctions a hair inside or outside the edges they split, and read exactly the wall's
// polygon would cross the split line or leave the edge bounding one facet side. The test
// is in floating point, a classification of imprecise input; it never applies to a vertex
// of a polygon that has the edge (a polygon narrower than the rounding is not read as
// touching itself), nor to a vertex within 2u of two edges (near a corner where they
// meet: which one it is on is not what the coordinates say); the pieces a-v, v-b then
// bend by at most 2u at v. pdr check (check/domain.cpp) classifies alike.
#include <algorithm>
#include <cmath>
#include <map>

#include "domain/bvh.hpp"
#include "domain/exact.hpp"
#include "domain/steps.hpp"

namespace pdr::domain::detail {

namespace {

using Edge = std::array<std::uint32_t, 2>;

Edge undirected(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

}  // namespace

void split_edges(const Plc& plc, double uncertainty, std::vector<FacetPolys>& polys) {
  const std::vector<Point>& pts = plc.points;
  std::vector<std::uint32_t> used;
  std::vector<Edge> edges;
  // (edge, loop) and (loop, vertex) over every loop, numbered across the facets: a vertex of
  // a loop with the edge is split off it only exactly.
  std::vector<std::pair<Edge, std::uint32_t>> edge_loops;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> loop_vertices;
  std::uint32_t loop_id = 0;
  for (const FacetPolys& fp : polys) {
    for (const auto& loop : fp.loops) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        used.push_back(loop[i]);
        edges.push_back(undirected(loop[i], loop[(i + 1) % loop.size()]));
        edge_loops.push_back({edges.back(), loop_id});
        loop_vertices.push_back({loop_id, loop[i]});
      }
      ++loop_id;
    }
    for (const auto& s : fp.segs) {
      used.insert(used.end(), s.begin(), s.end());
      edges.push_back(undirected(s[0], s[1]));
    }
    used.insert(used.end(), fp.points.begin(), fp.points.end());
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::sort(edge_loops.begin(), edge_loops.end());
  std::sort(loop_vertices.begin(), loop_vertices.end());
  auto in_loop_with = [&](const Edge& e, std::uint32_t v) {
    auto it = std::lower_bound(edge_loops.begin(), edge_loops.end(), std::make_pair(e, 0u));
    for (; it != edge_loops.end() && it->first == e; ++it)
      if (std::binary_search(loop_vertices.begin(), loop_vertices.end(),
                             std::make_pair(it->second, v)))
        return true;
    return false;
  };
  const double reach = 2 * uncertainty;
  // v within `reach` of the line of ab, its foot farther than `reach` from a and b.
  auto within_rounding = [&](const Point& a, const Point& b, const Point& v) {
    const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double av[3] = {v[0] - a[0], v[1] - a[1], v[2] - a[2]};
    const double len = std::sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
    if (!(len > 2 * reach)) return false;
    const double t = (ab[0] * av[0] + ab[1] * av[1] + ab[2] * av[2]) / (len * len);
    if (!(t * len > reach && (1 - t) * len > reach)) return false;
    const double c[3] = {ab[1] * av[2] - ab[2] * av[1], ab[2] * av[0] - ab[0] * av[2],
                         ab[0] * av[1] - ab[1] * av[0]};
    return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) <= reach * len;
  };

  std::vector<Box> boxes(used.size());
  for (std::size_t i = 0; i < used.size(); ++i) boxes[i].add(pts[used[i]]);
  const Bvh bvh(std::move(boxes));

  // Interior vertices of each edge, ordered from the smaller id to the larger: exact ones
  // at once, rounded ones (edge, vertex) after the pass over every edge.
  std::map<Edge, std::vector<std::uint32_t>> inner;
  std::vector<std::pair<std::uint32_t, Edge>> rounded;
  for (const Edge& e : edges) {
    const Point &a = pts[e[0]], &b = pts[e[1]];
    Box q;
    q.add(a);
    q.add(b);
    for (int k = 0; k < 3; ++k) {
      q.lo[k] -= reach;
      q.hi[k] += reach;
    }
    std::vector<std::uint32_t> found;
    bvh.for_overlapping(q, [&](std::uint32_t item) {
      const std::uint32_t v = used[item];
      if (v == e[0] || v == e[1]) return;
      if (collinear(a, b, pts[v])) {
        if (strictly_between(a, b, pts[v])) found.push_back(v);
      } else if (reach > 0 && within_rounding(a, b, pts[v]) && !in_loop_with(e, v)) {
        rounded.push_back({v, e});
      }
    });
    if (!found.empty()) inner.emplace(e, std::move(found));
  }
  // A vertex within the rounding of two edges lies near where they meet (or between two
  // edges closer than the rounding): the coordinates do not say which it is on, so it
  // splits neither and stays as given.
  std::sort(rounded.begin(), rounded.end());
  for (std::size_t i = 0; i < rounded.size();) {
    std::size_t j = i;
    while (j < rounded.size() && rounded[j].first == rounded[i].first) ++j;
    if (j == i + 1) inner[rounded[i].second].push_back(rounded[i].first);
    i = j;
  }
  // Ordered along the edge's dominant coordinate (exact for collinear vertices), ties by id.
  for (auto& [e, found] : inner) {
    const Point &a = pts[e[0]], &b = pts[e[1]];
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (std::abs(b[j] - a[j]) > std::abs(b[k] - a[k])) k = j;
    const bool up = a[k] < b[k];
    std::sort(found.begin(), found.end(), [&](std::uint32_t x, std::uint32_t y) {
      if (pts[x][k] != pts[y][k]) return up ? pts[x][k] < pts[y][k] : pts[x][k] > pts[y][k];
      return x < y;
    });
  }
  if (inner.empty()) return;

  // Appends the interior vertices of edge (u, w), in the direction u -> w.
  auto append_inner = [&](std::uint32_t u, std::uint32_t w, std::vector<std::uint32_t>& out) {
    auto it = inner.find(undirected(u, w));
    if (it == inner.end()) return;
    if (u < w) out.insert(out.end(), it->second.begin(), it->second.end());
    else out.insert(out.end(), it->second.rbegin(), it->second.rend());
  };
  for (std::size_t f = 0; f < polys.size(); ++f) {
    FacetPolys& fp = polys[f];
    for (std::size_t l = 0; l < fp.loops.size(); ++l) {
      std::vector<std::uint32_t>& loop = fp.loops[l];
      std::vector<std::uint32_t> split;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        split.push_back(loop[i]);
        append_inner(loop[i], loop[(i + 1) % loop.size()], split);
      }
      std::vector<std::uint32_t> sorted(split);
      std::sort(sorted.begin(), sorted.end());
      if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
        fail(plc, plc.facets[f].line,
             "simple polygon: an edge of polygon " + std::to_string(fp.loop_index[l] + 1) +
                 " of this facet passes through its own " + vertex_name(plc, *it) +
                 ", so the polygon touches itself; split it into simple polygons");
      loop = std::move(split);
    }
    std::vector<std::array<std::uint32_t, 2>> segs;
    for (const auto& s : fp.segs) {
      std::vector<std::uint32_t> chain{s[0]};
      append_inner(s[0], s[1], chain);
      chain.push_back(s[1]);
      for (std::size_t i = 0; i + 1 < chain.size(); ++i) segs.push_back({chain[i], chain[i + 1]});
    }
    fp.segs = std::move(segs);
  }
}

}  // namespace pdr::domain::detail
