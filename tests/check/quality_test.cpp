// quality.ratio and quality.shortest_edge (Theorem 1): exact at the bound, slivers caught.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>

#include "check_test_util.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

using Ids = std::set<std::string>;

// A Kuhn tet has R^2 = 3/4 and lmin = 1: ratio sqrt(3)/2, irrational. The doubles just
// below and above it must fail and pass: only exact arithmetic separates them.
TEST(Quality, RatioIsDecidedExactlyAtTheBound) {
  const MeshData m = kuhn_grid(1);
  const double r = std::sqrt(0.75);
  const double below = std::nextafter(r, 0.0), above = std::nextafter(r, 1.0);
  auto exceeds = [](double b) {  // b > sqrt(3)/2, exactly
    const mpq_class q(b);
    return q * q > mpq_class(3, 4);
  };
  Options o;
  for (double b : {below, r, above}) {
    o.ratio_bound = b;
    const Report rep = run(m, o);
    const bool expect_pass = exceeds(b);
    EXPECT_EQ(result(rep, "quality.ratio").status, expect_pass ? Status::Pass : Status::Fail)
        << "bound " << b;
  }
  o.ratio_bound = 2;
  EXPECT_NEAR(result(run(m, o), "quality.ratio").values.at("max_ratio"), r, 1e-12);
}

// A flat "cap": the apex hovers just above the base triangle, so the circumsphere is huge
// while the edges stay of unit size. (A sliver proper, four points near a square, has a
// good radius-edge ratio: the paper, §3, notes this bound does not exclude slivers.)
TEST(Quality, FlatTetAboveTheBoundFailsOnlyRatio) {
  MeshData m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.875, 0}, {0.5, 0.3125, 0.015625}};
  m.tets = {{0, 1, 2, 3}};
  if (exact::orient3d(m.points[0], m.points[1], m.points[2], m.points[3]) == Sign::Negative)
    std::swap(m.tets[0][1], m.tets[0][2]);
  Options o;
  o.ratio_bound = 2;
  const Report r = run(m, o);
  EXPECT_EQ(failed(r), Ids{"quality.ratio"}) << to_text(r);
  const Finding& f = result(r, "quality.ratio").findings.at(0);
  EXPECT_GT(*f.value, 2.0);
  o.ratio_bound = 1e6;
  EXPECT_TRUE(run(m, o).ok());
}

TEST(Quality, SliverInsideAGridFailsRatio) {
  // Push a vertex toward the opposite face of a tet: the tet flattens (ratio grows) while
  // staying positive.
  MeshData m = kuhn_grid(2);
  Options o;
  o.ratio_bound = 2;
  ASSERT_TRUE(run(m, o).ok());
  m.points[grid_id(2, 1, 1, 1)] = {1.0, 1.0, 0.0625};
  const Report r = run(m, o);
  EXPECT_TRUE(failed(r).count("quality.ratio")) << to_text(r);
}

TEST(Quality, ShortestEdgeIsStrict) {
  const MeshData m = kuhn_grid(2, 0.5);  // shortest edges have length exactly 0.5
  Options o;
  o.min_edge = 0.5;
  const Report at = run(m, o);
  EXPECT_EQ(failed(at), Ids{"quality.shortest_edge"});
  EXPECT_EQ(result(at, "quality.shortest_edge").violations, 3u * 2 * 3 * 3);  // axis edges
  o.min_edge = std::nextafter(0.5, 0.0);
  EXPECT_TRUE(run(m, o).ok());
  EXPECT_EQ(result(run(m, o), "quality.shortest_edge").values.at("min_edge"), 0.5);
}

TEST(Quality, WithoutBoundsTheExtremesAreStillReported) {
  const Report r = run(kuhn_grid(1));
  EXPECT_EQ(result(r, "quality.ratio").status, Status::Skipped);
  EXPECT_EQ(result(r, "quality.shortest_edge").values.at("min_edge"), 1.0);
}

TEST(Quality, InvalidBoundsAreSkipped) {
  Options o;
  o.ratio_bound = -1;
  o.min_edge = std::nan("");
  const Report r = run(kuhn_grid(1), o);
  EXPECT_EQ(result(r, "quality.ratio").status, Status::Skipped);
  EXPECT_EQ(result(r, "quality.shortest_edge").status, Status::Skipped);
}

}  // namespace
}  // namespace pdr::check::test
