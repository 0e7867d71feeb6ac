// The distance d of paper §2.1 by branch and bound over a bounding-volume hierarchy, its
// all-pairs reference, and the point/segment/triangle distances both use; see
// domain/distance.hpp.

#include "domain/distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <limits>

#include "domain/bvh.hpp"

namespace pdr::domain {

const char* component_kind_name(ComponentKind k) {
  switch (k) {
    case ComponentKind::Vertex: return "vertex";
    case ComponentKind::Segment: return "segment";
    case ComponentKind::Facet: return "facet";
  }
  return "?";
}

namespace {

struct Best {
  double d2 = std::numeric_limits<double>::infinity();
  FeatureSize pair;
  void offer(double x, ComponentKind k1, std::uint32_t i1, ComponentKind k2, std::uint32_t i2) {
    if (!(x < d2)) return;
    d2 = x;
    pair.first_kind = k1;
    pair.first = i1;
    pair.second_kind = k2;
    pair.second = i2;
  }
  FeatureSize result() const {
    FeatureSize r = pair;
    r.min_distance = std::sqrt(d2);
    r.d = r.min_distance / std::sqrt(2.0);
    return r;
  }
};

bool facet_has(const PlcDomain& dom, std::uint32_t f, std::uint32_t v) {
  const auto& vs = dom.facets[f].vertices;
  return std::binary_search(vs.begin(), vs.end(), v);
}

bool segments_share(const DomainSegment& s, const DomainSegment& t) {
  return s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b;
}

struct Prim {
  ComponentKind kind;
  std::uint32_t id;     // vertex id, segment index or facet index
  std::uint32_t tri;    // Facet: triangle index
};

// Every boundary vertex, segment and facet triangle, with its bounding box.
struct Primitives {
  std::vector<Prim> prims;
  std::vector<Box> boxes;
};

Primitives primitives(const PlcDomain& dom) {
  const std::vector<Point>& pts = dom.plc.points;
  Primitives out;
  for (std::uint32_t v = 0; v < pts.size(); ++v) {
    out.prims.push_back({ComponentKind::Vertex, v, 0});
    out.boxes.emplace_back().add(pts[v]);
  }
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    out.prims.push_back({ComponentKind::Segment, s, 0});
    Box& b = out.boxes.emplace_back();
    b.add(pts[dom.segments[s].a]);
    b.add(pts[dom.segments[s].b]);
  }
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
    for (std::uint32_t t = 0; t < dom.facets[f].tris.size(); ++t) {
      out.prims.push_back({ComponentKind::Facet, f, t});
      Box& b = out.boxes.emplace_back();
      for (std::uint32_t v : dom.facets[f].tris[t].v) b.add(pts[v]);
    }
  return out;
}

}  // namespace

FeatureSize feature_size(const PlcDomain& dom) {
  const std::vector<Point>& pts = dom.plc.points;
  const Primitives all = primitives(dom);
  const std::vector<Prim>& prims = all.prims;
  const std::vector<Box>& boxes = all.boxes;
  const Bvh bvh(boxes);

  Best best;
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s)
    best.offer(dist2_point_point(pts[dom.segments[s].a], pts[dom.segments[s].b]),
               ComponentKind::Vertex, dom.segments[s].a, ComponentKind::Vertex, dom.segments[s].b);
  auto bound = [&] { return best.d2; };

  for (std::uint32_t i = 0; i < prims.size(); ++i) {
    const Prim& q = prims[i];
    if (q.kind == ComponentKind::Facet) continue;
    const Box& qb = boxes[i];
    auto key = [&](const Box& b) { return box_gap2(qb, b); };
    if (q.kind == ComponentKind::Vertex) {
      const Point& p = pts[q.id];
      bvh.branch_and_bound(key, bound, [&](std::uint32_t j) {
        const Prim& o = prims[j];
        switch (o.kind) {
          case ComponentKind::Vertex:
            if (o.id != q.id)
              best.offer(dist2_point_point(p, pts[o.id]), q.kind, q.id, o.kind, o.id);
            break;
          case ComponentKind::Segment: {
            const DomainSegment& s = dom.segments[o.id];
            if (s.a != q.id && s.b != q.id)
              best.offer(dist2_point_segment(p, pts[s.a], pts[s.b]), q.kind, q.id, o.kind, o.id);
            break;
          }
          case ComponentKind::Facet: {
            if (facet_has(dom, o.id, q.id)) break;
            const auto& t = dom.facets[o.id].tris[o.tri].v;
            best.offer(dist2_point_triangle(p, pts[t[0]], pts[t[1]], pts[t[2]]), q.kind, q.id,
                       o.kind, o.id);
            break;
          }
        }
      });
    } else {
      const DomainSegment& s = dom.segments[q.id];
      bvh.branch_and_bound(key, bound, [&](std::uint32_t j) {
        const Prim& o = prims[j];
        if (o.kind != ComponentKind::Segment || o.id <= q.id) return;
        const DomainSegment& t = dom.segments[o.id];
        if (segments_share(s, t)) return;
        best.offer(dist2_segment_segment(pts[s.a], pts[s.b], pts[t.a], pts[t.b]), q.kind, q.id,
                   o.kind, o.id);
      });
    }
  }
  return best.result();
}

namespace {

bool facets_share(const PlcDomain& dom, std::uint32_t f, std::uint32_t g) {
  const auto &a = dom.facets[f].vertices, &b = dom.facets[g].vertices;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (a[i] == b[j]) return true;
    a[i] < b[j] ? ++i : ++j;
  }
  return false;
}

bool facet_has_segment_end(const PlcDomain& dom, std::uint32_t f, const DomainSegment& s) {
  return facet_has(dom, f, s.a) || facet_has(dom, f, s.b);
}

// The squared distance from segment s, or from triangle t of facet f (s = kNone), to the
// primitive `o` when o belongs to a component unrelated to the query's; infinity otherwise.
constexpr std::uint32_t kNoSeg = 0xFFFFFFFFu;
double unrelated_dist2(const PlcDomain& dom, std::uint32_t s, std::uint32_t f, std::uint32_t t,
                       const Prim& o) {
  const std::vector<Point>& pts = dom.plc.points;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (s != kNoSeg) {
    const DomainSegment& q = dom.segments[s];
    const Point &a = pts[q.a], &b = pts[q.b];
    switch (o.kind) {
      case ComponentKind::Vertex:
        return o.id == q.a || o.id == q.b ? kInf : dist2_point_segment(pts[o.id], a, b);
      case ComponentKind::Segment: {
        const DomainSegment& r = dom.segments[o.id];
        return segments_share(q, r) ? kInf : dist2_segment_segment(a, b, pts[r.a], pts[r.b]);
      }
      case ComponentKind::Facet: {
        if (facet_has_segment_end(dom, o.id, q)) return kInf;
        const auto& v = dom.facets[o.id].tris[o.tri].v;
        return dist2_segment_triangle(a, b, pts[v[0]], pts[v[1]], pts[v[2]]);
      }
    }
    return kInf;
  }
  const auto& w = dom.facets[f].tris[t].v;
  const Point &a = pts[w[0]], &b = pts[w[1]], &c = pts[w[2]];
  switch (o.kind) {
    case ComponentKind::Vertex:
      return facet_has(dom, f, o.id) ? kInf : dist2_point_triangle(pts[o.id], a, b, c);
    case ComponentKind::Segment: {
      const DomainSegment& r = dom.segments[o.id];
      return facet_has_segment_end(dom, f, r) ? kInf
                                              : dist2_segment_triangle(pts[r.a], pts[r.b], a, b, c);
    }
    case ComponentKind::Facet: {
      if (o.id == f || facets_share(dom, f, o.id)) return kInf;
      const auto& v = dom.facets[o.id].tris[o.tri].v;
      return dist2_triangle_triangle(a, b, c, pts[v[0]], pts[v[1]], pts[v[2]]);
    }
  }
  return kInf;
}

}  // namespace

LocalFeatureSizes local_feature_sizes(const PlcDomain& dom) {
  const std::vector<Point>& pts = dom.plc.points;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Primitives all = primitives(dom);
  const std::vector<Prim>& prims = all.prims;
  const std::vector<Box>& boxes = all.boxes;
  const Bvh bvh(boxes);
  // The nearest unrelated primitive to the query box, by branch and bound.
  auto nearest = [&](const Box& qb, std::uint32_t s, std::uint32_t f, std::uint32_t t,
                     double best) {
    bvh.branch_and_bound([&](const Box& b) { return box_gap2(qb, b); }, [&] { return best; },
                         [&](std::uint32_t j) {
                           best = std::min(best, unrelated_dist2(dom, s, f, t, prims[j]));
                         });
    return best;
  };
  LocalFeatureSizes out;
  out.segment_d.assign(dom.segments.size(), kInf);
  out.facet_d.assign(dom.facets.size(), kInf);
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    Box qb;
    qb.add(pts[dom.segments[s].a]);
    qb.add(pts[dom.segments[s].b]);
    out.segment_d[s] = std::sqrt(nearest(qb, s, 0, 0, kInf) / 2);
  }
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    if (!dom.facets[f].is_face) continue;
    double best = kInf;
    for (std::uint32_t t = 0; t < dom.facets[f].tris.size(); ++t) {
      Box qb;
      for (std::uint32_t v : dom.facets[f].tris[t].v) qb.add(pts[v]);
      best = nearest(qb, kNoSeg, f, t, best);
    }
    out.facet_d[f] = std::sqrt(best / 2);
  }
  return out;
}

struct UnrelatedDistance::Impl {
  PlcDomain dom;
  Primitives all;
  Bvh bvh;
  // The nearest primitive to p that `unrelated` accepts.
  template <class Unrelated>
  double nearest(const Point& p, Unrelated&& unrelated) const {
    const std::vector<Point>& pts = dom.plc.points;
    Box qb;
    qb.add(p);
    double best = std::numeric_limits<double>::infinity();
    bvh.branch_and_bound([&](const Box& b) { return box_gap2(qb, b); }, [&] { return best; },
                         [&](std::uint32_t j) {
                           const Prim& o = all.prims[j];
                           if (!unrelated(o)) return;
                           double d2 = best;
                           switch (o.kind) {
                             case ComponentKind::Vertex:
                               d2 = dist2_point_point(p, pts[o.id]);
                               break;
                             case ComponentKind::Segment: {
                               const DomainSegment& r = dom.segments[o.id];
                               d2 = dist2_point_segment(p, pts[r.a], pts[r.b]);
                               break;
                             }
                             case ComponentKind::Facet: {
                               const auto& v = dom.facets[o.id].tris[o.tri].v;
                               d2 = dist2_point_triangle(p, pts[v[0]], pts[v[1]], pts[v[2]]);
                               break;
                             }
                           }
                           best = std::min(best, d2);
                         });
    return std::sqrt(best);
  }
};

UnrelatedDistance::UnrelatedDistance(const PlcDomain& dom) : impl_(std::make_unique<Impl>()) {
  impl_->dom = dom;
  impl_->all = primitives(impl_->dom);
  impl_->bvh = Bvh(impl_->all.boxes);
}

UnrelatedDistance::~UnrelatedDistance() = default;

double UnrelatedDistance::segment_size_at(std::uint32_t s, const Point& p) const {
  double dist = to_segment_unrelated(s, p);
  for (const std::uint32_t f : impl_->dom.segments[s].facets)
    if (impl_->dom.facets[f].is_face) dist = std::min(dist, to_facet_unrelated(f, p));
  return (std::numbers::sqrt2 - 1) * dist;
}

double UnrelatedDistance::facet_size_at(std::uint32_t f, const Point& p) const {
  return to_facet_unrelated(f, p) / std::numbers::sqrt2;
}

double UnrelatedDistance::to_segment_unrelated(std::uint32_t s, const Point& p) const {
  const PlcDomain& dom = impl_->dom;
  const DomainSegment& q = dom.segments[s];
  return impl_->nearest(p, [&](const Prim& o) {
    switch (o.kind) {
      case ComponentKind::Vertex: return o.id != q.a && o.id != q.b;
      case ComponentKind::Segment: return !segments_share(q, dom.segments[o.id]);
      case ComponentKind::Facet: return !facet_has_segment_end(dom, o.id, q);
    }
    return false;
  });
}

double UnrelatedDistance::to_facet_unrelated(std::uint32_t f, const Point& p) const {
  const PlcDomain& dom = impl_->dom;
  return impl_->nearest(p, [&](const Prim& o) {
    switch (o.kind) {
      case ComponentKind::Vertex: return !facet_has(dom, f, o.id);
      case ComponentKind::Segment: return !facet_has_segment_end(dom, f, dom.segments[o.id]);
      case ComponentKind::Facet: return o.id != f && !facets_share(dom, f, o.id);
    }
    return false;
  });
}

LocalFeatureSizes local_feature_sizes_brute(const PlcDomain& dom) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::vector<Prim> prims = primitives(dom).prims;
  LocalFeatureSizes out;
  out.segment_d.assign(dom.segments.size(), kInf);
  out.facet_d.assign(dom.facets.size(), kInf);
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    double best = kInf;
    for (const Prim& o : prims) best = std::min(best, unrelated_dist2(dom, s, 0, 0, o));
    out.segment_d[s] = std::sqrt(best / 2);
  }
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    if (!dom.facets[f].is_face) continue;
    double best = kInf;
    for (std::uint32_t t = 0; t < dom.facets[f].tris.size(); ++t)
      for (const Prim& o : prims) best = std::min(best, unrelated_dist2(dom, kNoSeg, f, t, o));
    out.facet_d[f] = std::sqrt(best / 2);
  }
  return out;
}

FeatureSize feature_size_brute(const PlcDomain& dom) {
  const std::vector<Point>& pts = dom.plc.points;
  std::vector<std::uint32_t> verts, faces;
  for (std::uint32_t v = 0; v < pts.size(); ++v) verts.push_back(v);
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
    if (dom.facets[f].is_face) faces.push_back(f);
  const auto V = ComponentKind::Vertex, S = ComponentKind::Segment, F = ComponentKind::Facet;
  Best best;
  auto tri = [&](const FacetTri& t, int i) -> const Point& { return pts[t.v[i]]; };
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const Point& p = pts[verts[i]];
    for (std::size_t j = i + 1; j < verts.size(); ++j)
      best.offer(dist2_point_point(p, pts[verts[j]]), V, verts[i], V, verts[j]);
    for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
      const DomainSegment& S1 = dom.segments[s];
      if (S1.a != verts[i] && S1.b != verts[i])
        best.offer(dist2_point_segment(p, pts[S1.a], pts[S1.b]), V, verts[i], S, s);
    }
    for (std::uint32_t f : faces) {
      if (facet_has(dom, f, verts[i])) continue;
      for (const FacetTri& t : dom.facets[f].tris)
        best.offer(dist2_point_triangle(p, tri(t, 0), tri(t, 1), tri(t, 2)), V, verts[i], F, f);
    }
  }
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s) {
    const DomainSegment& A = dom.segments[s];
    for (std::uint32_t u = s + 1; u < dom.segments.size(); ++u) {
      const DomainSegment& B = dom.segments[u];
      if (!segments_share(A, B))
        best.offer(dist2_segment_segment(pts[A.a], pts[A.b], pts[B.a], pts[B.b]), S, s, S, u);
    }
    for (std::uint32_t f : faces) {
      if (facet_has(dom, f, A.a) || facet_has(dom, f, A.b)) continue;
      for (const FacetTri& t : dom.facets[f].tris)
        best.offer(dist2_segment_triangle(pts[A.a], pts[A.b], tri(t, 0), tri(t, 1), tri(t, 2)),
                   S, s, F, f);
    }
  }
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      const DomainFacet &A = dom.facets[faces[i]], &B = dom.facets[faces[j]];
      bool share = false;
      for (std::uint32_t v : A.vertices) share = share || facet_has(dom, faces[j], v);
      if (share) continue;
      for (const FacetTri& s : A.tris)
        for (const FacetTri& t : B.tris)
          best.offer(dist2_triangle_triangle(pts[s.v[0]], pts[s.v[1]], pts[s.v[2]], pts[t.v[0]],
                                             pts[t.v[1]], pts[t.v[2]]),
                     F, faces[i], F, faces[j]);
    }
  return best.result();
}

namespace {

using Vec = std::array<double, 3>;
Vec sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

double dist2_point_point(const Point& p, const Point& q) {
  const Vec d = sub(p, q);
  return dot(d, d);
}

double dist2_point_segment(const Point& p, const Point& a, const Point& b) {
  const Vec ab = sub(b, a), ap = sub(p, a);
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(ap, ab) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec d{ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
  return dot(d, d);
}

double dist2_point_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  // The foot of the perpendicular lies in the triangle iff p is on the inner side of all
  // three edge planes; otherwise the nearest point is on an edge.
  const Vec n = cross(sub(b, a), sub(c, a));
  const double nn = dot(n, n);
  if (nn > 0) {
    const bool in = dot(cross(sub(b, a), sub(p, a)), n) >= 0 &&
                    dot(cross(sub(c, b), sub(p, b)), n) >= 0 &&
                    dot(cross(sub(a, c), sub(p, c)), n) >= 0;
    if (in) {
      const double h = dot(sub(p, a), n);
      return h * h / nn;
    }
  }
  return std::min({dist2_point_segment(p, a, b), dist2_point_segment(p, b, c),
                   dist2_point_segment(p, c, a)});
}

double dist2_segment_segment(const Point& p, const Point& q, const Point& r, const Point& s) {
  // The squared distance between p + x(q-p) and r + y(s-r) is convex on [0,1]^2: its
  // minimum is at the interior critical point (the closest points of the two lines, when
  // not parallel) or on the boundary of the square (an endpoint against a segment).
  double best = std::min({dist2_point_segment(p, r, s), dist2_point_segment(q, r, s),
                          dist2_point_segment(r, p, q), dist2_point_segment(s, p, q)});
  const Vec d1 = sub(q, p), d2 = sub(s, r), r0 = sub(p, r);
  const double a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2);
  const double c = dot(d1, r0), f = dot(d2, r0);
  const double denom = a * e - b * b;
  if (denom > 1e-14 * a * e) {
    const double x = (b * f - c * e) / denom, y = (a * f - b * c) / denom;
    if (x > 0 && x < 1 && y > 0 && y < 1) {
      const Vec d{r0[0] + x * d1[0] - y * d2[0], r0[1] + x * d1[1] - y * d2[1],
                  r0[2] + x * d1[2] - y * d2[2]};
      best = std::min(best, dot(d, d));
    }
  }
  return best;
}

double dist2_segment_triangle(const Point& p, const Point& q, const Point& a, const Point& b,
                              const Point& c) {
  return std::min({dist2_point_triangle(p, a, b, c), dist2_point_triangle(q, a, b, c),
                   dist2_segment_segment(p, q, a, b), dist2_segment_segment(p, q, b, c),
                   dist2_segment_segment(p, q, c, a)});
}

double dist2_triangle_triangle(const Point& a, const Point& b, const Point& c, const Point& d,
                               const Point& e, const Point& f) {
  return std::min({dist2_segment_triangle(a, b, d, e, f), dist2_segment_triangle(b, c, d, e, f),
                   dist2_segment_triangle(c, a, d, e, f), dist2_segment_triangle(d, e, a, b, c),
                   dist2_segment_triangle(e, f, a, b, c), dist2_segment_triangle(f, d, a, b, c)});
}

}  // namespace pdr::domain
