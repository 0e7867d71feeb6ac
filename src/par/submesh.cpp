// Submesh: extraction from a partitioned mesh, migration out and in, relink notices
// (par/submesh.hpp).
#include "par/submesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "mesh/tables.hpp"

namespace pdr::par {

FaceKey face_key(Gid a, Gid b, Gid c) {
  // Three compare-exchanges sort three ids.
  if (b < a) std::swap(a, b);
  if (c < b) std::swap(b, c);
  if (b < a) std::swap(a, b);
  return FaceKey{{a, b, c}};
}

std::size_t GidHash::operator()(Gid g) const {
  g ^= g >> 30;
  g *= 0xBF58476D1CE4E5B9ull;
  g ^= g >> 27;
  g *= 0x94D049BB133111EBull;
  return static_cast<std::size_t>(g ^ (g >> 31));
}

namespace {

void sort3(VertexId& a, VertexId& b, VertexId& c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
}

}  // namespace

Submesh::VertexLabels& Submesh::list_for(VertexId v) {
  if (label_list_.size() <= v) label_list_.resize(points_.size(), kNoList);
  if (label_list_[v] == kNoList) {
    label_list_[v] = static_cast<std::uint32_t>(lists_.size());
    lists_.emplace_back();
  }
  return lists_[label_list_[v]];
}

std::uint32_t Submesh::edge_label(VertexId a, VertexId b) const {
  if (a > b) std::swap(a, b);
  if (const VertexLabels* l = list_at(a))
    for (const EdgeEntry& e : l->edges)
      if (e.b == b) return e.label;
  return kNoLabel;
}

std::uint32_t Submesh::face_label(VertexId a, VertexId b, VertexId c) const {
  sort3(a, b, c);
  if (const VertexLabels* l = list_at(a))
    for (const FaceEntry& f : l->faces)
      if (f.b == b && f.c == c) return f.label;
  return kNoLabel;
}

void Submesh::set_edge_label(VertexId a, VertexId b, std::uint32_t label) {
  if (label == kNoLabel || a >= points_.size() || b >= points_.size() || a == b)
    throw std::logic_error("submesh: a label on an edge that cannot have one");
  if (a > b) std::swap(a, b);
  std::vector<EdgeEntry>& edges = list_for(a).edges;
  for (EdgeEntry& e : edges)
    if (e.b == b) {
      e.label = label;
      return;
    }
  edges.push_back({b, label});
  ++label_count_;
}

void Submesh::set_face_label(VertexId a, VertexId b, VertexId c, std::uint32_t label) {
  sort3(a, b, c);
  if (label == kNoLabel || c >= points_.size() || a == b || b == c)
    throw std::logic_error("submesh: a label on a face that cannot have one");
  std::vector<FaceEntry>& faces = list_for(a).faces;
  for (FaceEntry& f : faces)
    if (f.b == b && f.c == c) {
      f.label = label;
      return;
    }
  faces.push_back({b, c, label});
  ++label_count_;
}

void Submesh::erase_edge_label(VertexId a, VertexId b) {
  if (a > b) std::swap(a, b);
  if (a >= label_list_.size() || label_list_[a] == kNoList) return;
  std::vector<EdgeEntry>& edges = lists_[label_list_[a]].edges;
  for (EdgeEntry& e : edges)
    if (e.b == b) {
      e = edges.back();
      edges.pop_back();
      --label_count_;
      return;
    }
}

void Submesh::erase_face_label(VertexId a, VertexId b, VertexId c) {
  sort3(a, b, c);
  if (a >= label_list_.size() || label_list_[a] == kNoList) return;
  std::vector<FaceEntry>& faces = lists_[label_list_[a]].faces;
  for (FaceEntry& f : faces)
    if (f.b == b && f.c == c) {
      f = faces.back();
      faces.pop_back();
      --label_count_;
      return;
    }
}

VertexId Submesh::find_vertex(Gid g) const {
  if (g == kGhostGid) return kGhostVertex;
  if (g < m0_local_.size()) return m0_local_[static_cast<std::size_t>(g)];
  if (const auto m = made_vertex(g); dense_ && m)
    return m->maker < fresh_local_.size() && m->serial < fresh_local_[m->maker].size()
               ? fresh_local_[m->maker][m->serial]
               : kNoVertex;
  const auto it = local_.find(g);
  return it == local_.end() ? kNoVertex : it->second;
}

VertexId* Submesh::vertex_slot(Gid g) {
  if (g < m0_local_.size()) return &m0_local_[static_cast<std::size_t>(g)];
  if (const auto m = made_vertex(g); dense_ && m) {
    if (fresh_local_.size() <= m->maker) fresh_local_.resize(m->maker + 1);
    std::vector<VertexId>& v = fresh_local_[m->maker];
    if (v.size() <= m->serial) v.resize(m->serial + m->serial / 2 + 64, kNoVertex);
    return &v[m->serial];
  }
  return &local_.try_emplace(g, kNoVertex).first->second;
}

void Submesh::collect_labels(std::span<const TetId> tets, Migration& m) const {
  for (const TetId t : tets) {
    const VertexId* v = store_.vertices(t);
    for (const auto& e : tables::kEdgeVertex)
      if (const std::uint32_t l = edge_label(v[e[0]], v[e[1]]); l != kNoLabel) {
        EdgeLabel x{{gid(v[e[0]]), gid(v[e[1]])}, l};
        std::sort(x.v.begin(), x.v.end());
        m.edge_labels.push_back(x);
      }
    for (const auto& f : tables::kFaceVertex)
      if (const std::uint32_t l = face_label(v[f[0]], v[f[1]], v[f[2]]); l != kNoLabel) {
        FaceLabel x{{gid(v[f[0]]), gid(v[f[1]]), gid(v[f[2]])}, l};
        std::sort(x.v.begin(), x.v.end());
        m.face_labels.push_back(x);
      }
  }
  const auto by_v = [](const auto& a, const auto& b) { return a.v < b.v; };
  const auto same_v = [](const auto& a, const auto& b) { return a.v == b.v; };
  std::sort(m.edge_labels.begin(), m.edge_labels.end(), by_v);
  m.edge_labels.erase(std::unique(m.edge_labels.begin(), m.edge_labels.end(), same_v),
                      m.edge_labels.end());
  std::sort(m.face_labels.begin(), m.face_labels.end(), by_v);
  m.face_labels.erase(std::unique(m.face_labels.begin(), m.face_labels.end(), same_v),
                      m.face_labels.end());
}

VertexId Submesh::local_vertex(Gid g, const Point* p, std::uint8_t tag) {
  if (g == kGhostGid) return kGhostVertex;
  VertexId* slot = vertex_slot(g);
  if (*slot == kNoVertex) {
    if (p == nullptr) throw std::logic_error("submesh: vertex " + std::to_string(g) + " unknown");
    *slot = static_cast<VertexId>(points_.size());
    points_.push_back(*p);
    gids_.push_back(g);
    tags_.push_back(tag);
  }
  return *slot;
}

FaceKey Submesh::key_of(TetId t, int f) const {
  const auto& fv = tables::kFaceVertex[f];
  return face_key(gid(store_.vertex(t, fv[0])), gid(store_.vertex(t, fv[1])),
                  gid(store_.vertex(t, fv[2])));
}

void Submesh::record_tet(TetId t, Gid g, std::uint32_t epoch, std::uint8_t inside) {
  if (slot_.size() < store_.slots()) slot_.resize(store_.slots());
  slot_[t] = SlotInfo{g, epoch, inside, 0};
  if (g != kNoGid) index_tet(g, t);
}

void Submesh::index_tet(Gid g, TetId t) {
  if (g < m0_slot_.size()) {
    m0_slot_[static_cast<std::size_t>(g)] = t;
    return;
  }
  if (!made_here(g)) {
    tet_at_[g] = t;
    return;
  }
  const std::size_t serial = static_cast<std::size_t>(g & ((Gid{1} << 40) - 1));
  // Serials come in order, so the index grows one entry at a time (its capacity doubles;
  // pages are touched only as serials reach them).
  if (slot_of_serial_.size() <= serial) slot_of_serial_.resize(serial + 1, kNoTet);
  slot_of_serial_[serial] = t;
}

void Submesh::unindex_tet(Gid g) {
  if (!made_here(g) && g >= m0_slot_.size()) tet_at_.erase(g);
}

TetId Submesh::find_tet(Gid g) const {
  TetId t = kNoTet;
  if (made_here(g)) {
    const std::size_t serial = static_cast<std::size_t>(g & ((Gid{1} << 40) - 1));
    if (serial < slot_of_serial_.size()) t = slot_of_serial_[serial];
  } else if (g < m0_slot_.size()) {
    t = m0_slot_[static_cast<std::size_t>(g)];
  } else if (const TetId* at = tet_at_.find(g)) {
    t = *at;
  }
  return t != kNoTet && t < slot_.size() && slot_[t].gid == g && store_.is_alive(t) ? t : kNoTet;
}

TetId Submesh::add_proxy(TetId t, int f, const Side& side) {
  const auto& fv = tables::kFaceVertex[f];
  const TetId p = store_.create(store_.vertex(t, fv[0]), store_.vertex(t, fv[1]),
                                store_.vertex(t, fv[2]), kRemoteVertex);
  record_tet(p, kNoGid, 0, 0);
  slot_[t].exposed = 1;  // the submesh across now names t
  store_.link(half_face(t, f), half_face(p, 3));
  side_[p] = side;
  ++proxies_;
  return p;
}

TetId Submesh::proxy_on(TetId t, const FaceKey& k) const {
  for (int f = 0; f < 4; ++f)
    if (const TetId u = store_.neighbour(t, f); store_.is_proxy(u) && key_of(t, f) == k) return u;
  return kNoTet;
}

void Submesh::drop_proxy(TetId proxy) {
  side_.erase(proxy);
  --proxies_;
  store_.destroy(proxy);
}

const Side& Submesh::proxy_side(TetId t) const {
  const Side* s = side_.find(t);
  if (s == nullptr) throw std::logic_error("submesh: tet " + std::to_string(t) + " is no live proxy");
  return *s;
}

void Submesh::claim(TetId proxy, const Claim& c) {
  Side* side = side_.find(proxy);
  if (side == nullptr) throw std::logic_error("submesh: a claim on a tet that is no live proxy");
  Claim& mine = side->claim;
  if (c.epoch > mine.epoch) mine = c;
}

Submesh Submesh::extract(ActorId k, const TetStore& s, std::span<const Point> pts,
                         std::span<const std::uint8_t> inside, const Partition& p,
                         std::span<const std::uint8_t> tags, bool dense) {
  Submesh m(k);
  if (dense) {
    m.m0_slot_.assign(s.slots(), kNoTet);
    m.m0_local_.assign(pts.size(), kNoVertex);
    m.dense_ = true;
  }
  std::vector<TetId> local(s.slots(), kNoTet);
  std::vector<TetId> mine;
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || p.part[t] != k) continue;
    VertexId v[4];
    for (int i = 0; i < 4; ++i) {
      const VertexId g = s.vertex(t, i);
      v[i] = g == kGhostVertex ? kGhostVertex
                               : m.local_vertex(g, &pts[g], g < tags.size() ? tags[g] : 0);
    }
    local[t] = m.store_.create(v[0], v[1], v[2], v[3]);
    mine.push_back(t);
  }
  for (const TetId t : mine) m.record_tet(local[t], t, 0, t < inside.size() ? inside[t] : 0);
  for (const TetId t : mine)
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (p.part[u] == k)
        m.store_.set_opposite(half_face(local[t], f), half_face(local[u], s.back_face(t, f)));
      else
        m.add_proxy(local[t], f, Side{u, Claim{p.part[u], 0}});
    }
  return m;
}

Migration Submesh::take(std::span<const TetId> tets, ActorId to, std::vector<Relink>& relinks) {
  if (to == id_) throw std::logic_error("submesh: a migration to itself");
  taken_.clear();
  seen_.clear();
  for (const TetId t : tets) {
    if (t >= store_.slots() || !store_.is_alive(t) || store_.is_proxy(t))
      throw std::logic_error("submesh: take of a dead tet or a proxy");
    taken_.insert(t);
  }
  Migration m;
  m.from = id_;
  m.to = to;
  m.tets.reserve(tets.size());
  m.vertices.reserve(tets.size() + 3);  // a connected set of tets: about one vertex a tet
  collect_labels(tets, m);
  std::vector<std::pair<TetId, int>>& keep_faces = keep_faces_;  // kept real tets' faces
  std::vector<Side>& keep_sides = keep_sides_;                    // to close, and theirs
  std::vector<TetId>& drop = drop_;
  keep_faces.clear();
  keep_sides.clear();
  drop.clear();
  for (const TetId t : tets) {
    TetRecord r;
    r.gid = slot_[t].gid;
    r.epoch = slot_[t].epoch + 1;
    const Claim now{to, r.epoch};
    for (int i = 0; i < 4; ++i) {
      const VertexId v = store_.vertex(t, i);
      r.v[static_cast<std::size_t>(i)] = gid(v);
      if (v != kGhostVertex && !seen_.contains(v)) {
        seen_.insert(v);
        m.vertices.push_back({gid(v), points_[v], tags_[v]});
      }
    }
    r.inside = slot_[t].inside;
    for (int f = 0; f < 4; ++f) {
      const TetId u = store_.neighbour(t, f);
      Side& across = r.across[static_cast<std::size_t>(f)];
      if (taken_.contains(u)) {
        across = Side{slot_[u].gid, Claim{kSameMigration, 0}};
      } else if (store_.is_proxy(u)) {
        across = proxy_side(u);
        // Tell the submesh believed to hold the tet across. When that is this one (the tet
        // is on its way here), nothing is sent: its arrival finds this move in moved_.
        if (across.claim.holder != id_)
          relinks.push_back({across.claim.holder, across.tet, key_of(t, f), r.gid, now,
                             across.claim.epoch});
        drop.push_back(u);
      } else {
        across = Side{slot_[u].gid, Claim{id_, slot_[u].epoch}};
        keep_faces.emplace_back(u, store_.back_face(t, f));
        keep_sides.push_back(Side{r.gid, now});
      }
    }
    moved_[r.gid] = now;
    m.tets.push_back(r);
  }
  for (std::size_t i = 0; i < keep_faces.size(); ++i)
    add_proxy(keep_faces[i].first, keep_faces[i].second, keep_sides[i]);
  for (const TetId u : drop) drop_proxy(u);
  for (const TetId t : tets) {
    unindex_tet(slot_[t].gid);
    record_tet(t, kNoGid, 0, 0);
    store_.destroy(t);
  }
  return m;
}

std::vector<TetId> Submesh::give(const Migration& m) {
  if (m.to != id_) throw std::logic_error("submesh: a migration for another submesh");
  for (const VertexRecord& v : m.vertices) local_vertex(v.gid, &v.p, v.tag);
  std::vector<TetId> ids;
  ids.reserve(m.tets.size());
  for (const TetRecord& r : m.tets) {
    VertexId v[4];
    for (int i = 0; i < 4; ++i) v[i] = local_vertex(r.v[static_cast<std::size_t>(i)], nullptr);
    const TetId t = store_.create(v[0], v[1], v[2], v[3]);
    record_tet(t, r.gid, r.epoch, r.inside);
    slot_[t].exposed = 1;  // its old holder, and proxies elsewhere, may name it
    ids.push_back(t);
  }
  for (const EdgeLabel& l : m.edge_labels)
    set_edge_label(local_vertex(l.v[0], nullptr), local_vertex(l.v[1], nullptr), l.label);
  for (const FaceLabel& l : m.face_labels)
    set_face_label(local_vertex(l.v[0], nullptr), local_vertex(l.v[1], nullptr),
                   local_vertex(l.v[2], nullptr), l.label);
  std::vector<std::pair<FaceKey, HalfFace>>& internal = internal_;  // between two of its tets
  internal.clear();
  for (std::size_t i = 0; i < m.tets.size(); ++i) {
    const TetId t = ids[i];
    for (int f = 0; f < 4; ++f) {
      const Side& across = m.tets[i].across[static_cast<std::size_t>(f)];
      const FaceKey k = key_of(t, f);
      if (across.claim.holder == kSameMigration) {
        internal.emplace_back(k, half_face(t, f));
        continue;
      }
      // The other side is here when the tet across is (M2: its face is closed by a
      // proxy): glue to it.
      const TetId x = find_tet(across.tet);
      if (const TetId proxy = x == kNoTet ? kNoTet : proxy_on(x, k); proxy != kNoTet) {
        const HalfFace back = store_.opposite(proxy, 3);
        drop_proxy(proxy);
        store_.link(half_face(t, f), back);
        continue;
      }
      // Elsewhere, or on its way here (claimed here but not here yet: the proxy then
      // names this submesh until the tet arrives and replaces it). If this submesh gave
      // that tet away, its own record of the move may be newer than the migration's.
      const TetId p = add_proxy(t, f, across);
      if (const Claim* gone = moved_.find(across.tet)) claim(p, *gone);
    }
  }
  std::sort(internal.begin(), internal.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < internal.size(); i += 2) {
    if (i + 1 == internal.size() || !(internal[i].first == internal[i + 1].first) ||
        (i + 2 < internal.size() && internal[i + 2].first == internal[i].first))
      throw std::logic_error("submesh: a migration whose internal faces do not pair up");
    store_.link(internal[i].second, internal[i + 1].second);
  }
  for (const TetId t : ids) {
    const auto w = waiting_.find(slot_[t].gid);
    if (w == waiting_.end()) continue;
    std::vector<Relink> notes = std::move(w->second);
    waiting_.erase(w);
    for (Relink& r : notes) relink(r);  // `about` is here now: applies
  }
  return ids;
}

VertexId Submesh::insert(const Cavity& c, std::uint8_t inside, std::uint8_t tag) {
  const VertexId v = local_vertex(fresh_vertex_gid(), &c.point, tag);
  for (const TetId t : c.conflict) {
    unindex_tet(slot_[t].gid);
    if (slot_[t].exposed != 0) moved_[slot_[t].gid] = Claim{kDeleted, ~std::uint32_t{0}};
  }
  committer_.commit(store_, c, v, points_.size());
  for (const TetId t : committer_.created()) record_tet(t, fresh_gid(), 0, inside);
  return v;
}

bool Submesh::relink(Relink& r) {
  if (const TetId about = find_tet(r.about); about != kNoTet) {
    // A proxy on that face, unless the moved tet is here too (then the face is inside),
    // and only one that still names the moved tet: after a commit, a new tet may have
    // the same face.
    if (const TetId p = proxy_on(about, r.face); p != kNoTet && proxy_side(p).tet == r.tet)
      claim(p, r.claim);
    return true;
  }
  if (const auto next = moved(r.about, r.about_epoch)) {
    if (next->holder == kDeleted) return true;  // moot: the face is gone with the tet
    r.recipient = next->holder;
    r.about_epoch = next->epoch;
    return false;
  }
  waiting_[r.about].push_back(r);  // on its way here
  return true;
}

std::optional<Claim> Submesh::moved(Gid g, std::uint32_t after) const {
  if (find_tet(g) != kNoTet) return std::nullopt;
  if (const Claim* gone = moved_.find(g); gone != nullptr && gone->epoch > after) return *gone;
  return std::nullopt;
}

std::size_t Submesh::waiting_relinks() const {
  std::size_t n = 0;
  for (const auto& [g, v] : waiting_) n += v.size();
  return n;
}

std::vector<std::string> Submesh::check() const {
  std::vector<std::string> out = store_.check_topology();
  std::size_t proxies = 0, foreign = 0;
  std::vector<FaceKey> faces;  // the proxies' faces: each closed by one proxy
  for (TetId t = 0; t < store_.slots(); ++t) {
    if (!store_.is_alive(t)) continue;
    if (!store_.is_proxy(t)) {
      if (!made_here(slot_[t].gid) && slot_[t].gid >= m0_slot_.size()) ++foreign;
      if (find_tet(slot_[t].gid) != t)
        out.push_back("submesh.tet-index: tet " + std::to_string(t) + " of submesh " +
                      std::to_string(id_) + " is not indexed by its global id");
      continue;
    }
    ++proxies;
    faces.push_back(key_of(t, 3));
    // Its side names a tet that is not here (else the face would be glued), and it is
    // found from the live real tet it closes (a broken link is check_topology's to report).
    const Side* side = side_.find(t);
    const TetId back = store_.neighbour(t, 3);
    if (side == nullptr || side->tet == kNoGid || find_tet(side->tet) != kNoTet ||
        back >= store_.slots() || !store_.is_alive(back) || store_.is_proxy(back) ||
        proxy_on(back, faces.back()) != t)
      out.push_back("submesh.proxy: proxy " + std::to_string(t) + " of submesh " +
                    std::to_string(id_) + " has no side, names a tet held here, or is not "
                    "found from its tet");
  }
  std::sort(faces.begin(), faces.end());
  if (std::adjacent_find(faces.begin(), faces.end()) != faces.end())
    out.push_back("submesh.proxy: two proxies of submesh " + std::to_string(id_) +
                  " close the same face");
  if (proxies != proxies_ || proxies != side_.size() || foreign != tet_at_.size())
    out.push_back("submesh.index: " + std::to_string(proxies) + " proxies, " +
                  std::to_string(proxies_) + " counted, " + std::to_string(side_.size()) +
                  " sides, " + std::to_string(tet_at_.size()) + " indexed tets");
  return out;
}

}  // namespace pdr::par
