// The whole mesh from the submeshes' tets; see par/assembly.hpp.
#include "par/assembly.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "mesh/tables.hpp"
#include "refine/conformity.hpp"
#include "refine/guard.hpp"
#include "surface/cavity.hpp"
#include "surface/locate.hpp"
#include "surface/split.hpp"

namespace pdr::par {

Piece piece_of(const Submesh& s) {
  const TetStore& st = s.store();
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::vector<std::uint32_t> index(st.slots(), kNone);  // slot -> index in the piece
  std::vector<std::uint32_t> vindex(s.points().size(), kNone);
  Piece p;
  p.tets.reserve(st.live());
  for (TetId t = 0; t < st.slots(); ++t) {
    if (!st.is_alive(t) || st.is_proxy(t)) continue;
    index[t] = static_cast<std::uint32_t>(p.tets.size());
    PieceTet& x = p.tets.emplace_back();
    for (int i = 0; i < 4; ++i) {
      const VertexId v = st.vertex(t, i);
      if (v == kGhostVertex) {
        x.v[static_cast<std::size_t>(i)] = kGhostVertex;
        continue;
      }
      if (vindex[v] == kNone) {
        vindex[v] = static_cast<std::uint32_t>(p.vertices.size());
        p.vertices.push_back({s.gid(v), s.points()[v], s.tag(v)});
      }
      x.v[static_cast<std::size_t>(i)] = vindex[v];
    }
    x.inside = static_cast<std::uint8_t>((s.inside(t) ? 1 : 0) | (s.deferred(t) ? 2 : 0));
  }
  for (TetId t = 0; t < st.slots(); ++t) {
    if (index[t] == kNone) continue;
    PieceTet& x = p.tets[index[t]];
    for (int f = 0; f < 4; ++f) {
      const TetId u = st.neighbour(t, f);
      x.across[static_cast<std::size_t>(f)] =
          st.is_proxy(u) ? kAcrossProxy
                         : 4 * index[u] + static_cast<std::uint32_t>(st.back_face(t, f));
    }
  }
  return p;
}

void put_piece(WireWriter& w, const Piece& p) { w.put_vector(p.vertices).put_vector(p.tets); }

Piece get_piece(WireReader& r) {
  Piece p;
  p.vertices = r.get_vector<VertexRecord>();
  p.tets = r.get_vector<PieceTet>();
  return p;
}

Assembly::Assembly(const refine::VolumeMesh& m, std::size_t tets)
    : n0_(m.dt.num_points()), points_(m.dt.points().begin(), m.dt.points().end()) {
  st_.reserve(tets);
  inside_.reserve(tets);
}

VertexId* Assembly::fresh_slot(Gid g) {
  const auto m = made_vertex(g);
  if (!m) throw std::logic_error("assembly: vertex " + std::to_string(g) + " is neither M_o's nor made in the phase");
  if (fresh_.size() <= m->maker) fresh_.resize(m->maker + 1);
  std::vector<VertexId>& by = fresh_[m->maker];
  if (by.size() <= m->serial) by.resize(m->serial + m->serial / 2 + 64, kNoVertex);
  return &by[m->serial];
}

VertexId Assembly::vertex(Gid g) const {
  if (g < n0_) return static_cast<VertexId>(g);
  const auto m = made_vertex(g);
  const VertexId v = m && m->maker < fresh_.size() && m->serial < fresh_[m->maker].size()
                         ? fresh_[m->maker][m->serial]
                         : kNoVertex;
  if (v == kNoVertex) throw std::logic_error("assembly: vertex " + std::to_string(g) + " is in no piece");
  return v;
}

void Assembly::add(const Piece& p) {
  vmap_.clear();
  for (const VertexRecord& v : p.vertices) {
    if (v.gid < n0_) {
      vmap_.push_back(static_cast<VertexId>(v.gid));
      continue;
    }
    VertexId* at = fresh_slot(v.gid);
    if (*at == kNoVertex) {
      *at = static_cast<VertexId>(points_.size());
      points_.push_back(v.p);
      fresh_tet_.push_back(kNoTet);
    }
    vmap_.push_back(*at);
  }
  const auto vertex = [&](std::uint32_t i) {
    if (i == kGhostVertex) return kGhostVertex;
    if (i >= vmap_.size()) throw std::logic_error("assembly: a piece's tet names no vertex of it");
    return vmap_[i];
  };
  ids_.clear();
  for (const PieceTet& x : p.tets) {
    ids_.push_back(st_.create(vertex(x.v[0]), vertex(x.v[1]), vertex(x.v[2]), vertex(x.v[3])));
    for (const std::uint32_t i : x.v)
      if (i != kGhostVertex && vmap_[i] >= n0_) fresh_tet_[vmap_[i] - n0_] = ids_.back();
    if (inside_.size() <= ids_.back()) inside_.resize(ids_.back() + 1, 0);
    inside_[ids_.back()] = x.inside & 1;
    if ((x.inside & 2) != 0) out_.deferred.push_back(ids_.back());
  }
  for (std::size_t j = 0; j < p.tets.size(); ++j)
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t a = p.tets[j].across[static_cast<std::size_t>(f)];
      if (a != kAcrossProxy) {
        st_.set_opposite(half_face(ids_[j], f), half_face(ids_.at(a >> 2), static_cast<int>(a & 3)));
        continue;
      }
      const auto& fv = tables::kFaceVertex[f];
      OpenFace o{{st_.vertex(ids_[j], fv[0]), st_.vertex(ids_[j], fv[1]), st_.vertex(ids_[j], fv[2])},
                 half_face(ids_[j], f)};
      std::sort(o.key.begin(), o.key.end());
      open_.push_back(o);
    }
}

Assembled Assembly::finish(refine::VolumeMesh& m, std::span<const SurfaceStep> steps) {
  if (m.dt.num_points() != n0_) throw std::logic_error("assembly: the mesh changed meanwhile");
  // Faces between pieces: each exactly twice.
  std::sort(open_.begin(), open_.end(),
            [](const OpenFace& a, const OpenFace& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < open_.size(); i += 2) {
    if (i + 1 == open_.size() || open_[i].key != open_[i + 1].key ||
        (i + 2 < open_.size() && open_[i + 2].key == open_[i].key))
      throw std::logic_error("assembly: a face between submeshes (vertices " +
                             std::to_string(open_[i].key[0]) + ", " +
                             std::to_string(open_[i].key[1]) + ", " +
                             std::to_string(open_[i].key[2]) + ") is not shared by two tets");
    st_.link(open_[i].h, open_[i + 1].h);
  }
  std::vector<OpenFace>().swap(open_);
  out_.added = points_.size() - n0_;
  m.dt.adopt(std::move(points_), std::move(st_));
  m.inside = std::move(inside_);
  for (std::size_t v = n0_; v < n0_ + out_.added; ++v)
    m.map_vertex(static_cast<VertexId>(v), refine::kNone);
  out_.encroached = change_d(m, steps);
  return std::move(out_);
}

std::size_t Assembly::change_d(refine::VolumeMesh& m, std::span<const SurfaceStep> steps) const {
  const auto fail = [](const std::string& what) {
    throw std::logic_error("assembly: the phase's change of D cannot be made: " + what);
  };
  const auto mapped = [&](Gid g) { return m.d2s[vertex(g)] != refine::kNone; };
  // The splits, each once its ends are in D.
  std::vector<const SurfaceStep*> todo, later;
  for (const SurfaceStep& r : steps)
    if (r.c == kNoGid) todo.push_back(&r);
  while (!todo.empty()) {
    later.clear();
    for (const SurfaceStep* r : todo) {
      if (!mapped(r->a) || !mapped(r->b)) {
        later.push_back(r);  // an end is the midpoint of a split not made yet
        continue;
      }
      const VertexId a = vertex(r->a), b = vertex(r->b), v = vertex(r->m);
      const auto s = m.surf.find_subsegment(m.d2s[a], m.d2s[b]);
      if (!s)
        fail("a split of a subsegment D does not have (vertices " + std::to_string(a) + ", " +
             std::to_string(b) + ")");
      const surface::SplitResult x = surface::split_subsegment_at(m.surf, *s, m.dt.point(v));
      m.remap_vertex(v, x.vertex);
    }
    if (later.size() == todo.size()) fail("splits of subsegments whose ends were never made");
    todo.swap(later);
  }
  // Then the subfacet circumcenters, located from a vertex of their subfacet in D.
  for (const SurfaceStep& r : steps)
    if (r.c != kNoGid) todo.push_back(&r);
  while (!todo.empty()) {
    later.clear();
    for (const SurfaceStep* r : todo) {
      const Gid* from = nullptr;
      for (const Gid* g : {&r->a, &r->b, &r->c})
        if (from == nullptr && mapped(*g)) from = g;
      if (from == nullptr) {
        later.push_back(r);  // its subfacet's vertices are all points not made yet
        continue;
      }
      const VertexId v = vertex(r->m);
      const Point& q = m.dt.point(v);
      const auto at = surface::locate_in_facet(m.surf, r->facet, q, m.d2s[vertex(*from)]);
      if (!at || at->on_subsegment) fail("a subfacet circumcenter outside its facet");
      const surface::FacetCavity cav =
          surface::build_facet_cavity(m.surf, r->facet, q, {at->subfacet}, std::nullopt);
      if (cav.status != surface::CavityStatus::Ok)
        fail(std::string("a subfacet circumcenter's facet cavity is ") +
             surface::cavity_status_name(cav.status));
      const std::uint32_t dv = m.surf.add_vertex(q, {surface::HomeKind::Facet, r->facet});
      surface::commit_facet_cavity(m.surf, cav, dv);
      m.remap_vertex(v, dv);
    }
    if (later.size() == todo.size()) fail("subfacets whose vertices were never made");
    todo.swap(later);
  }
  // Once D has them all (T has every new vertex already).
  refine::EncroachedLists missing, encroached;
  std::vector<TetId> star;
  for (const SurfaceStep& r : steps) {
    const VertexId v = vertex(r.m);
    refine::vertex_star(m, v, fresh_tet_[v - n0_], star);
    refine::missing_at(m, v, star, missing);
    refine::find_encroached(m, star, encroached);
  }
  for (const refine::Encroached& e : missing.subsegments) m.missing_subsegments.push_back(e.id);
  for (const refine::Encroached& e : missing.subfacets) m.missing_subfacets.push_back(e.id);
  return encroached.subsegments.size() + encroached.subfacets.size();
}

Assembled assemble(refine::VolumeMesh& m, std::span<const Piece> pieces,
                   std::span<const SurfaceStep> steps) {
  std::size_t tets = 0;
  for (const Piece& p : pieces) tets += p.tets.size();
  Assembly a(m, tets);
  for (const Piece& p : pieces) a.add(p);
  return a.finish(m, steps);
}

}  // namespace pdr::par
