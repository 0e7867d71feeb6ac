// locate: find where a point lies in a triangulation by a visibility walk (orient3d only).
//
// From a start tet, repeatedly cross a face whose plane strictly separates the tet from p
// (orient3d(face, p) > 0 with the face oriented outward, mesh/tables.hpp). The face to try
// first is drawn from a small seeded generator and the face just entered through is never
// re-tested ("remembering stochastic walk", Devillers, Pion & Teillaud 2002): this ends
// with probability 1 in any triangulation, and follows the same path for the same seed.
// The walk stops
//   - in a finite tet that contains p in its closure (no face separates), or
//   - on entering a ghost tet: p is strictly outside that hull face, so the ghost tet
//     conflicts with p (conflict.hpp) and seeds the cavity, or
//   - on entering a proxy tet (parallel layer: mesh/tet_store.hpp): the walk would go on
//     in another submesh; the result names the proxy.
// If p equals a vertex of the final tet (exact coordinate equality), the result says so:
// a duplicate is reported, never inserted. A point equal to a vertex lies in the closure
// of a tet only if it is that tet's vertex, so this test is complete.
// Paper §1.2, step 1 (point location).
#pragma once

#include <cstdint>
#include <span>

#include "geom/point.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

// xorshift32; deterministic, never zero.
struct WalkRng {
  std::uint32_t state = 0x9E3779B9u;
  std::uint32_t next() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  }
};

struct Location {
  enum class Kind : std::uint8_t {
    InTet,        // tet is finite and contains p in its closure; p is no vertex of it
    OutsideHull,  // tet is a ghost tet whose hull face has p strictly outside
    OnVertex,     // p equals vertex `vertex` of tet
    Remote,       // tet is a proxy: p lies beyond its face, in another submesh
  };
  Kind kind = Kind::InTet;
  TetId tet = kNoTet;
  VertexId vertex = kNoVertex;
  std::uint32_t steps = 0;  // tets visited, for statistics
};

// Precondition: `start` is a live tet of a valid triangulation of pts (store non-empty).
Location locate(const TetStore& s, std::span<const Point> pts, const Point& p, TetId start,
                WalkRng& rng);

}  // namespace pdr
