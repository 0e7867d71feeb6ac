// CavityCommitter::commit (insert.hpp).
#include "delaunay/insert.hpp"

#include <cassert>

#include "mesh/tables.hpp"

namespace pdr {

namespace {

constexpr std::uint64_t edge_key(VertexId a, VertexId b) {
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

}  // namespace

void CavityCommitter::reset_table(std::size_t entries) {
  int bits = 6;
  while ((std::size_t{1} << bits) < 2 * entries) ++bits;
  if (bits > table_bits_) {
    table_bits_ = bits;
    table_.assign(std::size_t{1} << bits, Slot{0, 0, 0});
    stamp_ = 0;
  }
  if (++stamp_ == 0) {  // stamps wrapped: clear for real
    for (Slot& e : table_) e.stamp = 0;
    stamp_ = 1;
  }
}

HalfFace CavityCommitter::match_or_store(VertexId a, VertexId b, HalfFace h) {
  const std::size_t mask = (std::size_t{1} << table_bits_) - 1;
  const std::uint64_t want = edge_key(b, a);
  const std::uint64_t mine = edge_key(a, b);
  // Both keys of an edge hash alike (symmetric mix), so the search for the reversed key
  // and the slot for this key share one probe sequence.
  const std::uint64_t sym = (static_cast<std::uint64_t>(a) + b) * 0x9E3779B97F4A7C15ull ^
                            (static_cast<std::uint64_t>(a ^ b) << 17);
  std::size_t i = static_cast<std::size_t>((sym * 0xBF58476D1CE4E5B9ull) >> (64 - table_bits_));
  for (;; i = (i + 1) & mask) {
    Slot& e = table_[i];
    if (e.stamp != stamp_) {
      e = Slot{mine, h, stamp_};
      return kNoHalfFace;
    }
    if (e.key == want) return e.value;
  }
}

TetId CavityCommitter::commit(TetStore& s, const Cavity& c, VertexId v) {
  const std::size_t nb = c.boundary.size();
  const std::size_t nc = c.conflict.size();
  assert(nb >= 4 && nc >= 1);
  // 1. Read everything the new tets need before any slot is overwritten.
  verts_.resize(4 * nb);
  outer_.resize(nb);
  for (std::size_t i = 0; i < nb; ++i) {
    const HalfFace h = c.boundary[i];
    const VertexId* tv = s.vertices(tet_of(h));
    for (int k = 0; k < 4; ++k) verts_[4 * i + k] = tv[k];
    verts_[4 * i + face_of(h)] = v;
    outer_[i] = s.opposite(h);
  }
  // 2. Choose ids: reuse the cavity's slots, then take fresh ones; free any left over.
  ids_.resize(nb);
  const std::size_t reuse = nb < nc ? nb : nc;
  for (std::size_t i = 0; i < reuse; ++i) ids_[i] = c.conflict[i];
  for (std::size_t i = reuse; i < nc; ++i) s.destroy(c.conflict[i]);
  for (std::size_t i = reuse; i < nb; ++i)
    ids_[i] = s.create(kNoVertex, kNoVertex, kNoVertex, kNoVertex);
  // 3. Write vertices and glue each new tet to the outside across its boundary face.
  for (std::size_t i = 0; i < nb; ++i) {
    const VertexId* nv = &verts_[4 * i];
    s.set_vertices(ids_[i], nv[0], nv[1], nv[2], nv[3]);
    s.link(half_face(ids_[i], face_of(c.boundary[i])), outer_[i]);
  }
  // 4. Glue new tets to each other across the faces holding v, by boundary edges.
  reset_table(3 * nb / 2);
  TetId finite = kNoTet;
  for (std::size_t i = 0; i < nb; ++i) {
    const int f = face_of(c.boundary[i]);
    const auto& fv = tables::kFaceVertex[f];
    const VertexId* nv = &verts_[4 * i];
    for (int k = 0; k < 3; ++k) {
      const int j = fv[k];  // face j holds v and the boundary edge opposite slot j
      const VertexId a = nv[fv[(k + 1) % 3]];
      const VertexId b = nv[fv[(k + 2) % 3]];
      const HalfFace mine = half_face(ids_[i], j);
      const HalfFace other = match_or_store(a, b, mine);
      if (other != kNoHalfFace) s.link(mine, other);
    }
    if (finite == kNoTet && nv[3] != kGhostVertex) finite = ids_[i];
  }
  return finite != kNoTet ? finite : ids_[0];
}

}  // namespace pdr
