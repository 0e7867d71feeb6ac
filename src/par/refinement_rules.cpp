// Fig. 2's step on a submesh with D as distributed; see par/refinement_rules.hpp.
#include "par/refinement_rules.hpp"

#include <algorithm>

#include "geom/construct.hpp"
#include "geom/encroach.hpp"
#include "mesh/tables.hpp"

namespace pdr::par {

RefinementRules::RefinementRules(const refine::VolumeMesh& m0, const refine::TetBounds& bounds,
                                 bool splits)
    : m0_(m0), bounds_(bounds), splits_enabled_(splits) {
  tags_.reserve(m0.dt.num_points());
  for (VertexId v = 0; v < m0.dt.num_points(); ++v)
    tags_.push_back(static_cast<std::uint8_t>(1 + static_cast<int>(m0.vertex_class(v))));
}

bool RefinementRules::wants(const Submesh& s, TetId t) const {
  const TetStore& st = s.store();
  const auto pts = s.points();
  const VertexId* v = st.vertices(t);
  return refine::is_bad(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], bounds_);
}

Point RefinementRules::point(const Submesh& s, TetId t) const {
  const auto pts = s.points();
  const VertexId* v = s.store().vertices(t);
  return construct::circumcenter(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]);
}

void RefinementRules::label(Submesh& s) const {
  const refine::SurfaceMesh& d = m0_.surf;
  const auto local = [&](std::uint32_t dv) {
    return dv < m0_.s2d.size() && m0_.s2d[dv] != refine::kNone ? s.find_vertex(m0_.s2d[dv])
                                                                : kNoVertex;
  };
  for (const refine::Subsegment& e : d.subsegments()) {
    const VertexId a = local(e.v[0]), b = local(e.v[1]);
    if (a != kNoVertex && b != kNoVertex) s.set_edge_label(a, b, e.segment);
  }
  for (const refine::Subfacet& f : d.subfacets()) {
    if (!f.alive) continue;
    const VertexId a = local(f.v[0]), b = local(f.v[1]), c = local(f.v[2]);
    if (a != kNoVertex && b != kNoVertex && c != kNoVertex) s.set_face_label(a, b, c, f.facet);
  }
}

refine::MaybeId RefinementRules::subsegment(const Submesh& s, VertexId a, VertexId b) const {
  if (!may_be(s.tag(a), kSegment) || !may_be(s.tag(b), kSegment)) return {};
  const std::uint32_t l = s.edge_label(a, b);
  return l == kNoLabel ? refine::MaybeId{} : refine::MaybeId{l};
}

refine::MaybeId RefinementRules::subfacet(const Submesh& s, VertexId a, VertexId b,
                                          VertexId c) const {
  if (s.tag(a) == kInterior || s.tag(b) == kInterior || s.tag(c) == kInterior) return {};
  const std::uint32_t l = s.face_label(a, b, c);
  return l == kNoLabel ? refine::MaybeId{} : refine::MaybeId{l};
}

std::optional<std::array<VertexId, 2>> RefinementRules::encroached_subsegment(
    const Submesh& s, TetId t, const Point& p) const {
  const TetStore& st = s.store();
  if (st.is_ghost(t) || st.is_proxy(t)) return std::nullopt;
  const VertexId* v = st.vertices(t);
  if (!may_touch_d(s, v)) return std::nullopt;
  const auto pts = s.points();
  for (const auto& e : tables::kEdgeVertex)
    if (subsegment(s, v[e[0]], v[e[1]]) &&
        in_diametral_ball(pts[v[e[0]]], pts[v[e[1]]], p) != Sign::Negative)
      return std::array<VertexId, 2>{v[e[0]], v[e[1]]};
  return std::nullopt;
}

bool RefinementRules::encroaches_subfacet(const Submesh& s, TetId t, const Point& p) const {
  const TetStore& st = s.store();
  if (st.is_ghost(t) || st.is_proxy(t)) return false;
  const VertexId* v = st.vertices(t);
  if (!may_touch_d(s, v)) return false;
  const auto pts = s.points();
  for (const auto& f : tables::kFaceVertex)
    if (subfacet(s, v[f[0]], v[f[1]], v[f[2]]) &&
        in_equatorial_ball(pts[v[f[0]]], pts[v[f[1]]], pts[v[f[2]]], p) != Sign::Negative)
      return true;
  return false;
}

Verdict RefinementRules::accept(const Submesh& s, const Cavity& c) {
  plan_.active = false;
  const TetStore& st = s.store();
  // Fig. 2: an encroached subsegment first.
  for (const auto* tets : {&c.conflict, &c.ring})
    for (const TetId t : *tets)
      if (const auto e = encroached_subsegment(s, t, c.point)) {
        Gid a = s.gid((*e)[0]), b = s.gid((*e)[1]);
        if (a > b) std::swap(a, b);
        if (!splits_enabled_ || refused_.count({a, b}) != 0) {
          ++deferred_.subsegment;
          return {};
        }
        const auto pts = s.points();
        return {Verdict::Kind::Split, a, b, construct::midpoint(pts[(*e)[0]], pts[(*e)[1]]),
                s.tet_gid(t)};
      }
  for (const TetId t : c.conflict)
    if (st.is_ghost(t) || !s.inside(t)) {
      ++deferred_.outside;
      return {};
    }
  for (const auto* tets : {&c.conflict, &c.ring})
    for (const TetId t : *tets)
      if (encroaches_subfacet(s, t, c.point)) {
        ++deferred_.subfacet;
        return {};
      }
  for (const TetId t : c.conflict) {
    // A subfacet face of a conflict tet survives only on the boundary (between two inside
    // conflict tets lies an internal facet, domain/domain.hpp, which the cavity would take
    // out of T).
    const VertexId* v = st.vertices(t);
    if (!may_touch_d(s, v)) continue;
    for (int f = 0; f < 4; ++f) {
      const auto& fv = tables::kFaceVertex[f];
      if (subfacet(s, v[fv[0]], v[fv[1]], v[fv[2]]) &&
          std::find(c.boundary.begin(), c.boundary.end(), half_face(t, f)) == c.boundary.end()) {
        ++deferred_.removed;
        return {};
      }
    }
  }
  // A subsegment edge of a conflict tet survives only as an edge of the boundary.
  kept_.clear();
  for (const TetId t : c.conflict) {
    const VertexId* v = st.vertices(t);
    if (!may_touch_d(s, v)) continue;
    for (const auto& e : tables::kEdgeVertex) {
      if (!subsegment(s, v[e[0]], v[e[1]])) continue;
      if (kept_.empty()) {
        for (const HalfFace h : c.boundary) {
          const VertexId* w = st.vertices(tet_of(h));
          const auto& f = tables::kFaceVertex[face_of(h)];
          for (int k = 0; k < 3; ++k) {
            const VertexId a = w[f[k]], b = w[f[(k + 1) % 3]];
            kept_.emplace_back(std::min(a, b), std::max(a, b));
          }
        }
        std::sort(kept_.begin(), kept_.end());
      }
      const std::pair<VertexId, VertexId> key(std::min(v[e[0]], v[e[1]]),
                                              std::max(v[e[0]], v[e[1]]));
      if (!std::binary_search(kept_.begin(), kept_.end(), key)) {
        ++deferred_.removed;
        return {};
      }
    }
  }
  return {Verdict::Kind::Commit};
}

namespace {

using Edge = std::pair<VertexId, VertexId>;
Edge edge(VertexId a, VertexId b) { return a < b ? Edge{a, b} : Edge{b, a}; }

}  // namespace

bool RefinementRules::accept_split(const Submesh& s, const Cavity& c, Gid ga, Gid gb) {
  plan_ = SplitPlan{};
  const VertexId a = s.find_vertex(ga), b = s.find_vertex(gb);
  if (a == kNoVertex || b == kNoVertex) return false;  // not here: split elsewhere
  const refine::MaybeId seg = subsegment(s, a, b);
  if (!seg) return false;  // split already
  const auto pts = s.points();
  if (!(construct::midpoint(pts[a], pts[b]) == c.point)) return false;
  const TetStore& st = s.store();
  const auto refuse = [&] {
    refused_.insert({std::min(ga, gb), std::max(ga, gb)});
    ++deferred_.split_refused;
    return false;
  };
  // The cavity's boundary: its edges, and the inside flag each new tet gets.
  std::vector<Edge> boundary_edges;
  std::vector<std::pair<Edge, std::uint8_t>> flag_at_edge;  // per boundary face's edge
  for (const HalfFace h : c.boundary) {
    const TetId t = tet_of(h);
    const VertexId* w = st.vertices(t);
    const auto& f = tables::kFaceVertex[face_of(h)];
    const TetId out = st.neighbour(t, face_of(h));
    bool in = !st.is_ghost(out) && s.inside(out);
    if (const refine::MaybeId sf = subfacet(s, w[f[0]], w[f[1]], w[f[2]]); sf && separates(*sf))
      in = !in;
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge(w[f[k]], w[f[(k + 1) % 3]]);
      boundary_edges.push_back(e);
      flag_at_edge.emplace_back(e, static_cast<std::uint8_t>(in));
    }
  }
  std::sort(boundary_edges.begin(), boundary_edges.end());
  const auto on_boundary = [&](const Edge& e) {
    return std::binary_search(boundary_edges.begin(), boundary_edges.end(), e);
  };
  if (on_boundary(edge(a, b))) return refuse();  // ab would stay
  // Subsegments and subfacets the cavity removes.
  const std::vector<std::uint32_t>& facets = m0_.surf.segments[*seg].facets;
  std::vector<std::pair<std::array<VertexId, 3>, std::uint32_t>> removed;
  bool has_ab = false;
  for (const TetId t : c.conflict) {
    const VertexId* v = st.vertices(t);
    if (st.is_ghost(t) || !may_touch_d(s, v)) continue;
    for (const auto& e : tables::kEdgeVertex) {
      if (!subsegment(s, v[e[0]], v[e[1]])) continue;
      const Edge x = edge(v[e[0]], v[e[1]]);
      if (x == edge(a, b))
        has_ab = true;
      else if (!on_boundary(x))
        return refuse();  // another subsegment would go
    }
    for (int f = 0; f < 4; ++f) {
      const auto& fv = tables::kFaceVertex[f];
      const refine::MaybeId sf = subfacet(s, v[fv[0]], v[fv[1]], v[fv[2]]);
      if (!sf || std::find(c.boundary.begin(), c.boundary.end(), half_face(t, f)) != c.boundary.end())
        continue;
      if (!std::binary_search(facets.begin(), facets.end(), *sf)) return refuse();
      std::array<VertexId, 3> k{v[fv[0]], v[fv[1]], v[fv[2]]};
      std::sort(k.begin(), k.end());
      removed.emplace_back(k, *sf);
    }
  }
  if (!has_ab) return refuse();
  std::sort(removed.begin(), removed.end());
  removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
  // Each facet's region: its boundary edges, ab excepted, fan out from m.
  std::vector<std::pair<std::pair<std::uint32_t, Edge>, int>> count;
  for (const auto& [k, f] : removed)
    for (int i = 0; i < 3; ++i) count.push_back({{f, edge(k[i], k[(i + 1) % 3])}, 1});
  std::sort(count.begin(), count.end());
  for (std::size_t i = 0; i < count.size();) {
    std::size_t j = i;
    while (j < count.size() && count[j].first == count[i].first) ++j;
    const auto& [f, e] = count[i].first;
    if (j - i == 1 && e != edge(a, b)) {
      if (!on_boundary(e)) return refuse();
      plan_.fan.push_back({{e.first, e.second}, f});
    } else if (j - i > 2) {
      return refuse();
    }
    i = j;
  }
  // Inside flags: across each new face (m, e), e an edge of two boundary faces, they
  // change exactly when (m, e) is a new subfacet of a separating facet.
  std::sort(flag_at_edge.begin(), flag_at_edge.end());
  for (std::size_t i = 0; i < flag_at_edge.size(); i += 2) {
    if (i + 1 == flag_at_edge.size() || flag_at_edge[i].first != flag_at_edge[i + 1].first)
      return refuse();
    const Edge& e = flag_at_edge[i].first;
    bool flips = false;
    for (const auto& [x, f] : plan_.fan)
      if (Edge{x[0], x[1]} == e && separates(f)) flips = true;
    if ((flag_at_edge[i].second != flag_at_edge[i + 1].second) != flips) return refuse();
  }
  plan_.active = true;
  plan_.a = a;
  plan_.b = b;
  plan_.segment = *seg;
  for (const auto& [k, f] : removed) plan_.removed.push_back(k);
  return true;
}

VertexId RefinementRules::commit(Submesh& s, const Cavity& c) {
  if (!plan_.active) return s.insert(c, 1, kInterior);
  plan_.active = false;
  const VertexId m = s.insert(c, 0, kSegment);
  const TetStore& st = s.store();
  for (const TetId t : s.created()) {
    int i = 0;
    while (st.vertex(t, i) != m) ++i;
    const TetId out = st.neighbour(t, i);
    bool in = !st.is_ghost(out) && s.inside(out);
    const VertexId* w = st.vertices(t);
    const auto& f = tables::kFaceVertex[i];
    if (const refine::MaybeId sf = subfacet(s, w[f[0]], w[f[1]], w[f[2]]); sf && separates(*sf))
      in = !in;
    s.set_inside(t, in);
  }
  s.erase_edge_label(plan_.a, plan_.b);
  s.set_edge_label(plan_.a, m, plan_.segment);
  s.set_edge_label(m, plan_.b, plan_.segment);
  for (const auto& k : plan_.removed) s.erase_face_label(k[0], k[1], k[2]);
  for (const auto& [e, f] : plan_.fan) s.set_face_label(m, e[0], e[1], f);
  splits_.push_back({s.gid(plan_.a), s.gid(plan_.b), s.gid(m), c.point});
  return m;
}

}  // namespace pdr::par
