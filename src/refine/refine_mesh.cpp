// VolumeMesh queries (paper §1.1); see refine_mesh.hpp.
#include "refine/refine_mesh.hpp"

#include "mesh/tables.hpp"

namespace pdr::refine {

std::optional<std::uint32_t> VolumeMesh::subfacet(VertexId a, VertexId b, VertexId c) const {
  if (a >= d2s.size() || b >= d2s.size() || c >= d2s.size()) return std::nullopt;
  const std::uint32_t sa = d2s[a], sb = d2s[b], sc = d2s[c];
  if (sa == kNone || sb == kNone || sc == kNone) return std::nullopt;
  // Every subfacet listed at sa contains sa; one with the edge {sb, sc} is {sa, sb, sc}.
  for (const std::uint32_t t : surf.vertex_subfacets(sa)) {
    const Subfacet& f = surf.subfacet(t);
    if (f.alive && edge_index(f, sb, sc) >= 0) return t;
  }
  return std::nullopt;
}

std::optional<std::uint32_t> VolumeMesh::subsegment(VertexId a, VertexId b) const {
  if (a >= d2s.size() || b >= d2s.size()) return std::nullopt;
  const std::uint32_t sa = d2s[a], sb = d2s[b];
  if (sa == kNone || sb == kNone) return std::nullopt;
  return surf.find_subsegment(sa, sb);
}

std::optional<std::uint32_t> VolumeMesh::face_subfacet(TetId t, int f) const {
  const TetStore& s = dt.store();
  const VertexId a = s.vertex(t, tables::kFaceVertex[f][0]);
  const VertexId b = s.vertex(t, tables::kFaceVertex[f][1]);
  const VertexId c = s.vertex(t, tables::kFaceVertex[f][2]);
  if (a == kGhostVertex || b == kGhostVertex || c == kGhostVertex) return std::nullopt;
  return subfacet(a, b, c);
}

std::size_t VolumeMesh::inside_tets() const {
  std::size_t n = 0;
  const TetStore& s = dt.store();
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t) && !s.is_ghost(t) && is_inside(t)) ++n;
  return n;
}

void star_of(const TetStore& s, VertexId v, TetId start, std::vector<TetId>& out,
             std::vector<std::uint8_t>& mark) {
  out.clear();
  if (mark.size() < s.slots()) mark.resize(s.slots(), 0);
  out.push_back(start);
  mark[start] = 1;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const TetId t = out[i];
    for (int f = 0; f < 4; ++f) {
      if (s.vertex(t, f) == v) continue;  // the face opposite v leaves the star
      const TetId n = s.neighbour(t, f);
      if (!mark[n]) {
        mark[n] = 1;
        out.push_back(n);
      }
    }
  }
  for (const TetId t : out) mark[t] = 0;
}

VertexId commit_point(VolumeMesh& m, const Cavity& c, std::uint32_t surf_vertex,
                      std::vector<TetId>& star, std::vector<std::uint8_t>& mark) {
  const VertexId v = m.dt.add_point(c.point);
  const TetId t0 = m.dt.commit(c, v);
  m.d2s.push_back(surf_vertex);
  if (surf_vertex != kNone) {
    if (m.s2d.size() <= surf_vertex) m.s2d.resize(surf_vertex + 1, kNone);
    m.s2d[surf_vertex] = v;
  }
  const TetStore& s = m.dt.store();
  if (m.inside.size() < s.slots()) m.inside.resize(s.slots() + s.slots() / 2, 0);
  star_of(s, v, t0, star, mark);
  for (const TetId t : star) {
    if (s.is_ghost(t)) {
      m.inside[t] = 0;
      continue;
    }
    int k = 0;
    while (s.vertex(t, k) != v) ++k;
    const TetId n = s.neighbour(t, k);
    const bool flip = m.face_subfacet(t, k).has_value();
    m.inside[t] = static_cast<std::uint8_t>((s.is_ghost(n) ? 0 : m.inside[n]) ^ (flip ? 1 : 0));
  }
  return v;
}

}  // namespace pdr::refine
