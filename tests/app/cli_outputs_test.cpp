// Every output format of `pdr mesh` opens in the tools people use (test-only dependencies;
// each part is skipped when its tool is missing): meshio (/usr/bin/python3) reads the .vtu,
// .msh, .mesh and .node/.ele files and Gmsh the .msh and .mesh files (Gmsh 4.8 reads neither
// .vtu nor TetGen files), and each reports the summary's vertices, tets and boundary faces;
// in the .msh file every element lies in a physical group (meshio used to refuse pdr's .msh:
// "Incompatible cell data 'gmsh:physical'").
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli_support.hpp"

namespace {

using namespace pdr::cli_test;

std::string data(const std::string& name) { return std::string(PDR_DATA_DIR) + "/" + name; }

// The counts a tool printed as "<label> <points> <tets> <triangles>" lines, by label.
std::string counts_line(const std::string& out, const std::string& label) {
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(label + " ", 0) == 0) return line.substr(label.size() + 1);
  return "missing: " + out;
}

class Outputs : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    const Outcome r = run("mesh " + data("cube-in-cube.poly") + " -o " + path("m") +
                              " --max-volume 2 --formats node,vtu,msh,mesh --json",
                          false);
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    want_ = std::to_string(j.at("vertices").get<std::size_t>()) + " " +
            std::to_string(j.at("tets").get<std::size_t>()) + " " +
            std::to_string(j.at("boundary_faces").get<std::size_t>());
  }
  std::string want_;  // "<vertices> <tets> <boundary faces>"
};

TEST_F(Outputs, MeshioReadsEveryFormat) {
  if (std::system("/usr/bin/python3 -c 'import meshio' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 has no meshio";
  write("r.py", R"(import sys, meshio
def n(m, t): return sum(len(c.data) for c in m.cells if c.type == t)
for f in sys.argv[1:]:
    m = meshio.read(f)
    if f.endswith(".ele"):  # meshio's TetGen reader reads .node/.ele; .face by its header
        tri = int(open(f[:-4] + ".face").readline().split()[0])
    else:
        tri = n(m, "triangle")
    if f.endswith(".msh"):  # one physical tag per element of every block
        phys = m.cell_data["gmsh:physical"]
        assert len(phys) == len(m.cells) and all(len(p) == len(c.data) for p, c in zip(phys, m.cells))
    print(f[-4:].lstrip("."), len(m.points), n(m, "tetra"), tri)
)");
  const Outcome r = shell(dir_.string(), "/usr/bin/python3 r.py m.vtu m.msh m.mesh m.ele");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* format : {"vtu", "msh", "mesh", "ele"})
    EXPECT_EQ(counts_line(r.out, format), want_) << format;
}

TEST_F(Outputs, GmshReadsMshAndMedit) {
  if (!on_path("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  for (const char* file : {"m.msh", "m.mesh"}) {
    write("c.geo", std::string("Merge \"") + file + "\";\n"
                   "Printf(\"counts %g %g %g\", Mesh.NbNodes, Mesh.NbTetrahedra, "
                   "Mesh.NbTriangles);\n"
                   "v() = Physical Volume{:};\ns() = Physical Surface{:};\n"
                   "Printf(\"physical %g %g\", #v(), #s());\n");
    const Outcome r = shell(dir_.string(), "gmsh - c.geo");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("Error"), std::string::npos) << r.out;
    EXPECT_EQ(counts_line(r.out, "counts"), want_) << file;
    if (std::string(file) == "m.msh") {
      // cube-in-cube: one region, facet markers 1 (outer cube) and 2 (the void's cube)
      EXPECT_EQ(counts_line(r.out, "physical"), "1 2") << r.out;
    }
  }
}

}  // namespace
