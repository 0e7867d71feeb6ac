// The partitioned output of a parallel run (src/app/partitioned_output.hpp): one piece per
// rank holding that rank's tets, the rank as the cell field "owner". A rank may end with no
// tets (its neighbours' cavities can take them all); its piece is then an empty, readable
// grid, and the pieces still hold the whole mesh.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../io/io_test_util.hpp"
#include "app/partitioned_output.hpp"
#include "io/vtu.hpp"

namespace pdr::app {
namespace {

// Two tets sharing the face 012.
MeshData bipyramid() {
  MeshData m;
  m.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 5}, {1, 1, -5}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  return m;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PartitionedOutput, EveryRankHasAPieceAndEmptyOnesRead) {
  io::test::ScratchDir dir;
  const MeshData m = bipyramid();
  // Ranks 0 and 2 hold nothing, rank 1 both tets, rank 3 none either.
  const auto paths = write_partitioned_vtu(m, {1, 1}, 4, dir / "out");
  ASSERT_EQ(paths.size(), 5u);
  const std::string pvtu = read_text(dir / "out.pvtu");
  for (int r = 0; r < 4; ++r)
    EXPECT_NE(pvtu.find("<Piece Source=\"out_p" + std::to_string(r) + ".vtu\"/>"),
              std::string::npos)
        << pvtu;
  std::size_t tets = 0;
  for (int r = 0; r < 4; ++r) {
    const MeshData piece = io::read_vtu(dir / ("out_p" + std::to_string(r) + ".vtu"));
    EXPECT_EQ(piece.tets.size(), r == 1 ? 2u : 0u) << "piece " << r;
    EXPECT_EQ(piece.points.size(), r == 1 ? 5u : 0u) << "piece " << r;
    tets += piece.tets.size();
  }
  EXPECT_EQ(tets, m.tets.size());
  // Nothing but the pieces and the .pvtu (no temporaries left).
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.pvtu", "out_p0.vtu", "out_p1.vtu",
                                                      "out_p2.vtu", "out_p3.vtu"}));
}

TEST(PartitionedOutput, PiecesSplitTheMeshByOwner) {
  io::test::ScratchDir dir;
  const MeshData m = bipyramid();
  write_partitioned_vtu(m, {1, 0}, 2, dir / "out");
  const MeshData p0 = io::read_vtu(dir / "out_p0.vtu");
  const MeshData p1 = io::read_vtu(dir / "out_p1.vtu");
  ASSERT_EQ(p0.tets.size(), 1u);
  ASSERT_EQ(p1.tets.size(), 1u);
  // Each piece renumbers its own four points: tet 1 (apex below) in piece 0.
  ASSERT_EQ(p0.points.size(), 4u);
  EXPECT_EQ(p0.points[p0.tets[0][3]], m.points[4]);
  EXPECT_EQ(p1.points[p1.tets[0][3]], m.points[3]);
}

}  // namespace
}  // namespace pdr::app
