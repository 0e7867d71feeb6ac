// Fig. 2's step on a submesh with D as distributed; see par/refinement_rules.hpp.
#include "par/refinement_rules.hpp"

#include <algorithm>

#include "geom/construct.hpp"
#include "geom/encroach.hpp"
#include "mesh/tables.hpp"

namespace pdr::par {

RefinementRules::RefinementRules(const refine::VolumeMesh& m0, const refine::TetBounds& bounds)
    : m0_(m0), bounds_(bounds) {
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

// Whether p lies in the closed diametral ball of a subsegment edge of real tet t, or in the
// closed equatorial ball of a subfacet face of it (counted by kind).
bool RefinementRules::encroaches(const Submesh& s, TetId t, const Point& p) {
  const TetStore& st = s.store();
  if (st.is_ghost(t) || st.is_proxy(t)) return false;
  const VertexId* v = st.vertices(t);
  if (!may_touch_d(s, v)) return false;
  const auto pts = s.points();
  for (const auto& e : tables::kEdgeVertex)
    if (subsegment(s, v[e[0]], v[e[1]]) &&
        in_diametral_ball(pts[v[e[0]]], pts[v[e[1]]], p) != Sign::Negative) {
      ++deferred_.subsegment;
      return true;
    }
  for (const auto& f : tables::kFaceVertex)
    if (subfacet(s, v[f[0]], v[f[1]], v[f[2]]) &&
        in_equatorial_ball(pts[v[f[0]]], pts[v[f[1]]], pts[v[f[2]]], p) != Sign::Negative) {
      ++deferred_.subfacet;
      return true;
    }
  return false;
}

bool RefinementRules::accept(const Submesh& s, const Cavity& c) {
  const TetStore& st = s.store();
  for (const TetId t : c.conflict)
    if (st.is_ghost(t) || !s.inside(t)) {
      ++deferred_.outside;
      return false;
    }
  for (const TetId t : c.conflict) {
    if (encroaches(s, t, c.point)) return false;
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
        return false;
      }
    }
  }
  for (const TetId t : c.ring)
    if (encroaches(s, t, c.point)) return false;
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
        return false;
      }
    }
  }
  return true;
}

}  // namespace pdr::par
