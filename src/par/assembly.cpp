// The whole mesh from the submeshes' tets; see par/assembly.hpp.
#include "par/assembly.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "mesh/tables.hpp"

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

namespace {

// A face by its vertex ids, sorted, and the half-face it is of.
struct OpenFace {
  std::array<VertexId, 3> key;
  HalfFace h;
};

}  // namespace

Assembled assemble(refine::VolumeMesh& m, std::span<const Piece> pieces) {
  Assembled out;
  const std::size_t n0 = m.dt.num_points();
  std::vector<Point> points(m.dt.points().begin(), m.dt.points().end());
  std::unordered_map<Gid, VertexId> fresh;  // vertices made in the parallel phase
  std::size_t total = 0;
  for (const Piece& p : pieces) total += p.tets.size();
  TetStore st;
  st.reserve(total);
  std::vector<std::uint8_t> inside;
  inside.reserve(total);
  std::vector<OpenFace> open;
  std::vector<VertexId> vmap;
  std::vector<TetId> ids;
  for (const Piece& p : pieces) {
    vmap.clear();
    for (const VertexRecord& v : p.vertices) {
      if (v.gid < n0) {
        vmap.push_back(static_cast<VertexId>(v.gid));
        continue;
      }
      const auto [it, added] = fresh.try_emplace(v.gid, static_cast<VertexId>(points.size()));
      if (added) points.push_back(v.p);
      vmap.push_back(it->second);
    }
    const auto vertex = [&](std::uint32_t i) { return i == kGhostVertex ? kGhostVertex : vmap.at(i); };
    ids.clear();
    for (const PieceTet& x : p.tets) {
      ids.push_back(st.create(vertex(x.v[0]), vertex(x.v[1]), vertex(x.v[2]), vertex(x.v[3])));
      if (inside.size() <= ids.back()) inside.resize(ids.back() + 1, 0);
      inside[ids.back()] = x.inside & 1;
      if ((x.inside & 2) != 0) out.deferred.push_back(ids.back());
    }
    for (std::size_t j = 0; j < p.tets.size(); ++j)
      for (int f = 0; f < 4; ++f) {
        const std::uint32_t a = p.tets[j].across[static_cast<std::size_t>(f)];
        if (a != kAcrossProxy) {
          st.set_opposite(half_face(ids[j], f), half_face(ids.at(a >> 2), static_cast<int>(a & 3)));
          continue;
        }
        const auto& fv = tables::kFaceVertex[f];
        OpenFace o{{st.vertex(ids[j], fv[0]), st.vertex(ids[j], fv[1]), st.vertex(ids[j], fv[2])},
                   half_face(ids[j], f)};
        std::sort(o.key.begin(), o.key.end());
        open.push_back(o);
      }
  }
  // Faces between pieces: each exactly twice.
  std::sort(open.begin(), open.end(),
            [](const OpenFace& a, const OpenFace& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < open.size(); i += 2) {
    if (i + 1 == open.size() || open[i].key != open[i + 1].key ||
        (i + 2 < open.size() && open[i + 2].key == open[i].key))
      throw std::logic_error("assembly: a face between submeshes (vertices " +
                             std::to_string(open[i].key[0]) + ", " +
                             std::to_string(open[i].key[1]) + ", " +
                             std::to_string(open[i].key[2]) + ") is not shared by two tets");
    st.link(open[i].h, open[i + 1].h);
  }
  out.added = points.size() - n0;
  m.dt.adopt(std::move(points), std::move(st));
  m.inside = std::move(inside);
  for (std::size_t v = n0; v < n0 + out.added; ++v)
    m.map_vertex(static_cast<VertexId>(v), refine::kNone);
  return out;
}

}  // namespace pdr::par
