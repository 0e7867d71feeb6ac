// pdr check on Gmsh's own meshes of pdr's test domains (tests/oracle/data/*.geo), saved by
// one gmsh run in every format pdr reads that Gmsh writes: msh 4.1 and 2.2, ASCII and
// binary, medit .mesh (Gmsh writes legacy .vtk, not .vtu: tetgen_oracle_test covers .vtu).
// Each file's verdict equals the independent brute-force GMP verdict (oracle_util.hpp),
// and every format gets the same verdict.
#include <gtest/gtest.h>

#include "io/mesh_io.hpp"
#include "oracle/oracle_util.hpp"

namespace pdr::oracle::test {
namespace {

constexpr const char* kSaves = R"(
Mesh 3;
Mesh.MshFileVersion = 4.1; Mesh.Binary = 0; Save "a41.msh";
Mesh.Binary = 1; Save "b41.msh";
Mesh.MshFileVersion = 2.2; Mesh.Binary = 0; Save "a22.msh";
Mesh.Binary = 1; Save "b22.msh";
Mesh.Binary = 0; Save "a.mesh";
)";

// `factor` scales Gmsh's mesh size (Mesh.MeshSizeFactor): the brute-force oracle costs
// #tets x #points GMP determinants of Gmsh's full-precision coordinates; keep meshes small.
void expect_formats_agree(const std::string& geo, int factor) {
  if (!have_tool("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  ScratchDir dir;
  write_text(dir / "run.geo", "Include \"" + oracle_data(geo) + "\";\nMesh.MeshSizeFactor = " +
                                  std::to_string(factor) + ";\n" + kSaves);
  ASSERT_EQ(run_in(dir.str(), "gmsh run.geo -v 0 -parse_and_exit"), 0)
      << pdr::io::test::read_text(dir / "log.txt");
  std::set<std::string> first;
  bool have_first = false;
  for (const char* out : {"a41.msh", "b41.msh", "a22.msh", "b22.msh", "a.mesh"}) {
    const MeshData m = io::read_mesh(dir / out);
    ASSERT_GT(m.tets.size(), 0u) << out;
    const check::Report r = expect_same_verdict(m, 2.0, geo + " " + out);
    // Validity and conformity hold for Gmsh's meshes whatever their Delaunay verdict.
    EXPECT_EQ(check::test::result(r, "validity.orientation").status, check::Status::Pass) << out;
    EXPECT_EQ(check::test::result(r, "validity.boundary_closed").status, check::Status::Pass)
        << out;
    const std::set<std::string> f = check::test::failed(r);
    if (!have_first) {
      first = f;
      have_first = true;
    } else {
      EXPECT_EQ(f, first) << out;
    }
  }
}

TEST(GmshOracle, BoxInEveryFormat) { expect_formats_agree("box.geo", 3); }

TEST(GmshOracle, CubeInCubeInEveryFormat) { expect_formats_agree("cube-in-cube.geo", 3); }

}  // namespace
}  // namespace pdr::oracle::test
