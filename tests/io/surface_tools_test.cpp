// Surface files written by the tools (test-only dependencies; each test is skipped when its
// tool is missing): Gmsh's surface meshes of OpenCASCADE solids and meshio's files of a box
// of 12 triangles, in every format and variant, read back as the same domain: the same
// facets (each a plane side, a side with a hole where a solid stands on another or a
// square hole goes through) and the same points.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "io/mesh_io.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

bool have_meshio() {
  return std::system("/usr/bin/python3 -c 'import meshio' >/dev/null 2>&1") == 0;
}

std::size_t holes(const Plc& plc) {
  std::size_t n = 0;
  for (const PlcFacet& f : plc.facets) n += f.holes.size();
  return n;
}

struct Solid {
  const char* name;
  const char* geo;  // OpenCASCADE commands after SetFactory
  std::size_t facets, holes;
};

constexpr Solid kSolids[] = {
    {"box", "Box(1) = {0,0,0, 1,1,1};", 6, 0},
    // A box on a box: the big top is a square with a square hole.
    {"step", "Box(1) = {0,0,0, 2,2,1}; Box(2) = {0.5,0.5,1, 1,1,1};\n"
             "BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }", 11, 1},
    // A square hole through a slab: top and bottom have a hole, 4 + 4 sides.
    {"frame", "Box(1) = {0,0,0, 3,3,1}; Box(2) = {1,1,-1, 1,1,3};\n"
              "BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }", 10, 2},
};

TEST(SurfaceTools, GmshSurfacesReadAsTheSolidsSides) {
  if (!have_tool("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  for (const Solid& solid : kSolids) {
    SCOPED_TRACE(solid.name);
    ScratchDir dir;
    write_text(dir / "s.geo", std::string("SetFactory(\"OpenCASCADE\");\n") + solid.geo +
                                  "\nMesh.MeshSizeMin = 0.5;\nMesh.MeshSizeMax = 0.5;\n");
    const std::string flags[][2] = {{"stl", "a.stl"},       {"stl -bin", "b.stl"},
                                    {"mesh", "a.mesh"},     {"msh22", "a22.msh"},
                                    {"msh22 -bin", "b22.msh"}, {"msh41", "a41.msh"},
                                    {"msh41 -bin", "b41.msh"}};
    std::vector<Plc> plcs;
    for (const auto& [format, file] : flags) {
      ASSERT_EQ(run_in(dir.str(), "gmsh -2 s.geo -format " + format + " -o " + file), 0)
          << read_text(dir / "log.txt");
      plcs.push_back(read_domain(dir / file));
      const Plc& plc = plcs.back();
      EXPECT_EQ(plc.facets.size(), solid.facets) << file;
      EXPECT_EQ(holes(plc), solid.holes) << file;
    }
    // Binary STL holds float32: on these axis-aligned solids the plane coordinates stay
    // exact and the boundary vertices are the same in every format up to rounding.
    for (const Plc& plc : plcs) EXPECT_EQ(plc.points.size(), plcs[0].points.size());
  }
}

// meshio writes the box of 12 triangles in each format and variant, and of 6 squares in
// those that hold squares; each reads as 6 squares.
TEST(SurfaceTools, MeshioBoxInEveryFormat) {
  if (!have_meshio()) GTEST_SKIP() << "/usr/bin/python3 has no meshio";
  ScratchDir dir;
  write_text(dir / "w.py", R"(import meshio, numpy as np
p = np.array([[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]], dtype=float)
t = np.array([[0,2,1],[0,3,2],[4,5,6],[4,6,7],[0,1,5],[0,5,4],[1,2,6],[1,6,5],[2,3,6],
              [3,7,6],[0,7,3],[0,4,7]])
m = meshio.Mesh(p, [("triangle", t)])
m.write("a.off")
m.write("a.stl", binary=False)
m.write("b.stl", binary=True)
m.write("a.ply", binary=False)
m.write("b.ply", binary=True)
m.write("a.mesh")
m.write("a22.msh", file_format="gmsh22", binary=False)
m.write("b22.msh", file_format="gmsh22", binary=True)
m.write("a41.msh", file_format="gmsh", binary=False)
m.write("b41.msh", file_format="gmsh", binary=True)
q = np.array([[0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7]])
m = meshio.Mesh(p, [("quad", q)])
m.write("q.ply", binary=True)
m.write("q.mesh")
m.write("q22.msh", file_format="gmsh22", binary=False)
m.write("q41.msh", file_format="gmsh", binary=True)
)");
  ASSERT_EQ(run_in(dir.str(), "/usr/bin/python3 w.py"), 0) << read_text(dir / "log.txt");
  for (const char* file : {"a.off", "a.stl", "b.stl", "a.ply", "b.ply", "a.mesh", "a22.msh",
                           "b22.msh", "a41.msh", "b41.msh", "q.ply", "q.mesh", "q22.msh",
                           "q41.msh"}) {
    SCOPED_TRACE(file);
    const Plc plc = read_domain(dir / file);
    EXPECT_EQ(plc.facets.size(), 6u);
    EXPECT_EQ(plc.points.size(), 8u);
    for (const PlcFacet& f : plc.facets) {
      ASSERT_EQ(f.polygons.size(), 1u);
      EXPECT_EQ(f.polygons[0].size(), 4u);
    }
  }
}

}  // namespace
}  // namespace pdr::io::test
