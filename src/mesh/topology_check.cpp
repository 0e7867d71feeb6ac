// TetStore::reserve, and TetStore::check_topology: the combinatorial invariants of tet_store.hpp, decided
// without geometry (orientation and the Delaunay property are checked elsewhere, with
// predicates). Pure: reads the store, returns the violations found (at most a few dozen,
// so a broken store does not flood a test log).
#include <algorithm>
#include <array>
#include <sstream>

#include "mesh/tables.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

namespace {

constexpr std::size_t kMaxReports = 32;

std::string vertex_name(VertexId v) {
  if (v == kGhostVertex) return "ghost";
  if (v == kDeadVertex) return "dead";
  return std::to_string(v);
}

std::array<VertexId, 3> face_vertices(const TetStore& s, TetId t, int f) {
  const auto& fv = tables::kFaceVertex[f];
  return {s.vertex(t, fv[0]), s.vertex(t, fv[1]), s.vertex(t, fv[2])};
}

// True when b is a cyclic rotation of the reverse of a.
bool reversed_rotation(const std::array<VertexId, 3>& a, const std::array<VertexId, 3>& b) {
  const std::array<VertexId, 3> r{a[0], a[2], a[1]};
  for (int k = 0; k < 3; ++k)
    if (b[0] == r[k] && b[1] == r[(k + 1) % 3] && b[2] == r[(k + 2) % 3]) return true;
  return false;
}

}  // namespace

void TetStore::reserve(std::size_t tets) {
  data_.reserve(kRecord * tets);
}

std::vector<std::string> TetStore::check_topology() const {
  std::vector<std::string> out;
  auto report = [&](const std::string& s) {
    if (out.size() < kMaxReports) out.push_back(s);
  };
  const std::size_t n = slots();
  std::size_t alive = 0;
  for (TetId t = 0; t < n; ++t) {
    if (!is_alive(t)) continue;
    ++alive;
    const VertexId* v = vertices(t);
    const bool proxy = v[3] == kRemoteVertex;
    for (int i = 0; i < 4; ++i) {
      if (proxy && (i == 3 || v[i] == kGhostVertex)) continue;
      if (v[i] == kDeadVertex || v[i] == kNoVertex || v[i] == kRemoteVertex)
        report("tet-vertices: tet " + std::to_string(t) + " slot " + std::to_string(i) +
               " holds a reserved id");
      if (v[i] == kGhostVertex && i != 3)
        report("ghost-in-slot-3: tet " + std::to_string(t) + " has the ghost in slot " +
               std::to_string(i));
      for (int j = i + 1; j < 4; ++j)
        if (v[i] == v[j])
          report("tet-vertices-distinct: tet " + std::to_string(t) + " repeats vertex " +
                 vertex_name(v[i]));
    }
    for (int f = 0; f < 4; ++f) {
      const HalfFace h = half_face(t, f);
      const HalfFace o = opposite(h);
      std::ostringstream where;
      where << "tet " << t << " face " << f;
      if (proxy && f != 3) {
        if (o != kNoHalfFace) report("proxy-open: " + where.str() + " of a proxy is linked");
        continue;
      }
      if (o == kNoHalfFace || tet_of(o) >= n) {
        report("adjacency-defined: " + where.str() + " has no neighbour");
        continue;
      }
      const TetId u = tet_of(o);
      if (!is_alive(u)) {
        report("adjacency-live: " + where.str() + " points to dead tet " + std::to_string(u));
        continue;
      }
      if (u == t) {
        report("adjacency-not-self: " + where.str() + " points to its own tet");
        continue;
      }
      if (opposite(o) != h) {
        report("adjacency-symmetric: " + where.str() + " -> tet " + std::to_string(u) +
               " face " + std::to_string(face_of(o)) + " which does not point back");
        continue;
      }
      if (!reversed_rotation(face_vertices(*this, t, f), face_vertices(*this, u, face_of(o))))
        report("shared-face-opposite-orientation: " + where.str() + " and tet " +
               std::to_string(u) + " face " + std::to_string(face_of(o)) +
               " do not share the face in opposite orientation");
      if (is_ghost(t) && is_ghost(u) && f == 3)
        report("hull-face-finite-side: ghost tet " + std::to_string(t) +
               " has a ghost across its hull face");
      if (is_proxy(u) && face_of(o) != 3)
        report("proxy-face-3: " + where.str() + " is glued to an open face of proxy " +
               std::to_string(u));
      if (proxy && is_proxy(u))
        report("proxy-local-side: proxy " + std::to_string(t) + " is glued to proxy " +
               std::to_string(u));
    }
  }
  if (alive != live_)
    report("live-count: counted " + std::to_string(alive) + " live tets, store says " +
           std::to_string(live_));
  // The free list holds exactly the dead slots.
  std::size_t free_count = 0;
  for (TetId t = free_head_; t != kNoTet && free_count <= n; t = opposite(t, 0)) {
    if (t >= n || is_alive(t)) {
      report("free-list: holds live or out-of-range tet " + std::to_string(t));
      break;
    }
    ++free_count;
  }
  if (free_count + alive != n)
    report("free-list: " + std::to_string(free_count) + " free + " + std::to_string(alive) +
           " live != " + std::to_string(n) + " slots");
  return out;
}

}  // namespace pdr
