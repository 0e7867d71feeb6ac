// The ranks' listing of the output mesh (par/mesh_parts.hpp): vertex numbers in the order
// the parts are joined, and when a part is final (no deferred tet, nothing encroached
// around a vertex made on ∂Ω). par_refinement_test compares whole listings with the
// assembled mesh's export.
#include "par/mesh_parts.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "mesh/tables.hpp"
#include "par/cavity_search.hpp"
#include "par/par_meshes.hpp"
#include "par/partition.hpp"
#include "par/refinement_rules.hpp"

namespace pdr::par {
namespace {

Gid made(std::size_t maker, std::size_t serial) {
  return (Gid{maker} + 1) << 40 | kVertexBit | Gid{serial};
}

TEST(VertexNumbers, FollowTheJoinOrderOfTheRanksSubmeshes) {
  // Five submeshes on two ranks: rank 0 lists submeshes 0, 2, 4, rank 1 then 1, 3.
  const std::uint64_t counts[] = {3, 5, 2, 4, 1};
  const VertexNumbers num(100, counts, 2);
  EXPECT_EQ(num.total(), 115u);
  EXPECT_EQ(num(7), 7u);  // M_o's vertices keep their ids
  EXPECT_EQ(num(made(0, 0)), 100u);
  EXPECT_EQ(num(made(0, 2)), 102u);
  EXPECT_EQ(num(made(2, 0)), 103u);
  EXPECT_EQ(num(made(4, 0)), 105u);
  EXPECT_EQ(num(made(1, 0)), 106u);
  EXPECT_EQ(num(made(3, 3)), 114u);
  EXPECT_THROW(num(made(0, 3)), std::logic_error);  // beyond the submesh's count
  EXPECT_THROW(num(made(4, 1)), std::logic_error);
  EXPECT_THROW(num(made(5, 0)), std::logic_error);  // no such submesh
}

TEST(SurfaceClosed, EveryEdgeInAnEvenNumberOfFaces) {
  std::vector<Tri> tet{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  EXPECT_TRUE(surface_closed(tet));
  std::vector<Tri> two = tet;  // a second tet sharing only the edge {0, 1}: four faces on it
  for (const Tri& f : std::vector<Tri>{{0, 1, 4}, {0, 5, 1}, {1, 5, 4}, {4, 5, 0}}) two.push_back(f);
  EXPECT_TRUE(surface_closed(two));
  tet.pop_back();
  EXPECT_FALSE(surface_closed(tet));
  EXPECT_TRUE(surface_closed({}));
}

// Submesh 0 of a two-part cut of M_o, labelled with D.
Submesh labelled_part(const refine::VolumeMesh& m, const RefinementRules& rules) {
  const Partition part = partition_tets(m.dt.store(), m.inside, 2, 1);
  Submesh s = Submesh::extract(0, m.dt.store(), m.dt.points(), m.inside, part, rules.vertex_tags());
  rules.label(s);
  return s;
}

// An inside real tet of s with a face that is a subfacet (labelled), and that face.
std::pair<TetId, int> tet_on_d(const Submesh& s) {
  const TetStore& st = s.store();
  for (TetId t = 0; t < st.slots(); ++t) {
    if (!st.is_alive(t) || st.is_proxy(t) || st.is_ghost(t) || !s.inside(t)) continue;
    const VertexId* v = st.vertices(t);
    for (int f = 0; f < 4; ++f) {
      const auto& fv = tables::kFaceVertex[f];
      if (s.face_label(v[fv[0]], v[fv[1]], v[fv[2]]) != kNoLabel) return {t, f};
    }
  }
  return {kNoTet, 0};
}

TEST(PartIsFinal, NotWithADeferredTet) {
  const refine::VolumeMesh& m = test::cube_in_cube();
  const RefinementRules rules(m, {2.0, std::nullopt, std::nullopt}, true);
  Submesh s = labelled_part(m, rules);
  EXPECT_TRUE(part_is_final(s));
  const auto [t, f] = tet_on_d(s);
  ASSERT_NE(t, kNoTet);
  s.mark_deferred(t);
  EXPECT_FALSE(part_is_final(s));
}

// A vertex made next to a subfacet, inside its equatorial ball: as a point on ∂Ω (a
// subfacet circumcenter's tag) its star holds the subfacet with the vertex encroaching it,
// so the part is not final; as an interior point (a tet's circumcenter) its star is not
// searched, as the assembly does not search it (par/assembly.hpp).
TEST(PartIsFinal, NotWithAnElementEncroachedAroundAVertexMadeOnD) {
  const refine::VolumeMesh& m = test::cube_in_cube();
  const RefinementRules rules(m, {2.0, std::nullopt, std::nullopt}, true);
  for (const auto cls : {refine::VertexClass::Facet, refine::VertexClass::Interior}) {
    Submesh s = labelled_part(m, rules);
    const auto [t, f] = tet_on_d(s);
    ASSERT_NE(t, kNoTet);
    const VertexId* v = s.store().vertices(t);
    const auto& fv = tables::kFaceVertex[f];
    const auto pts = s.points();
    Point p{};
    for (int k = 0; k < 3; ++k)  // the face's centroid, a hundredth of the way to the apex
      p[k] = (pts[v[fv[0]]][k] + pts[v[fv[1]]][k] + pts[v[fv[2]]][k]) / 3 * 0.99 + pts[v[f]][k] * 0.01;
    CavitySearch search;
    const RootCavity& rc = search.root_cavity(s, p, t);
    ASSERT_EQ(rc.kind, RootCavity::Kind::Complete);
    s.insert(rc.cavity, 1, static_cast<std::uint8_t>(1 + static_cast<int>(cls)));
    EXPECT_EQ(part_is_final(s), cls == refine::VertexClass::Interior);
  }
}

}  // namespace
}  // namespace pdr::par
