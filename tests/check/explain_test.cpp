// explain_tet and tet_fields (check/explain.hpp, check/fields.hpp): a planted violation is
// described in full, and the per-tet fields mark exactly the tets the findings name.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "check/explain.hpp"
#include "check/fields.hpp"
#include "check_test_util.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

MeshData moved_vertex_mesh() {
  MeshData m = kuhn_grid(3);
  m.points[grid_id(3, 1, 1, 1)] = {1.0625, 1.125, 0.9375};  // as in delaunay_test.cpp
  return m;
}

Report full_report(const MeshData& m) {
  Options o;
  o.ratio_bound = 2.0;
  o.max_reported = 1u << 20;
  return run(m, o);
}

TEST(Explain, ViolatingTetListsTheVertexInsideItsSphere) {
  const MeshData m = moved_vertex_mesh();
  const Report r = full_report(m);
  const CheckResult& d = result(r, "delaunay.empty_sphere");
  ASSERT_FALSE(d.findings.empty());
  const Finding& f = d.findings.front();
  const TetExplanation e = explain_tet(view_of(m), r, f.id);
  EXPECT_TRUE(e.indices_valid);
  EXPECT_EQ(e.orientation, Sign::Positive);
  ASSERT_GE(e.inside_total, 1u);
  EXPECT_EQ(e.inside.front(), f.vertices.back());  // the offender comes last in the finding
  ASSERT_TRUE(e.ratio_below_bound.has_value());
  EXPECT_EQ(*e.ratio_below_bound, *e.ratio < 2.0);
  bool named = false;
  for (const auto& [id, g] : e.findings) named = named || id == "delaunay.empty_sphere";
  EXPECT_TRUE(named);
  EXPECT_NE(to_text(e).find("strictly inside the circumsphere (exact): "), std::string::npos);
  EXPECT_EQ(to_json(e)["inside_total"], e.inside_total);
}

TEST(Explain, CleanTetHasNothingInsideAndNoFindings) {
  const MeshData m = kuhn_grid(2);
  const Report r = full_report(m);
  const TetExplanation e = explain_tet(view_of(m), r, 0);
  EXPECT_EQ(e.inside_total, 0u);
  EXPECT_GT(e.cospherical_total, 0u);  // the cube's corners are cospherical
  EXPECT_TRUE(e.findings.empty());
  ASSERT_TRUE(e.ratio.has_value());
  EXPECT_NEAR(*e.ratio, std::sqrt(3.0) / 2.0, 1e-12);  // Kuhn tet: R = sqrt(3)/2, lmin = 1
}

// A Kuhn grid scaled by 2^-366 (edges about 1e-110): every coordinate difference is below
// the filters' range. The orientation, the spheres and the ratio must come out as for the
// unit grid (the checker's own range handling), not as the underflowed floating-point
// values (a zero orientation, an empty or NaN ratio).
TEST(Explain, TinyTetIsExplainedAsItsUnitCopy) {
  const MeshData unit = kuhn_grid(2);
  MeshData tiny = unit;
  for (Point& p : tiny.points)
    for (double& x : p) x = std::ldexp(x, -366);
  const Report ru = full_report(unit), rt = full_report(tiny);
  EXPECT_TRUE(rt.ok());
  for (std::uint64_t t = 0; t < unit.tets.size(); ++t) {
    const TetExplanation u = explain_tet(view_of(unit), ru, t);
    const TetExplanation e = explain_tet(view_of(tiny), rt, t);
    EXPECT_EQ(e.orientation, u.orientation) << "tet " << t;
    EXPECT_EQ(e.inside_total, u.inside_total) << "tet " << t;
    EXPECT_EQ(e.cospherical_total, u.cospherical_total) << "tet " << t;
    ASSERT_TRUE(e.ratio.has_value() && u.ratio.has_value()) << "tet " << t;
    EXPECT_NEAR(*e.ratio, *u.ratio, 1e-12 * *u.ratio) << "tet " << t;
    EXPECT_EQ(e.ratio_below_bound, u.ratio_below_bound) << "tet " << t;
    ASSERT_TRUE(e.circumradius.has_value());
    EXPECT_NEAR(std::ldexp(*e.circumradius, 366), *u.circumradius, 1e-12) << "tet " << t;
  }
  const std::vector<TetField> fu = tet_fields(view_of(unit), ru);
  const std::vector<TetField> ft = tet_fields(view_of(tiny), rt);
  ASSERT_EQ(ft[0].name, "ratio");
  for (std::size_t t = 0; t < unit.tets.size(); ++t)
    EXPECT_NEAR(ft[0].values[t], fu[0].values[t], 1e-12 * fu[0].values[t]) << "tet " << t;
}

TEST(Explain, OutOfRangeTetThrows) {
  const MeshData m = kuhn_grid(1);
  EXPECT_THROW(explain_tet(view_of(m), full_report(m), m.tets.size()), std::out_of_range);
}

TEST(Fields, MarkExactlyTheViolatingTets) {
  const MeshData m = moved_vertex_mesh();
  const Report r = full_report(m);
  const std::vector<TetField> fields = tet_fields(view_of(m), r);
  ASSERT_GE(fields.size(), 3u);
  EXPECT_EQ(fields[0].name, "ratio");
  EXPECT_EQ(fields[1].name, "failed_checks");
  const TetField* del = nullptr;
  for (const TetField& f : fields)
    if (f.name == "fail:delaunay.empty_sphere") del = &f;
  ASSERT_NE(del, nullptr);
  const CheckResult& d = result(r, "delaunay.empty_sphere");
  std::uint64_t marked = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    EXPECT_EQ(fields[0].values[t] > 0, true);
    marked += del->values[t] == 1.0;
    EXPECT_GE(fields[1].values[t], del->values[t]);
  }
  EXPECT_EQ(marked, d.violations);
}

TEST(Fields, FaceFindingsNameTheTetsOfTheFace) {
  MeshData m = kuhn_grid(1);
  m.tets.push_back(m.tets[0]);  // a duplicated tet: its faces are in three tets
  const Report r = full_report(m);
  const std::vector<TetField> fields = tet_fields(view_of(m), r);
  const TetField* sharing = nullptr;
  for (const TetField& f : fields)
    if (f.name == "fail:validity.face_sharing") sharing = &f;
  ASSERT_NE(sharing, nullptr) << to_text(r);
  EXPECT_EQ(sharing->values[0], 1.0);
  EXPECT_EQ(sharing->values.back(), 1.0);
}

}  // namespace
}  // namespace pdr::check::test
