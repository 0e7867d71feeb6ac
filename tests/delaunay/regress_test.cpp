// Replays the regression corpus tests/regress/delaunay-*.node (shrunk counterexamples
// and hand-made degenerate sets): each must pass every oracle and give the same canonical
// tetrahedralization for the BRIO order and for several plain insertion orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "delaunay/bulk.hpp"
#include "delaunay/oracle.hpp"
#include "delaunay/point_sets.hpp"

namespace pdr {
namespace {

std::vector<std::filesystem::path> corpus() {
  std::vector<std::filesystem::path> out;
  const std::filesystem::path dir = std::filesystem::path(PDR_SOURCE_DIR) / "tests" / "regress";
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("delaunay-", 0) == 0 && e.path().extension() == ".node")
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Regress, CorpusIsPresent) { EXPECT_GE(corpus().size(), 3u); }

TEST(Regress, EveryCaseIsDelaunayAndOrderIndependent) {
  for (const auto& path : corpus()) {
    SCOPED_TRACE(path.filename().string());
    const std::vector<Point> pts = testing::read_node_file(path.string());
    Delaunay ref(pts);
    ASSERT_EQ(bulk_insert(ref).status, BulkStatus::Ok);
    const auto v = testing::check_all(ref);
    EXPECT_TRUE(v.empty()) << v.front();
    const auto canon = testing::canonical_tets(ref);
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      Delaunay dt(testing::shuffled(pts, seed));
      BulkOptions plain;
      plain.spatial_sort = false;
      ASSERT_EQ(bulk_insert(dt, plain).status, BulkStatus::Ok);
      EXPECT_TRUE(testing::check_all(dt).empty()) << "seed " << seed;
      EXPECT_EQ(testing::canonical_tets(dt), canon) << "seed " << seed;
    }
  }
}

}  // namespace
}  // namespace pdr
