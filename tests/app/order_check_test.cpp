// The order-independence check (src/app/order_check.hpp): a Delaunay tetrahedralization
// passes whatever the rebuild's seed; the other tetrahedralization of the same five points
// (a 2-3 flip of a bipyramid) is found out, and so is one foreign tet. As `pdr check`'s
// order.independence: a tetrahedralization of cospherical points that breaks the ties
// unlike the symbolic perturbation warns (every missing tet a tie), a non-Delaunay one
// fails (also where a vertex lies on a sphere that another vertex is strictly inside), and
// a vertex set that cannot be rebuilt is skipped.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "app/order_check.hpp"
#include "check/check.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/delaunay.hpp"
#include "delaunay/export.hpp"
#include "geom/exact.hpp"
#include "geom/predicates.hpp"

namespace pdr::app {
namespace {

// A triangle abc in z = 0 pierced by the segment de: two tets (abcd, abce) or three
// (dea, deb, dec) fill the bipyramid; with d, e far above and below the triangle the
// two-tet one is Delaunay (e is outside abcd's sphere: center (2, 2, 1.9), R^2 = 11.61,
// |e - center|^2 = 49.61).
MeshData bipyramid(bool delaunay) {
  MeshData m;
  m.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 5}, {1, 1, -5}};
  if (delaunay)
    m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  else
    m.tets = {{3, 4, 0, 1}, {3, 4, 1, 2}, {3, 4, 2, 0}};
  return m;
}

TEST(OrderCheck, TheDelaunayBipyramidPasses) {
  const MeshData m = bipyramid(true);
  for (std::uint64_t seed : {1u, 2u, 77u}) {
    const OrderCheck r = check_order_independence(m, seed);
    EXPECT_TRUE(r.ok()) << seed;
    EXPECT_EQ(r.tets, 2u);
  }
}

TEST(OrderCheck, TheFlippedBipyramidIsFound) {
  const OrderCheck r = check_order_independence(bipyramid(false), 1);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.missing, 3u);
  ASSERT_FALSE(r.first.empty());
  EXPECT_EQ(r.first.front(), (std::array<std::uint32_t, 4>{0, 1, 3, 4}));
}

// The kernel's Delaunay tetrahedralization of an n^3 grid with a deterministic jitter,
// vertex ids as given.
MeshData jittered_grid_dt(int n) {
  std::vector<Point> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        pts.push_back({i + 0.001 * ((i * 7 + j * 3 + k) % 5), j + 0.0013 * ((i + j * 5) % 7),
                       k + 0.0007 * ((j + k * 3) % 11)});
  Delaunay dt(pts);
  BulkOptions o;
  o.renumber = false;
  EXPECT_EQ(bulk_insert(dt, o).status, BulkStatus::Ok);
  return to_mesh_data(dt);
}

// A kernel-built Delaunay tetrahedralization of a grid with jitter passes for several
// seeds; changing one tet's vertex to a non-Delaunay quadruple is found.
TEST(OrderCheck, KernelMeshPassesAndOneForeignTetIsFound) {
  MeshData m = jittered_grid_dt(6);
  for (std::uint64_t seed : {5u, 6u}) EXPECT_TRUE(check_order_independence(m, seed).ok());
  m.tets[0][0] = m.tets[0][0] == 0 ? 215u : 0u;  // far from the tet's other vertices
  EXPECT_EQ(check_order_independence(m, 5).missing, 1u);
}

// The misses are looked up in blocks on several threads: the count and the first listed
// (in mesh order) are the same for any number of threads.
TEST(OrderCheck, TheMissesListedDoNotDependOnThreads) {
  MeshData m = jittered_grid_dt(8);
  std::size_t changed = 0;
  for (std::size_t t = 0; t < m.tets.size(); t += 37, ++changed)
    m.tets[t][0] = m.tets[t][0] == 0 ? 511u : 0u;  // far from the tet's other vertices
  const OrderCheck one = check_order_independence(m, rebuild_dt(m.points, 5), 5, 3, false, 1);
  EXPECT_EQ(one.missing, changed);
  ASSERT_EQ(one.first_index.size(), 3u);
  EXPECT_EQ(one.first_index, (std::vector<std::size_t>{0, 37, 74}));
  for (unsigned threads : {2u, 3u, 8u}) {
    const OrderCheck r = check_order_independence(m, rebuild_dt(m.points, 5), 5, 3, false, threads);
    EXPECT_EQ(r.missing, one.missing) << threads;
    EXPECT_EQ(r.first, one.first) << threads;
    EXPECT_EQ(r.first_index, one.first_index) << threads;
  }
}

check::CheckResult as_check(const MeshData& m) {
  check::Report report = check::check_mesh(check::view_of(m), check::Options{});
  add_order_check(report, m, kOrderCheckSeed);
  EXPECT_EQ(report.checks.back().id, "order.independence");
  EXPECT_EQ(report.seconds.count("order"), 1u);
  return report.checks.back();
}

// The unit cube's eight corners are cospherical: each of its triangulations below is
// Delaunay (no vertex strictly inside a sphere), and DT(V) is the one the perturbation picks.
std::vector<MeshData> cube_triangulations() {
  const std::vector<Point> corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  // Corner i = x + 2y + 4z. Two five-tet ones (a middle tet and four corners cut off) and
  // Kuhn's six tets around the diagonal 0-7; each tet as given, oriented below.
  const std::vector<std::vector<std::array<std::uint32_t, 4>>> splits = {
      {{1, 2, 4, 7}, {0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}},
      {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}},
      {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};
  std::vector<MeshData> out;
  for (const auto& tets : splits) {
    MeshData m;
    m.points = corners;
    for (auto t : tets) {
      if (orient3d(corners[t[0]], corners[t[1]], corners[t[2]], corners[t[3]]) == Sign::Negative)
        std::swap(t[0], t[1]);
      m.tets.push_back(t);
    }
    out.push_back(std::move(m));
  }
  return out;
}

// Where the checker's report decides the order check (delaunay.empty_sphere passed and
// listed its on-sphere pairs), the perturbed signs of those pairs give exactly the rebuild's
// verdict: on a kernel mesh in general position (nothing missing), on the cube's three
// triangulations (ties broken three ways: the same tets missing), and on kernel meshes of
// grid points (cospherical everywhere) whatever their insertion order.
void expect_report_decides_as_the_rebuild(const MeshData& m) {
  const check::Report report = check::check_mesh(check::view_of(m), check::Options{});
  ASSERT_TRUE(report.ok()) << check::to_text(report);
  ASSERT_TRUE(order_implied(report));
  const OrderCheck local = order_from_report(m, report, kOrderCheckSeed, 1000);
  const OrderCheck rebuilt = check_order_independence(m, kOrderCheckSeed, 1000);
  EXPECT_EQ(local.missing, rebuilt.missing);
  EXPECT_EQ(local.first_index, rebuilt.first_index);
  EXPECT_EQ(local.ties, local.missing);
}

TEST(OrderCheck, TheReportDecidesAsTheRebuildDoes) {
  expect_report_decides_as_the_rebuild(jittered_grid_dt(6));
  std::size_t missing = 0;
  for (const MeshData& c : cube_triangulations()) {
    expect_report_decides_as_the_rebuild(c);
    const check::Report report = check::check_mesh(check::view_of(c), check::Options{});
    missing += order_from_report(c, report, kOrderCheckSeed).missing;
  }
  EXPECT_GT(missing, 0u);  // some tie broken unlike the perturbation is found
  for (std::uint64_t seed : {3u, 4u, 5u}) {
    std::vector<Point> pts;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 3; ++k) pts.push_back({double(i), double(j), double(k)});
    Delaunay dt(pts);
    BulkOptions o;
    o.seed = seed;
    o.renumber = false;
    ASSERT_EQ(bulk_insert(dt, o).status, BulkStatus::Ok);
    const MeshData g = to_mesh_data(dt);
    expect_report_decides_as_the_rebuild(g);
    const check::Report report = check::check_mesh(check::view_of(g), check::Options{});
    EXPECT_GT(report.on_sphere.size(), 0u);
    EXPECT_EQ(order_from_report(g, report, kOrderCheckSeed).missing, 0u);
  }
  EXPECT_FALSE(order_implied(check::check_mesh(check::view_of(bipyramid(false)), check::Options{})));
}

TEST(OrderCheck, CosphericalTiesBrokenAnotherWayWarnOnly) {
  std::size_t warned = 0, passed = 0;
  for (const MeshData& m : cube_triangulations()) {
    const check::Report report = check::check_mesh(check::view_of(m), check::Options{});
    ASSERT_TRUE(report.ok()) << check::to_text(report);  // valid and Delaunay
    const OrderCheck oc = check_order_independence(m, kOrderCheckSeed);
    EXPECT_EQ(oc.ties, oc.missing);  // every difference is a tie
    const check::CheckResult c = as_check(m);
    EXPECT_EQ(c.violations, oc.missing);  // flagged, as ties
    for (const check::Finding& f : c.findings) {  // the fifth vertex is on the sphere
      ASSERT_EQ(f.points.size(), 5u);
      EXPECT_EQ(exact::insphere(f.points[0], f.points[1], f.points[2], f.points[3], f.points[4]),
                Sign::Zero);
    }
    if (oc.missing == 0) {
      EXPECT_EQ(c.status, check::Status::Pass);
      ++passed;
    } else {
      EXPECT_EQ(c.status, check::Status::Warn);
      EXPECT_EQ(c.counts.at("cospherical_ties"), oc.missing);
      ASSERT_FALSE(c.findings.empty());
      EXPECT_EQ(c.findings.front().vertices.size(), 5u);  // the tet and a vertex on its sphere
      ++warned;
    }
  }
  EXPECT_GE(warned, 2u);  // DT(V) is one triangulation; at least two of three differ
  EXPECT_LE(passed, 1u);
}

TEST(OrderCheck, NonDelaunayFailsAndAnUnrebuildableSetIsSkipped) {
  // The other tetrahedralization of five points in general position: no tie anywhere.
  EXPECT_EQ(check_order_independence(bipyramid(false), kOrderCheckSeed).ties, 0u);
  const check::CheckResult flipped = as_check(bipyramid(false));
  EXPECT_EQ(flipped.status, check::Status::Fail);
  EXPECT_EQ(flipped.violations, 3u);
  EXPECT_EQ(flipped.counts.at("cospherical_ties"), 0u);
  const check::CheckResult delaunay = as_check(bipyramid(true));
  EXPECT_EQ(delaunay.status, check::Status::Pass);
  EXPECT_EQ(delaunay.counts.at("implied"), 1u);  // no vertex on a sphere: nothing rebuilt
  EXPECT_EQ(flipped.counts.count("implied"), 0u);

  // A vertex strictly inside every sphere of the cube's tets (its centre, in no tet):
  // every tet also has a corner exactly on its sphere, but no difference is a tie here.
  for (MeshData m : cube_triangulations()) {
    m.points.push_back({0.5, 0.5, 0.5});
    const check::CheckResult c = as_check(m);
    EXPECT_EQ(c.status, check::Status::Fail);
    EXPECT_EQ(c.violations, m.tets.size());
    EXPECT_EQ(c.counts.at("cospherical_ties"), 0u);
    EXPECT_GT(check_order_independence(m, kOrderCheckSeed).ties, 0u);
  }

  MeshData dup = bipyramid(true);
  dup.points.push_back(dup.points[0]);
  dup.tets.push_back({5, 2, 1, 3});
  const check::CheckResult skipped = as_check(dup);
  EXPECT_EQ(skipped.status, check::Status::Skipped);
  EXPECT_NE(skipped.reason.find("validity.duplicate_vertices"), std::string::npos);
}

}  // namespace
}  // namespace pdr::app
