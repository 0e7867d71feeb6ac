// `pdr check` end to end on a foreign mesh (a hand-written TetGen file pair, so no tool is
// needed): --json follows docs/check-report-schema.md, --explain T describes tet T in full,
// --vtu OUT.vtu writes the per-tet fields, and a bad --explain is a usage error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli_support.hpp"
#include "io/io_test_util.hpp"

namespace {

using pdr::io::test::read_text;
using pdr::io::test::ScratchDir;
using pdr::io::test::write_text;

using pdr::cli_test::Outcome;
using pdr::cli_test::run;

// The unit cube in 6 Kuhn tets (1-based, as TetGen writes), with vertex 8 = (1,1,1) pushed
// out to (1.25,1.25,1.25) along the diagonal: every tet stays positive, none stays Delaunay.
void write_mesh(const ScratchDir& dir) {
  write_text(dir / "k.node",
             "8 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 0 0 1\n6 1 0 1\n7 0 1 1\n"
             "8 1.25 1.25 1.25\n");
  write_text(dir / "k.ele",
             "6 4 0\n1 1 2 4 8\n2 1 4 3 8\n3 1 3 7 8\n4 1 7 5 8\n5 1 5 6 8\n6 1 6 2 8\n");
}

TEST(CheckCli, JsonFollowsTheDocumentedSchema) {
  ScratchDir dir;
  write_mesh(dir);
  const Outcome r = run("check " + dir / "k" + " --ratio 2 --json", false);
  EXPECT_EQ(r.code, 1) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema_version"], 1);
  EXPECT_EQ(j["ok"], false);
  EXPECT_EQ(j["mesh"]["tets"], 6);
  bool saw = false;
  for (const auto& c : j["checks"]) {
    for (const char* key : {"id", "invariant", "status", "reason", "checked", "violations",
                            "counts", "values", "findings"})
      EXPECT_TRUE(c.contains(key)) << key;
    if (c["id"] == "delaunay.empty_sphere") {
      saw = true;
      EXPECT_EQ(c["status"], "fail");
      EXPECT_EQ(c["violations"], 6);
      ASSERT_FALSE(c["findings"].empty());
      const auto& f = c["findings"][0];
      EXPECT_EQ(f["kind"], "tet");
      EXPECT_EQ(f["points"].size(), f["vertices"].size());
      EXPECT_EQ(f["points"][0].size(), 3u);
    }
  }
  EXPECT_TRUE(saw);
}

TEST(CheckCli, ExplainDescribesOneTet) {
  ScratchDir dir;
  write_mesh(dir);
  const Outcome t = run("check " + dir / "k" + " --ratio 2 --explain 0");
  EXPECT_EQ(t.code, 1) << t.out;
  EXPECT_NE(t.out.find("explain tet 0: vertices 0 1 3 7"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("orientation (exact): positive"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("delaunay.empty_sphere: vertex"), std::string::npos) << t.out;

  const Outcome j = run("check " + dir / "k" + " --explain 5 --json", false);
  const nlohmann::json e = nlohmann::json::parse(j.out)["explain"];
  EXPECT_EQ(e["tet"], 5);
  EXPECT_GT(e["inside_total"].get<int>(), 0);
  EXPECT_EQ(e["orientation"], 1);

  const Outcome bad = run("check " + dir / "k" + " --explain 6");
  EXPECT_EQ(bad.code, 2) << bad.out;
  EXPECT_NE(bad.out.find("the mesh has 6 tets"), std::string::npos) << bad.out;
}

TEST(CheckCli, VtuHoldsThePerTetFields) {
  ScratchDir dir;
  write_mesh(dir);
  const Outcome r = run("check " + dir / "k" + " --ratio 2 --vtu " + dir / "k.vtu");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("wrote " + dir / "k.vtu"), std::string::npos) << r.out;
  const std::string vtu = read_text(dir / "k.vtu");
  for (const char* name : {"\"ratio\"", "\"failed_checks\"", "\"fail:delaunay.empty_sphere\""})
    EXPECT_NE(vtu.find(name), std::string::npos) << name;
  // The mesh itself reads back unchanged through pdr's own reader.
  EXPECT_EQ(run("check " + dir / "k.vtu" + " --json", false).code, 1);
}

}  // namespace
