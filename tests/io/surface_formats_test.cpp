// The surface readers one format at a time (OFF, STL, PLY, medit, Gmsh): hand-written files of each variant
// the format headers list, read as the box of surface_shapes.hpp, and malformed files
// rejected with file:line (text) or the face's number (binary).
#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>

#include "io/error.hpp"
#include "io/mesh_io.hpp"
#include "io_test_util.hpp"
#include "surface_shapes.hpp"

namespace pdr::io::test {
namespace {

Plc read_as(const ScratchDir& dir, const std::string& name, const std::string& bytes) {
  write_text(dir / name, bytes);
  return read_domain(dir / name);
}

// The message of the InputError that reading `bytes` as file `name` throws ("" if none).
std::string error_of(const std::string& name, const std::string& bytes) {
  ScratchDir dir;
  try {
    (void)read_as(dir, name, bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// `value` as the bytes of a T in byte order `order`.
template <class T>
void put(std::string& out, T value, std::endian order) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (order != std::endian::native) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

std::string stl_ascii(const Shape& s) {
  std::ostringstream o;
  o.precision(17);
  o << "solid box\n";
  for (const auto& f : s.faces) {
    o << "  facet normal 0 0 0\n    outer loop\n";
    for (std::uint32_t v : f)
      o << "      vertex " << s.points[v][0] << ' ' << s.points[v][1] << ' ' << s.points[v][2]
        << '\n';
    o << "    endloop\n  endfacet\n";
  }
  o << "endsolid box\n";
  return o.str();
}

std::string stl_binary(const Shape& s) {
  std::string out = "solid but binary";  // binary writers often begin the header so
  out.resize(80, ' ');
  put<std::uint32_t>(out, static_cast<std::uint32_t>(s.faces.size()), std::endian::little);
  for (const auto& f : s.faces) {
    for (int k = 0; k < 3; ++k) put<float>(out, 0.0f, std::endian::little);
    for (std::uint32_t v : f)
      for (double x : s.points[v]) put<float>(out, static_cast<float>(x), std::endian::little);
    put<std::uint16_t>(out, 0, std::endian::little);
  }
  return out;
}

// The shape as PLY in `format` (ascii, binary_little_endian, binary_big_endian): vertices
// with z before y and an extra colour, an extra "edge" element between vertices and faces,
// float coordinates, uchar counts and int indices.
std::string ply(const Shape& s, const std::string& format) {
  std::ostringstream h;
  h << "ply\nformat " << format << " 1.0\ncomment by hand\nelement vertex " << s.points.size()
    << "\nproperty float x\nproperty float z\nproperty float y\nproperty uchar red\n"
    << "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
    << "element face " << s.faces.size() << "\nproperty list uchar int vertex_indices\n"
    << "end_header\n";
  std::string out = h.str();
  if (format == "ascii") {
    std::ostringstream d;
    for (const Point& p : s.points) d << p[0] << ' ' << p[2] << ' ' << p[1] << " 255\n";
    d << "0 1\n";
    for (const auto& f : s.faces) {
      d << f.size();
      for (std::uint32_t v : f) d << ' ' << v;
      d << '\n';
    }
    return out + d.str();
  }
  const std::endian order =
      format == "binary_big_endian" ? std::endian::big : std::endian::little;
  for (const Point& p : s.points) {
    for (int k : {0, 2, 1}) put<float>(out, static_cast<float>(p[k]), order);
    put<std::uint8_t>(out, 255, order);
  }
  put<std::int32_t>(out, 0, order);
  put<std::int32_t>(out, 1, order);
  for (const auto& f : s.faces) {
    put<std::uint8_t>(out, static_cast<std::uint8_t>(f.size()), order);
    for (std::uint32_t v : f) put<std::int32_t>(out, static_cast<std::int32_t>(v), order);
  }
  return out;
}

void expect_box(const Plc& plc) {
  EXPECT_EQ(plc.facets.size(), 6u);
  EXPECT_EQ(plc.points.size(), 8u);
}

TEST(SurfaceFormats, Off) {
  ScratchDir dir;
  expect_box(read_as(dir, "b.off", off_text(box_triangles())));
  // Counts on the keyword line, comments, colours after coordinates and faces.
  const Plc plc = read_as(dir, "t.off",
                          "COFF 4 4 6 # a tetrahedron\n"
                          "0 0 0 255 0 0 255\n1 0 0 0 0 0 0\n0 1 0 0 0 0 0\n0 0 1 0 0 0 0\n"
                          "3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  EXPECT_EQ(plc.facets.size(), 4u);
  EXPECT_EQ(plc.point_lines[1], 3u);
  EXPECT_EQ(plc.facets[3].line, 9u);
  std::string m = error_of("x.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_NE(m.find("x.off:6: corner index 3 is out of range"), std::string::npos) << m;
  m = error_of("x.off", "4OFF\n");
  EXPECT_NE(m.find("x.off:1: expected the keyword OFF"), std::string::npos) << m;
  m = error_of("x.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n");
  EXPECT_NE(m.find("x.off:7: unexpected '3' after the last face"), std::string::npos) << m;
}

TEST(SurfaceFormats, Obj) {
  ScratchDir dir;
  expect_box(read_as(dir, "b.obj", obj_text(box_triangles())));
  // Negative (relative) indices, the three corner forms, a vertex colour and a weight.
  const Plc plc = read_as(dir, "t.obj",
                          "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 1.0\nv 0 0 1\n"
                          "f -4 -2 -3\nf 1//1 2//1 4//1\nf 2/1 3/1 4/1\nf +1/1/1 4/1/1 3/1/1\n");
  EXPECT_EQ(plc.facets.size(), 4u);
  EXPECT_EQ(plc.points.size(), 4u);
  EXPECT_EQ(plc.point_lines[1], 2u);
  EXPECT_EQ(plc.facets[3].line, 8u);
  std::string m = error_of("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  EXPECT_NE(m.find("x.obj:4: corner index 4 is out of range: 3 vertices"), std::string::npos) << m;
  m = error_of("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n");
  EXPECT_NE(m.find("x.obj:4: corner index -4 is out of range"), std::string::npos) << m;
  m = error_of("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 2\n");
  EXPECT_NE(m.find("x.obj:4: corner index 0 is out of range"), std::string::npos) << m;
  m = error_of("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a/2 3\n");
  EXPECT_NE(m.find("x.obj:4: expected a face corner"), std::string::npos) << m;
  m = error_of("x.obj", "v 0 0 zero\n");
  EXPECT_NE(m.find("x.obj:1:"), std::string::npos) << m;
  m = error_of("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n 3\n");
  EXPECT_NE(m.find("x.obj:4: a line continued"), std::string::npos) << m;
  m = error_of("x.obj", "v 0 0 0\nv 1 0 0\ng a \\\n b\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(m.find("x.obj:3: a line continued"), std::string::npos) << m;
  m = error_of("x.obj", "# nothing\nv 0 0 0\n");
  EXPECT_NE(m, "");  // no faces
}

TEST(SurfaceFormats, StlAscii) {
  ScratchDir dir;
  expect_box(read_as(dir, "b.stl", stl_ascii(box_triangles())));
  // Two solids, upper-case keywords, CRLF line ends: the box split in two solids.
  std::string two = stl_ascii(box_triangles());
  const std::size_t mid = two.find("  facet", two.size() / 2);
  two.insert(mid, "endsolid a\r\nSOLID b\r\n");
  expect_box(read_as(dir, "c.stl", two));
  // Quads as 4-vertex loops.
  expect_box(read_as(dir, "q.stl", stl_ascii(box_squares())));
  // Upper case from the first keyword on (read as binary, and refused, before).
  std::string upper = stl_ascii(box_triangles());
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  expect_box(read_as(dir, "u.stl", upper));

  std::string bad = stl_ascii(box_triangles());
  bad.replace(bad.find("endloop"), 7, "endlop");
  std::string m = error_of("x.stl", bad);
  EXPECT_NE(m.find("x.stl:7: expected 'vertex <x> <y> <z>' or 'endloop' of face 1"),
            std::string::npos) << m;
  bad = stl_ascii(box_triangles());
  bad.replace(bad.find("vertex 0 0 0"), 12, "vertex 0 inf 0");
  m = error_of("x.stl", bad);
  EXPECT_NE(m.find("x.stl:4:"), std::string::npos) << m;
  m = error_of("x.stl", "hello\n");
  EXPECT_NE(m.find("x.stl:1: an ASCII STL file starts with 'solid'"), std::string::npos) << m;
}

TEST(SurfaceFormats, StlBinary) {
  ScratchDir dir;
  const std::string bin = stl_binary(box_triangles());
  ASSERT_EQ(bin.size(), 84u + 50u * 12u);
  expect_box(read_as(dir, "b.stl", bin));

  // A NaN in the 5th triangle's second corner: the face is named, no line.
  std::string nan = bin;
  const std::size_t at = 84 + 4 * 50 + 12 + 12 + 4;
  const float q = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan.data() + at, &q, 4);
  std::string m = error_of("x.stl", nan);
  EXPECT_NE(m.find("x.stl: face 5: a corner has a coordinate that is not a finite number"),
            std::string::npos) << m;
  // Truncated: the size no longer matches the count, and the header does not say solid.
  std::string cut = bin.substr(0, bin.size() - 10);
  cut.replace(0, 5, "heade");
  m = error_of("x.stl", cut);
  EXPECT_NE(m.find("binary STL: the header declares 12 triangles"), std::string::npos) << m;
  // An open surface from a binary file: the face is named by number.
  Shape open = box_triangles();
  open.faces.pop_back();
  m = error_of("x.stl", stl_binary(open));
  EXPECT_NE(m.find("x.stl: face "), std::string::npos) << m;
  EXPECT_NE(m.find("closed surface"), std::string::npos) << m;
}

TEST(SurfaceFormats, Ply) {
  ScratchDir dir;
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    expect_box(read_as(dir, "t.ply", ply(box_triangles(), format)));
    expect_box(read_as(dir, "q.ply", ply(box_squares(), format)));
  }
  const Plc a = read_as(dir, "a.ply", ply(box_triangles(), "ascii"));
  EXPECT_EQ(a.points[2], (Point{0, 1, 0}));  // y and z where the header says
  EXPECT_EQ(a.point_lines[0], 15u);
  EXPECT_EQ(a.facets[0].line, 24u);

  // Out of range index (ASCII: the face's line; binary: its number).
  Shape bad = box_triangles();
  bad.faces[2][1] = 8;
  std::string m = error_of("x.ply", ply(bad, "ascii"));
  EXPECT_NE(m.find("x.ply:26: face 3: corner index 8 is out of range"), std::string::npos) << m;
  m = error_of("x.ply", ply(bad, "binary_big_endian"));
  EXPECT_NE(m.find("x.ply: face 3: corner index 8"), std::string::npos) << m;
  // Truncated and overlong binary data.
  const std::string bin = ply(box_triangles(), "binary_little_endian");
  m = error_of("x.ply", bin.substr(0, bin.size() - 3));
  EXPECT_NE(m.find("x.ply: at byte offset"), std::string::npos) << m;
  EXPECT_NE(m.find("truncated"), std::string::npos) << m;
  m = error_of("x.ply", bin + "xx");
  EXPECT_NE(m.find("2 bytes are left after the last element"), std::string::npos) << m;
  // Header errors.
  m = error_of("x.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty long x\n");
  EXPECT_NE(m.find("x.ply:4: unknown PLY property type 'long'"), std::string::npos) << m;
  m = error_of("x.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                        "element face 0\nproperty list uchar int vertex_indices\nend_header\n");
  EXPECT_NE(m.find("the vertex element needs the properties x, y and z"), std::string::npos)
      << m;
  m = error_of("x.ply", "PLY\n");
  EXPECT_NE(m.find("x.ply:1: a PLY file starts with the line 'ply'"), std::string::npos) << m;
}

// The box's bottom and top as squares, the four sides as triangles (refs: 1 for squares,
// 2 for triangles), in medit's layout: Vertices on lines 5-12, Triangles from line 15,
// Quadrilaterals from line 25.
// `drop_last` leaves the last triangle out (the surface is then open).
std::string medit_box(bool drop_last = false) {
  const Shape q = box_squares();
  std::ostringstream o;
  o << "MeshVersionFormatted 2\nDimension 3\nVertices\n8\n";
  for (const Point& p : q.points) o << p[0] << ' ' << p[1] << ' ' << p[2] << " 0\n";
  o << "Triangles\n" << (drop_last ? 7 : 8) << '\n';
  for (std::size_t f = 2; f < 6; ++f) {
    const auto& c = q.faces[f];
    o << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1 << " 2\n";
    if (f < 5 || !drop_last) o << c[0] + 1 << ' ' << c[2] + 1 << ' ' << c[3] + 1 << " 2\n";
  }
  o << "Quadrilaterals\n2\n";
  for (std::size_t f = 0; f < 2; ++f) {
    const auto& c = q.faces[f];
    o << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1 << ' ' << c[3] + 1 << " 1\n";
  }
  o << "Edges\n1\n1 2 0\nEnd\n";
  return o.str();
}

TEST(SurfaceFormats, Medit) {
  ScratchDir dir;
  const Plc plc = read_as(dir, "b.mesh", medit_box());
  expect_box(plc);
  EXPECT_EQ(plc.facets[0].marker, 2);          // the first triangle's side
  EXPECT_EQ(plc.facets[0].line, 15u);
  EXPECT_EQ(plc.facets[4].marker, 1);          // the squares come after the triangles
  EXPECT_EQ(plc.facets[4].line, 25u);
  // A side with the wrong ref is a facet of its own beside its other half.
  std::string refs = medit_box();
  refs.replace(refs.find(" 2\n", refs.find("Triangles")), 3, " 3\n");
  EXPECT_EQ(read_as(dir, "r.mesh", refs).facets.size(), 7u);
  // The last triangle dropped: the first face at an open edge is named, with medit's
  // 1-based vertex numbers (face 1, the y = 0 side's first triangle, ends at x = 1).
  const std::string m = error_of("x.mesh", medit_box(true));
  EXPECT_NE(m.find("x.mesh:15: face 1: closed surface: the edge from vertex 2 (1, 0, 0) to "
                   "vertex 6 (1, 0, 1) belongs to no other face"),
            std::string::npos) << m;
}

TEST(SurfaceFormats, GmshQuadsTrianglesAndLines) {
  ScratchDir dir;
  // MSH 2.2: nodes tagged 11..18, a line element (skipped), the bottom and top as quads
  // (type 3) with physical tag 5, the sides as triangles (type 2) with physical tag 6.
  const Shape q = box_squares();
  std::ostringstream o;
  o << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n";
  for (std::size_t i = 0; i < 8; ++i)
    o << 11 + i << ' ' << q.points[i][0] << ' ' << q.points[i][1] << ' ' << q.points[i][2] << '\n';
  o << "$EndNodes\n$Elements\n11\n1 1 2 0 1 11 12\n";
  int id = 2;
  for (std::size_t f = 0; f < 6; ++f) {
    const auto& c = q.faces[f];
    if (f < 2) {
      o << id++ << " 3 2 5 1";
      for (std::uint32_t v : c) o << ' ' << 11 + v;
      o << '\n';
    } else {
      o << id++ << " 2 2 6 2 " << 11 + c[0] << ' ' << 11 + c[1] << ' ' << 11 + c[2] << '\n';
      o << id++ << " 2 2 6 2 " << 11 + c[0] << ' ' << 11 + c[2] << ' ' << 11 + c[3] << '\n';
    }
  }
  o << "$EndElements\n";
  const Plc plc = read_as(dir, "b.msh", o.str());
  expect_box(plc);
  EXPECT_EQ(plc.facets[0].marker, 5);
  EXPECT_EQ(plc.facets[0].line, 18u);
  EXPECT_EQ(plc.facets[2].marker, 6);
  // A face through an undefined node.
  std::string bad = o.str();
  bad.replace(bad.find("2 3 2 5 1 11"), 12, "2 3 2 5 1 99");
  const std::string m = error_of("x.msh", bad);
  EXPECT_NE(m.find("x.msh:18: element 2 uses node 99"), std::string::npos) << m;
}

}  // namespace
}  // namespace pdr::io::test
