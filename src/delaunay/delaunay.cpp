// Delaunay: the first tet, and insertion as locate + cavity + commit (delaunay.hpp).
#include "delaunay/delaunay.hpp"

#include <cassert>
#include <stdexcept>
#include <utility>

#include "geom/predicates.hpp"
#include "mesh/tables.hpp"

namespace pdr {

std::size_t Delaunay::count_finite_tets() const {
  std::size_t n = 0;
  for (TetId t = 0; t < store_.slots(); ++t)
    if (store_.is_alive(t) && !store_.is_ghost(t)) ++n;
  return n;
}

void Delaunay::init(VertexId a, VertexId b, VertexId c, VertexId d) {
  assert(empty());
  store_.clear();
  const Sign o = orient3d(points_[a], points_[b], points_[c], points_[d]);
  // Always checked (O(1)): a flat first tet would corrupt everything after it.
  if (o == Sign::Zero)
    throw std::invalid_argument("Delaunay::init: the four points are coplanar");
  if (o == Sign::Negative) std::swap(a, b);
  const TetId t = store_.create(a, b, c, d);
  // Ghost tet across face f: the face's outward orientation, then the ghost (tables.hpp).
  TetId ghost[4];
  for (int f = 0; f < 4; ++f) {
    const auto& fv = tables::kFaceVertex[f];
    ghost[f] = store_.create(store_.vertex(t, fv[0]), store_.vertex(t, fv[1]),
                             store_.vertex(t, fv[2]), kGhostVertex);
    store_.link(half_face(t, f), half_face(ghost[f], 3));
  }
  // Ghost tets meet each other across faces (edge, ghost): pair them by directed edges;
  // ghost face j (j < 3) holds the ghost and the hull edge opposite slot j.
  for (int f = 0; f < 4; ++f) {
    for (int j = 0; j < 3; ++j) {
      if (store_.opposite(ghost[f], j) != kNoHalfFace) continue;
      const VertexId x = store_.vertex(ghost[f], (j + 1) % 3);
      const VertexId y = store_.vertex(ghost[f], (j + 2) % 3);
      for (int g = 0; g < 4; ++g) {
        if (g == f) continue;
        for (int k = 0; k < 3; ++k) {
          if (store_.vertex(ghost[g], (k + 1) % 3) == y &&
              store_.vertex(ghost[g], (k + 2) % 3) == x)
            store_.link(half_face(ghost[f], j), half_face(ghost[g], k));
        }
      }
    }
  }
  last_ = t;
}

Location Delaunay::locate(const Point& p, TetId hint) {
  if (hint == kNoTet) hint = last_;
  return pdr::locate(store_, points_, p, hint, rng_);
}

InsertResult Delaunay::commit(const Cavity& c) {
  const VertexId v = add_point(c.point);
  return {Outcome::Inserted, v, commit(c, v)};
}

TetId Delaunay::commit(const Cavity& c, VertexId v) {
  assert(points_[v] == c.point);
  stats_.conflict_tets += c.conflict.size();
  stats_.boundary_faces += c.boundary.size();
  ++stats_.inserted;
  last_ = committer_.commit(store_, c, v, points_.size());
#ifndef NDEBUG
  // Debug level: the new tets are positive (star-shapedness of the cavity, §1.2).
  for (TetId t : committer_.created()) {
    const VertexId* w = store_.vertices(t);
    if (w[3] != kGhostVertex)
      assert(orient3d(points_[w[0]], points_[w[1]], points_[w[2]], points_[w[3]]) ==
             Sign::Positive);
  }
#endif
  return last_;
}

InsertResult Delaunay::insert(const Point& p, TetId hint) {
  const Location loc = locate(p, hint);
  stats_.walk_steps += loc.steps;
  if (loc.kind == Location::Kind::OnVertex) {
    ++stats_.duplicates;
    return {Outcome::Duplicate, loc.vertex, loc.tet};
  }
  build_cavity(p, loc.tet, cavity_);
  return commit(cavity_);
}

InsertResult Delaunay::insert(VertexId v, TetId hint) {
  const Point& p = points_[v];
  const Location loc = locate(p, hint);
  stats_.walk_steps += loc.steps;
  if (loc.kind == Location::Kind::OnVertex) {
    ++stats_.duplicates;
    return {Outcome::Duplicate, loc.vertex, loc.tet};
  }
  build_cavity(p, loc.tet, cavity_);
  return {Outcome::Inserted, v, commit(cavity_, v)};
}

void Delaunay::adopt(std::vector<Point> points, TetStore store) {
  points_ = std::move(points);
  store_ = std::move(store);
  last_ = kNoTet;
  const auto newest = static_cast<VertexId>(points_.size() - 1);
  for (TetId t = static_cast<TetId>(store_.slots()); t-- > 0 && last_ == kNoTet;)
    if (store_.is_alive(t) && !store_.is_ghost(t))
      for (int i = 0; i < 4; ++i)
        if (store_.vertex(t, i) == newest) last_ = t;
}

}  // namespace pdr
