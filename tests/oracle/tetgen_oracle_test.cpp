// pdr check on TetGen's own meshes of pdr's test domains (data/*.poly), in every TetGen
// file variant (1-based, 0-based -z, 10-node -o2, region attributes -A) and re-encoded as
// .vtu (ASCII, inline base64, appended base64 and raw): each verdict equals the
// independent brute-force GMP verdict (oracle_util.hpp). And what is true of TetGen's
// output: its default mesh optimisation leaves non-Delaunay tets, and on an inadmissible
// domain (the tee's 70-degree edges) tets of ratio above 2 remain despite -q2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/mesh_io.hpp"
#include "io/vtu.hpp"
#include "oracle/oracle_util.hpp"

namespace pdr::oracle::test {
namespace {

using check::test::result;

// Runs `tetgen FLAGS DOMAIN.poly` in a fresh copy of the domain; returns PREFIX (DOMAIN.1).
std::string tetgen(const ScratchDir& dir, const std::string& domain, const std::string& flags) {
  write_text(dir / (domain + ".poly"), pdr::io::test::read_text(data(domain + ".poly")));
  const int rc = run_in(dir.str(), "tetgen " + flags + " " + domain + ".poly");
  EXPECT_EQ(rc, 0) << flags << ": " << pdr::io::test::read_text(dir / "log.txt");
  return dir / (domain + ".1");
}

TEST(TetgenOracle, EveryFileVariantGetsTheIndependentVerdict) {
  if (!have_tool("tetgen")) GTEST_SKIP() << "tetgen is not on PATH";
  // The brute-force oracle runs on the first variant; the others must give its report.
  std::string first;
  for (const std::string flags : {"-pqa15Q", "-pqa15zQ", "-pqa15o2Q", "-pqa15AQ"}) {
    ScratchDir dir;
    const MeshData m = io::read_mesh(tetgen(dir, "cube-in-cube", flags));
    ASSERT_GT(m.tets.size(), 100u) << flags;
    check::Options o;
    o.ratio_bound = 2.0;
    o.max_reported = m.tets.size() + m.points.size();
    const check::Report r =
        first.empty() ? expect_same_verdict(m, 2.0, flags) : check::test::run(m, o);
    EXPECT_EQ(result(r, "validity.orientation").status, check::Status::Pass) << flags;
    EXPECT_EQ(result(r, "validity.faces").status, check::Status::Pass) << flags;
    // Every variant holds the same mesh: the same report, to the last finding.
    const std::string j = check::to_json(r).dump();
    if (first.empty()) first = j;
    EXPECT_EQ(j, first) << flags;
  }
}

TEST(TetgenOracle, VtuEncodingsGetTheSameReport) {
  if (!have_tool("tetgen")) GTEST_SKIP() << "tetgen is not on PATH";
  ScratchDir dir;
  const MeshData m = io::read_mesh(tetgen(dir, "box", "-pq1.2a0.5Q"));
  const std::string want = check::to_json(expect_same_verdict(m, 2.0, "node/ele")).dump();
  for (io::VtuEncoding enc : {io::VtuEncoding::Ascii, io::VtuEncoding::InlineBase64,
                              io::VtuEncoding::AppendedBase64, io::VtuEncoding::AppendedRaw}) {
    io::VtuOptions o;
    o.encoding = enc;
    io::write_vtu(m, dir / "m.vtu", {}, {}, o);
    const MeshData back = io::read_mesh(dir / "m.vtu");
    check::Options co;
    co.ratio_bound = 2.0;
    co.max_reported = m.tets.size() + m.points.size();
    EXPECT_EQ(check::to_json(check::test::run(back, co)).dump(), want)
        << static_cast<int>(enc);
  }
}

TEST(TetgenOracle, DefaultOptimisationLeavesNonDelaunayTets) {
  if (!have_tool("tetgen")) GTEST_SKIP() << "tetgen is not on PATH";
  ScratchDir dir;
  const MeshData opt = io::read_mesh(tetgen(dir, "cube-in-cube", "-pqa10Q"));
  const check::Report r = expect_same_verdict(opt, 2.0, "default optimisation");
  EXPECT_EQ(result(r, "delaunay.empty_sphere").status, check::Status::Fail);
  EXPECT_EQ(result(r, "validity.orientation").status, check::Status::Pass);
  // Without the optimisation (-O0) the same run is Delaunay.
  ScratchDir dir0;
  const MeshData plain = io::read_mesh(tetgen(dir0, "cube-in-cube", "-pqa10O0Q"));
  const check::Report r0 = expect_same_verdict(plain, 2.0, "-O0");
  EXPECT_EQ(result(r0, "delaunay.empty_sphere").status, check::Status::Pass);
}

TEST(TetgenOracle, InadmissibleDomainKeepsTetsAboveRatio2) {
  if (!have_tool("tetgen")) GTEST_SKIP() << "tetgen is not on PATH";
  ScratchDir dir;
  // 1875 tets: the oracle judges orientation and ratio only (Delaunay is covered above).
  const MeshData m = io::read_mesh(tetgen(dir, "tee", "-pqa1Q"));
  const check::Report r = expect_same_verdict(m, 2.0, "tee -pqa1", false);
  EXPECT_EQ(result(r, "quality.ratio").status, check::Status::Fail);
  EXPECT_GT(result(r, "quality.ratio").values.at("max_ratio"), 2.0);
}

}  // namespace
}  // namespace pdr::oracle::test
