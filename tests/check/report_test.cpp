// Report rendering: JSON schema fields, stable ids and order, text naming failed checks.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "check_test_util.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

const std::vector<std::string> kIds = {
    "validity.indices", "validity.coordinates", "validity.orientation", "validity.duplicate_vertices",
    "validity.unreferenced_vertices", "validity.face_sharing", "validity.boundary_closed",
    "validity.faces", "validity.overlap", "delaunay.empty_sphere", "quality.ratio",
    "quality.shortest_edge", "conformity.vertices", "conformity.segments", "conformity.facets",
    "conformity.volume", "encroachment.subsegments", "encroachment.subfacets"};

TEST(Report, JsonHasSchemaAndEveryCheckInOrder) {
  MeshData m = kuhn_grid(2);
  std::swap(m.tets[3][0], m.tets[3][1]);
  Options o;
  o.ratio_bound = 2;
  const nlohmann::json j = to_json(run(m, box_domain(2), o));
  EXPECT_EQ(j.at("schema_version"), 1);
  EXPECT_EQ(j.at("ok"), false);
  EXPECT_EQ(j.at("mesh").at("tets"), 48);
  EXPECT_EQ(j.at("options").at("ratio_bound"), 2.0);
  EXPECT_TRUE(j.at("options").at("min_edge").is_null());
  ASSERT_EQ(j.at("checks").size(), kIds.size());
  for (std::size_t i = 0; i < kIds.size(); ++i) {
    const auto& c = j.at("checks")[i];
    EXPECT_EQ(c.at("id"), kIds[i]);
    EXPECT_FALSE(c.at("invariant").get<std::string>().empty());
    for (const char* key : {"status", "reason", "checked", "violations", "counts", "values", "findings"})
      EXPECT_TRUE(c.contains(key)) << key;
  }
  const auto& orient = j.at("checks")[2];
  EXPECT_EQ(orient.at("status"), "fail");
  const auto& f = orient.at("findings")[0];
  EXPECT_EQ(f.at("kind"), "tet");
  EXPECT_EQ(f.at("id"), 3);
  EXPECT_EQ(f.at("points").size(), 4u);
  EXPECT_EQ(f.at("message").get<std::string>().rfind("validity.orientation", 0), 0u);
  EXPECT_FALSE(j.contains("seconds"));
}

TEST(Report, TextNamesFailedChecksFirstAndDiagnosticsStartWithTheId) {
  MeshData m = kuhn_grid(2);
  std::swap(m.tets[3][0], m.tets[3][1]);
  const Report r = run(m);
  const std::string text = to_text(r);
  EXPECT_EQ(text.rfind("pdr check: FAIL (failed: validity.orientation)", 0), 0u) << text;
  EXPECT_NE(text.find("FAIL  validity.orientation: 1 of 48 violate"), std::string::npos) << text;
  EXPECT_NE(text.find("      validity.orientation: tet 3 is inverted"), std::string::npos) << text;
  EXPECT_NE(text.find("SKIP  conformity.facets: no domain given"), std::string::npos) << text;
  EXPECT_EQ(to_text(run(kuhn_grid(1))).rfind("pdr check: PASS", 0), 0u);
}

TEST(Report, FindingsAreCappedButCountsAreNot) {
  MeshData m = kuhn_grid(3);
  for (std::size_t t = 0; t < m.tets.size(); t += 2) std::swap(m.tets[t][0], m.tets[t][1]);
  Options o;
  o.max_reported = 4;
  const Report r = run(m, o);
  const CheckResult& c = result(r, "validity.orientation");
  EXPECT_EQ(c.violations, m.tets.size() / 2);
  ASSERT_EQ(c.findings.size(), 4u);
  EXPECT_EQ(c.findings[3].id, 6u);  // the first four by id: 0, 2, 4, 6
}

}  // namespace
}  // namespace pdr::check::test
