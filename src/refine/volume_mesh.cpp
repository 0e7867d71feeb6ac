// VolumeMesh queries (paper §1.1); see refine/volume_mesh.hpp.
#include "refine/volume_mesh.hpp"

#include <algorithm>
#include <stdexcept>

namespace pdr::refine {

void VolumeMesh::map_vertex(VertexId v, std::uint32_t surf_vertex) {
  d2s.push_back(surf_vertex);
  VertexClass k = VertexClass::Interior;
  if (surf_vertex != kNone) {
    if (s2d.size() <= surf_vertex) s2d.resize(surf_vertex + 1, kNone);
    s2d[surf_vertex] = v;
    k = surf.home(surf_vertex).kind == HomeKind::Facet ? VertexClass::Facet
                                                       : VertexClass::Segment;
  }
  vclass.push_back(k);
}

void VolumeMesh::remap_vertex(VertexId v, std::uint32_t surf_vertex) {
  if (v >= d2s.size() || d2s[v] != kNone)
    throw std::logic_error("volume: remap of a vertex that is not off the surface");
  d2s[v] = surf_vertex;
  if (s2d.size() <= surf_vertex) s2d.resize(surf_vertex + 1, kNone);
  s2d[surf_vertex] = v;
  vclass[v] = surf.home(surf_vertex).kind == HomeKind::Facet ? VertexClass::Facet
                                                             : VertexClass::Segment;
}

MaybeId VolumeMesh::find_subfacet(VertexId a, VertexId b, VertexId c) const {
  const std::uint32_t sa = d2s[a], sb = d2s[b], sc = d2s[c];
  // A vertex inside a facet is in that facet's subfacets only: with two inside different
  // facets there is none (most faces of a thin plate, whose tets span its two sides).
  std::uint32_t facet = kNone;
  for (const VertexId x : {a, b, c}) {
    if (vclass[x] != VertexClass::Facet) continue;
    const std::uint32_t f = surf.home(d2s[x]).id;
    if (facet != kNone && f != facet) return {};
    facet = f;
  }
  const std::optional<std::uint32_t> t = surf.find_subfacet(sa, sb, sc);
  return t ? MaybeId(*t) : MaybeId();
}

MaybeId VolumeMesh::find_subsegment(VertexId a, VertexId b) const {
  const std::optional<std::uint32_t> s = surf.find_subsegment(d2s[a], d2s[b]);
  return s ? MaybeId(*s) : MaybeId();
}

std::size_t VolumeMesh::inside_tets() const {
  std::size_t n = 0;
  const TetStore& s = dt.store();
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t) && !s.is_ghost(t) && is_inside(t)) ++n;
  return n;
}

VertexId commit_point(VolumeMesh& m, const Cavity& c, std::uint32_t surf_vertex,
                      std::vector<TetId>& star) {
  const VertexId v = m.dt.add_point(c.point);
  m.dt.commit(c, v);
  m.map_vertex(v, surf_vertex);
  const TetStore& s = m.dt.store();
  if (m.inside.size() < s.slots()) m.inside.resize(s.slots() + s.slots() / 2, 0);
  // New tet i holds v at the slot of boundary face i, glued there to the old neighbour
  // (delaunay.hpp last_created).
  const std::span<const TetId> made = m.dt.last_created();
  star.assign(made.begin(), made.end());
  for (std::size_t i = 0; i < made.size(); ++i) {
    const TetId t = made[i];
    if (s.is_ghost(t)) {
      m.inside[t] = 0;
      continue;
    }
    const int k = face_of(c.boundary[i]);
    const TetId n = s.neighbour(t, k);
    const bool flip = m.face_flips(t, k);
    m.inside[t] = static_cast<std::uint8_t>((s.is_ghost(n) ? 0 : m.inside[n]) ^ (flip ? 1 : 0));
  }
  return v;
}

void vertex_star(const VolumeMesh& m, VertexId v, TetId start, std::vector<TetId>& star) {
  const TetStore& s = m.dt.store();
  // Tets already in the star, by slot, stamped with this call's epoch: linear in the star
  // (a search of the list made a vertex of degree k cost k^2: a fine surface patch next to
  // a coarse vertex spent most of a run here).
  thread_local std::vector<std::uint32_t> seen;
  thread_local std::uint32_t epoch = 0;
  if (seen.size() < s.slots()) seen.resize(s.slots(), 0);
  if (++epoch == 0) {
    std::fill(seen.begin(), seen.end(), 0);
    epoch = 1;
  }
  star.assign(1, start);
  seen[start] = epoch;
  // The tets of the star are adjacent across their faces that hold v.
  for (std::size_t i = 0; i < star.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      if (s.vertex(star[i], k) == v) continue;
      const TetId n = s.neighbour(star[i], k);
      if (seen[n] == epoch) continue;
      seen[n] = epoch;
      star.push_back(n);
    }
}

}  // namespace pdr::refine
