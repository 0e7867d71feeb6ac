// Fig. 2's step on a submesh with D as distributed; see par/refinement_rules.hpp.
#include "par/refinement_rules.hpp"

#include <stdexcept>

#include <algorithm>

#include "geom/construct.hpp"
#include "geom/encroach.hpp"
#include "refine/closure.hpp"
#include "surface/chart.hpp"
#include "mesh/tables.hpp"

namespace pdr::par {

RefinementRules::RefinementRules(const refine::VolumeMesh& m0, const refine::TetBounds& bounds,
                                 bool surface_steps)
    : m0_(m0), bounds_(bounds), surface_steps_enabled_(surface_steps) {
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

refine::MaybeId RefinementRules::subsegment(const Submesh& s, VertexId a, VertexId b) {
  if (!may_be(s.tag(a), kSegment) || !may_be(s.tag(b), kSegment)) return {};
  const std::uint32_t l = s.edge_label(a, b);
  return l == kNoLabel ? refine::MaybeId{} : refine::MaybeId{l};
}

refine::MaybeId RefinementRules::subfacet(const Submesh& s, VertexId a, VertexId b,
                                          VertexId c) {
  if (s.tag(a) == kInterior || s.tag(b) == kInterior || s.tag(c) == kInterior) return {};
  const std::uint32_t l = s.face_label(a, b, c);
  return l == kNoLabel ? refine::MaybeId{} : refine::MaybeId{l};
}

std::optional<std::array<VertexId, 2>> RefinementRules::encroached_subsegment(
    const Submesh& s, std::initializer_list<const std::vector<TetId>*> tets,
    const Point& p) const {
  const TetStore& st = s.store();
  for (const auto* list : tets)
    for (const TetId t : *list) {
      if (st.is_ghost(t) || st.is_proxy(t)) continue;
      if (const auto e = encroached_edge(s, st.vertices(t), p)) return e;
    }
  return std::nullopt;
}

std::optional<std::array<VertexId, 2>> RefinementRules::encroached_edge(const Submesh& s,
                                                                        const VertexId* v,
                                                                        const Point& p) const {
  if (!may_touch_d(s, v)) return std::nullopt;
  const auto pts = s.points();
  for (const auto& e : tables::kEdgeVertex)
    if (subsegment(s, v[e[0]], v[e[1]]) &&
        in_diametral_ball(pts[v[e[0]]], pts[v[e[1]]], p) != Sign::Negative)
      return std::array<VertexId, 2>{v[e[0]], v[e[1]]};
  return std::nullopt;
}

RefinementRules::Key RefinementRules::key(const Submesh& s, std::array<VertexId, 3> v) const {
  Key k{s.gid(v[0]), s.gid(v[1]), v[2] == kNoVertex ? kNoGid : s.gid(v[2])};
  std::sort(k.begin(), k.end());  // kNoGid, the largest, last
  return k;
}

Point RefinementRules::facet_point(const Submesh& s, const std::array<VertexId, 3>& v,
                                   std::uint32_t facet) const {
  const auto pts = s.points();
  std::array<Point, 3> q{pts[v[0]], pts[v[1]], pts[v[2]]};
  std::sort(q.begin(), q.end());  // the same point whichever tet names the subfacet
  return surface::place_on_facet(m0_.surf.facets[facet].chart,
                                 construct::triangle_circumcenter(q[0], q[1], q[2]));
}

Verdict RefinementRules::refine_element(const Submesh& s, std::array<VertexId, 3> v,
                                        TetId near) {
  const bool facet = v[2] != kNoVertex;
  const Key k = key(s, v);
  if (!surface_steps_enabled_ || refused_.count(k) != 0) {
    ++(facet ? deferred_.subfacet : deferred_.subsegment);
    return {};
  }
  const auto pts = s.points();
  Verdict out{facet ? Verdict::Kind::Facet : Verdict::Kind::Split, k[0], k[1], k[2]};
  out.p = facet ? facet_point(s, v, *subfacet(s, v[0], v[1], v[2]))
                : construct::midpoint(pts[v[0]], pts[v[1]]);
  out.near = s.tet_gid(near);
  return out;
}

namespace {
enum EarlyReason : std::uint8_t { kOutside = 1, kSubsegment = 2, kSubfacet = 3 };
}  // namespace

std::uint8_t RefinementRules::defers_at(const Submesh& s, TetId u, const Point& p) {
  const TetStore& st = s.store();
  if (st.is_ghost(u) || !s.inside(u)) return kOutside;
  const VertexId* v = st.vertices(u);
  if (!may_touch_d(s, v)) return 0;
  if (encroached_edge(s, v, p)) return kSubsegment;
  const auto pts = s.points();
  for (int f = 0; f < 4; ++f) {
    const auto& fv = tables::kFaceVertex[f];
    if (subfacet(s, v[fv[0]], v[fv[1]], v[fv[2]]) &&
        in_equatorial_ball(pts[v[fv[0]]], pts[v[fv[1]]], pts[v[fv[2]]], p) != Sign::Negative)
      return kSubfacet;
  }
  return 0;
}

void RefinementRules::count_early_deferral(std::uint8_t reason) {
  if (reason == kOutside) ++deferred_.outside;
  if (reason == kSubsegment) ++deferred_.subsegment;
  if (reason == kSubfacet) ++deferred_.subfacet;
}

Verdict RefinementRules::accept(const Submesh& s, const Cavity& c) {
  plan_.kind = Plan::Kind::None;
  if (points_left_ == 0) {
    ++deferred_.cap;
    return {};
  }
  const TetStore& st = s.store();
  const auto pts = s.points();
  // One pass over the closure (conflict tets, then the ring) reads each edge's and face's
  // label once and gathers what Fig. 2's order then decides on: an encroached subsegment
  // first (the first one met: it ends the pass), then the largest encroached subfacet,
  // then a conflict tet outside Ω, then an element of D the cavity would take out of T.
  std::optional<std::array<VertexId, 3>> best;  // the largest encroached subfacet
  std::array<Point, 3> best_p{};
  TetId best_t = kNoTet;  // a closure tet with that face: where its point's search starts
  bool outside = false, removed = false;
  kept_.clear();
  const auto survives = [&](VertexId a, VertexId b) {
    // A subsegment edge of a conflict tet survives only as an edge of the boundary.
    if (kept_.empty()) {
      for (const HalfFace h : c.boundary) {
        const VertexId* w = st.vertices(tet_of(h));
        const auto& f = tables::kFaceVertex[face_of(h)];
        for (int k = 0; k < 3; ++k) {
          const VertexId x = w[f[k]], y = w[f[(k + 1) % 3]];
          kept_.emplace_back(std::min(x, y), std::max(x, y));
        }
      }
      std::sort(kept_.begin(), kept_.end());
    }
    return std::binary_search(kept_.begin(), kept_.end(),
                              std::pair<VertexId, VertexId>(std::min(a, b), std::max(a, b)));
  };
  for (const auto* list : {&c.conflict, &c.ring}) {
    const bool conflict = list == &c.conflict;
    for (const TetId t : *list) {
      if (st.is_ghost(t) || st.is_proxy(t)) {
        outside = outside || conflict;
        continue;
      }
      if (conflict && !s.inside(t)) outside = true;
      const VertexId* v = st.vertices(t);
      if (!may_touch_d(s, v)) continue;
      for (const auto& e : tables::kEdgeVertex) {
        const VertexId a = v[e[0]], b = v[e[1]];
        if (!subsegment(s, a, b)) continue;
        if (in_diametral_ball(pts[a], pts[b], c.point) != Sign::Negative)
          return refine_element(s, {a, b, kNoVertex}, t);
        if (conflict && !removed && !survives(a, b)) removed = true;
      }
      for (int f = 0; f < 4; ++f) {
        const auto& fv = tables::kFaceVertex[f];
        const std::array<VertexId, 3> x{v[fv[0]], v[fv[1]], v[fv[2]]};
        if (!subfacet(s, x[0], x[1], x[2])) continue;
        const std::array<Point, 3> q{pts[x[0]], pts[x[1]], pts[x[2]]};
        if (in_equatorial_ball(q[0], q[1], q[2], c.point) != Sign::Negative &&
            (!best || refine::larger_subfacet(q, best_p)))
          best = x, best_p = q, best_t = t;
        // A subfacet face of a conflict tet survives only on the boundary (between two
        // inside conflict tets lies an internal facet, domain/domain.hpp, which the
        // cavity would take out of T).
        if (conflict && !removed &&
            std::find(c.boundary.begin(), c.boundary.end(), half_face(t, f)) == c.boundary.end())
          removed = true;
      }
    }
  }
  if (best) return refine_element(s, *best, best_t);
  if (outside) {
    ++deferred_.outside;
    return {};
  }
  if (removed) {
    ++deferred_.removed;
    return {};
  }
  return {Verdict::Kind::Commit};
}

namespace {

using Edge = std::pair<VertexId, VertexId>;
Edge edge(VertexId a, VertexId b) { return a < b ? Edge{a, b} : Edge{b, a}; }

}  // namespace

Verdict RefinementRules::accept_surface(const Submesh& s, const Cavity& c, Gid ga, Gid gb,
                                        Gid gc) {
  plan_ = Plan{};
  if (points_left_ == 0) return {};  // dropped: its tet's step is then deferred (cap)
  const bool facet_step = gc != kNoGid;
  const VertexId a = s.find_vertex(ga), b = s.find_vertex(gb),
                 cc = facet_step ? s.find_vertex(gc) : kNoVertex;
  // Dropped when the element is gone (another step changed D meanwhile: the tet whose
  // step this was is tried again) or its point is not this one.
  if (a == kNoVertex || b == kNoVertex || (facet_step && cc == kNoVertex)) return {};
  // The element is still in the mesh only as an edge or a face of a conflict tet (its
  // point conflicts with every tet holding it: exactly, with the exact constructions the
  // caller enables these steps for; were a point rounded off its facet, a live element
  // could fail this test and its step be dropped again and again); a label kept of an
  // element no longer held may be one that is gone (Submesh M4).
  const TetStore& st = s.store();
  const bool held = std::any_of(c.conflict.begin(), c.conflict.end(), [&](TetId t) {
    const VertexId* w = st.vertices(t);
    const auto has = [&](VertexId x) { return std::find(w, w + 4, x) != w + 4; };
    return has(a) && has(b) && (!facet_step || has(cc));
  });
  if (!held) return {};
  const std::array<VertexId, 3> v{a, b, cc};
  const auto refuse = [&]() -> Verdict {
    refused_.insert(key(s, v));
    ++deferred_.refused;
    return {};
  };
  if (!facet_step) {
    const refine::MaybeId seg = subsegment(s, a, b);
    const auto pts = s.points();
    if (!seg || construct::midpoint(pts[a], pts[b]) != c.point) return {};
    const std::vector<std::uint32_t>& facets = m0_.surf.segments[*seg].facets;
    if (!plan(s, c, std::array<VertexId, 2>{a, b}, facets, nullptr)) return refuse();
    plan_.kind = Plan::Kind::Split;
    plan_.label = *seg;
  } else {
    const refine::MaybeId f = subfacet(s, a, b, cc);
    if (!f || facet_point(s, v, *f) != c.point) return {};
    // Fig. 2: a subfacet circumcenter that encroaches a subsegment refines it instead.
    if (const auto e = encroached_subsegment(s, {&c.conflict, &c.ring}, c.point)) {
      const Verdict split = refine_element(s, {(*e)[0], (*e)[1], kNoVertex}, c.seed);
      if (split.kind != Verdict::Kind::Split) refused_.insert(key(s, v));  // counted there
      return split;
    }
    const std::uint32_t only[1] = {*f};
    if (!plan(s, c, std::nullopt, only, &v)) return refuse();
    plan_.kind = Plan::Kind::Facet;
    plan_.label = *f;
  }
  plan_.element = {ga, gb, gc};
  return {Verdict::Kind::Commit};
}

bool RefinementRules::plan(const Submesh& s, const Cavity& c,
                           std::optional<std::array<VertexId, 2>> split,
                           std::span<const std::uint32_t> facets,
                           const std::array<VertexId, 3>* subfacet_removed) {
  const TetStore& st = s.store();
  // The cavity's boundary: its edges, and the inside flag each new tet gets.
  auto& boundary_edges = plan_edges_;
  auto& flag_at_edge = plan_flags_;  // per boundary face's edge
  boundary_edges.clear();
  flag_at_edge.clear();
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
  // The subsegment split, or an edge that no tet has.
  const Edge ab = split ? edge((*split)[0], (*split)[1]) : Edge{kNoVertex, kNoVertex};
  if (split && on_boundary(ab)) return false;  // ab would stay
  // Subsegments and subfacets the cavity removes.
  auto& removed = plan_removed_;
  removed.clear();
  bool has_ab = false;
  for (const TetId t : c.conflict) {
    const VertexId* v = st.vertices(t);
    if (st.is_ghost(t) || !may_touch_d(s, v)) continue;
    for (const auto& e : tables::kEdgeVertex) {
      if (!subsegment(s, v[e[0]], v[e[1]])) continue;
      const Edge x = edge(v[e[0]], v[e[1]]);
      if (x == ab)
        has_ab = true;
      else if (!on_boundary(x))
        return false;  // another subsegment would go
    }
    for (int f = 0; f < 4; ++f) {
      const auto& fv = tables::kFaceVertex[f];
      const refine::MaybeId sf = subfacet(s, v[fv[0]], v[fv[1]], v[fv[2]]);
      if (!sf || std::find(c.boundary.begin(), c.boundary.end(), half_face(t, f)) != c.boundary.end())
        continue;
      if (std::find(facets.begin(), facets.end(), *sf) == facets.end()) return false;
      std::array<VertexId, 3> k{v[fv[0]], v[fv[1]], v[fv[2]]};
      std::sort(k.begin(), k.end());
      removed.emplace_back(k, *sf);
    }
  }
  if (split && !has_ab) return false;
  std::sort(removed.begin(), removed.end());
  removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
  if (subfacet_removed != nullptr) {
    std::array<VertexId, 3> k = *subfacet_removed;
    std::sort(k.begin(), k.end());
    if (std::find_if(removed.begin(), removed.end(), [&](const auto& r) { return r.first == k; }) ==
        removed.end())
      return false;  // the subfacet would stay
  }
  // Each facet's region: its boundary edges (ab excepted) fan out from the new vertex.
  auto& count = plan_region_;  // the removed subfacets' edges, by facet
  count.clear();
  for (const auto& [k, f] : removed)
    for (int i = 0; i < 3; ++i) count.push_back({f, edge(k[i], k[(i + 1) % 3])});
  std::sort(count.begin(), count.end());
  for (std::size_t i = 0; i < count.size();) {
    std::size_t j = i;
    while (j < count.size() && count[j] == count[i]) ++j;
    const auto& [f, e] = count[i];
    if (j - i == 1 && e != ab) {
      if (!on_boundary(e)) return false;
      plan_.fan.push_back({{e.first, e.second}, f});
    } else if (j - i > 2) {
      return false;
    }
    i = j;
  }
  // Inside flags: across each new face (q, e), e an edge of two boundary faces, they
  // change exactly when (q, e) is a new subfacet of a separating facet.
  std::sort(flag_at_edge.begin(), flag_at_edge.end());
  for (std::size_t i = 0; i < flag_at_edge.size(); i += 2) {
    if (i + 1 == flag_at_edge.size() || flag_at_edge[i].first != flag_at_edge[i + 1].first)
      return false;
    const Edge& e = flag_at_edge[i].first;
    bool flips = false;
    for (const auto& [x, f] : plan_.fan)
      if (Edge{x[0], x[1]} == e && separates(f)) flips = true;
    if ((flag_at_edge[i].second != flag_at_edge[i + 1].second) != flips) return false;
  }
  if (split) plan_.a = (*split)[0], plan_.b = (*split)[1];
  for (const auto& [k, f] : removed) plan_.removed.push_back(k);
  return true;
}

VertexId RefinementRules::commit(Submesh& s, const Cavity& c) {
  if (points_left_ == 0) throw std::logic_error("refinement rules: a commit past the point budget");
  --points_left_;
  if (plan_.kind == Plan::Kind::None) return s.insert(c, 1, kInterior);
  const bool split = plan_.kind == Plan::Kind::Split;
  plan_.kind = Plan::Kind::None;
  const VertexId m = s.insert(c, 0, split ? kSegment : kFacet);
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
  if (split) {
    s.erase_edge_label(plan_.a, plan_.b);
    s.set_edge_label(plan_.a, m, plan_.label);
    s.set_edge_label(m, plan_.b, plan_.label);
  }
  for (const auto& k : plan_.removed) s.erase_face_label(k[0], k[1], k[2]);
  for (const auto& [e, f] : plan_.fan) s.set_face_label(m, e[0], e[1], f);
  steps_.push_back({plan_.element[0], plan_.element[1], plan_.element[2], s.gid(m), c.point,
                    split ? 0u : plan_.label});
  return m;
}

}  // namespace pdr::par
