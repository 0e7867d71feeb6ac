// Round trips: every writer followed by its reader gives back the same MeshData, bit for
// bit (coordinates compared as bits, so -0.0, subnormals and huge values count), for random
// meshes (RapidCheck) and for the cube. What a format cannot carry is compared loosely:
// Gmsh has no point markers; empty marker arrays equal all-zero ones.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>

#include "io/gmsh.hpp"
#include "io/medit.hpp"
#include "io/mesh_io.hpp"
#include "io/tetgen.hpp"
#include "io/vtu.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

rc::Gen<double> coordinate() {
  return rc::gen::oneOf(
      rc::gen::suchThat(rc::gen::arbitrary<double>(), [](double x) { return std::isfinite(x); }),
      rc::gen::element(0.0, -0.0, 0.1, 1.0 / 3.0, 5e-324, -2.2250738585072014e-308,
                       1.7976931348623157e308, -1e-300, 123456789.123456789),
      rc::gen::map(rc::gen::inRange(-1000, 1000), [](int i) { return i / 8.0; }));
}

rc::Gen<int> marker() {
  return rc::gen::oneOf(rc::gen::inRange(-5, 6),
                        rc::gen::element(std::numeric_limits<int>::min(),
                                         std::numeric_limits<int>::max(), 0));
}

// Markers: empty, or one per element.
rc::Gen<std::vector<int>> markers(std::size_t n) {
  return rc::gen::oneOf(rc::gen::just(std::vector<int>{}), rc::gen::container<std::vector<int>>(n, marker()));
}

MeshData random_mesh() {
  MeshData m;
  const auto np = *rc::gen::inRange<std::size_t>(1, 40);
  m.points = *rc::gen::container<std::vector<Point>>(
      np, rc::gen::apply([](double x, double y, double z) { return Point{x, y, z}; },
                         coordinate(), coordinate(), coordinate()));
  const auto index = rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(np));
  const auto nt = *rc::gen::inRange<std::size_t>(1, 50);
  m.tets = *rc::gen::container<std::vector<Tet>>(
      nt, rc::gen::apply([](std::uint32_t a, std::uint32_t b, std::uint32_t c,
                            std::uint32_t d) { return Tet{a, b, c, d}; },
                         index, index, index, index));
  const auto nf = *rc::gen::inRange<std::size_t>(0, 30);
  m.faces = *rc::gen::container<std::vector<Tri>>(
      nf, rc::gen::apply([](std::uint32_t a, std::uint32_t b,
                            std::uint32_t c) { return Tri{a, b, c}; },
                         index, index, index));
  m.point_markers = *markers(np);
  m.tet_regions = *markers(nt);
  m.face_markers = nf ? *markers(nf) : std::vector<int>{};
  return m;
}

void round_trips(const MeshData& m) {
  ScratchDir dir;
  write_tetgen_mesh(m, dir / "t");
  expect_same_mesh(m, read_tetgen_mesh(dir / "t"), true, "tetgen");
  write_gmsh(m, dir / "g.msh");
  expect_same_mesh(m, read_gmsh(dir / "g.msh"), false, "gmsh 4.1");
  write_medit(m, dir / "m.mesh");
  expect_same_mesh(m, read_medit(dir / "m.mesh"), true, "medit");
  for (VtuEncoding e : {VtuEncoding::Ascii, VtuEncoding::InlineBase64,
                        VtuEncoding::AppendedBase64, VtuEncoding::AppendedRaw}) {
    const std::string path = dir / ("v" + std::to_string(static_cast<int>(e)) + ".vtu");
    write_vtu(m, path, {}, {}, VtuOptions{e, true});
    expect_same_mesh(m, read_vtu(path), true, "vtu encoding " + std::to_string(static_cast<int>(e)));
  }
  // write_mesh writes all four, readable through read_mesh.
  const MeshFormat all[] = {MeshFormat::TetGen, MeshFormat::Vtu, MeshFormat::Msh,
                            MeshFormat::Medit};
  write_mesh(m, dir / "all", all);
  for (const char* ext : {".ele", ".vtu", ".msh", ".mesh"})
    expect_same_mesh(m, read_mesh(dir / (std::string("all") + ext)),
                     std::string(ext) != ".msh", std::string("write_mesh ") + ext);
}

RC_GTEST_PROP(RoundTrip, EveryWriterReaderPairIsBitExact, ()) {
  const MeshData m = random_mesh();
  round_trips(m);
  RC_ASSERT(!::testing::Test::HasFailure());
}

TEST(RoundTrip, Cube) { round_trips(cube_mesh()); }

TEST(RoundTrip, PointsOnly) {
  MeshData m;
  m.points = {{1, 2, 3}};
  ScratchDir dir;
  write_tetgen_mesh(m, dir / "p");
  expect_same_mesh(m, read_tetgen_mesh(dir / "p"), true, "tetgen points only");
  write_vtu(m, dir / "p.vtu");
  expect_same_mesh(m, read_vtu(dir / "p.vtu"), true, "vtu points only");
}

TEST(RoundTrip, FormatNames) {
  EXPECT_EQ(parse_mesh_format("node"), MeshFormat::TetGen);
  EXPECT_EQ(parse_mesh_format("vtu"), MeshFormat::Vtu);
  EXPECT_EQ(parse_mesh_format("msh"), MeshFormat::Msh);
  EXPECT_EQ(parse_mesh_format("mesh"), MeshFormat::Medit);
  EXPECT_THROW(parse_mesh_format("stl"), std::invalid_argument);
  EXPECT_EQ(output_paths("a/b", MeshFormat::TetGen),
            (std::vector<std::string>{"a/b.node", "a/b.ele", "a/b.face"}));
}

}  // namespace
}  // namespace pdr::io::test
