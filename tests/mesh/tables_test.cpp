// The local numbering tables (mesh/tables.hpp): the static_asserts run when this file
// compiles; here the same facts are checked with real geometry (exact predicates).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "geom/exact.hpp"
#include "mesh/tables.hpp"

namespace pdr {
namespace {

using tables::kEdgeFace;
using tables::kEdgeVertex;
using tables::kFaceVertex;

// With v a positive tet, face f as listed has v_f strictly on its negative side: the
// face normal points out of the tet.
void expect_faces_outward(const std::array<Point, 4>& v) {
  ASSERT_EQ(exact::orient3d(v[0], v[1], v[2], v[3]), Sign::Positive);
  for (int f = 0; f < 4; ++f) {
    const auto& fv = kFaceVertex[f];
    EXPECT_EQ(exact::orient3d(v[fv[0]], v[fv[1]], v[fv[2]], v[f]), Sign::Negative)
        << "face " << f;
  }
}

TEST(Tables, UnitTetFacesPointOutward) {
  const std::array<Point, 4> v{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  expect_faces_outward(v);
  // Points just beyond each face, chosen exactly.
  const std::array<Point, 4> beyond{{{1, 1, 1}, {-1, 0.25, 0.25}, {0.25, -1, 0.25},
                                     {0.25, 0.25, -1}}};
  for (int f = 0; f < 4; ++f) {
    const auto& fv = kFaceVertex[f];
    EXPECT_EQ(exact::orient3d(v[fv[0]], v[fv[1]], v[fv[2]], beyond[f]), Sign::Positive)
        << "face " << f;
  }
}

TEST(Tables, EdgesLieOnTheirFaces) {
  for (int e = 0; e < 6; ++e)
    for (int k = 0; k < 2; ++k) {
      const auto& fv = kFaceVertex[kEdgeFace[e][k]];
      for (int end = 0; end < 2; ++end)
        EXPECT_NE(std::find(fv.begin(), fv.end(), kEdgeVertex[e][end]), fv.end());
    }
}

RC_GTEST_PROP(Tables, RandomPositiveTetFacesPointOutward, ()) {
  auto coord = rc::gen::map(rc::gen::inRange(-1000, 1001), [](int x) { return x / 8.0; });
  std::array<Point, 4> v;
  for (auto& p : v) p = {*coord, *coord, *coord};
  const Sign o = exact::orient3d(v[0], v[1], v[2], v[3]);
  RC_PRE(o != Sign::Zero);
  if (o == Sign::Negative) std::swap(v[0], v[1]);
  for (int f = 0; f < 4; ++f) {
    const auto& fv = kFaceVertex[f];
    RC_ASSERT(exact::orient3d(v[fv[0]], v[fv[1]], v[fv[2]], v[f]) == Sign::Negative);
  }
}

}  // namespace
}  // namespace pdr
