// End-to-end tests of `pdr delaunay`, `pdr check` and the default job (src/app): what a
// user sees. Each test works in its own temporary directory, runs the real binary, and
// asserts the exit code (README "Exit codes"), the files left behind and the messages.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli_support.hpp"

namespace {

using namespace pdr::cli_test;

TEST_F(Cli, DelaunayWritesCheckedOutputThatCheckAccepts) {
  write_points("pts.node", 2000);
  const Outcome d = run("delaunay " + path("pts.node") + " -o " + path("out") +
                    " --formats node,vtu,msh,mesh --json");
  ASSERT_EQ(d.code, 0) << d.out;
  const auto j = nlohmann::json::parse(d.out);
  EXPECT_EQ(j["check"], "pass");
  EXPECT_EQ(j["points"], 2008);
  EXPECT_GT(j["tets"].get<int>(), 2008 * 5);
  for (const char* ext : {".node", ".ele", ".face", ".vtu", ".msh", ".mesh"})
    EXPECT_TRUE(fs::exists(path(std::string("out") + ext))) << ext;
  for (const char* m : {"out", "out.msh", "out.mesh", "out.vtu"}) {
    const Outcome c = run("check " + path(m));
    EXPECT_EQ(c.code, 0) << m << "\n" << c.out;
  }
}

TEST_F(Cli, CheckFindsAFlippedTetAndNamesTheCheck) {
  write_points("pts.node", 300);
  ASSERT_EQ(run("delaunay " + path("pts.node") + " -o " + path("m")).code, 0);
  // Swap two vertices of the first tet of m.ele: it becomes negatively oriented.
  std::ifstream in(path("m.ele"));
  std::string header, line, rest;
  std::getline(in, header);
  std::getline(in, line);
  std::stringstream all;
  all << in.rdbuf();
  std::istringstream t(line);
  long id, a, b, c, d;
  t >> id >> a >> b >> c >> d;
  std::ostringstream out;
  out << header << '\n' << id << ' ' << b << ' ' << a << ' ' << c << ' ' << d << '\n' << all.str();
  write("m.ele", out.str());
  const Outcome r = run("check " + path("m") + " --json");
  EXPECT_EQ(r.code, 1) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  bool orientation_failed = false;
  for (const auto& c : j["checks"])
    if (c["id"] == "validity.orientation") orientation_failed = c["status"] == "fail";
  EXPECT_TRUE(orientation_failed) << r.out;
  EXPECT_NE(run("check " + path("m")).out.find("validity.orientation"), std::string::npos);
}

TEST_F(Cli, MalformedInputExits2WithFileAndLineAndWritesNothing) {
  write("bad.node", "4 3 0 0\n1 0 0 0\n2 1 0 zero\n3 0 1 0\n4 0 0 1\n");
  const Outcome r = run("delaunay " + path("bad.node") + " -o " + path("out"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("bad.node:3"), std::string::npos) << r.out;
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().rfind("out", 0), std::string::npos)
        << "left behind: " << e.path();
}

TEST_F(Cli, CoplanarPointsAreBadInput) {
  write("flat.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 2 3 0\n");
  const Outcome r = run("delaunay " + path("flat.node") + " -o " + path("out"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("flat.node"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("out.ele")));
}

TEST_F(Cli, DuplicatesAreReportedNotInserted) {
  write("dup.node", "6 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 0\n6 1 1 1\n");
  const Outcome r = run("delaunay " + path("dup.node") + " -o " + path("out") + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["duplicates"], 1);
  EXPECT_EQ(j["check"], "pass");
}

// The output lists the input's points in the input's order (vertex i of out.node is point
// i of the input), without the copies that were not inserted. Many copies over a large
// set (inserted in another order than given: a spatial sort) made the dropped copies'
// ids point at the wrong vertices: exit 4, "tet 104 has vertex 60 but there are 60 points".
TEST_F(Cli, OutputKeepsTheInputOrderAndDropsOnlyCopies) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> cell(0, 5);
  std::vector<std::array<int, 3>> pts;
  for (int i = 0; i < 3000; ++i) pts.push_back({cell(rng), cell(rng), cell(rng)});
  std::ostringstream s;
  s << pts.size() << " 3 0 0\n";
  for (std::size_t i = 0; i < pts.size(); ++i)
    s << i + 1 << ' ' << pts[i][0] << ' ' << pts[i][1] << ' ' << pts[i][2] << '\n';
  write("dups.node", s.str());
  write_points("pts.node", 2000);
  for (const char* name : {"dups", "pts"}) {
    SCOPED_TRACE(name);
    const Outcome r = run("delaunay " + path(std::string(name) + ".node") + " -o " +
                          path(std::string("out-") + name) + " --json");
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["check"], "pass");
    // Each output vertex is the next input point with its coordinates.
    const auto read_node = [&](const std::string& file) {
      std::ifstream in(path(file));
      std::size_t n = 0, dim = 0, attrs = 0, markers = 0;
      in >> n >> dim >> attrs >> markers;
      std::vector<std::array<double, 3>> out(n);
      for (auto& p : out) {
        long id = 0;
        in >> id >> p[0] >> p[1] >> p[2];
      }
      return out;
    };
    const auto input = read_node(std::string(name) + ".node");
    const auto output = read_node(std::string("out-") + name + ".node");
    EXPECT_EQ(output.size() + j["duplicates"].get<std::size_t>(), input.size());
    std::size_t next = 0;
    for (const auto& p : output) {
      while (next < input.size() && input[next] != p) ++next;
      ASSERT_LT(next, input.size()) << "an output vertex out of the input's order";
      ++next;
    }
    if (j["duplicates"] == 0) {
      EXPECT_EQ(output, input);
    }
  }
  EXPECT_EQ(nlohmann::json::parse(run("delaunay " + path("dups.node") + " -o " + path("again") +
                                      " --json").out)["vertices"],
            216);
}

TEST_F(Cli, MalformedMeshForCheckExits2) {
  write("m.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write("m.ele", "1 4 0\n1 1 2 3 9\n");
  const Outcome r = run("check " + path("m"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("m.ele:2"), std::string::npos) << r.out;
}

TEST_F(Cli, ANonNumericSubmeshCountIsAUsageError) {  // was exit 4 (an uncaught stoll)
  const Outcome r = run("mesh " + std::string(PDR_DATA_DIR) + "/box.poly -o " + path("out") +
                        " --submeshes abc");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("a number of submeshes"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("out.ele")));
}

TEST_F(Cli, UnknownFormatIsAUsageError) {
  write_points("pts.node", 10);
  const Outcome r = run("delaunay " + path("pts.node") + " -o " + path("out") + " --formats stl");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_FALSE(fs::exists(path("out.ele")));
}

TEST_F(Cli, DefaultJobMeshesCubeInCubeChecksAndWrites) {
  const Outcome r = run("-o " + path("def/x") + " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["check"], "pass");
  EXPECT_EQ(j["admissible"], true);
  EXPECT_LT(j["ratio_max"].get<double>(), 2.0);
  EXPECT_GT(j["tets"].get<int>(), 1000);
  for (const char* ext : {".node", ".ele", ".face", ".vtu"})
    EXPECT_TRUE(fs::exists(path(std::string("def/x") + ext))) << ext;
}

TEST_F(Cli, TetgenMeshOfABoxIsValidAndConforms) {
  if (!on_path("tetgen")) GTEST_SKIP() << "tetgen not installed";
  fs::copy_file(fs::path(PDR_DATA_DIR) / "box.poly", path("box.poly"));
  ASSERT_EQ(std::system(("cd " + dir_.string() + " && tetgen -pQ box.poly >/dev/null").c_str()), 0);
  const Outcome r = run("check " + path("box.1") + " --domain " + path("box.poly") + " --json");
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& c : j["checks"]) {
    const std::string id = c["id"];
    if (id.rfind("validity.", 0) == 0 || id.rfind("conformity.", 0) == 0) {
      EXPECT_NE(c["status"], "fail") << id << "\n" << r.out;
    }
  }
}

// order.independence (app/order_check.hpp) in pdr check: TetGen without its optimisation
// (-O0) leaves a Delaunay mesh whose cospherical ties may be broken unlike pdr's, which
// passes or warns, never fails; pdr's own mesh equals DT(V) exactly.
TEST_F(Cli, CheckRunsOrderIndependenceOnAnyMesher) {
  auto order_status = [](const nlohmann::json& j) {
    for (const auto& c : j["checks"])
      if (c["id"] == "order.independence") return c["status"].get<std::string>();
    return std::string("absent");
  };
  fs::copy_file(fs::path(PDR_DATA_DIR) / "cube-in-cube.poly", path("cc.poly"));
  ASSERT_EQ(run("mesh " + path("cc.poly") + " -o " + path("own") + " --max-volume 0.1").code, 0);
  const Outcome own = run("check " + path("own") + " --domain " + path("cc.poly") + " --json");
  ASSERT_EQ(own.code, 0) << own.out;
  EXPECT_EQ(order_status(nlohmann::json::parse(own.out)), "pass");
  if (!on_path("tetgen")) GTEST_SKIP() << "tetgen not installed";
  ASSERT_EQ(std::system(("cd " + dir_.string() + " && tetgen -pq1.4a0.1O0Q cc.poly").c_str()), 0);
  const Outcome tg = run("check " + path("cc.1") + " --domain " + path("cc.poly") + " --json");
  const auto j = nlohmann::json::parse(tg.out);
  const std::string st = order_status(j);
  EXPECT_TRUE(st == "pass" || st == "warn") << tg.out;
  for (const auto& c : j["checks"])
    if (c["id"] == "delaunay.empty_sphere") {
      EXPECT_EQ(c["status"], "pass") << tg.out;
    }
}

}  // namespace
