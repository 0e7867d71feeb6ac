// End-to-end tests of surface domains (io/surface.hpp) through `pdr mesh` and
// `pdr check --domain`: a box of 12 triangles meshes exactly as the box of 6 squares, a
// facet with a hole meshes and passes the check, and a defective surface exits 2 with
// file:line and writes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli_support.hpp"
#include "io/surface_shapes.hpp"

namespace {

using namespace pdr::cli_test;
using pdr::io::test::off_text;

nlohmann::json mesh_json(const std::string& args) {
  const Outcome r = run("mesh " + args + " --json", false);
  EXPECT_EQ(r.code, 0) << r.out;
  return nlohmann::json::parse(r.out);
}

TEST_F(Cli, SurfaceBoxOfTrianglesMeshesAsTheBoxOfSquares) {
  write("tri.off", off_text(pdr::io::test::box_triangles()));
  write("quad.off", off_text(pdr::io::test::box_squares()));
  const auto t = mesh_json(path("tri.off") + " -o " + path("t") + " --max-volume 0.01");
  const auto q = mesh_json(path("quad.off") + " -o " + path("q") + " --max-volume 0.01");
  EXPECT_EQ(t.at("check"), "pass");
  EXPECT_EQ(t.at("tets"), q.at("tets"));
  EXPECT_EQ(t.at("boundary_faces"), q.at("boundary_faces"));
  EXPECT_EQ(t.at("vertices"), q.at("vertices"));
  for (const char* m : {"t", "q"}) {
    const Outcome c = run("check " + path(m) + " --domain " + path("tri.off"));
    EXPECT_EQ(c.code, 0) << c.out;
  }
}

TEST_F(Cli, SurfaceFacetWithAHoleMeshesAndPassesTheCheck) {
  write("step.off", off_text(pdr::io::test::step()));
  const auto j = mesh_json(path("step.off") + " -o " + path("s") + " --max-volume 0.1");
  EXPECT_EQ(j.at("check"), "pass");
  const Outcome c = run("check " + path("s") + " --domain " + path("step.off"));
  EXPECT_EQ(c.code, 0) << c.out;
}

TEST_F(Cli, SurfaceObjMeshesAsTheOff) {
  write("step.off", off_text(pdr::io::test::step()));
  write("step.obj", pdr::io::test::obj_text(pdr::io::test::step()));
  const auto o = mesh_json(path("step.off") + " -o " + path("o") + " --max-volume 0.1");
  const auto w = mesh_json(path("step.obj") + " -o " + path("w") + " --max-volume 0.1");
  EXPECT_EQ(w.at("check"), "pass");
  EXPECT_EQ(w.at("tets"), o.at("tets"));
  EXPECT_EQ(w.at("vertices"), o.at("vertices"));
  const Outcome c = run("check " + path("o") + " --domain " + path("step.obj"));
  EXPECT_EQ(c.code, 0) << c.out;
}

// A quad mesh as a modelling tool writes it (OBJ): a square prism twisted by 30 degrees in
// four layers, each side a quad that is not planar (a bilinear patch). The quads are split
// into triangles (io/surface.hpp step 0b); the mesh passes the check, also of the file as
// the domain. Before, every such quad was refused (exit 2, "planar facet").
TEST_F(Cli, SurfaceOfNonPlanarQuadsMeshes) {
  pdr::io::test::Shape twisted;
  constexpr int kLayers = 4;
  for (int l = 0; l <= kLayers; ++l)
    for (int i = 0; i < 4; ++i) {
      const double t = std::numbers::pi / 2 * i + std::numbers::pi / 6 * l / kLayers;
      twisted.points.push_back({std::cos(t), std::sin(t), 0.5 * l});
    }
  const auto id = [](int l, int i) { return static_cast<std::uint32_t>(4 * l + i % 4); };
  twisted.faces.push_back({id(0, 3), id(0, 2), id(0, 1), id(0, 0)});
  twisted.faces.push_back({id(kLayers, 0), id(kLayers, 1), id(kLayers, 2), id(kLayers, 3)});
  for (int l = 0; l < kLayers; ++l)
    for (int i = 0; i < 4; ++i)
      twisted.faces.push_back({id(l, i), id(l, i + 1), id(l + 1, i + 1), id(l + 1, i)});
  write("twisted.obj", pdr::io::test::obj_text(twisted));
  const auto j = mesh_json(path("twisted.obj") + " -o " + path("t") + " --max-volume 0.01");
  EXPECT_EQ(j.at("check"), "pass") << j.dump(1);
  const Outcome c = run("check " + path("t") + " --domain " + path("twisted.obj"));
  EXPECT_EQ(c.code, 0) << c.out;
}

TEST_F(Cli, SurfaceWithAnOpenEdgeExits2AndWritesNothing) {
  pdr::io::test::Shape open = pdr::io::test::box_squares();
  open.faces.pop_back();
  write("open.off", off_text(open));
  const Outcome r = run("mesh " + path("open.off") + " -o " + path("x"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("open.off:11: face 1: closed surface:"), std::string::npos) << r.out;
  EXPECT_TRUE(left_behind("x").empty());
}

// A part far from the origin (CAD and survey coordinates): the unit box of 2 x 2 grids of
// triangles, rotated and moved by 1e7, where the rounding of a coordinate (2e-9) is more
// than 1e-9 of a side. The coordinates' own rounding is read as their precision
// (io/precision.hpp: full doubles are known to a few units in the last place): the
// triangles of a side merge, the right angles read as right, and it meshes by default
// (before, it was refused: "planar facet"); so it does under --planarity-tolerance 1e-8,
// and `pdr check` passes the mesh with either. A facet that is not planar is refused with
// a message naming the option.
TEST_F(Cli, PlanarityToleranceOptionAcceptsAFarPart) {
  pdr::io::test::Shape box = pdr::io::test::box_grid();
  std::vector<std::vector<std::uint32_t>> tris;
  for (const auto& f : box.faces) {
    tris.push_back({f[0], f[1], f[2]});
    tris.push_back({f[0], f[2], f[3]});
  }
  box.faces = tris;
  const double c = std::cos(0.7), d = std::sin(0.7), e = std::cos(1.1), g = std::sin(1.1);
  for (pdr::Point& x : box.points) {
    const pdr::Point y{c * x[0] - d * x[1], d * x[0] + c * x[1], x[2]};
    x = {y[0] + 1e7, e * y[1] - g * y[2] + 7e6, g * y[1] + e * y[2] - 3e6};
  }
  write("far.off", off_text(box));
  for (const std::string option : {"", " --planarity-tolerance 1e-8"}) {
    const auto j = mesh_json(path("far.off") + " -o " + path("f") + " --max-volume 0.01" + option);
    EXPECT_EQ(j.at("check"), "pass") << option;
    EXPECT_EQ(j.at("admissible"), true) << option;  // its right angles, bent as much, read as right
    const Outcome c1 = run("check " + path("f") + " --domain " + path("far.off") + option);
    EXPECT_EQ(c1.code, 0) << option << "\n" << c1.out;
  }
  write("warped.poly",
        "8 3 0 0\n0 0 0 0\n1 1 0 0\n2 1 1 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 1 1 1.001\n7 0 1 1\n"
        "6 0\n1\n4 0 3 2 1\n1\n4 4 5 6 7\n1\n4 0 1 5 4\n1\n4 1 2 6 5\n1\n4 2 3 7 6\n"
        "1\n4 3 0 4 7\n0\n0\n");
  const Outcome refused = run("mesh " + path("warped.poly") + " -o " + path("wout"));
  EXPECT_EQ(refused.code, 2) << refused.out;
  EXPECT_NE(refused.out.find("planar facet"), std::string::npos) << refused.out;
  EXPECT_NE(refused.out.find("--planarity-tolerance"), std::string::npos) << refused.out;
  EXPECT_TRUE(left_behind("wout").empty());
}

// A file written with 7 significant digits, as most ASCII STL and OFF writers print: a
// prism over a regular 48-gon (a cylinder as CAD tools tessellate it), turned by a
// rotation, its sides quads planar only to the rounding (2e-7 against sides 0.13 wide).
// Its coordinates' precision is inferred (io/precision.hpp): the quads are read as planar
// and their right angles as right, so it meshes as the exact prism does (admissible, the
// check passing) instead of as 96 needle triangles of 4 degrees, inadmissible, which
// took 40 s and 35 times the tets. `pdr check --domain` infers the same.
TEST_F(Cli, SurfaceWrittenWithSevenDigitsMeshesAsTheExactOne) {
  constexpr int kSides = 48;
  const double c = std::cos(0.7), d = std::sin(0.7), e = std::cos(1.1), g = std::sin(1.1);
  auto text = [&](int digits) {
    std::ostringstream o;
    o << "OFF\n" << 2 * kSides << " " << kSides + 2 << " 0\n";
    for (const double z : {0.0, 2.0})
      for (int k = 0; k < kSides; ++k) {
        const double t = 2 * std::numbers::pi * k / kSides, x = std::cos(t), y = std::sin(t);
        const double rx = c * x - d * y, ry = e * (d * x + c * y) - g * z, rz = g * (d * x + c * y) + e * z;
        char buf[120];
        std::snprintf(buf, sizeof buf, "%.*g %.*g %.*g\n", digits, rx, digits, ry, digits, rz);
        o << buf;
      }
    o << kSides;
    for (int k = kSides - 1; k >= 0; --k) o << " " << k;
    o << "\n" << kSides;
    for (int k = 0; k < kSides; ++k) o << " " << kSides + k;
    o << "\n";
    for (int k = 0; k < kSides; ++k)
      o << "4 " << k << " " << (k + 1) % kSides << " " << kSides + (k + 1) % kSides << " "
        << kSides + k << "\n";
    return o.str();
  };
  write("exact.off", text(17));
  write("seven.off", text(7));
  const auto x = mesh_json(path("exact.off") + " -o " + path("x") + " --max-volume 0.01");
  const auto s = mesh_json(path("seven.off") + " -o " + path("s") + " --max-volume 0.01 --audit");
  EXPECT_EQ(s.at("admissible"), true) << s.dump(1);
  EXPECT_EQ(s.at("check"), "pass");
  EXPECT_FALSE(s.contains("audit")) << s.dump(1);
  EXPECT_EQ(s.at("planarity").at("coordinate_digits"), 7);
  EXPECT_GT(s.at("planarity").at("coordinate_uncertainty").get<double>(), 0.0);
  EXPECT_LT(s.at("tets").get<double>(), 1.2 * x.at("tets").get<double>());
  const Outcome c1 = run("check " + path("s") + " --domain " + path("seven.off"));
  EXPECT_EQ(c1.code, 0) << c1.out;
}

// Gmsh's surfaces of rotated OpenCASCADE solids (a file written by another tool, as users
// have them): a box, a box with a cylindrical hole through it, and the same with a
// spherical void. Their sides are straight only to a few ulps; each meshes (exit 0) and
// passes the check. Before the facet triangulations were constrained Delaunay, the first
// two were refused (exit 2: two facets said to cross).
TEST_F(Cli, GmshSurfacesOfRotatedSolidsMesh) {
  if (!on_path("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  const char* solids[] = {
      "Box(1) = {0,0,0, 2,1,1};",
      "Box(1) = {0,0,0, 2,1,1}; Cylinder(2) = {0.5,0.5,-0.1, 0,0,1.2, 0.25};\n"
      "BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }",
      "Box(1) = {0,0,0, 2,1,1}; Cylinder(2) = {0.5,0.5,-0.1, 0,0,1.2, 0.25};\n"
      "Sphere(3) = {1.5,0.5,0.5, 0.3};\n"
      "BooleanDifference{ Volume{1}; Delete; }{ Volume{2,3}; Delete; }"};
  for (const char* solid : solids) {
    SCOPED_TRACE(solid);
    write("s.geo", std::string("SetFactory(\"OpenCASCADE\");\n") + solid +
                       "\nRotate {{1,1,0},{0,0,0}, 0.3} { Volume{1}; }\nMesh.MeshSizeMax = 0.3;\n");
    const Outcome g = shell(path(""), "gmsh -2 s.geo -format stl -o s.stl");
    ASSERT_EQ(g.code, 0) << g.out;
    const auto j = mesh_json(path("s.stl") + " -o " + path("m") + " --max-volume 0.005");
    EXPECT_EQ(j.at("check"), "pass");
  }
}

// Random solids as a new user's CAD parts come: a cube with one to three random boxes,
// cylinders or spheres added or cut away, rotated at random, surface-meshed by Gmsh. Outside
// the theory (curved sides become many small facets at small angles), so each must end in
// exit 0, or exit 3 with only the quality and encroachment checks failing: never a
// refused input, a broken mesh or an internal error. (40 such solids ran by hand at
// V = 0.002: 22 exit 0, 18 exit 3.)
TEST_F(Cli, GmshRandomRotatedSolidsEndInExit0Or3) {
  if (!on_path("gmsh")) GTEST_SKIP() << "gmsh is not on PATH";
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    std::mt19937_64 rng(seed);
    const auto u = [&](double lo, double hi) {
      return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    std::ostringstream geo;
    geo.precision(17);
    geo << "SetFactory(\"OpenCASCADE\");\nBox(1) = {-1,-1,-1, 2,2,2};\n";
    const int n = static_cast<int>(u(1, 4));
    for (int i = 2; i < 2 + n; ++i) {
      const double kind = u(0, 1);
      if (kind < 0.5)
        geo << "Box(" << i << ") = {" << u(-1, 1) << "," << u(-1, 1) << "," << u(-1, 1) << ", "
            << u(0.3, 1.5) << "," << u(0.3, 1.5) << "," << u(0.3, 1.5) << "};\n";
      else if (kind < 0.75)
        geo << "Cylinder(" << i << ") = {" << u(-1, 1) << "," << u(-1, 1) << "," << u(-1, 1)
            << ", " << u(-1, 1) << "," << u(-1, 1) << "," << u(-1, 1) << ", " << u(0.15, 0.5)
            << "};\n";
      else
        geo << "Sphere(" << i << ") = {" << u(-1, 1) << "," << u(-1, 1) << "," << u(-1, 1)
            << ", " << u(0.2, 0.6) << "};\n";
    }
    geo << (u(0, 1) < 0.5 ? "BooleanDifference" : "BooleanUnion")
        << "{ Volume{1}; Delete; }{ Volume{2:" << 1 + n << "}; Delete; }\n";
    geo << "Rotate {{" << u(-1, 1) << "," << u(-1, 1) << "," << u(-1, 1) << "},{0,0,0}, "
        << u(0, 3) << "} { Volume{:}; }\nMesh.MeshSizeMax = 0.25;\n";
    SCOPED_TRACE(geo.str());
    write("r.geo", geo.str());
    const Outcome g = shell(path(""), "gmsh -2 r.geo -format stl -o r.stl");
    ASSERT_EQ(g.code, 0) << g.out;
    const Outcome r = run("mesh " + path("r.stl") + " -o " + path("m") + " --max-volume 0.002 --json",
                          false);
    ASSERT_TRUE(r.code == 0 || r.code == 3) << "exit " << r.code << "\n" << r.out;
    const auto j = nlohmann::json::parse(r.out);
    std::printf("seed %llu: exit %d, %s tets\n", static_cast<unsigned long long>(seed), r.code,
                j.at("tets").dump().c_str());
    if (r.code == 0) {
      EXPECT_EQ(j.at("check"), "pass");
      continue;
    }
    for (const auto& failed : j.at("check_failed")) {
      const std::string id = failed.get<std::string>();
      EXPECT_TRUE(id == "quality.ratio" || id.rfind("encroachment.", 0) == 0) << id;
    }
  }
}

}  // namespace
