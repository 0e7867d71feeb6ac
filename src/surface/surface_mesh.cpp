// SurfaceMesh storage and incidence queries (paper §1.1, §2.1); see surface/surface_mesh.hpp.
#include "surface/surface_mesh.hpp"

#include <algorithm>
#include <utility>

#include "geom/construct.hpp"

namespace pdr::surface {

namespace {

void erase_value(std::vector<std::uint32_t>& v, std::uint32_t x) {
  const auto it = std::find(v.begin(), v.end(), x);
  if (it != v.end()) {
    *it = v.back();
    v.pop_back();
  }
}

}  // namespace

int vertex_index(const Subfacet& t, std::uint32_t v) {
  return t.v[0] == v ? 0 : (t.v[1] == v ? 1 : 2);
}

int edge_index(const Subfacet& t, std::uint32_t u, std::uint32_t w) {
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t p = t.v[(i + 1) % 3], q = t.v[(i + 2) % 3];
    if ((p == u && q == w) || (p == w && q == u)) return i;
  }
  return -1;
}

std::optional<std::uint32_t> SurfaceMesh::find_subsegment(std::uint32_t u, std::uint32_t w) const {
  // The shorter list: an input vertex of a triangulated surface ends six segments or more,
  // a vertex inside a segment two subsegments.
  if (vsegs_[w].size() < vsegs_[u].size()) std::swap(u, w);
  for (const std::uint32_t s : vsegs_[u]) {
    const Subsegment& g = subsegments_[s];
    if ((g.v[0] == u && g.v[1] == w) || (g.v[0] == w && g.v[1] == u)) return s;
  }
  return std::nullopt;
}

std::optional<std::uint32_t> SurfaceMesh::find_subfacet(std::uint32_t a, std::uint32_t b,
                                                         std::uint32_t c) const {
  if (a == b || a == c || b == c) return std::nullopt;
  // Every subfacet listed at a vertex contains it; one with the edge of the other two is
  // the face. The shortest of the three lists is scanned: a vertex at a sharp edge can hold
  // thousands of subfacets (a 1.2-degree fin of triangles spent 30% of its run here).
  if (vtris_[b].size() < vtris_[a].size()) std::swap(a, b);
  if (vtris_[c].size() < vtris_[a].size()) std::swap(a, c);
  for (const std::uint32_t t : vtris_[a]) {
    const std::array<std::uint32_t, 3>& v = subfacets_[t].v;  // holds a
    if ((v[0] == b || v[1] == b || v[2] == b) && (v[0] == c || v[1] == c || v[2] == c))
      return t;
  }
  return std::nullopt;
}

std::vector<std::uint32_t> SurfaceMesh::subfacets_on_edge(std::uint32_t f, std::uint32_t u,
                                                          std::uint32_t w) const {
  std::vector<std::uint32_t> out;
  for (const std::uint32_t t : vtris_[u])
    if (subfacets_[t].facet == f && edge_index(subfacets_[t], u, w) >= 0) out.push_back(t);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint32_t> SurfaceMesh::chain(std::uint32_t s) const {
  const SurfaceSegment& seg = segments[s];
  std::vector<std::uint32_t> out{seg.a};
  // Exactly one subsegment of s starts at each vertex of the chain but b (v[0] is nearer
  // a); the length cap stops a corrupted (cyclic) chain, which the audit reports.
  while (out.back() != seg.b && out.size() <= subsegments_.size()) {
    std::optional<std::uint32_t> next;
    for (const std::uint32_t g : vsegs_[out.back()])
      if (subsegments_[g].segment == s && subsegments_[g].v[0] == out.back()) next = g;
    if (!next) break;
    out.push_back(subsegments_[*next].v[1]);
  }
  return out;
}

std::vector<std::uint32_t> SurfaceMesh::facet_subfacets(std::uint32_t f) const {
  if (f >= ftris_.size()) return {};
  std::vector<std::uint32_t> out = ftris_[f];
  std::sort(out.begin(), out.end());
  return out;
}

std::string SurfaceMesh::facet_name(std::uint32_t f) const {
  return "facet " + std::to_string(f) + " (" + source + ":" + std::to_string(facets[f].line) + ")";
}

std::string SurfaceMesh::segment_name(std::uint32_t s) const {
  return "segment " + std::to_string(s) + " (vertices " + std::to_string(segments[s].a) + ", " +
         std::to_string(segments[s].b) + ")";
}

std::uint32_t SurfaceMesh::add_vertex(const Point& p, Home home) {
  const auto v = static_cast<std::uint32_t>(points_.size());
  points_.push_back(p);
  if (home.kind == HomeKind::Input) home.id = v;
  homes_.push_back(home);
  vsegs_.emplace_back();
  vtris_.emplace_back();
  return v;
}

std::uint32_t SurfaceMesh::add_subsegment(std::uint32_t u, std::uint32_t w, std::uint32_t segment) {
  const auto s = static_cast<std::uint32_t>(subsegments_.size());
  subsegments_.push_back({{u, w}, segment});
  vsegs_[u].push_back(s);
  vsegs_[w].push_back(s);
  return s;
}

std::uint32_t SurfaceMesh::split_subsegment_record(std::uint32_t s, std::uint32_t m) {
  const std::uint32_t w = subsegments_[s].v[1];
  const auto n = static_cast<std::uint32_t>(subsegments_.size());
  subsegments_.push_back({{m, w}, subsegments_[s].segment});
  subsegments_[s].v[1] = m;
  erase_value(vsegs_[w], s);
  vsegs_[w].push_back(n);
  vsegs_[m].push_back(s);
  vsegs_[m].push_back(n);
  return n;
}

std::uint32_t SurfaceMesh::add_subfacet(const Subfacet& t) {
  std::uint32_t id;
  if (!free_.empty()) {
    id = free_.back();
    free_.pop_back();
    subfacets_[id] = t;
  } else {
    id = static_cast<std::uint32_t>(subfacets_.size());
    subfacets_.push_back(t);
  }
  subfacets_[id].alive = true;
  for (const std::uint32_t v : t.v) vtris_[v].push_back(id);
  if (t.facet >= ftris_.size()) ftris_.resize(t.facet + 1);
  if (id >= fpos_.size()) fpos_.resize(subfacets_.size());
  fpos_[id] = static_cast<std::uint32_t>(ftris_[t.facet].size());
  ftris_[t.facet].push_back(id);
  return id;
}

void SurfaceMesh::kill_subfacet(std::uint32_t t) {
  Subfacet& s = subfacets_[t];
  if (!s.alive) return;
  s.alive = false;
  for (const std::uint32_t v : s.v) erase_value(vtris_[v], t);
  std::vector<std::uint32_t>& of = ftris_[s.facet];
  const std::uint32_t i = fpos_[t];
  of[i] = of.back();
  fpos_[of[i]] = i;
  of.pop_back();
  free_.push_back(t);
}

double SurfaceMesh::subsegment_size(std::uint32_t s) const {
  const Subsegment& x = subsegment(s);
  if (!sizer) return segment_size(x.segment);
  const Point m = construct::midpoint(point(x.v[0]), point(x.v[1]));
  return std::max(segment_size(x.segment), sizer->segment_size_at(x.segment, m));
}

double SurfaceMesh::subfacet_size(std::uint32_t t) const {
  const Subfacet& x = subfacet(t);
  if (!sizer) return facet_size(x.facet);
  const Point c = construct::triangle_circumcenter(point(x.v[0]), point(x.v[1]), point(x.v[2]));
  return std::max(facet_size(x.facet), sizer->facet_size_at(x.facet, c));
}

}  // namespace pdr::surface
