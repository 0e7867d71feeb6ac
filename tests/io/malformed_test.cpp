// Malformed inputs: each case asserts that reading throws InputError whose message names
// the file and whose line is the line of the problem (0 for whole-file problems and for
// binary data, where the message gives the byte offset instead).
#include <gtest/gtest.h>

#include <functional>

#include "io/mesh_io.hpp"
#include "io_test_util.hpp"

namespace pdr::io::test {
namespace {

struct Case {
  std::string name;
  std::string file;                  // the file given to the reader
  std::string content;
  std::size_t line;                  // expected InputError::line()
  std::string needle;                // expected in the message
  std::vector<std::pair<std::string, std::string>> siblings = {};  // other files
  bool domain = false;               // read_domain instead of read_mesh
};

const std::string kNode4 = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
const std::string kEle1 = "1 4 0\n1 1 2 3 4\n";

const std::string kMsh22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
    "$EndNodes\n$Elements\n1\n1 4 0 1 2 3 4\n$EndElements\n";
const std::string kMsh41 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n"
    "1 0 0\n0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";
const std::string kMedit =
    "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
    "0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
const std::string kVtu =
    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n<UnstructuredGrid>\n"
    "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n"
    "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0\n"
    "0 1 0 0 0 1</DataArray>\n</Points>\n<Cells>\n"
    "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
    "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n"
    "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";

// `text` with its line `n` (1-based) replaced by `by`.
std::string with_line(const std::string& text, std::size_t n, const std::string& by) {
  std::size_t begin = 0;
  for (std::size_t i = 1; i < n; ++i) begin = text.find('\n', begin) + 1;
  const std::size_t end = text.find('\n', begin);
  return text.substr(0, begin) + by + text.substr(end);
}

std::string first_lines(const std::string& text, std::size_t n) {
  std::size_t end = 0;
  for (std::size_t i = 0; i < n; ++i) end = text.find('\n', end) + 1;
  return text.substr(0, end);
}

template <class T>
std::string bytes_of(T v) {
  return std::string(reinterpret_cast<const char*>(&v), sizeof v);
}

std::vector<Case> cases() {
  const std::string poly = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n1 0\n1\n3 1 2 3\n0\n0\n";
  std::string bin_elements = "$MeshFormat\n2.2 1 8\n" + bytes_of<std::int32_t>(1) +
                             "\n$EndMeshFormat\n$Nodes\n1\n" + bytes_of<std::int32_t>(1) +
                             bytes_of(0.0) + bytes_of(0.0) + bytes_of(0.0) +
                             "\n$EndNodes\n$Elements\n1\n" + bytes_of<std::int32_t>(4) +
                             bytes_of<std::int32_t>(1) + bytes_of<std::int32_t>(0) +
                             bytes_of<std::int32_t>(1) + bytes_of<std::int32_t>(1);
  std::string raw_vtu = with_line(kVtu, 11,
                                  "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" "
                                  "offset=\"0\"/>");
  raw_vtu = raw_vtu.substr(0, raw_vtu.find("</VTKFile>")) +
            "<AppendedData encoding=\"raw\">_" + bytes_of<std::uint32_t>(1);
  return {
      // TetGen .node (as a domain)
      {"node bad token", "a.node", with_line(kNode4, 3, "2 1 0 zz"), 3, "found 'zz'", {}, true},
      {"node truncated", "a.node",
       "5 3 0 0\n1 0.0 0.0 0.0\n2 1.0 0.0 0.0\n3 0.0 1.0 0.0\n4 0.0 0.0 1.0\n", 5,
       "unexpected end of file", {}, true},
      {"node huge count", "a.node", "99999999999 3 0 0\n1 0 0 0\n", 1, "more than", {}, true},
      {"node first index", "a.node", "1 3 0 0\n2 0 0 0\n", 2, "must be 0 or 1", {}, true},
      {"node sequence", "a.node", "3 3 0 0\n1 0 0 0\n3 0 0 0\n2 0 0 0\n", 3, "out of sequence",
       {}, true},
      {"node dimension", "a.node", with_line(kNode4, 1, "4 2 0 0"), 1, "dimension 2", {}, true},
      {"node extra token", "a.node", with_line(kNode4, 2, "1 0 0 0 7"), 2, "unexpected '7'", {},
       true},
      {"node nan", "a.node", with_line(kNode4, 2, "1 nan 0 0"), 2, "finite", {}, true},
      {"node marker flag", "a.node", with_line(kNode4, 1, "4 3 0 2"), 1, "marker flag", {}, true},
      {"node missing marker", "a.node", with_line(kNode4, 1, "4 3 0 1"), 2, "missing", {}, true},
      // TetGen .ele / .face
      {"ele index range", "m.ele", with_line(kEle1, 2, "1 1 2 3 5"), 2, "out of range",
       {{"m.node", kNode4}}},
      {"ele nodes per tet", "m.ele", with_line(kEle1, 1, "1 7 0"), 1, "7 nodes",
       {{"m.node", kNode4}}},
      {"ele truncated", "m.ele", "2 4 0\n1    1    2    3    4\n", 2, "unexpected end of file",
       {{"m.node", kNode4}}},
      {"ele too many", "m.ele", kEle1 + "2 1 2 3 4\n", 3, "after the last tet",
       {{"m.node", kNode4}}},
      {"ele attribute", "m.ele", "1 4 1\n1 1 2 3 4 x\n", 2, "found 'x'", {{"m.node", kNode4}}},
      {"ele base mismatch", "m.ele", "1 4 0\n0 0 1 2 3\n", 2, "out of range",
       {{"m.node", kNode4}}},
      {"face token count", "m.ele", kEle1, 2, "3 values", {{"m.node", kNode4},
                                                          {"m.face", "1 1\n1 1 2 3\n"}}},
      {"face marker", "m.ele", kEle1, 2, "face marker", {{"m.node", kNode4},
                                                        {"m.face", "1 1\n1 1 2 3 x\n"}}},
      // TetGen .poly / .smesh
      {"poly corner range", "p.poly", with_line(poly, 8, "3 1 2 9"), 8, "out of range", {}, true},
      // index - base overflowed int64 before the range test (found by UBSan)
      {"poly corner most negative", "p.poly",
       with_line(poly, 8, "3 1 2 -9223372036854775808"), 8, "out of range", {}, true},
      {"ele index most negative", "m.ele", with_line(kEle1, 2, "1 1 2 3 -9223372036854775808"),
       2, "out of range", {{"m.node", kNode4}}},
      {"poly empty facet", "p.poly", with_line(poly, 7, "0"), 7, "at least one polygon", {},
       true},
      {"poly missing node", "p.poly", "0 3 0 0\n1 0\n1\n3 1 2 3\n", 1, "p.node", {}, true},
      {"poly trailing", "p.poly", poly + "1\n", 11, "after the region list", {}, true},
      {"poly hole line", "p.poly", with_line(poly, 9, "1\n1 0.5 0.5"), 10, "missing", {}, true},
      {"smesh corner range", "s.smesh", kNode4 + "1 0\n3 1 2 0\n", 7, "out of range", {}, true},
      // Gmsh
      {"msh version", "g.msh", with_line(kMsh22, 2, "3.0 0 8"), 2, "version 3.0"},
      {"msh missing node", "g.msh", with_line(kMsh22, 13, "1 4 0 1 2 3 5"), 13, "node 5"},
      {"msh section end", "g.msh", with_line(kMsh22, 10, "$EndNode"), 10, "$EndNodes"},
      {"msh duplicate tag", "g.msh", with_line(kMsh22, 9, "3 0 0 1"), 9, "defined twice"},
      {"msh no tets", "g.msh", with_line(kMsh22, 13, "1 2 0 1 2 3"), 0, "no tetrahedra"},
      {"msh not msh", "g.msh", "hello\n", 1, "$MeshFormat"},
      {"msh41 count", "g.msh", with_line(kMsh41, 17, "1 2 1 2"), 19, "declares 2"},
      {"msh41 coordinate", "g.msh", with_line(kMsh41, 13, "0 1 x"), 13, "found 'x'"},
      {"msh binary truncated", "g.msh", bin_elements, 0, "byte offset"},
      // medit
      {"mesh keyword", "m.mesh", with_line(kMedit, 9, "Tetrahedron"), 9, "unknown keyword"},
      {"mesh index", "m.mesh", with_line(kMedit, 11, "1 2 3 5 0"), 11, "out of range"},
      {"mesh dimension", "m.mesh", with_line(kMedit, 2, "Dimension 2"), 2, "dimension 2"},
      {"mesh truncated", "m.mesh", first_lines(kMedit, 6), 6, "unexpected end of file"},
      // VTU
      {"vtu compressed", "v.vtu",
       with_line(kVtu, 1, "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                          "compressor=\"vtkLZ4DataCompressor\">"),
       1, "re-export uncompressed"},
      {"vtu not grid", "v.vtu", with_line(kVtu, 1, "<VTKFile type=\"PolyData\">"), 1,
       "UnstructuredGrid"},
      {"vtu point count", "v.vtu",
       with_line(kVtu, 3, "<Piece NumberOfPoints=\"four\" NumberOfCells=\"1\">"), 3,
       "NumberOfPoints"},
      {"vtu connectivity", "v.vtu",
       with_line(kVtu, 9, "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">"
                          "0 1 2 4</DataArray>"),
       9, "uses point 4"},
      {"vtu ascii token", "v.vtu", with_line(kVtu, 6, "0 1 x 0 0 1</DataArray>"), 6,
       "found 'x'"},
      {"vtu base64", "v.vtu",
       with_line(kVtu, 10, "<DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">"
                           "@@@@</DataArray>"),
       10, "invalid base64"},
      {"vtu appended offset", "v.vtu",
       with_line(kVtu, 11, "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" "
                           "offset=\"99999\"/>\n<AppendedData encoding=\"raw\">_AAAA"
                           "</AppendedData>"),
       11, "beyond"},
      {"vtu raw truncated", "v.vtu", raw_vtu, 0, "byte offset"},
  };
}

TEST(Malformed, EveryCaseNamesFileAndLine) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    ScratchDir dir;
    write_text(dir / c.file, c.content);
    for (const auto& [name, text] : c.siblings) write_text(dir / name, text);
    try {
      if (c.domain) (void)read_domain(dir / c.file);
      else (void)read_mesh(dir / c.file);
      ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
      const std::string what = e.what();
      const std::string& culprit =
          c.name.rfind("face", 0) == 0 ? std::string("m.face") : c.file;
      EXPECT_NE(what.find(culprit), std::string::npos) << what;
      EXPECT_EQ(e.line(), c.line) << what;
      EXPECT_NE(what.find(c.needle), std::string::npos) << what;
    }
  }
}

TEST(Malformed, MissingAndUnknownFiles) {
  ScratchDir dir;
  EXPECT_THROW((void)read_mesh(dir / "none.msh"), InputError);
  EXPECT_THROW((void)read_mesh(dir / "none"), InputError);
  write_text(dir / "x.stl", "solid\n");
  EXPECT_THROW((void)read_mesh(dir / "x.stl"), InputError);
  EXPECT_THROW((void)read_domain(dir / "x.stl"), InputError);
  EXPECT_THROW((void)read_mesh(dir.str()), InputError);  // a directory
}

}  // namespace
}  // namespace pdr::io::test
