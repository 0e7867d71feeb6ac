// The remembering stochastic visibility walk (walk.hpp).
#include "delaunay/walk.hpp"

#include "delaunay/semistatic.hpp"
#include "geom/predicates.hpp"
#include "mesh/tables.hpp"

namespace pdr {

namespace {

// orient3d(a,b,c,p) > 0, with the inlined semi-static filter first (semistatic.hpp).
inline bool beyond(const Point& a, const Point& b, const Point& c, const Point& p) {
  const Filtered quick = semistatic::orient3d(a.data(), b.data(), c.data(), p.data());
  if (quick != Filtered::Unsure) return quick == Filtered::Positive;
  return orient3d(a, b, c, p) == Sign::Positive;
}

bool same_point(const Point& a, const Point& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

}  // namespace

Location locate(const TetStore& s, std::span<const Point> pts, const Point& p, TetId start,
                WalkRng& rng) {
  Location out;
  TetId t = start;
  int entered = -1;  // face of t we came through: p is known not to lie beyond it
  if (s.is_ghost(t)) {
    const VertexId* v = s.vertices(t);
    if (beyond(pts[v[0]], pts[v[1]], pts[v[2]], p)) {
      out.kind = Location::Kind::OutsideHull;
      out.tet = t;
      out.steps = 1;
      return out;
    }
    const HalfFace h = s.opposite(t, 3);
    t = tet_of(h);
    entered = face_of(h);
    if (s.is_proxy(t)) {  // the tet behind the hull face lives in another submesh
      out.kind = Location::Kind::Remote;
      out.tet = t;
      out.steps = 1;
      return out;
    }
  }
  std::uint32_t steps = 1;
  for (;;) {
    const VertexId* v = s.vertices(t);
    // The next tet is one of the neighbours: start loading them while the tests run.
    for (int f = 0; f < 4; ++f) s.prefetch(s.neighbour(t, f));
    const int first = static_cast<int>(rng.next() & 3u);
    int crossed = -1;
    for (int k = 0; k < 4; ++k) {
      const int f = (first + k) & 3;
      if (f == entered) continue;
      const auto& fv = tables::kFaceVertex[f];
      if (beyond(pts[v[fv[0]]], pts[v[fv[1]]], pts[v[fv[2]]], p)) {
        crossed = f;
        break;
      }
    }
    if (crossed < 0) break;
    const HalfFace h = s.opposite(t, crossed);
    t = tet_of(h);
    entered = face_of(h);
    ++steps;
    if (s.vertex(t, 3) >= kFirstSpecialVertex) [[unlikely]] {
      out.kind = s.is_ghost(t) ? Location::Kind::OutsideHull : Location::Kind::Remote;
      out.tet = t;
      out.steps = steps;
      return out;
    }
  }
  out.tet = t;
  out.steps = steps;
  const VertexId* v = s.vertices(t);
  for (int i = 0; i < 4; ++i) {
    if (same_point(pts[v[i]], p)) {
      out.kind = Location::Kind::OnVertex;
      out.vertex = v[i];
      return out;
    }
  }
  out.kind = Location::Kind::InTet;
  return out;
}

}  // namespace pdr
