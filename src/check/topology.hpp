// Topology of a tet soup: its distinct faces (with the tets holding each), its boundary
// faces (held by one tet), and its distinct edges. Computed from scratch, without trusting
// any adjacency the mesh producer may have had; requires valid indices and < 2^30 tets.
//
// Local numbering: face `f` of tet (v0, v1, v2, v3) is the face opposite vertex vf. For a
// positive tet these vertex orders make each face's normal (b-a)x(c-a) point outward:
//
//        f=0: (v1, v2, v3)   f=1: (v0, v3, v2)   f=2: (v0, v1, v3)   f=3: (v0, v2, v1)
//
// (each is an odd permutation of the tet with the apex moved last, so orient3d(face, apex)
// = -orient3d(tet) < 0).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "check/check.hpp"
#include "mesh/huge_pages.hpp"

namespace pdr::check {

inline constexpr std::array<std::array<int, 3>, 4> kFaceVertices = {
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

// Parity of the permutation taking (v0,v1,v2,v3) to (face f in kFaceVertices order, vf):
// always odd, which is what makes the table outward.
constexpr bool face_table_is_odd() {
  for (int f = 0; f < 4; ++f) {
    const std::array<int, 4> p = {kFaceVertices[f][0], kFaceVertices[f][1], kFaceVertices[f][2], f};
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j] ? 1 : 0;
    if (inversions % 2 == 0) return false;
  }
  return true;
}
static_assert(face_table_is_odd(), "face table must orient faces outward");

struct FaceRef {
  std::uint32_t tet;
  std::uint8_t local;  // face index in kFaceVertices
  // face_of(tet, local) is an odd permutation of the sorted face (for a tet of distinct
  // vertices; meaningless otherwise). Since (face_of(t, f), t[f]) is an odd permutation of
  // t, the sorted face followed by the apex is an even permutation of t exactly when this
  // is set; and the two holders of a face list it in opposite orientations exactly when
  // they differ here. The checks read it instead of the tet.
  std::uint8_t odd;
};

// mesh/huge_pages.hpp's allocator (large arrays advised for huge pages), except that a
// resize leaves trivially constructible elements uninitialized: the topology's arrays are
// sized once, then filled by every thread, each faulting in its own pages, instead of
// first zeroed by one.
template <class T>
struct UninitAllocator : HugePageAllocator<T> {
  template <class U>
  struct rebind {
    using other = UninitAllocator<U>;
  };
  UninitAllocator() = default;
  template <class U>
  UninitAllocator(const UninitAllocator<U>&) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) == 0)
      ::new (static_cast<void*>(p)) U;
    else
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <class T>
using FilledArray = std::vector<T, UninitAllocator<T>>;
// (A default member initializer would make the resize write every element on one thread.)
static_assert(std::is_trivially_default_constructible_v<FaceRef> &&
              std::is_trivially_default_constructible_v<Tri>);

struct Topology {
  FilledArray<Tri> faces;                 // distinct faces, vertex ids sorted, in lex order
  FilledArray<std::uint32_t> face_start;  // faces.size() + 1 offsets into refs
  FilledArray<FaceRef> refs;              // the tets holding each face
  FilledArray<std::uint32_t> boundary;    // indices of faces held by exactly one tet
  FilledArray<std::uint64_t> edges;       // distinct edges (u << 32 | v), u < v, sorted

  std::span<const FaceRef> holders(std::size_t face) const {
    return {refs.data() + face_start[face], refs.data() + face_start[face + 1]};
  }
  std::optional<std::size_t> find_face(Tri sorted_vertices) const;
  bool has_edge(std::uint32_t u, std::uint32_t v) const;
};

Topology build_topology(std::span<const Tet> tets, unsigned threads);
// As above, with per-thread stamp arrays (one entry per vertex) only while threads x
// vertices <= stamp_entries (the default allows 2^28); 0 always sorts repeats away.
Topology build_topology(std::span<const Tet> tets, unsigned threads, std::size_t stamp_entries);

inline std::uint64_t edge_key(std::uint32_t u, std::uint32_t v) {
  if (u > v) std::swap(u, v);
  return (std::uint64_t{u} << 32) | v;
}

// The face of tet t opposite local vertex f, oriented outward for a positive tet.
inline Tri face_of(const Tet& t, int f) {
  return {t[kFaceVertices[f][0]], t[kFaceVertices[f][1]], t[kFaceVertices[f][2]]};
}

}  // namespace pdr::check
