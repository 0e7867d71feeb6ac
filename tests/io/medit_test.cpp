// medit .mesh: a hand-written free-form file (mixed-case keywords, tokens split over lines,
// comments, skipped sections) and quadratic elements.
#include <gtest/gtest.h>

#include "io/medit.hpp"
#include "io/mesh_io.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

const std::string kData = PDR_IO_TEST_DATA;

TEST(Medit, HandWrittenCube) {
  ReadInfo info;
  const MeshData m = read_mesh(kData + "/cube.mesh", &info);
  expect_same_mesh(cube_mesh(), m, true, "cube.mesh");
  EXPECT_EQ(info.skipped_elements, 1u);  // one edge
  EXPECT_EQ(face_orientation(m).positive, 12u);
}

TEST(Medit, QuadraticTetsAndTrianglesKeepCorners) {
  ScratchDir dir;
  write_text(dir / "q.mesh",
             "MeshVersionFormatted 1\nDimension 3\nVertices\n10\n"
             "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n.5 0 0 0\n.5 .5 0 0\n0 .5 0 0\n"
             "0 0 .5 0\n.5 0 .5 0\n0 .5 .5 0\n"
             "TetrahedraP2\n1\n1 2 3 4 5 6 7 8 9 10 3\n"
             "TrianglesP2\n1\n1 3 2 7 6 5 9\nEnd\n");
  ReadInfo info;
  const MeshData m = read_medit(dir / "q.mesh", &info);
  EXPECT_EQ(m.points.size(), 4u);
  EXPECT_EQ(info.dropped_high_order_nodes, 6u);
  EXPECT_EQ(m.tets, (std::vector<Tet>{{0, 1, 2, 3}}));
  EXPECT_EQ(m.tet_regions, (std::vector<int>{3}));
  EXPECT_EQ(m.faces, (std::vector<Tri>{{0, 2, 1}}));
  EXPECT_EQ(m.face_markers, (std::vector<int>{9}));
  EXPECT_TRUE(m.point_markers.empty());  // all refs 0
}

TEST(Medit, WriterOutputReadsBack) {
  ScratchDir dir;
  write_medit(cube_mesh(), dir / "w.mesh");
  expect_same_mesh(cube_mesh(), read_medit(dir / "w.mesh"), true, "written medit");
  EXPECT_EQ(read_text(dir / "w.mesh").rfind("MeshVersionFormatted 2\n", 0), 0u);
}

}  // namespace
}  // namespace pdr::io::test
