// VTK .vtu: a hand-written ASCII file, and binary variants built here (inline base64 with
// UInt32 headers encoded as separate streams, appended base64, appended raw with UInt64
// headers), Float32 points, Int64/UInt32 connectivity, quadratic tets, skipped cell types,
// several pieces; and the writer's four encodings with cell and point fields.
#include <gtest/gtest.h>

#include <cstring>

#if PDR_IO_TEST_ZLIB
#include <zlib.h>
#endif

#include "io/base64.hpp"
#include "io/mesh_io.hpp"
#include "io/vtu.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

template <class T>
std::string raw(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <class H>
std::string framed(const std::string& data) {
  const H n = static_cast<H>(data.size());
  return std::string(reinterpret_cast<const char*>(&n), sizeof n) + data;
}

// The cube as cells: 6 tets (type 10), 1 hexahedron (type 12, skipped), 12 triangles.
struct CubeCells {
  std::vector<float> xyz;
  std::vector<std::int64_t> conn, offsets;
  std::vector<std::uint8_t> types;
  std::vector<std::int32_t> region, marker;
  CubeCells() {
    const MeshData c = cube_mesh();
    for (const Point& p : c.points)
      for (double x : p) xyz.push_back(static_cast<float>(x));
    for (std::size_t t = 0; t < 6; ++t) {
      conn.insert(conn.end(), c.tets[t].begin(), c.tets[t].end());
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      types.push_back(10);
      region.push_back(c.tet_regions[t]);
      marker.push_back(0);
    }
    for (std::int64_t v = 0; v < 8; ++v) conn.push_back(v);
    offsets.push_back(static_cast<std::int64_t>(conn.size()));
    types.push_back(12);
    region.push_back(0);
    marker.push_back(0);
    for (std::size_t f = 0; f < 12; ++f) {
      conn.insert(conn.end(), c.faces[f].begin(), c.faces[f].end());
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      types.push_back(5);
      region.push_back(0);
      marker.push_back(c.face_markers[f]);
    }
  }
};

std::string header(const char* htype) {
  return std::string("<?xml version=\"1.0\"?>\n<!-- written by hand -->\n"
                     "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                     "byte_order=\"LittleEndian\" header_type=\"") + htype + "\">\n"
                     "<UnstructuredGrid>\n<Piece NumberOfPoints=\"8\" NumberOfCells=\"19\">\n";
}

template <class T>
std::string ascii(const std::vector<T>& v) {
  std::string s;
  for (const T& x : v) s += std::to_string(+x) + " ";
  return s;
}

void expect_cube(const MeshData& m, const std::string& label) {
  MeshData want = cube_mesh();
  want.point_markers.clear();
  expect_same_mesh(want, m, true, label);
}

TEST(Vtu, AsciiHandWritten) {
  ScratchDir dir;
  const CubeCells c;
  std::string s = header("UInt32");
  s += "<CellData Scalars=\"pdr_region\">\n"
       "<DataArray type=\"Int32\" Name=\"pdr_region\" format=\"ascii\">" + ascii(c.region) +
       "</DataArray>\n<DataArray type=\"Int32\" Name=\"pdr_face_marker\" format=\"ascii\">\n" +
       ascii(c.marker) + "\n</DataArray>\n</CellData>\n<Points>\n"
       "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n" +
       ascii(c.xyz) + "\n</DataArray>\n</Points>\n<Cells>\n"
       "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" + ascii(c.conn) +
       "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
       ascii(c.offsets) + "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
       "format=\"ascii\">" + ascii(c.types) + "</DataArray>\n</Cells>\n</Piece>\n"
       "</UnstructuredGrid>\n</VTKFile>\n";
  write_text(dir / "a.vtu", s);
  ReadInfo info;
  expect_cube(read_mesh(dir / "a.vtu", &info), "ascii");
  EXPECT_EQ(info.skipped_elements, 1u);
}

TEST(Vtu, InlineBase64WithUInt32HeadersAsSeparateStreams) {
  ScratchDir dir;
  const CubeCells c;
  auto b64 = [](const std::string& data) {
    std::string out;  // header and data as two padded base64 streams, as VTK may write
    const std::uint32_t n = static_cast<std::uint32_t>(data.size());
    base64_encode(std::string_view(reinterpret_cast<const char*>(&n), 4), out);
    out += "\n   ";
    base64_encode(data, out);
    return out;
  };
  std::vector<std::uint32_t> conn32(c.conn.begin(), c.conn.end());
  std::string s = header("UInt32");
  s += "<CellData>\n<DataArray type=\"Int32\" Name=\"pdr_region\" format=\"binary\">" +
       b64(raw(c.region)) + "</DataArray>\n</CellData>\n<Points>\n"
       "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" +
       b64(raw(c.xyz)) + "</DataArray>\n</Points>\n<Cells>\n"
       "<DataArray type=\"UInt32\" Name=\"connectivity\" format=\"binary\">" +
       b64(raw(conn32)) + "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
       "format=\"binary\">" + b64(raw(c.offsets)) + "</DataArray>\n<DataArray type=\"UInt8\" "
       "Name=\"types\" format=\"binary\">" + b64(raw(c.types)) + "</DataArray>\n</Cells>\n"
       "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_text(dir / "b.vtu", s);
  MeshData m = read_vtu(dir / "b.vtu");
  EXPECT_TRUE(m.face_markers.empty());
  m.face_markers = cube_mesh().face_markers;
  expect_cube(m, "inline base64");
}

// Appended data: base64 (UInt32 headers, one stream per array) or raw (UInt64 headers).
std::string appended_file(bool raw_encoding) {
  const CubeCells c;
  const std::vector<std::string> arrays = {raw(c.region), raw(c.marker), raw(c.xyz),
                                           raw(c.conn), raw(c.offsets), raw(c.types)};
  std::vector<std::size_t> offsets;
  std::string block;
  for (const std::string& a : arrays) {
    offsets.push_back(block.size());
    if (raw_encoding) block += framed<std::uint64_t>(a);
    else base64_encode(framed<std::uint32_t>(a), block);
  }
  auto da = [&](const char* type, const char* name, int k, const char* extra = "") {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" " + extra +
           "format=\"appended\" offset=\"" + std::to_string(offsets[k]) + "\"/>\n";
  };
  std::string s = header(raw_encoding ? "UInt64" : "UInt32");
  s += "<CellData>\n" + da("Int32", "pdr_region", 0) + da("Int32", "pdr_face_marker", 1) +
       "</CellData>\n<Points>\n" + da("Float32", "Points", 2, "NumberOfComponents=\"3\" ") +
       "</Points>\n<Cells>\n" + da("Int64", "connectivity", 3) + da("Int64", "offsets", 4) +
       da("UInt8", "types", 5) + "</Cells>\n</Piece>\n</UnstructuredGrid>\n" +
       "<AppendedData encoding=\"" + (raw_encoding ? "raw" : "base64") + "\">\n  _" + block +
       "\n</AppendedData>\n</VTKFile>\n";
  return s;
}

TEST(Vtu, AppendedBase64) {
  ScratchDir dir;
  write_text(dir / "c.vtu", appended_file(false));
  expect_cube(read_vtu(dir / "c.vtu"), "appended base64");
}

TEST(Vtu, AppendedRaw) {
  ScratchDir dir;
  write_text(dir / "d.vtu", appended_file(true));
  expect_cube(read_vtu(dir / "d.vtu"), "appended raw");
}

TEST(Vtu, QuadraticTetAndTwoPieces) {
  ScratchDir dir;
  std::string s =
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>\n"
      "<Piece NumberOfPoints=\"10\" NumberOfCells=\"1\">\n<Points>\n"
      "<DataArray type=\"Float64\" NumberOfComponents=\"3\">0 0 0 1 0 0 0 1 0 0 0 1 "
      ".5 0 0 .5 .5 0 0 .5 0 0 0 .5 .5 0 .5 0 .5 .5</DataArray>\n</Points>\n<Cells>\n"
      "<DataArray type=\"Int32\" Name=\"connectivity\">0 1 2 3 4 5 6 7 8 9</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"offsets\">10</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"types\">24</DataArray>\n</Cells>\n</Piece>\n"
      "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n"
      "<DataArray type=\"Float64\" NumberOfComponents=\"3\">2 0 0 3 0 0 2 1 0 2 0 1"
      "</DataArray>\n</Points>\n<Cells>\n"
      "<DataArray type=\"Int32\" Name=\"connectivity\">0 1 2 3</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"offsets\">4</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"types\">10</DataArray>\n</Cells>\n</Piece>\n"
      "</UnstructuredGrid>\n</VTKFile>\n";
  write_text(dir / "q.vtu", s);
  ReadInfo info;
  const MeshData m = read_vtu(dir / "q.vtu", &info);
  EXPECT_EQ(info.dropped_high_order_nodes, 6u);
  ASSERT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.tets, (std::vector<Tet>{{0, 1, 2, 3}, {4, 5, 6, 7}}));
  EXPECT_EQ(m.points[4], (Point{2, 0, 0}));
  EXPECT_EQ(tet_orientation(m).positive, 2u);
}

#if PDR_IO_TEST_ZLIB
// vtkZLibDataCompressor layout: header [#blocks, block size, last block size, compressed
// sizes...] then the compressed blocks; block size 40 gives several blocks and a short last.
template <class H>
std::pair<std::string, std::string> zlib_blocks(const std::string& data) {
  const std::size_t block = 40;
  std::vector<H> head = {static_cast<H>((data.size() + block - 1) / block),
                         static_cast<H>(block), static_cast<H>(data.size() % block)};
  std::string body;
  for (std::size_t at = 0; at < data.size(); at += block) {
    const std::size_t n = std::min(block, data.size() - at);
    uLongf len = compressBound(static_cast<uLong>(n));
    std::string out(len, '\0');
    compress2(reinterpret_cast<Bytef*>(out.data()), &len,
              reinterpret_cast<const Bytef*>(data.data() + at), static_cast<uLong>(n), 6);
    out.resize(len);
    head.push_back(static_cast<H>(len));
    body += out;
  }
  return {raw(head), body};
}

TEST(Vtu, ZlibCompressedInlineAndAppendedRaw) {
  ScratchDir dir;
  const CubeCells c;
  const std::vector<std::string> arrays = {raw(c.xyz), raw(c.conn), raw(c.offsets),
                                           raw(c.types)};
  // Inline binary, UInt32 headers: header and blocks as two base64 streams (VTK's way).
  auto inline_b64 = [](const std::string& data) {
    const auto [head, body] = zlib_blocks<std::uint32_t>(data);
    std::string out;
    base64_encode(head, out);
    base64_encode(body, out);
    return out;
  };
  std::string s = "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                  "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n"
                  "<Piece NumberOfPoints=\"8\" NumberOfCells=\"19\">\n<Points>\n"
                  "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" +
                  inline_b64(arrays[0]) + "</DataArray>\n</Points>\n<Cells>\n"
                  "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">" +
                  inline_b64(arrays[1]) + "</DataArray>\n"
                  "<DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">" +
                  inline_b64(arrays[2]) + "</DataArray>\n"
                  "<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">" +
                  inline_b64(arrays[3]) + "</DataArray>\n</Cells>\n</Piece>\n"
                  "</UnstructuredGrid>\n</VTKFile>\n";
  write_text(dir / "z1.vtu", s);
  MeshData want = cube_mesh();
  want.point_markers.clear();
  want.tet_regions.clear();
  want.face_markers.clear();
  expect_same_mesh(want, read_vtu(dir / "z1.vtu"), true, "zlib inline");

  // Appended raw, UInt64 headers.
  std::string block;
  std::vector<std::size_t> offsets;
  for (const std::string& a : arrays) {
    offsets.push_back(block.size());
    const auto [head, body] = zlib_blocks<std::uint64_t>(a);
    block += head + body;
  }
  auto da = [&](const char* type, const char* name, int k, const char* extra = "") {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" " + extra +
           "format=\"appended\" offset=\"" + std::to_string(offsets[k]) + "\"/>\n";
  };
  s = "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" header_type=\"UInt64\" "
      "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n"
      "<Piece NumberOfPoints=\"8\" NumberOfCells=\"19\">\n<Points>\n" +
      da("Float32", "Points", 0, "NumberOfComponents=\"3\" ") + "</Points>\n<Cells>\n" +
      da("Int64", "connectivity", 1) + da("Int64", "offsets", 2) + da("UInt8", "types", 3) +
      "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">_" + block +
      "</AppendedData>\n</VTKFile>\n";
  write_text(dir / "z2.vtu", s);
  expect_same_mesh(want, read_vtu(dir / "z2.vtu"), true, "zlib appended raw");

  // A corrupt block is an InputError naming the array.
  const std::string mark = "<AppendedData encoding=\"raw\">_";
  s[s.find(mark) + mark.size() + 6 * 8 + 4] ^= 0x55;  // Points: 3 blocks, 6 header words
  write_text(dir / "z3.vtu", s);
  try {
    (void)read_vtu(dir / "z3.vtu");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("DataArray 'Points'"), std::string::npos) << e.what();
  }
}
#endif

TEST(Vtu, WriterEncodingsWithFields) {
  ScratchDir dir;
  const MeshData c = cube_mesh();
  const std::vector<CellField> cells = {{"quality \"q\" <&>", {1, 2, 3, 4, 5, 6}}};
  const std::vector<PointField> points = {{"dist", {0, 1, 2, 3, 4, 5, 6, 7}}};
  std::size_t raw_size = 0, base64_size = 0;
  for (VtuEncoding e : {VtuEncoding::Ascii, VtuEncoding::InlineBase64,
                        VtuEncoding::AppendedBase64, VtuEncoding::AppendedRaw}) {
    const std::string path = dir / ("w" + std::to_string(static_cast<int>(e)) + ".vtu");
    write_vtu(c, path, cells, points, VtuOptions{e, true});
    expect_same_mesh(c, read_vtu(path), true, path);
    const std::string text = read_text(path);
    EXPECT_NE(text.find("Name=\"dist\""), std::string::npos);
    EXPECT_NE(text.find("quality &quot;q&quot; &lt;&amp;&gt;"), std::string::npos);
    if (e == VtuEncoding::AppendedRaw) raw_size = text.size();
    if (e == VtuEncoding::AppendedBase64) base64_size = text.size();
  }
  EXPECT_LT(raw_size, base64_size);
  // Without faces, only tets are written.
  write_vtu(c, dir / "nofaces.vtu", {}, {}, VtuOptions{VtuEncoding::AppendedRaw, false});
  EXPECT_TRUE(read_vtu(dir / "nofaces.vtu").faces.empty());
  // Field sizes are checked before any file is created.
  EXPECT_THROW(write_vtu(c, dir / "bad.vtu", {{"x", {1.0}}}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.vtu"));
}

}  // namespace
}  // namespace pdr::io::test
