// Real files from the tools (test-only dependencies; each test is skipped when its tool is
// not on PATH): TetGen and Gmsh meshes read with every tet positive and every face outward
// after the format mapping (the experiments behind the conventions in tetgen.hpp, gmsh.hpp,
// medit.hpp), the same Gmsh mesh read identically from msh22/msh41 ASCII/binary and medit,
// and pdr's own .node/.ele, .msh and .mesh files loaded by tetgen and gmsh.
#include <gtest/gtest.h>

#include "io/gmsh.hpp"
#include "io/medit.hpp"
#include "io/mesh_io.hpp"
#include "io/tetgen.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

// A 2x2x2 box with a 1x1x1 void in the middle: facet markers 1 (outside) and 2 (void),
// one region with attribute 5.
constexpr const char* kVoidPoly = R"(16 3 0 0
1 0 0 0
2 2 0 0
3 2 2 0
4 0 2 0
5 0 0 2
6 2 0 2
7 2 2 2
8 0 2 2
9 .5 .5 .5
10 1.5 .5 .5
11 1.5 1.5 .5
12 .5 1.5 .5
13 .5 .5 1.5
14 1.5 .5 1.5
15 1.5 1.5 1.5
16 .5 1.5 1.5
12 1
1 0 1
4 1 2 3 4
1 0 1
4 5 6 7 8
1 0 1
4 1 2 6 5
1 0 1
4 2 3 7 6
1 0 1
4 3 4 8 7
1 0 1
4 4 1 5 8
1 0 2
4 9 10 11 12
1 0 2
4 13 14 15 16
1 0 2
4 9 10 14 13
1 0 2
4 10 11 15 14
1 0 2
4 11 12 16 15
1 0 2
4 12 9 13 16
1
1 1 1 1
1
1 0.1 0.1 0.1 5 -1
)";

void expect_well_oriented(const MeshData& m, const std::string& label,
                          bool interior_faces = false) {
  SCOPED_TRACE(label);
  ASSERT_FALSE(m.tets.empty());
  const Orientation t = tet_orientation(m);
  EXPECT_EQ(t.positive, m.tets.size());
  // Every boundary face outward; faces between regions (tetgen -r) are interior.
  const Orientation f = face_orientation(m);
  EXPECT_EQ(f.negative, 0u);
  EXPECT_GT(f.positive, 0u);
  EXPECT_EQ(f.positive + f.zero, m.faces.size());
  if (!interior_faces) {
    EXPECT_EQ(f.zero, 0u);
  }
}

TEST(TetgenTool, MeshesReadPositiveWithOutwardFaces) {
  if (!have_tool("tetgen")) GTEST_SKIP() << "tetgen is not on PATH";
  ScratchDir dir;
  write_text(dir / "v.poly", kVoidPoly);
  const Plc plc = read_domain(dir / "v.poly");
  EXPECT_EQ(plc.facets.size(), 12u);
  EXPECT_EQ(plc.holes.size(), 1u);
  // Default (1-based), -z (0-based), -o2 (10-node tets, 6-node faces), -nn (face
  // neighbours), -A (region attributes).
  for (const std::string flags : {"-pq1.4a0.05AQ", "-pq1.4a0.05zQ", "-pq1.4a0.05o2Q",
                                  "-pq1.4a0.05nnQ"}) {
    ASSERT_EQ(run_in(dir.str(), "tetgen " + flags + " v.poly"), 0) << flags;
    ReadInfo info;
    const MeshData m = read_mesh(dir / "v.1", &info);
    expect_well_oriented(m, flags);
    EXPECT_FALSE(m.faces.empty());
    for (int marker : m.face_markers) EXPECT_TRUE(marker == 1 || marker == 2) << flags;
    if (flags == "-pq1.4a0.05AQ") {
      ASSERT_EQ(m.tet_regions.size(), m.tets.size());
      for (int r : m.tet_regions) EXPECT_EQ(r, 5);
    }
    if (flags == "-pq1.4a0.05o2Q") {
      EXPECT_GT(info.dropped_high_order_nodes, 0u);
    }
  }
}

TEST(TetgenTool, ReadsPdrFiles) {
  if (!have_tool("tetgen")) GTEST_SKIP() << "tetgen is not on PATH";
  ScratchDir dir;
  write_tetgen_mesh(cube_mesh(), dir / "c");
  ASSERT_EQ(run_in(dir.str(), "tetgen -rQ c"), 0);
  const MeshData back = read_tetgen_mesh(dir / "c.1");
  MeshData want = cube_mesh();
  EXPECT_EQ(canonical(back).tets, canonical(want).tets);
  EXPECT_EQ(back.tet_regions, want.tet_regions);
  expect_well_oriented(back, "tetgen -r", true);
}

// Meshes an OpenCASCADE box once and saves it in every format and variant (one gmsh run:
// its start-up dominates the cost), then at second order.
constexpr const char* kBoxGeo = R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Surface(7) = {1, 2, 3};
Physical Surface(8) = {4, 5, 6};
Physical Volume(3) = {1};
Mesh.CharacteristicLengthMax = 0.4;
Mesh 3;
Mesh.MshFileVersion = 4.1; Mesh.Binary = 0; Save "a41.msh";
Mesh.Binary = 1; Save "b41.msh";
Mesh.MshFileVersion = 2.2; Mesh.Binary = 0; Save "a22.msh";
Mesh.Binary = 1; Save "b22.msh";
Mesh.Binary = 0; Save "a.mesh";
SetOrder 2;
Mesh.MshFileVersion = 4.1; Save "q.msh";
)";

TEST(GmshTool, AllFormatsAndVariantsReadTheSameMesh) {
  if (!have_tool("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  ScratchDir dir;
  write_text(dir / "box.geo", kBoxGeo);
  ASSERT_EQ(run_in(dir.str(), "gmsh box.geo -v 0 -parse_and_exit"), 0)
      << read_text(dir / "log.txt");
  MeshData first;
  for (const char* out : {"a41.msh", "b41.msh", "a22.msh", "b22.msh", "a.mesh"}) {
    const MeshData m = read_mesh(dir / out);
    expect_well_oriented(m, out);
    if (std::string(out) != "a.mesh") {
      EXPECT_EQ(m.tet_regions, std::vector<int>(m.tets.size(), 3)) << out;
      for (int marker : m.face_markers) EXPECT_TRUE(marker == 7 || marker == 8) << out;
    }
    if (first.tets.empty()) {
      first = m;
    } else {
      // ASCII holds 16 significant digits, binary the exact bits.
      EXPECT_EQ(canonical(m, 0x1p-30), canonical(first, 0x1p-30)) << out;
    }
  }
  // Second order: 10-node tets and 6-node triangles read by their corners.
  ReadInfo info;
  const MeshData q = read_mesh(dir / "q.msh", &info);
  expect_well_oriented(q, "order 2");
  EXPECT_GT(info.dropped_high_order_nodes, 0u);
  EXPECT_EQ(q.points.size(), first.points.size());
  EXPECT_EQ(canonical(q, 0x1p-30), canonical(first, 0x1p-30));
}

TEST(GmshTool, LoadsPdrMshAndMeditFiles) {
  if (!have_tool("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  ScratchDir dir;
  const MeshData c = cube_mesh();
  write_gmsh(c, dir / "w.msh");
  write_medit(c, dir / "w.mesh");
  for (const char* in : {"w.msh", "w.mesh"}) {
    ASSERT_EQ(run_in(dir.str(), std::string("gmsh ") + in + " -0 -format msh41 -o back.msh"), 0);
    const std::string log = read_text(dir / "log.txt");
    EXPECT_EQ(log.find("Error"), std::string::npos) << in << ": " << log;
    const MeshData back = read_gmsh(dir / "back.msh");
    EXPECT_EQ(canonical(back), canonical(c)) << in;
    if (std::string(in) == "w.msh") {
      EXPECT_EQ(back.tet_regions, c.tet_regions);
      EXPECT_EQ(back.face_markers, c.face_markers);
    }
  }
}

}  // namespace
}  // namespace pdr::io::test
