// Gmsh MSH: hand-written ASCII 2.2 and 4.1 files (sparse node tags, physical tags, skipped
// points/lines/quads, 6-node triangles and 10-node tets, parametric nodes) and binary 2.2
// and 4.1 files built byte by byte here, all of the same cube.
#include <gtest/gtest.h>

#include "io/gmsh.hpp"
#include "io/mesh_io.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

const std::string kData = PDR_IO_TEST_DATA;

struct Bytes {
  std::string s;
  template <class T>
  Bytes& put(T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  Bytes& text(std::string_view t) {
    s.append(t);
    return *this;
  }
};

std::uint32_t tag_of(std::uint32_t i) { return 10 * (i + 1); }

std::string binary22(const MeshData& c) {
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n");
  b.text("$Nodes\n8\n");
  for (std::uint32_t i = 0; i < 8; ++i) {
    b.put<std::int32_t>(static_cast<std::int32_t>(tag_of(i)));
    for (double x : c.points[i]) b.put(x);
  }
  b.text("\n$EndNodes\n$Elements\n19\n");
  b.put<std::int32_t>(1).put<std::int32_t>(1).put<std::int32_t>(2);  // one line, skipped
  b.put<std::int32_t>(1).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(10).put<std::int32_t>(20);
  b.put<std::int32_t>(2).put<std::int32_t>(12).put<std::int32_t>(2);
  for (std::size_t f = 0; f < 12; ++f) {
    b.put<std::int32_t>(static_cast<std::int32_t>(f + 2)).put<std::int32_t>(c.face_markers[f]);
    b.put<std::int32_t>(1);
    for (std::uint32_t v : c.faces[f]) b.put<std::int32_t>(static_cast<std::int32_t>(tag_of(v)));
  }
  b.put<std::int32_t>(4).put<std::int32_t>(6).put<std::int32_t>(2);
  for (std::size_t t = 0; t < 6; ++t) {
    b.put<std::int32_t>(static_cast<std::int32_t>(t + 14)).put<std::int32_t>(c.tet_regions[t]);
    b.put<std::int32_t>(1);
    for (std::uint32_t v : c.tets[t]) b.put<std::int32_t>(static_cast<std::int32_t>(tag_of(v)));
  }
  b.text("\n$EndElements\n");
  return b.s;
}

std::string binary41(const MeshData& c) {
  Bytes b;
  b.text("$MeshFormat\n4.1 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n");
  b.text("$Entities\n").put<std::uint64_t>(0).put<std::uint64_t>(0);
  b.put<std::uint64_t>(6).put<std::uint64_t>(2);
  for (int dim = 2; dim <= 3; ++dim)
    for (int e = 1; e <= (dim == 2 ? 6 : 2); ++e) {
      b.put<std::int32_t>(e);
      for (int k = 0; k < 6; ++k) b.put<double>(0);
      b.put<std::uint64_t>(1).put<std::int32_t>(dim == 2 ? e : 6 + e);
      b.put<std::uint64_t>(1).put<std::int32_t>(-1);  // one bounding entity
    }
  b.text("\n$EndEntities\n$Nodes\n");
  b.put<std::uint64_t>(1).put<std::uint64_t>(8).put<std::uint64_t>(10).put<std::uint64_t>(80);
  b.put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(0).put<std::uint64_t>(8);
  for (std::uint32_t i = 0; i < 8; ++i) b.put<std::uint64_t>(tag_of(i));
  for (const Point& p : c.points)
    for (double x : p) b.put(x);
  b.text("\n$EndNodes\n$Elements\n");
  b.put<std::uint64_t>(8).put<std::uint64_t>(18).put<std::uint64_t>(1).put<std::uint64_t>(18);
  std::uint64_t id = 1;
  for (int side = 1; side <= 6; ++side) {
    b.put<std::int32_t>(2).put<std::int32_t>(side).put<std::int32_t>(2).put<std::uint64_t>(2);
    for (std::size_t f = 2 * (side - 1); f < 2 * static_cast<std::size_t>(side); ++f) {
      b.put<std::uint64_t>(id++);
      for (std::uint32_t v : c.faces[f]) b.put<std::uint64_t>(tag_of(v));
    }
  }
  for (int vol = 1; vol <= 2; ++vol) {
    b.put<std::int32_t>(3).put<std::int32_t>(vol).put<std::int32_t>(4).put<std::uint64_t>(3);
    for (std::size_t t = 3 * (vol - 1); t < 3 * static_cast<std::size_t>(vol); ++t) {
      b.put<std::uint64_t>(id++);
      for (std::uint32_t v : c.tets[t]) b.put<std::uint64_t>(tag_of(v));
    }
  }
  b.text("\n$EndElements\n");
  return b.s;
}

TEST(Gmsh, Ascii22HandWritten) {
  ReadInfo info;
  const MeshData m = read_mesh(kData + "/cube22.msh", &info);
  expect_same_mesh(cube_mesh(), m, false, "cube22.msh");
  EXPECT_TRUE(m.point_markers.empty());
  EXPECT_EQ(info.skipped_elements, 3u);  // a point, a line, a quad
  EXPECT_EQ(tet_orientation(m).positive, 6u);
}

TEST(Gmsh, Ascii41HandWrittenWithQuadraticElements) {
  ReadInfo info;
  const MeshData m = read_gmsh(kData + "/cube41.msh", &info);
  expect_same_mesh(cube_mesh(), m, false, "cube41.msh");
  EXPECT_EQ(info.skipped_elements, 2u);
  EXPECT_EQ(info.dropped_high_order_nodes, 12u);
}

TEST(Gmsh, Binary22) {
  ScratchDir dir;
  write_text(dir / "b22.msh", binary22(cube_mesh()));
  ReadInfo info;
  expect_same_mesh(cube_mesh(), read_gmsh(dir / "b22.msh", &info), false, "binary 2.2");
  EXPECT_EQ(info.skipped_elements, 1u);
}

TEST(Gmsh, Binary41) {
  ScratchDir dir;
  write_text(dir / "b41.msh", binary41(cube_mesh()));
  expect_same_mesh(cube_mesh(), read_gmsh(dir / "b41.msh"), false, "binary 4.1");
}

TEST(Gmsh, HugeSparseShuffledNodeTags) {
  ScratchDir dir;
  // Tags far apart (sorted lookup), listed out of order.
  const MeshData c = cube_mesh();
  const std::uint64_t tags[8] = {7000000000001, 5, 99999999999, 3, 123456789012, 8, 1, 42};
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n";
  for (int i : {3, 1, 7, 0, 2, 6, 4, 5})
    s += std::to_string(tags[i]) + " " + std::to_string(c.points[i][0]) + " " +
         std::to_string(c.points[i][1]) + " " + std::to_string(c.points[i][2]) + "\n";
  s += "$EndNodes\n$Elements\n6\n";
  for (std::size_t t = 0; t < 6; ++t) {
    s += std::to_string(t + 1) + " 4 0";
    for (std::uint32_t v : c.tets[t]) {
      s += ' ';
      s += std::to_string(tags[v]);
    }
    s += "\n";
  }
  s += "$EndElements\n";
  write_text(dir / "sparse.msh", s);
  const MeshData m = read_gmsh(dir / "sparse.msh");
  MeshData want = c;
  want.faces.clear();
  EXPECT_EQ(canonical(m), canonical(want));
  EXPECT_EQ(m.points[0], c.points[3]);  // points keep the order of $Nodes
}

TEST(Gmsh, WriterOutputReadsBack) {
  ScratchDir dir;
  write_gmsh(cube_mesh(), dir / "w.msh");
  expect_same_mesh(cube_mesh(), read_gmsh(dir / "w.msh"), false, "written 4.1");
}

}  // namespace
}  // namespace pdr::io::test
