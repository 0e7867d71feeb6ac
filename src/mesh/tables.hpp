// Local numbering of a tetrahedron: every constant table of the kernel, in one place.
//
// A tet stores its vertices in slots 0..3. Face f is the face OPPOSITE slot f. The pdr
// orientation convention (geom/predicates.hpp): tet (v0,v1,v2,v3) is *positive* iff
// orient3d(v0,v1,v2,v3) > 0, i.e. v3 lies on the side of plane (v0,v1,v2) towards which
// (v1-v0)x(v2-v0) points. Every live tet in the store is positive.
//
//                 v3
//                /|\             face 0 = (v1 v2 v3)     opposite v0
//               / | \            face 1 = (v0 v3 v2)     opposite v1
//              /  |  \           face 2 = (v0 v1 v3)     opposite v2
//            v0 --|-- v2         face 3 = (v0 v2 v1)     opposite v3
//              \  |  /
//               \ | /            each listed so that (b-a)x(c-a) points OUT of the tet:
//                \|/             orient3d(face f, v_f) < 0, and orient3d(face f, q) > 0
//                 v1             for q strictly beyond face f (the walk's test).
//
// Invariants checked below by static_assert:
//   - face f lists the three slots other than f, each once;
//   - (face f, f) is an odd permutation of (0,1,2,3): the face is oriented outward;
//   - every edge appears in exactly two faces, traversed in opposite directions (the
//     faces of the tet form a consistently oriented closed surface).
// Ghost tets (tet_store.hpp) keep the ghost vertex in slot 3, so their face 3 is the hull
// face, whose outward orientation (away from the ghost) is kFaceVertex[3]; read the other
// way, slots (0,1,2) of a ghost tet are the hull face oriented OUT of the hull.
#pragma once

#include <array>

namespace pdr::tables {

// kFaceVertex[f] = slots of face f, ordered so the face normal points out of the tet.
inline constexpr std::array<std::array<int, 3>, 4> kFaceVertex{{
    {1, 2, 3},
    {0, 3, 2},
    {0, 1, 3},
    {0, 2, 1},
}};

// The six edges as slot pairs (i < j), and for each edge the two faces that contain it
// (the faces opposite the two slots not on the edge).
inline constexpr std::array<std::array<int, 2>, 6> kEdgeVertex{{
    {0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3},
}};
inline constexpr std::array<std::array<int, 2>, 6> kEdgeFace{{
    {2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1},
}};

// ---- compile-time checks of the invariants above -------------------------------------

namespace detail {

// Parity of the permutation (p0,p1,p2,p3) of (0,1,2,3): true when odd.
constexpr bool odd_permutation(std::array<int, 4> p) {
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (p[i] > p[j]) ++inversions;
  return inversions % 2 == 1;
}

constexpr bool faces_are_complements() {
  for (int f = 0; f < 4; ++f) {
    int seen = 0;
    for (int k = 0; k < 3; ++k) {
      int s = kFaceVertex[f][k];
      if (s < 0 || s > 3 || s == f || (seen & (1 << s))) return false;
      seen |= 1 << s;
    }
  }
  return true;
}

constexpr bool faces_point_outward() {
  for (int f = 0; f < 4; ++f) {
    const auto& v = kFaceVertex[f];
    if (!odd_permutation({v[0], v[1], v[2], f})) return false;
  }
  return true;
}

// Count, over all faces, directed edges a->b (cyclic order within the face).
constexpr int directed_edge_count(int a, int b) {
  int n = 0;
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k)
      if (kFaceVertex[f][k] == a && kFaceVertex[f][(k + 1) % 3] == b) ++n;
  return n;
}

constexpr bool faces_consistently_oriented() {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (a != b && directed_edge_count(a, b) != 1) return false;
  return true;
}

constexpr bool edge_faces_match() {
  for (int e = 0; e < 6; ++e) {
    int a = kEdgeVertex[e][0], b = kEdgeVertex[e][1];
    if (!(a < b)) return false;
    for (int k = 0; k < 2; ++k) {
      int f = kEdgeFace[e][k];
      if (f == a || f == b) return false;  // the face must contain both ends
    }
    if (kEdgeFace[e][0] == kEdgeFace[e][1]) return false;
  }
  return true;
}

}  // namespace detail

static_assert(detail::faces_are_complements(), "face f must list the slots other than f");
static_assert(detail::faces_point_outward(), "faces must be oriented out of a positive tet");
static_assert(detail::faces_consistently_oriented(),
              "each directed edge must occur in exactly one face");
static_assert(detail::edge_faces_match(), "kEdgeFace must list the faces holding each edge");

}  // namespace pdr::tables
