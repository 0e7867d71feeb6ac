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

void CavityCommitter::number_boundary_vertices(std::size_t nb, std::size_t vertex_count) {
  if (vertex_local_.size() < 2 * (vertex_count + 1))
    vertex_local_.resize(2 * (vertex_count + 1) + vertex_count / 2, 0);
  if (++commit_stamp_ == 0) {  // stamps wrapped: forget all
    for (std::size_t i = 0; i < vertex_local_.size(); i += 2) vertex_local_[i] = 0;
    commit_stamp_ = 1;
  }
  const std::size_t ghost_entry = vertex_count;
  local_.resize(3 * nb);
  std::uint32_t locals = 0;
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& fv = tables::kFaceVertex[faces_[i]];
    for (int k = 0; k < 3; ++k) {
      const VertexId x = verts_[4 * i + fv[k]];
      const std::size_t entry = x == kGhostVertex ? ghost_entry : std::size_t{x};
      std::uint32_t* e = &vertex_local_[2 * entry];
      // Branch-free (whether a vertex is new is random): a vertex seen first in this
      // commit takes the next number.
      const std::uint32_t old = e[1];
      const std::uint32_t fresh = 0u - static_cast<std::uint32_t>(e[0] != commit_stamp_);
      const std::uint32_t number = old ^ ((old ^ locals) & fresh);
      locals -= fresh;  // fresh is 0 or all ones
      e[0] = commit_stamp_;
      e[1] = number;
      local_[3 * i + k] = number;
    }
  }
  locals_ = locals;
}

void CavityCommitter::pair_dense(TetStore& s, std::size_t nb) {
  const std::size_t L = locals_;
  if (edge_face_.size() < L * L) edge_face_.resize(L * L);
  // Pass 1: directed edge (a,b) of boundary face i -> the face of new tet i holding it.
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& fv = tables::kFaceVertex[faces_[i]];
    const std::uint32_t* l = &local_[3 * i];
    edge_face_[l[1] * L + l[2]] = half_face(ids_[i], fv[0]);
    edge_face_[l[2] * L + l[0]] = half_face(ids_[i], fv[1]);
    edge_face_[l[0] * L + l[1]] = half_face(ids_[i], fv[2]);
  }
  // Pass 2: the neighbour across that face holds the reversed edge.
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& fv = tables::kFaceVertex[faces_[i]];
    const std::uint32_t* l = &local_[3 * i];
    s.set_opposite(half_face(ids_[i], fv[0]), edge_face_[l[2] * L + l[1]]);
    s.set_opposite(half_face(ids_[i], fv[1]), edge_face_[l[0] * L + l[2]]);
    s.set_opposite(half_face(ids_[i], fv[2]), edge_face_[l[1] * L + l[0]]);
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
    if (e.stamp != table_stamp_) {
      e = Slot{mine, h, table_stamp_};
      return kNoHalfFace;
    }
    if (e.key == want) return e.value;
  }
}

void CavityCommitter::pair_hashed(TetStore& s, std::size_t nb) {
  int bits = 6;
  while ((std::size_t{1} << bits) < 3 * nb) ++bits;  // load <= 1/2 (3nb/2 entries)
  if (bits > table_bits_) {
    table_bits_ = bits;
    table_.assign(std::size_t{1} << bits, Slot{0, 0, 0});
    table_stamp_ = 0;
  }
  if (++table_stamp_ == 0) {
    for (Slot& e : table_) e.stamp = 0;
    table_stamp_ = 1;
  }
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& fv = tables::kFaceVertex[faces_[i]];
    const VertexId* nv = &verts_[4 * i];
    for (int k = 0; k < 3; ++k) {
      const VertexId a = nv[fv[(k + 1) % 3]];
      const VertexId b = nv[fv[(k + 2) % 3]];
      const HalfFace mine = half_face(ids_[i], fv[k]);
      const HalfFace other = match_or_store(a, b, mine);
      if (other != kNoHalfFace) s.link(mine, other);
    }
  }
}

TetId CavityCommitter::commit(TetStore& s, const Cavity& c, VertexId v,
                              std::size_t vertex_count) {
  const std::size_t nb = c.boundary.size();
  const std::size_t nc = c.conflict.size();
  assert(nb >= 4 && nc >= 1);
  // 1. Read everything the new tets need before any slot is overwritten.
  verts_.resize(4 * nb);
  faces_.resize(nb);
  ids_.resize(nb);
  for (std::size_t i = 0; i < nb; ++i) {
    const HalfFace h = c.boundary[i];
    const VertexId* tv = s.vertices(tet_of(h));
    for (int k = 0; k < 4; ++k) verts_[4 * i + k] = tv[k];
    verts_[4 * i + face_of(h)] = v;
    faces_[i] = face_of(h);
    ids_[i] = s.opposite(h);  // the outside half-face, until step 3 replaces it
  }
  // 2. Choose ids: reuse the cavity's slots, then take fresh ones; free any left over.
  const std::size_t reuse = nb < nc ? nb : nc;
  for (std::size_t i = reuse; i < nc; ++i) s.destroy(c.conflict[i]);
  // 3. Write each new tet and glue it to the outside across its boundary face.
  TetId finite = kNoTet;
  for (std::size_t i = 0; i < nb; ++i) {
    const HalfFace outside = ids_[i];
    const VertexId* nv = &verts_[4 * i];
    TetId t;
    if (i < reuse) {
      t = c.conflict[i];
      s.set_vertices(t, nv[0], nv[1], nv[2], nv[3]);
    } else {
      t = s.create(nv[0], nv[1], nv[2], nv[3]);
    }
    ids_[i] = t;
    s.link(half_face(t, faces_[i]), outside);
    if (finite == kNoTet && nv[3] != kGhostVertex) finite = t;
  }
  // 4. Glue new tets to each other across the faces holding v.
  number_boundary_vertices(nb, vertex_count);
  if (locals_ <= dense_limit_) pair_dense(s, nb);
  else pair_hashed(s, nb);
  return finite != kNoTet ? finite : ids_[0];
}

}  // namespace pdr
