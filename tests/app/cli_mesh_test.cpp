// End-to-end tests of `pdr mesh` (src/app/cmd_mesh.cpp): exit codes (0 done, 2 bad input
// or usage with file:line and nothing written, 3 quality not guaranteed), the --json
// summary's documented fields, --no-check, --formats, and the admissibility report of an
// inadmissible domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli_support.hpp"

namespace {

using namespace pdr::cli_test;

std::string data(const std::string& name) { return std::string(PDR_DATA_DIR) + "/" + name; }

// data/box.poly without comments: line 1 the node header, lines 2-9 the points, line 10
// the facet header, then per facet its header and polygon (facet k: lines 9 + 2k, 10 + 2k),
// line 23 the holes, line 24 the regions. `edit(lines)` changes it before it is written.
std::vector<std::string> box_lines() {
  return {"8 3 0 0",   "1 0 0 0",   "2 3 0 0",   "3 3 2 0",     "4 0 2 0",     "5 0 0 1",
          "6 3 0 1",   "7 3 2 1",   "8 0 2 1",   "6 1",         "1 0 1",       "4 1 2 3 4",
          "1 0 1",     "4 5 6 7 8", "1 0 1",     "4 1 2 6 5",   "1 0 1",       "4 2 3 7 6",
          "1 0 1",     "4 3 4 8 7", "1 0 1",     "4 4 1 5 8",   "0",           "0"};
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

TEST_F(Cli, MeshWritesEveryFormatAndTheJsonSummaryHasTheDocumentedFields) {
  const Outcome r = run("mesh " + data("cube-in-cube.poly") + " -o " + path("m") +
                        " --formats node,vtu,msh,mesh --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);  // throws unless the output is one JSON value
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j["command"], "mesh");
  EXPECT_GT(j["vertices"].get<int>(), 16);
  EXPECT_GT(j["tets"].get<int>(), 100);
  for (const char* phase : {"analyze", "surface", "initial", "refine", "write", "check"})
    EXPECT_GE(j["seconds"][phase].get<double>(), 0.0) << phase;
  EXPECT_GT(j["tets_per_second"].get<double>(), 0.0);
  EXPECT_GT(j["peak_rss_bytes"].get<double>(), 0.0);
  EXPECT_GT(j["ratio_min"].get<double>(), 0.0);
  EXPECT_LE(j["ratio_min"].get<double>(), j["ratio_max"].get<double>());
  EXPECT_LT(j["ratio_max"].get<double>(), 2.0);
  // Ratio < 2 does not bound dihedral angles (slivers: the cube-in-cube mesh has a tet of
  // 4 nearly coplanar cospherical vertices, whose angles round to 0 and 180 degrees).
  EXPECT_GE(j["dihedral_min_deg"].get<double>(), 0.0);
  EXPECT_LT(j["dihedral_min_deg"].get<double>(), j["dihedral_max_deg"].get<double>());
  EXPECT_LE(j["dihedral_max_deg"].get<double>(), 180.0);
  EXPECT_EQ(j["admissible"], true);
  EXPECT_TRUE(j["admissibility_violations"].is_array());
  EXPECT_TRUE(j["admissibility_violations"].empty());
  EXPECT_EQ(j["check"], "pass");
  EXPECT_EQ(j["written"].size(), 6u);
  for (const char* ext : {".node", ".ele", ".face", ".vtu", ".msh", ".mesh"})
    EXPECT_TRUE(fs::exists(path(std::string("m") + ext))) << ext;
  // Every written format is read back and passes the exact checker against the domain.
  for (const char* m : {"m", "m.msh", "m.mesh", "m.vtu"}) {
    const Outcome c = run("check " + path(m) + " --domain " + data("cube-in-cube.poly") +
                          " --ratio 2");
    EXPECT_EQ(c.code, 0) << m << "\n" << c.out;
  }
}

TEST_F(Cli, MeshNoCheckSaysTheCheckWasSkipped) {
  const Outcome r = run("mesh " + data("box.poly") + " -o " + path("m") + " --no-check --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["check"], "skipped (--no-check)");
  EXPECT_FALSE(j["seconds"].contains("check")) << j["seconds"];
  const Outcome t = run("mesh " + data("box.poly") + " -o " + path("t") + " --no-check");
  ASSERT_EQ(t.code, 0) << t.out;
  EXPECT_NE(t.out.find("check: skipped (--no-check)"), std::string::npos) << t.out;
  EXPECT_TRUE(fs::exists(path("t.ele")));
}

// Each malformed domain exits 2, names bad.poly and the line, and leaves nothing behind
// (not even the output folder).
TEST_F(Cli, MeshMalformedDomainsExit2WithFileAndLineAndWriteNothing) {
  struct Case {
    const char* what;
    std::size_t line;  // 1-based line to replace
    const char* text;
    const char* where;  // expected in the message
  };
  const Case cases[] = {
      {"vertex index out of range", 14, "4 5 6 7 9", "bad.poly:14"},
      {"coordinate not a number", 4, "3 3 two 0", "bad.poly:4"},
      {"coordinate out of range", 3, "2 1e40 0 0", "bad.poly:3"},
      {"polygon visits a vertex twice", 12, "4 1 2 3 1", "bad.poly:11"},
      {"non-planar facet", 8, "7 3 2 1.5", "bad.poly:"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    auto lines = box_lines();
    lines[c.line - 1] = c.text;
    write("bad.poly", joined(lines));
    const Outcome r = run("mesh " + path("bad.poly") + " -o " + path("sub/out") + " --json");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find(c.where), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(path("sub"))) << r.out;
    EXPECT_TRUE(left_behind("out").empty());
  }
}

TEST_F(Cli, MeshUsageErrorsExit2AndWriteNothing) {
  for (const std::string& args :
       {"mesh " + data("box.poly"),                                       // no -o
        "mesh " + path("missing.poly") + " -o " + path("out"),           // no such file
        "mesh " + data("box.poly") + " -o " + path("out") + " --ratio 0.5",
        "mesh " + data("box.poly") + " -o " + path("out") + " --formats node,stl",
        "mesh " + data("box.poly") + " -o " + path("out") + " --max-volume -1"}) {
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    EXPECT_TRUE(left_behind("out").empty()) << args;
  }
}

// The tee (data/tee.poly: 70-degree angles at the two flange tips) is meshed but reported
// inadmissible, with every violating angle: its kind, its degrees (< 90) and the input
// lines of what meets there.
TEST_F(Cli, MeshReportsEachViolatingAngleOfAnInadmissibleDomain) {
  const Outcome r = run("mesh " + data("tee.poly") + " -o " + path("m") + " --json");
  ASSERT_TRUE(r.code == 0 || r.code == 3) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["admissible"], false);
  const auto& v = j["admissibility_violations"];
  ASSERT_TRUE(v.is_array());
  ASSERT_FALSE(v.empty()) << r.out;
  std::vector<std::string> kinds;
  for (const auto& e : v) {
    EXPECT_LT(e["degrees"].get<double>(), 90.0) << e;
    EXPECT_GT(e["degrees"].get<double>(), 69.0) << e;
    EXPECT_TRUE(e.contains("kind")) << e;
    EXPECT_FALSE(e["facets"].empty() && e["segments"].empty()) << e;
    kinds.push_back(e["kind"]);
  }
  // The two tip edges (facet-facet) and the four tip corners in the caps.
  EXPECT_EQ(std::count(kinds.begin(), kinds.end(), "facet-facet"), 2) << v;
  EXPECT_GE(std::count(kinds.begin(), kinds.end(), "segment-segment"), 4) << v;
  const Outcome t = run("mesh " + data("tee.poly") + " -o " + path("t"));
  EXPECT_NE(t.out.find("admissible: false"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("facet-facet"), std::string::npos) << t.out;
}

// With a vertex cap below what the tee needs, the mesh is written but the quality is not
// guaranteed: exit 3, with the reason.
TEST_F(Cli, MeshThatCannotBeFinishedExits3AndSaysWhy) {
  const Outcome r = run("mesh " + data("tee.poly") + " -o " + path("m") +
                        " --max-vertices 1 --json");
  ASSERT_EQ(r.code, 3) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["quality"].get<std::string>().rfind("NOT GUARANTEED", 0), 0u) << r.out;
  EXPECT_NE(j["stop_reason"].get<std::string>().find("refine.cap"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(path("m.ele")));
}

// Stopped by the vertex cap with every tet already below B: the size bound is unmet, so
// the run still says "not guaranteed" (exit 3), never success.
TEST_F(Cli, MeshStoppedByTheCapBeforeTheSizeBoundExits3) {
  const Outcome r = run("mesh " + data("box.poly") + " -o " + path("c") +
                        " --max-volume 0.001 --max-vertices 1 --json");
  ASSERT_EQ(r.code, 3) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["quality"].get<std::string>().find("refine.cap"), std::string::npos) << r.out;
  EXPECT_EQ(j["check"], "pass") << r.out;
}

}  // namespace
