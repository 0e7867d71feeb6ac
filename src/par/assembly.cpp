// The whole mesh from the submeshes' tets; see par/assembly.hpp.
#include "par/assembly.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>
#include <tuple>
#include <unordered_set>
#include <stdexcept>
#include <string>

#include "mesh/tables.hpp"
#include "refine/conformity.hpp"
#include "refine/guard.hpp"
#include "surface/cavity.hpp"
#include "surface/locate.hpp"
#include "surface/split.hpp"

namespace pdr::par {
namespace {

// Runs work(w) for w in [0, workers) on as many threads (this one is worker 0; fewer when
// no thread is to be had: work(w) must then leave worker w's share to the others, as a
// shared counter does) and rethrows the first exception once all have ended.
template <class Work>
void on_workers(std::size_t workers, Work work) {
  std::vector<std::exception_ptr> errors(workers);
  const auto guarded = [&](std::size_t w) {
    try {
      work(w);
    } catch (...) {
      errors[w] = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) {
      try {
        pool.emplace_back(guarded, w);
      } catch (const std::system_error&) {
        for (std::size_t rest = w; rest < workers; ++rest) guarded(rest);  // on this thread
        break;
      }
    }
    guarded(0);
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

std::size_t cores() { return std::max<std::size_t>(1, std::thread::hardware_concurrency()); }

}  // namespace

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
    if (t + 8 < st.slots() && index[t + 8] != kNone)  // its neighbours, scattered, meanwhile
      for (int f = 0; f < 4; ++f) st.prefetch(st.neighbour(t + 8, f));
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

PieceView::PieceView(const Piece& p)
    : nv_(p.vertices.size()),
      nt_(p.tets.size()),
      v_(reinterpret_cast<const std::byte*>(p.vertices.data())),
      t_(reinterpret_cast<const std::byte*>(p.tets.data())) {}

PieceView get_piece_view(WireReader& r) {
  PieceView v;
  std::tie(v.nv_, v.v_) = r.get_vector_in_place<VertexRecord>();
  std::tie(v.nt_, v.t_) = r.get_vector_in_place<PieceTet>();
  return v;
}

Assembly::Assembly(const refine::VolumeMesh& m)
    : n0_(m.dt.num_points()), points_(m.dt.points().begin(), m.dt.points().end()) {}

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

void Assembly::add(const PieceView& p) {
  Added& a = added_.emplace_back();
  a.piece = p;
  a.first = static_cast<TetId>(tets_);
  tets_ += p.tet_count();
  a.map.reserve(p.vertex_count());
  for (std::size_t i = 0; i < p.vertex_count(); ++i) {
    const VertexRecord v = p.vertex(i);
    if (v.gid < n0_) {
      a.map.push_back(static_cast<VertexId>(v.gid));
      continue;
    }
    VertexId* at = fresh_slot(v.gid);
    if (*at == kNoVertex) {
      *at = static_cast<VertexId>(points_.size());
      points_.push_back(v.p);
      fresh_tet_.push_back(kNoTet);
    }
    a.map.push_back(*at);
  }
}

void Assembly::write_tets(const Added& a, std::size_t begin, std::size_t end,
                          std::vector<OpenFace>& open, std::vector<TetId>& deferred) {
  const std::size_t n = a.piece.tet_count();
  const auto vertex = [&](std::uint32_t i) {
    if (i == kGhostVertex) return kGhostVertex;
    if (i >= a.map.size()) throw std::logic_error("assembly: a piece's tet names no vertex of it");
    return a.map[i];
  };
  for (std::size_t j = begin; j < end; ++j) {
    const PieceTet x = a.piece.tet(j);
    const auto t = static_cast<TetId>(a.first + j);
    st_.set_vertices(t, vertex(x.v[0]), vertex(x.v[1]), vertex(x.v[2]), vertex(x.v[3]));
    for (const std::uint32_t i : x.v)
      if (i != kGhostVertex && a.map[i] >= n0_)  // any tet holding it will do
        std::atomic_ref<TetId>(fresh_tet_[a.map[i] - n0_]).store(t, std::memory_order_relaxed);
    inside_[t] = x.inside & 1;
    if ((x.inside & 2) != 0) deferred.push_back(t);
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t across = x.across[static_cast<std::size_t>(f)];
      if (across != kAcrossProxy) {
        if ((across >> 2) >= n) throw std::logic_error("assembly: a piece's tet names no tet of it");
        st_.set_opposite(half_face(t, f), 4 * a.first + across);
        continue;
      }
      const auto& fv = tables::kFaceVertex[f];
      OpenFace o{{st_.vertex(t, fv[0]), st_.vertex(t, fv[1]), st_.vertex(t, fv[2])}, half_face(t, f)};
      std::sort(o.key.begin(), o.key.end());
      open.push_back(o);
    }
  }
}

Assembled Assembly::finish(refine::VolumeMesh& m, std::span<const SurfaceStep> steps) {
  if (m.dt.num_points() != n0_) throw std::logic_error("assembly: the mesh changed meanwhile");
  st_.append(tets_);
  inside_.assign(tets_, 0);
  // The tets, in blocks taken by every core in turn; each worker keeps its own lists.
  struct Block {
    std::size_t piece, begin, end;
  };
  constexpr std::size_t kBlock = 1 << 16;
  std::vector<Block> blocks;
  for (std::size_t p = 0; p < added_.size(); ++p)
    for (std::size_t b = 0; b < added_[p].piece.tet_count(); b += kBlock)
      blocks.push_back({p, b, std::min(added_[p].piece.tet_count(), b + kBlock)});
  const std::size_t workers = std::clamp<std::size_t>(cores(), 1, std::max<std::size_t>(1, blocks.size()));
  std::vector<std::vector<OpenFace>> open(workers);
  std::vector<std::vector<TetId>> deferred(workers);
  std::atomic<std::size_t> next{0};
  on_workers(workers, [&](std::size_t w) {
    try {
      for (std::size_t b; (b = next.fetch_add(1)) < blocks.size();)
        write_tets(added_[blocks[b].piece], blocks[b].begin, blocks[b].end, open[w], deferred[w]);
    } catch (...) {
      next = blocks.size();  // the others stop too
      throw;
    }
  });
  std::vector<OpenFace> faces;
  for (std::size_t w = 0; w < workers; ++w) {
    faces.insert(faces.end(), open[w].begin(), open[w].end());
    std::vector<OpenFace>().swap(open[w]);
    out_.deferred.insert(out_.deferred.end(), deferred[w].begin(), deferred[w].end());
  }
  std::sort(out_.deferred.begin(), out_.deferred.end());  // slot order, whatever the threads
  // Faces between pieces: each exactly twice.
  std::sort(faces.begin(), faces.end(),
            [](const OpenFace& a, const OpenFace& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < faces.size(); i += 2) {
    if (i + 1 == faces.size() || faces[i].key != faces[i + 1].key ||
        (i + 2 < faces.size() && faces[i + 2].key == faces[i].key))
      throw std::logic_error("assembly: a face between submeshes (vertices " +
                             std::to_string(faces[i].key[0]) + ", " +
                             std::to_string(faces[i].key[1]) + ", " +
                             std::to_string(faces[i].key[2]) + ") is not shared by two tets");
    st_.link(faces[i].h, faces[i + 1].h);
  }
  std::vector<OpenFace>().swap(faces);
  std::vector<Added>().swap(added_);
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
  // Once D has them all (T has every new vertex already). Read-only, so the steps are
  // shared out in runs over every core, and the runs' lists joined in step order: the
  // same lists as one pass gives (missing_at lists an element once, find_encroached each
  // time it is met).
  struct Found {
    refine::EncroachedLists missing;
    std::size_t encroached = 0;
  };
  const std::size_t workers = std::clamp<std::size_t>(cores(), 1, std::max<std::size_t>(1, steps.size() / 1024));
  std::vector<Found> found(workers);
  on_workers(workers, [&](std::size_t w) {
    std::vector<TetId> star;
    refine::EncroachedLists encroached;
    for (std::size_t i = steps.size() * w / workers; i < steps.size() * (w + 1) / workers; ++i) {
      const VertexId v = vertex(steps[i].m);
      refine::vertex_star(m, v, fresh_tet_[v - n0_], star);
      refine::missing_at(m, v, star, found[w].missing);
      refine::find_encroached(m, star, encroached);
    }
    found[w].encroached = encroached.subsegments.size() + encroached.subfacets.size();
  });
  std::unordered_set<std::uint32_t> listed_subsegments, listed_subfacets;
  std::size_t encroached = 0;
  for (const Found& f : found) {
    for (const refine::Encroached& e : f.missing.subsegments)
      if (listed_subsegments.insert(e.id).second) m.missing_subsegments.push_back(e.id);
    for (const refine::Encroached& e : f.missing.subfacets)
      if (listed_subfacets.insert(e.id).second) m.missing_subfacets.push_back(e.id);
    encroached += f.encroached;
  }
  return encroached;
}

Assembled assemble(refine::VolumeMesh& m, std::span<const Piece> pieces,
                   std::span<const SurfaceStep> steps) {
  Assembly a(m);
  for (const Piece& p : pieces) a.add(PieceView(p));
  return a.finish(m, steps);
}

}  // namespace pdr::par
