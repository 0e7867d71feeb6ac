// The output mesh listed by the ranks; see par/mesh_parts.hpp.
#include "par/mesh_parts.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geom/encroach.hpp"
#include "mesh/huge_pages.hpp"
#include "mesh/tables.hpp"
#include "par/refinement_rules.hpp"

namespace pdr::par {
namespace {

// Vertex v of s was made in the phase on ∂Ω.
bool made_on_d(const Submesh& s, VertexId v) {
  // The tag first: a byte a vertex, where the global id is eight (most vertices are not
  // on ∂Ω, and their global ids are then not read).
  return RefinementRules::made_on_d(s.tag(v)) && made_vertex(s.gid(v)).has_value();
}

// The facet of face f of real tet t (its label), or kNoLabel.
std::uint32_t face_facet(const Submesh& s, TetId t, int f) {
  const VertexId* v = s.store().vertices(t);
  const auto& fv = tables::kFaceVertex[f];
  const refine::MaybeId facet = RefinementRules::subfacet(s, v[fv[0]], v[fv[1]], v[fv[2]]);
  return facet ? *facet : kNoLabel;
}

// An element of D of real tet t is encroached (strictly) by a vertex of t.
bool encroached_in(const Submesh& s, TetId t) {
  const VertexId* v = s.store().vertices(t);
  const auto pts = s.points();
  for (const auto& e : tables::kEdgeVertex) {
    const VertexId a = v[e[0]], b = v[e[1]];
    if (!RefinementRules::subsegment(s, a, b)) continue;
    for (int k = 0; k < 4; ++k)
      if (k != e[0] && k != e[1] && in_diametral_ball(pts[a], pts[b], pts[v[k]]) == Sign::Positive)
        return true;
  }
  for (int f = 0; f < 4; ++f) {
    if (face_facet(s, t, f) == kNoLabel) continue;
    const auto& fv = tables::kFaceVertex[f];
    if (in_equatorial_ball(pts[v[fv[0]]], pts[v[fv[1]]], pts[v[fv[2]]], pts[v[f]]) == Sign::Positive)
      return true;
  }
  return false;
}

}  // namespace

VertexNumbers::VertexNumbers(std::size_t m0_vertices, std::span<const std::uint64_t> made,
                             int ranks)
    : n0_(m0_vertices), made_(made.begin(), made.end()), first_(made.size(), 0) {
  std::size_t next = n0_;
  for (int r = 0; r < ranks; ++r)
    for (std::size_t k = static_cast<std::size_t>(r); k < made_.size(); k += static_cast<std::size_t>(ranks)) {
      first_[k] = next;
      next += made_[k];
    }
  if (next > kGhostVertex) throw std::length_error("mesh parts: more vertices than 32-bit ids");
  total_ = next;
}

std::uint32_t VertexNumbers::operator()(Gid g) const {
  if (g < n0_) return static_cast<std::uint32_t>(g);
  const auto m = made_vertex(g);
  if (!m || m->maker >= made_.size() || m->serial >= made_[m->maker])
    throw std::logic_error("mesh parts: vertex " + std::to_string(g) + " is no vertex of the run");
  return static_cast<std::uint32_t>(first_[m->maker] + m->serial);
}

bool part_is_final(const Submesh& s) {
  const TetStore& st = s.store();
  for (TetId t = 0; t < st.slots(); ++t) {
    if (!st.is_alive(t) || st.is_proxy(t) || st.is_ghost(t)) continue;
    if (s.deferred(t)) return false;
    const VertexId* v = st.vertices(t);
    if ((made_on_d(s, v[0]) || made_on_d(s, v[1]) || made_on_d(s, v[2]) || made_on_d(s, v[3])) &&
        encroached_in(s, t))
      return false;
  }
  return true;
}

void add_part(const Submesh& s, const VertexNumbers& num, std::span<const int> facet_markers,
              MeshData& out, refine::QualityRange& q) {
  const TetStore& st = s.store();
  const auto pts = s.points();
  reserve_huge(out.tets, out.tets.size() + s.real_tets());
  // Each vertex's number once (a tet's four would each decode its global id).
  std::vector<std::uint32_t> number(pts.size());
  for (VertexId v = 0; v < pts.size(); ++v) number[v] = num(s.gid(v));
  for (TetId t = 0; t < st.slots(); ++t) {
    if (constexpr TetId kAhead = 8; t + kAhead < st.slots())  // scattered points, meanwhile
      for (int k = 0; k < 4; ++k)
        if (const VertexId w = st.vertex(t + kAhead, k); w < pts.size()) __builtin_prefetch(&pts[w]);
    if (!st.is_alive(t) || st.is_proxy(t) || st.is_ghost(t) || !s.inside(t)) continue;
    const VertexId* v = st.vertices(t);
    q.add(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]);
    const Tet n{number[v[0]], number[v[1]], number[v[2]], number[v[3]]};
    out.tets.push_back(n);
    if (!RefinementRules::may_have_subfacet(s, v)) continue;  // most tets: no face to look up
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t facet = face_facet(s, t, f);
      if (facet == kNoLabel) continue;
      const auto& fv = tables::kFaceVertex[f];
      out.faces.push_back({n[static_cast<std::size_t>(fv[0])], n[static_cast<std::size_t>(fv[1])],
                           n[static_cast<std::size_t>(fv[2])]});
      out.face_markers.push_back(facet < facet_markers.size() ? facet_markers[facet] : 0);
    }
  }
}

namespace {

// The values that occur an odd number of times in `v`, sorted (v is sorted in place).
std::vector<std::uint64_t> odd_ones(std::vector<std::uint64_t>& v) {
  std::sort(v.begin(), v.end());
  std::vector<std::uint64_t> odd;
  for (std::size_t i = 0; i < v.size();) {
    std::size_t j = i;
    while (j < v.size() && v[j] == v[i]) ++j;
    if ((j - i) % 2 != 0) odd.push_back(v[i]);
    i = j;
  }
  return odd;
}

}  // namespace

std::vector<std::uint64_t> odd_edges(std::span<const Tri> faces) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * faces.size());
  for (const Tri& f : faces)
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = f[static_cast<std::size_t>(i)], b = f[static_cast<std::size_t>((i + 1) % 3)];
      edges.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  return odd_ones(edges);
}

bool edges_pair_up(std::vector<std::uint64_t> edges) { return odd_ones(edges).empty(); }

bool surface_closed(std::span<const Tri> faces) { return odd_edges(faces).empty(); }

}  // namespace pdr::par
