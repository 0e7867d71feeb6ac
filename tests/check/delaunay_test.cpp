// delaunay.empty_sphere: the grid-accelerated checker agrees with a brute-force GMP oracle
// (every tet against every vertex); cospherical vertices are counted, not failed; reports
// do not depend on the thread count.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <optional>
#include <nlohmann/json.hpp>

#include "check_test_util.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/delaunay.hpp"
#include "delaunay/export.hpp"
#include "geom/predicates.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

using Ids = std::set<std::string>;

TEST(Delaunay, CubeVerticesAreCosphericalNotInside) {
  const Report r = run(kuhn_grid(1));
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "cospherical"), 6u * 4);
}

TEST(Delaunay, MovedVertexFailsOnlyEmptySphere) {
  MeshData m = kuhn_grid(3);
  const std::uint32_t v = grid_id(3, 1, 1, 1);
  m.points[v] = {1.0625, 1.125, 0.9375};  // stays inside its star: orientation holds
  const Report r = run(m);
  EXPECT_EQ(failed(r), Ids{"delaunay.empty_sphere"}) << to_text(r);
  const Finding& f = result(r, "delaunay.empty_sphere").findings.at(0);
  EXPECT_EQ(f.kind, "tet");
  EXPECT_EQ(f.vertices.size(), 5u);
}

TEST(Delaunay, MovedVertexFarAwayAlsoInvertsTets) {
  MeshData m = kuhn_grid(3);
  m.points[grid_id(3, 1, 1, 1)] = {2.5, 2.5, 2.5};
  const Report r = run(m);
  EXPECT_TRUE(failed(r).count("validity.orientation")) << to_text(r);
}

TEST(Delaunay, NonConvexMeshIsCheckedAgainstAllVertices) {
  // Two tets far apart plus a vertex of one inside the other's circumsphere: they share
  // nothing, so a neighbours-only test would miss it.
  MeshData m;
  m.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 1},
              {1.2, 1.1, 1.3}, {1.25, 1.1, 1.3}, {1.2, 1.15, 1.3}, {1.2, 1.1, 1.35}};
  m.tets = {{5, 6, 7, 8}};
  m.tets.push_back({0, 1, 2, 3});
  const Report r = run(m);
  EXPECT_TRUE(failed(r).count("delaunay.empty_sphere"));
  EXPECT_EQ(result(r, "delaunay.empty_sphere").findings.at(0).id, 1u);
}

TEST(Delaunay, ReportDoesNotDependOnThreads) {
  MeshData m = kuhn_grid(4);
  for (std::size_t i = 0; i < m.points.size(); i += 7) m.points[i][0] += 0.0625;
  Options o;
  o.max_reported = 5;
  const std::vector<nlohmann::json> reports = reports_for_threads(m, o);
  for (const nlohmann::json& j : reports) EXPECT_EQ(j.dump(), reports.front().dump());
}

// Random small meshes: a jittered Kuhn cube (dyadic jitter hits exact ties, arbitrary
// doubles exercise the GMP path; tets may even invert) plus extra unreferenced points,
// which every circumsphere must also exclude. The checker's verdict must equal the
// brute-force oracle's (which costs a 5x5 GMP determinant per pair: keep meshes small).
MeshData jittered_cube(const std::vector<int>& jit, const std::vector<double>& noise,
                       const std::vector<int>& extra) {
  MeshData m = kuhn_grid(1);
  for (std::size_t i = 0; i + 2 < extra.size(); i += 3)
    m.points.push_back({extra[i] * 0.125, extra[i + 1] * 0.125, extra[i + 2] * 0.125});
  for (std::size_t i = 0; i < m.points.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const std::size_t k = 3 * i + static_cast<std::size_t>(c);
      m.points[i][c] += jit[k % jit.size()] * 0.0625 + noise[k % noise.size()];
    }
  return m;
}

// The report's delaunay.empty_sphere against the oracle's verdict on m.
void expect_report_matches_oracle(const Report& r, const OracleVerdict& v) {
  const CheckResult& d = result(r, "delaunay.empty_sphere");
  RC_ASSERT(d.violations == v.violating_tets.size());
  RC_ASSERT(count(r, "delaunay.empty_sphere", "violating_pairs") == v.violating_pairs);
  RC_ASSERT(count(r, "delaunay.empty_sphere", "cospherical") == v.cospherical);
  std::set<std::uint64_t> ids;
  for (const Finding& f : d.findings) ids.insert(f.id);
  RC_ASSERT(ids == v.violating_tets);
}

void expect_agrees_with_oracle(const MeshData& m) {
  Options o;
  o.max_reported = 1000;
  expect_report_matches_oracle(run(m, o), delaunay_oracle(m));
}

RC_GTEST_PROP(Delaunay, AgreesWithBruteForceOracleOnDyadicJitter, ()) {
  const auto jit = *rc::gen::container<std::vector<int>>(42, rc::gen::inRange(-3, 4));
  const auto extra = *rc::gen::container<std::vector<int>>(18, rc::gen::inRange(-2, 11));
  expect_agrees_with_oracle(jittered_cube(jit, {0.0}, extra));
}

RC_GTEST_PROP(Delaunay, AgreesWithBruteForceOracleOnArbitraryNoise, ()) {
  const auto jit = *rc::gen::container<std::vector<int>>(42, rc::gen::inRange(-2, 3));
  const auto raw = *rc::gen::container<std::vector<int>>(42, rc::gen::inRange(-1000, 1001));
  const auto extra = *rc::gen::container<std::vector<int>>(18, rc::gen::inRange(-2, 11));
  std::vector<double> noise;
  const double scale = *rc::gen::element(1e-3, 1e-9, 1e-15);
  for (int x : raw) noise.push_back(x * scale / 1000.0);
  expect_agrees_with_oracle(jittered_cube(jit, noise, extra));
}

TEST(Delaunay, AgreesWithBruteForceOracleOnAJitteredGrid) {
  MeshData m = kuhn_grid(2);
  for (std::size_t i = 0; i < m.points.size(); ++i)
    m.points[i][i % 3] += (static_cast<int>(i * 7 % 5) - 2) * 0.0625;
  Options o;
  o.max_reported = 1000;
  const Report r = run(m, o);
  const OracleVerdict v = delaunay_oracle(m);
  EXPECT_GT(v.violating_tets.size(), 0u);
  EXPECT_EQ(result(r, "delaunay.empty_sphere").violations, v.violating_tets.size());
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "cospherical"), v.cospherical);
}

// The Delaunay lemma (delaunay_empty.cpp) spares the vertex query of tets far from the
// boundary. Two Delaunay tetrahedralizations side by side, DT(A) and DT(B) (the kernel's),
// make a mesh whose every interior face is locally Delaunay while the flat tets on A's hull
// have spheres reaching deep into B: only the tets whose balls come near the boundary are
// queried, and that must find every violation. Apart (a gap between the hulls) the lemma
// decides; overlapping, validity.overlap fails and every tet is queried again. Either way
// the verdict is the brute-force oracle's.
// (nullopt where a cloud does not span space.)
std::optional<MeshData> two_triangulations(const std::vector<int>& a, const std::vector<int>& b,
                                           double shift) {
  const auto dt_of = [](const std::vector<int>& c, double dx) {
    std::set<std::array<int, 3>> distinct;  // a repeat would leave a vertex in no tet
    for (std::size_t i = 0; i + 2 < c.size(); i += 3) distinct.insert({c[i], c[i + 1], c[i + 2]});
    std::vector<Point> pts;
    for (const auto& [x, y, z] : distinct) pts.push_back({x / 64.0 + dx, y / 64.0, z / 64.0 + 1e-3 * (x % 7)});
    Delaunay dt(pts);
    BulkOptions o;
    o.renumber = false;
    if (bulk_insert(dt, o).status != BulkStatus::Ok) return MeshData{};
    return to_mesh_data(dt);
  };
  MeshData m = dt_of(a, 0);
  const MeshData other = dt_of(b, shift);
  if (m.tets.empty() || other.tets.empty()) return std::nullopt;
  const auto base = static_cast<std::uint32_t>(m.points.size());
  m.points.insert(m.points.end(), other.points.begin(), other.points.end());
  for (Tet t : other.tets) {
    for (std::uint32_t& v : t) v += base;
    m.tets.push_back(t);
  }
  return m;
}

void expect_lemma_agrees(double shift, bool apart) {
  // Points in [0, 1)^3 each; overlapping, the same cloud twice.
  const auto cloud = [] { return *rc::gen::container<std::vector<int>>(3 * 9, rc::gen::inRange(0, 64)); };
  const std::vector<int> a = cloud();
  const std::optional<MeshData> both = two_triangulations(a, apart ? cloud() : a, shift);
  RC_PRE(both.has_value());
  const MeshData& m = *both;
  Options o;
  o.max_reported = 1000;
  const Report r = run(m, o);
  RC_ASSERT(result(r, "validity.overlap").status == (apart ? Status::Pass : Status::Fail));
  const OracleVerdict v = delaunay_oracle(m);
  RC_TAG(v.violating_tets.empty() ? "delaunay" : "not delaunay");
  RC_ASSERT(count(r, "delaunay.empty_sphere", "lemma") == (apart ? 1u : 0u));
  expect_report_matches_oracle(r, v);
}

RC_GTEST_PROP(Delaunay, LemmaAgreesWithOracleAcrossAGap, ()) {
  expect_lemma_agrees(*rc::gen::element(1.01, 1.1, 1.5), true);
}

RC_GTEST_PROP(Delaunay, OverlapSendsEveryTetToTheQuery, ()) {
  expect_lemma_agrees(*rc::gen::element(1.0 / 512, 1.0 / 4096), false);
}

TEST(Delaunay, LemmaQueriesOnlyTetsNearTheBoundaryOrAtATie) {
  // A Kuhn grid: every face of a cube's six tets is a tie, and the faces between cubes
  // are not (the neighbour cube's far corner is outside the sphere). The lemma decides;
  // the queried tets are those at a tie or near the boundary: all of them here, and the
  // cospherical pairs are the oracle's.
  const MeshData m = kuhn_grid(3);
  const Report r = run(m);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "lemma"), 1u);
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "cospherical"), delaunay_oracle(m).cospherical);
  // A jittered grid in general position, 12^3 points: the tets far from the boundary
  // (about 40% here, more in a larger mesh) are not queried.
  std::vector<Point> pts;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 12; ++k)
        pts.push_back({i + 0.01 * ((i * 7 + j * 3 + k) % 5), j + 0.013 * ((i + j * 5) % 7),
                       k + 0.007 * ((j + k * 3) % 11)});
  Delaunay dt(pts);
  ASSERT_EQ(bulk_insert(dt, BulkOptions{}).status, BulkStatus::Ok);
  const MeshData g = to_mesh_data(dt);
  const Report rg = run(g);
  EXPECT_TRUE(rg.ok()) << to_text(rg);
  EXPECT_EQ(count(rg, "delaunay.empty_sphere", "lemma"), 1u);
  EXPECT_GT(count(rg, "delaunay.empty_sphere", "queried_tets"), 0u);
  EXPECT_LT(count(rg, "delaunay.empty_sphere", "queried_tets"), g.tets.size() * 3 / 4)
      << g.tets.size() << " tets";
  EXPECT_EQ(count(rg, "delaunay.empty_sphere", "cospherical"), 0u);
}

// The on-sphere pairs the order check decides from (Report::on_sphere) are every pair of a
// tet and a vertex exactly on its sphere, also where the lemma searched only the tets at a
// tie: a jittered grid in general position around one exact cube deep inside, whose eight
// corners are cospherical. Brute force with the kernel's predicates (not the checker's).
TEST(Delaunay, OnSpherePairsAreEveryCosphericalPair) {
  std::vector<Point> pts;
  const int n = 9;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const bool cube = i >= 4 && i <= 5 && j >= 4 && j <= 5 && k >= 4 && k <= 5;
        pts.push_back({i + (cube ? 0 : 0.01 * ((i * 7 + j * 3 + k) % 5)),
                       j + (cube ? 0 : 0.013 * ((i + j * 5) % 7)),
                       k + (cube ? 0 : 0.007 * ((j + k * 3) % 11))});
      }
  Delaunay dt(pts);
  ASSERT_EQ(bulk_insert(dt, BulkOptions{}).status, BulkStatus::Ok);
  const MeshData m = to_mesh_data(dt);
  const Report r = run(m);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "lemma"), 1u);
  EXPECT_LT(count(r, "delaunay.empty_sphere", "queried_tets"), m.tets.size() * 3 / 4);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> brute;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const Tet& k = m.tets[t];
    const Point &a = m.points[k[0]], &b = m.points[k[1]], &c = m.points[k[2]], &d = m.points[k[3]];
    for (std::uint32_t v = 0; v < m.points.size(); ++v)
      if (std::find(k.begin(), k.end(), v) == k.end() && pdr::insphere(a, b, c, d, m.points[v]) == Sign::Zero)
        brute.emplace_back(t, v);
  }
  EXPECT_GT(brute.size(), 0u);
  EXPECT_TRUE(r.on_sphere_complete);
  EXPECT_EQ(r.on_sphere, brute);
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "cospherical"), brute.size());
}

}  // namespace
}  // namespace pdr::check::test
