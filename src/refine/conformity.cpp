// Conformity of T to D during refinement; see refine/conformity.hpp.
#include "refine/conformity.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "mesh/tables.hpp"

namespace pdr::refine {
namespace {

bool holds(const VertexId* v, VertexId x) {
  return v[0] == x || v[1] == x || v[2] == x || v[3] == x;
}

// Ids are reused after splits: an entry with the same id and other vertices was a former
// element, gone from D (next() would drop it as stale), so it now stands for this one.
// True when the element was not listed yet (new, or in place of a former one).
bool add_element(std::vector<Encroached>& list, std::uint32_t id,
                 const std::array<std::uint32_t, 3>& v) {
  for (Encroached& e : list)
    if (e.id == id) {
      if (e.v == v) return false;
      e.v = v;
      return true;
    }
  list.push_back({id, v, kNone, kNoTet});
  return true;
}

bool add_subfacet(const VolumeMesh& m, std::uint32_t id, EncroachedLists& out) {
  return add_element(out.subfacets, id, m.surf.subfacet(id).v);
}

bool add_subsegment(const VolumeMesh& m, std::uint32_t id, EncroachedLists& out) {
  const Subsegment& x = m.surf.subsegment(id);
  return add_element(out.subsegments, id, {x.v[0], x.v[1], 0});
}

}  // namespace

void doomed_elements(const VolumeMesh& m, const Cavity& c, EncroachedLists& out) {
  const TetStore& s = m.dt.store();
  // Linear in the cavity (a skinny tet's cavity at a sharp angle spans much of T): a
  // sorted copy of the conflict tets, and the edges of the boundary faces in a hash set,
  // each built only when a subfacet or subsegment asks.
  std::vector<TetId> sorted;
  std::unordered_set<std::uint64_t> boundary_edges;
  const auto key = [](VertexId a, VertexId b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  };
  const std::size_t subfacets_before = out.subfacets.size();
  const std::size_t subsegments_before = out.subsegments.size();
  for (const TetId t : c.conflict) {
    const VertexId* v = s.vertices(t);
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (!sf) continue;
      if (sorted.empty()) {
        sorted.assign(c.conflict.begin(), c.conflict.end());
        std::sort(sorted.begin(), sorted.end());
      }
      if (std::binary_search(sorted.begin(), sorted.end(), s.neighbour(t, f)))
        out.subfacets.push_back({*sf, m.surf.subfacet(*sf).v, kNone, kNoTet});
    }
    for (const auto& [i, j] : tables::kEdgeVertex) {
      const auto sub = m.subsegment(v[i], v[j]);
      if (!sub) continue;
      if (boundary_edges.empty())
        for (const HalfFace h : c.boundary) {
          const VertexId* w = s.vertices(tet_of(h));
          const auto& fv = tables::kFaceVertex[face_of(h)];
          for (int k = 0; k < 3; ++k)
            boundary_edges.insert(key(w[fv[k]], w[fv[(k + 1) % 3]]));
        }
      if (boundary_edges.count(key(v[i], v[j])) == 0) {
        const Subsegment& x = m.surf.subsegment(*sub);
        out.subsegments.push_back({*sub, {x.v[0], x.v[1], 0}, kNone, kNoTet});
      }
    }
  }
  // Each element once (a subfacet is seen from both its tets, a subsegment from each tet
  // around it); the lists before this call are kept as they were.
  const auto dedupe = [](std::vector<Encroached>& list, std::size_t from) {
    const auto by_id = [](const Encroached& a, const Encroached& b) { return a.id < b.id; };
    std::sort(list.begin() + static_cast<std::ptrdiff_t>(from), list.end(), by_id);
    list.erase(std::unique(list.begin() + static_cast<std::ptrdiff_t>(from), list.end(),
                           [](const Encroached& a, const Encroached& b) { return a.id == b.id; }),
               list.end());
  };
  dedupe(out.subfacets, subfacets_before);
  dedupe(out.subsegments, subsegments_before);
}

bool missing_at(const VolumeMesh& m, VertexId v, std::span<const TetId> star,
                EncroachedLists& out) {
  bool fresh = false;
  if (v >= m.d2s.size() || m.d2s[v] == kNone) return fresh;
  const std::uint32_t sv = m.d2s[v];
  const TetStore& s = m.dt.store();
  // Every tet of the star holds v: {v, a, b} is a face and {v, a} an edge of T iff some
  // tet of the star holds a and b, or a.
  auto in_star = [&](VertexId a, VertexId b) {
    for (const TetId t : star)
      if (!s.is_ghost(t) && holds(s.vertices(t), a) && holds(s.vertices(t), b)) return true;
    return false;
  };
  for (const std::uint32_t id : m.surf.vertex_subfacets(sv)) {
    const Subfacet& f = m.surf.subfacet(id);
    if (!f.alive) continue;
    VertexId other[2];
    int k = 0;
    for (const std::uint32_t x : f.v)
      if (x != sv) other[k++] = m.s2d[x];
    if (!in_star(other[0], other[1])) fresh = add_subfacet(m, id, out) || fresh;
  }
  for (const std::uint32_t id : m.surf.vertex_subsegments(sv)) {
    const Subsegment& x = m.surf.subsegment(id);
    if (x.v[0] != sv && x.v[1] != sv) continue;  // a stale entry
    const VertexId a = m.s2d[x.v[0] == sv ? x.v[1] : x.v[0]];
    if (!in_star(a, a)) fresh = add_subsegment(m, id, out) || fresh;
  }
  return fresh;
}

std::vector<TetId> reflag(VolumeMesh& m, std::span<const TetId> made) {
  const TetStore& s = m.dt.store();
  std::vector<TetId> live;
  for (const TetId t : made)
    if (t < s.slots() && s.is_alive(t) && !s.is_ghost(t)) live.push_back(t);
  std::sort(live.begin(), live.end());
  live.erase(std::unique(live.begin(), live.end()), live.end());
  // The index of t in `live`, or live.size() when t is not there.
  auto index = [&](TetId t) {
    const auto it = std::lower_bound(live.begin(), live.end(), t);
    return static_cast<std::size_t>(it != live.end() && *it == t ? it - live.begin()
                                                                  : live.end() - live.begin());
  };
  std::vector<std::uint8_t> done(live.size(), 0);
  std::vector<TetId> queue;
  // Seeds: tets with a neighbour whose flag predates the break.
  for (std::size_t i = 0; i < live.size(); ++i)
    for (int f = 0; f < 4; ++f) {
      const TetId n = s.neighbour(live[i], f);
      if (!s.is_ghost(n) && index(n) < live.size()) continue;
      const bool across = m.face_flips(live[i], f);
      m.inside[live[i]] = static_cast<std::uint8_t>((s.is_ghost(n) ? 0 : m.inside[n]) ^ across);
      done[i] = 1;
      queue.push_back(live[i]);
      break;
    }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const TetId t = queue[q];
    for (int f = 0; f < 4; ++f) {
      const TetId n = s.neighbour(t, f);
      if (s.is_ghost(n)) continue;
      const std::size_t j = index(n);
      if (j == live.size() || done[j]) continue;
      const bool across = m.face_flips(t, f);
      m.inside[n] = static_cast<std::uint8_t>(m.inside[t] ^ across);
      done[j] = 1;
      queue.push_back(n);
    }
  }
  return live;
}

bool star_flags_consistent(const VolumeMesh& m, std::span<const TetId> star) {
  const TetStore& s = m.dt.store();
  for (const TetId t : star) {
    if (s.is_ghost(t)) continue;
    for (int f = 0; f < 4; ++f) {
      const TetId n = s.neighbour(t, f);
      const int other = s.is_ghost(n) ? 0 : m.inside[n];
      if ((m.inside[t] ^ other) != (m.face_flips(t, f) ? 1 : 0)) return false;
    }
  }
  return true;
}

std::vector<TetId> reflag_all(VolumeMesh& m, std::size_t& conflicts) {
  const TetStore& s = m.dt.store();
  std::vector<std::uint8_t> flag(s.slots(), 2);  // 2: not reached yet
  std::vector<TetId> queue;
  conflicts = 0;
  auto reach = [&](TetId n, std::uint8_t value) {
    if (flag[n] == 2) {
      flag[n] = value;
      queue.push_back(n);
    } else if (flag[n] != value) {
      ++conflicts;
    }
  };
  for (TetId g = 0; g < s.slots(); ++g) {
    if (!s.is_alive(g) || !s.is_ghost(g)) continue;
    for (int f = 0; f < 4; ++f) {
      const TetId n = s.neighbour(g, f);
      if (!s.is_ghost(n)) reach(n, m.face_flips(n, s.back_face(g, f)) ? 1 : 0);
    }
  }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const TetId t = queue[q];
    for (int f = 0; f < 4; ++f) {
      const TetId n = s.neighbour(t, f);
      if (s.is_ghost(n)) continue;
      reach(n, static_cast<std::uint8_t>(flag[t] ^ (m.face_flips(t, f) ? 1 : 0)));
    }
  }
  conflicts /= 2;  // each disagreeing face is met from both sides
  std::vector<TetId> changed;
  for (TetId t = 0; t < s.slots(); ++t)
    if (flag[t] != 2 && flag[t] != m.inside[t]) {
      m.inside[t] = flag[t];
      changed.push_back(t);
    }
  return changed;
}

void ConformityTracker::start(const VolumeMesh& m) {
  if (m.missing_subfacets.empty() && m.missing_subsegments.empty()) return;
  for (const std::uint32_t id : m.missing_subsegments) add(true, m, id);
  for (const std::uint32_t id : m.missing_subfacets) add(false, m, id);
  const TetStore& s = m.dt.store();
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t)) dirty_.push_back(t);
}

void ConformityTracker::doomed_none() {
  doomed_.subsegments.clear();
  doomed_.subfacets.clear();
}

const EncroachedLists& ConformityTracker::doomed(const VolumeMesh& m, const Cavity& c) {
  doomed_none();
  doomed_elements(m, c, doomed_);
  return doomed_;
}

bool ConformityTracker::committed(const VolumeMesh& m, VertexId v, std::span<const TetId> star) {
  bool fresh = false;  // an element listed that was not (a reused id counts as new)
  for (const Encroached& e : doomed_.subsegments) fresh = add(true, m, e.id) || fresh;
  for (const Encroached& e : doomed_.subfacets) fresh = add(false, m, e.id) || fresh;
  found_.subsegments.clear();
  found_.subfacets.clear();
  missing_at(m, v, star, found_);
  for (const Encroached& e : found_.subsegments) fresh = add(true, m, e.id) || fresh;
  for (const Encroached& e : found_.subfacets) fresh = add(false, m, e.id) || fresh;
  if (fresh || broken()) dirty_.insert(dirty_.end(), star.begin(), star.end());
  return fresh;
}

std::optional<ConformityTracker::Next> ConformityTracker::next(const SurfaceMesh& s) {
  while (!segments_.list.empty() || !facets_.list.empty()) {
    const bool seg = !segments_.list.empty();
    const Encroached e = (seg ? segments_ : facets_).pop();
    if (seg ? still_subsegment(s, e) : still_subfacet(s, e)) return Next{seg, e};
  }
  return std::nullopt;
}

void ConformityTracker::wait_again(const Next& n) {
  (n.subsegment ? segments_ : facets_).push(n.e);
}

bool ConformityTracker::Missing::add(std::uint32_t id, const std::array<std::uint32_t, 3>& v) {
  if (const auto it = at.find(id); it != at.end()) {
    Encroached& e = list[it->second];
    if (e.v == v) return false;
    e.v = v;
    return true;
  }
  push({id, v, kNone, kNoTet});
  return true;
}

void ConformityTracker::Missing::push(const Encroached& e) {
  const auto [it, fresh] = at.try_emplace(e.id, list.size());
  if (fresh)
    list.push_back(e);
  else
    list[it->second] = e;  // listed again meanwhile: once
}

Encroached ConformityTracker::Missing::pop() {
  const Encroached e = list.back();
  list.pop_back();
  at.erase(e.id);
  return e;
}

bool ConformityTracker::add(bool subsegment, const VolumeMesh& m, std::uint32_t id) {
  if (subsegment) {
    const Subsegment& x = m.surf.subsegment(id);
    return segments_.add(id, {x.v[0], x.v[1], 0});
  }
  return facets_.add(id, m.surf.subfacet(id).v);
}

std::vector<TetId> ConformityTracker::restore(VolumeMesh& m) {
  std::vector<TetId> made = reflag(m, dirty_);
  dirty_.clear();
  return made;
}

std::vector<ConformityTracker::Next> ConformityTracker::abandon(VolumeMesh& m) {
  std::vector<Next> left;
  while (const auto n = next(m.surf)) left.push_back(*n);
  if (broken()) restore(m);
  return left;
}

}  // namespace pdr::refine
