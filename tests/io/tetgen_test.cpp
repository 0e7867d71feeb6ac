// TetGen formats: hand-written .node/.ele/.face (0- and 1-based, attributes, markers,
// comments, 10-node tets, -nn and -o2 face lines) and .node/.poly/.smesh domains.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_io.hpp"
#include "io/tetgen.hpp"
#include "io/tetgen_lines.hpp"
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

// The files formatted in parts (io/tetgen_lines.hpp: the ranks' writer, each rank its own
// run of entities, par/rank_files.hpp) are byte for byte the whole writer's, with and
// without the optional columns, cut anywhere (an empty part too).
TEST(TetgenMesh, LinesInPartsAreTheWholeWritersFiles) {
  const auto slurp = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  MeshData bare = cube_mesh();
  bare.point_markers.clear();
  bare.tet_regions.clear();
  for (const MeshData& m : {cube_mesh(), bare}) {
    ScratchDir dir;
    write_tetgen_mesh(m, dir / "m");
    const std::string node = slurp(dir / "m.node"), ele = slurp(dir / "m.ele"),
                      face = slurp(dir / "m.face");
    for (std::size_t cut = 0; cut <= 6; ++cut) {  // parts [0, cut) and [cut, n)
      const auto part = [&](auto&& lines, const auto& all, const auto& extra, std::size_t n) {
        const std::size_t c = std::min(cut, n);
        TextSink a, b;
        lines(a, std::span(all).first(c), 0,
              extra.empty() ? std::span<const int>() : std::span<const int>(extra).first(c));
        lines(b, std::span(all).subspan(c), c,
              extra.empty() ? std::span<const int>() : std::span<const int>(extra).subspan(c));
        tetgen_lines::tail(b);
        return a.text() + b.text();
      };
      TextSink hn, he, hf;
      tetgen_lines::node_header(hn, m.points.size(), !m.point_markers.empty());
      tetgen_lines::ele_header(he, m.tets.size(), !m.tet_regions.empty());
      tetgen_lines::face_header(hf, m.faces.size(), !m.face_markers.empty());
      EXPECT_EQ(hn.text() + part(tetgen_lines::nodes, m.points, m.point_markers, m.points.size()), node)
          << "cut " << cut;
      EXPECT_EQ(he.text() + part(tetgen_lines::eles, m.tets, m.tet_regions, m.tets.size()), ele)
          << "cut " << cut;
      EXPECT_EQ(hf.text() + part(tetgen_lines::faces, m.faces, m.face_markers, m.faces.size()), face)
          << "cut " << cut;
    }
  }
}

// The lengths counted from the digits are the lengths written, at every number of digits
// (vertex numbers up to 2^32 - 1, line numbers past 2^32, negative and positive regions),
// and a sink that hands its text to a function in pieces hands it all, in order.
TEST(TetgenMesh, CountedLengthsAreTheWrittenOnes) {
  std::vector<Tet> tets;
  std::vector<int> regions;
  std::uint64_t p10 = 1;
  for (int d = 0; d <= 10; ++d, p10 *= 10)
    for (const std::uint64_t v : {p10 - 2, p10 - 1, p10, p10 + 1}) {
      const auto u = static_cast<std::uint32_t>(std::min<std::uint64_t>(v, 0xFFFFFFFEu));
      tets.push_back({u, u / 3, 0, 0xFFFFFFFEu});
      const auto m = static_cast<int>(std::min<std::uint64_t>(v, 0x7FFFFFFF));
      regions.push_back(d % 2 == 0 ? m : -m);
    }
  regions.back() = std::numeric_limits<int>::min();
  for (const std::size_t first : {std::size_t{0}, std::size_t{9}, std::size_t{99'999'999'990},
                                  std::size_t{1} << 40}) {
    for (const bool with_regions : {false, true}) {
      const std::span<const int> r = with_regions ? std::span<const int>(regions) : std::span<const int>();
      TextSink a;
      tetgen_lines::eles(a, tets, first, r);
      EXPECT_EQ(tetgen_lines::eles_bytes(tets, first, r), a.text().size()) << first;
    }
  }
  std::vector<Tet> many(300'000, Tet{123456, 7, 89, 1000000});  // several 1 MiB pieces
  TextSink whole;
  tetgen_lines::eles(whole, many, 0, {});
  std::string joined;
  std::size_t pieces = 0;
  TextSink streamed([&](std::string_view piece) {
    joined += piece;
    ++pieces;
  });
  tetgen_lines::eles(streamed, many, 0, {});
  streamed.flush();
  EXPECT_GT(pieces, 2u);
  EXPECT_EQ(joined, whole.text());
  EXPECT_EQ(tetgen_lines::eles_bytes(many, 0, {}), joined.size());
  EXPECT_THROW(TextSink(std::function<void(std::string_view)>()), std::invalid_argument);
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
