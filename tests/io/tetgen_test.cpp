// TetGen formats: hand-written .node/.ele/.face (0- and 1-based, attributes, markers,
// comments, 10-node tets, -nn and -o2 face lines) and .node/.poly/.smesh domains.
#include <gtest/gtest.h>

#include "io/mesh_io.hpp"
#include "io/tetgen.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

const std::string kData = PDR_IO_TEST_DATA;

TEST(TetgenMesh, CubeOneBasedWithAttributesAndMarkers) {
  const MeshData m = read_mesh(kData + "/cube.ele");
  expect_same_mesh(cube_mesh(), m, true, "cube.ele");
  EXPECT_EQ(tet_orientation(m).positive, 6u);
  EXPECT_EQ(face_orientation(m).positive, 12u);  // swapped to outward on read
  // By prefix and by .node name too.
  expect_same_mesh(cube_mesh(), read_mesh(kData + "/cube"), true, "prefix");
  expect_same_mesh(cube_mesh(), read_mesh(kData + "/cube.node"), true, "cube.node");
}

TEST(TetgenMesh, ZeroBasedTenNodeTetsAndNeighbourFaces) {
  ScratchDir dir;
  // 0-based (first index 0), 10-node tet, real-valued attribute (not a region), faces
  // with -o2 mid-edge nodes and -nn neighbours, no face markers.
  write_text(dir / "t.node",
             "# tetgen -zo2\n10 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n"
             "4 .5 0 0\n5 .5 .5 0\n6 0 .5 0\n7 0 0 .5\n8 .5 0 .5\n9 0 .5 .5\n");
  write_text(dir / "t.ele", "1 10 1\n0  0 1 2 3  4 5 6 7 8 9  0.25\n");
  write_text(dir / "t.face",
             "2 0\n0  0 1 2  4 5 6  0 -1\n"  // 6 nodes + 2 neighbours
             "1  0 3 1  -1 0\n");            // 3 nodes + 2 neighbours
  ReadInfo info;
  const MeshData m = read_tetgen_mesh(dir / "t", &info);
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_EQ(info.dropped_high_order_nodes, 6u);
  EXPECT_EQ(m.tets, (std::vector<Tet>{{0, 1, 2, 3}}));
  EXPECT_TRUE(m.tet_regions.empty());  // 0.25 is not a region number
  EXPECT_EQ(m.faces, (std::vector<Tri>{{0, 2, 1}, {0, 1, 3}}));
  EXPECT_TRUE(m.face_markers.empty());
  EXPECT_EQ(face_orientation(m).positive, 2u);
}

TEST(TetgenMesh, FaceFileIsOptional) {
  ScratchDir dir;
  write_text(dir / "a.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write_text(dir / "a.ele", "1 4 0\n1 1 2 3 4\n");
  const MeshData m = read_mesh(dir / "a");
  EXPECT_EQ(m.tets.size(), 1u);
  EXPECT_TRUE(m.faces.empty());
}

TEST(TetgenDomain, NodePointsAndNodeDomain) {
  const std::vector<Point> pts = read_tetgen_points(kData + "/cube.node");
  EXPECT_EQ(pts, cube_mesh().points);
  const Plc plc = read_domain(kData + "/cube.node");
  EXPECT_EQ(plc.points, cube_mesh().points);
  EXPECT_EQ(plc.point_markers, cube_mesh().point_markers);
  EXPECT_TRUE(plc.facets.empty());
  EXPECT_EQ(plc.point_lines, (std::vector<std::size_t>{3, 4, 6, 7, 8, 9, 10, 11}));
}

constexpr const char* kPoly = R"(# a box with a square hole in its top facet
8 3 0 1
0  0 0 0  1
1  2 0 0  1
2  2 2 0  1
3  0 2 0  1
4  0 0 2  2
5  2 0 2  2
6  2 2 2  2
7  0 2 2  2
# facets
3 1
1 0 5
4  0 1 2 3
2 1 6       # top: outer polygon, an inner polygon, one hole
4  4 5 6 7
4  4 5 6 7
1  1 1 2
1
3  3 7 4
1   # volume holes
1  1 1 1
2
1  0.5 0.5 0.5  10  0.01
2  1.5 1.5 1.5  20
)";

TEST(TetgenDomain, PolyWithFacetHolesVolumeHolesAndRegions) {
  ScratchDir dir;
  write_text(dir / "box.poly", kPoly);
  const Plc plc = read_domain(dir / "box.poly");
  EXPECT_EQ(plc.source, dir / "box.poly");
  ASSERT_EQ(plc.points.size(), 8u);
  EXPECT_EQ(plc.points[6], (Point{2, 2, 2}));
  EXPECT_EQ(plc.point_markers[4], 2);
  EXPECT_EQ(plc.point_lines[0], 3u);
  ASSERT_EQ(plc.facets.size(), 3u);
  EXPECT_EQ(plc.facets[0].marker, 5);
  EXPECT_EQ(plc.facets[0].line, 13u);
  EXPECT_EQ(plc.facets[0].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2, 3}}));
  EXPECT_EQ(plc.facets[1].marker, 6);
  EXPECT_EQ(plc.facets[1].polygons.size(), 2u);
  EXPECT_EQ(plc.facets[1].holes, (std::vector<Point>{{1, 1, 2}}));
  EXPECT_EQ(plc.facets[2].marker, 0);  // header "1": no holes, no marker
  EXPECT_EQ(plc.facets[2].polygons, (std::vector<std::vector<std::uint32_t>>{{3, 7, 4}}));
  EXPECT_EQ(plc.holes, (std::vector<Point>{{1, 1, 1}}));
  EXPECT_EQ(plc.hole_lines, (std::vector<std::size_t>{22}));
  ASSERT_EQ(plc.regions.size(), 2u);
  EXPECT_EQ(plc.regions[0].attribute, 10);
  EXPECT_EQ(plc.regions[0].max_volume, 0.01);
  EXPECT_EQ(plc.regions[1].max_volume, -1);
  EXPECT_EQ(plc.regions[1].line, 25u);
}

TEST(TetgenDomain, PolyWithoutPointsReadsSiblingNodeAndMayOmitLists) {
  ScratchDir dir;
  write_text(dir / "c.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write_text(dir / "c.poly", "0 3 0 0\n1 0\n1\n3 1 2 3\n");  // no hole or region list
  const Plc plc = read_domain(dir / "c.poly");
  EXPECT_EQ(plc.points.size(), 4u);
  ASSERT_EQ(plc.facets.size(), 1u);
  EXPECT_EQ(plc.facets[0].polygons[0], (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_TRUE(plc.holes.empty());
  EXPECT_TRUE(plc.regions.empty());
}

TEST(TetgenDomain, Smesh) {
  ScratchDir dir;
  write_text(dir / "s.smesh",
             "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n"
             "4 1\n3 0 2 1 11\n3 0 1 3 12\n3 1 2 3 13\n3 0 3 2 14\n"
             "0\n1\n0  0.1 0.1 0.1  3\n");
  const Plc plc = read_domain(dir / "s.smesh");
  ASSERT_EQ(plc.facets.size(), 4u);
  EXPECT_EQ(plc.facets[0].polygons[0], (std::vector<std::uint32_t>{0, 2, 1}));
  EXPECT_EQ(plc.facets[3].marker, 14);
  EXPECT_EQ(plc.facets[3].line, 10u);
  ASSERT_EQ(plc.regions.size(), 1u);
  EXPECT_EQ(plc.regions[0].attribute, 3);
}

}  // namespace
}  // namespace pdr::io::test
