// medit .mesh reader, as a mesh (read_medit) and as a surface domain (read_medit_surface);
// see medit.hpp for the format and conventions.
#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "io/file_bytes.hpp"
#include "io/medit.hpp"
#include "io/mesh_assembly.hpp"
#include "io/surface.hpp"
#include "io/text_scanner.hpp"

namespace pdr::io {

namespace {

bool keyword_is(std::string_view tok, std::string_view kw) {
  return tok.size() == kw.size() &&
         std::equal(tok.begin(), tok.end(), kw.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) ==
                  std::tolower(static_cast<unsigned char>(b));
         });
}

// Sections skipped, with the number of tokens per entity and whether they are elements.
struct Skipped {
  const char* name;
  int tokens;
  bool element;
};
constexpr Skipped kSkipped[] = {
    {"Edges", 3, true},         {"EdgesP2", 4, true},
    {"QuadrilateralsQ2", 10, true}, {"Hexahedra", 9, true},    {"HexahedraQ2", 28, true},
    {"Prisms", 7, true},        {"Pyramids", 6, true},         {"Corners", 1, false},
    {"Ridges", 1, false},       {"RequiredVertices", 1, false}, {"RequiredEdges", 1, false},
    {"RequiredTriangles", 1, false}, {"RequiredQuadrilaterals", 1, false},
    {"RequiredTetrahedra", 1, false}, {"Normals", 3, false},   {"Tangents", 3, false},
    {"NormalAtVertices", 2, false}, {"TangentAtVertices", 2, false},
    {"NormalAtTriangleVertices", 3, false}, {"NormalAtQuadrilateralVertices", 3, false},
    {"TangentAtEdges", 3, false},
};

// The next token of the stream, failing at the end of the file.
std::string_view next(TextScanner& s, const char* what) {
  const std::string_view tok = s.token_any();
  if (tok.empty())
    s.fail(std::string("unexpected end of file while expecting ") + what +
           "; the file is truncated or a count is too large");
  return tok;
}

template <class T>
T next_number(TextScanner& s, const char* what) {
  const std::string_view tok = next(s, what);
  T v{};
  if (!parse_number(tok, v))
    s.fail(std::string("expected a number for ") + what + ", found '" +
           std::string(tok.substr(0, 40)) + "'; fix the number");
  return v;
}

std::size_t next_count(TextScanner& s, const char* what, std::size_t tokens) {
  const auto n = next_number<std::uint64_t>(s, what);
  if (n > s.size() / (2 * tokens))
    s.fail(std::string(what) + " " + std::to_string(n) + " is more than the file can hold; "
           "the count is wrong or the file is truncated");
  return static_cast<std::size_t>(n);
}

std::uint32_t next_index(TextScanner& s, std::size_t npts, const char* what) {
  const auto v = next_number<std::int64_t>(s, what);
  if (v < 1 || static_cast<std::uint64_t>(v) > npts)
    s.fail(std::string(what) + " " + std::to_string(v) + " is out of range: the vertices are "
           "numbered 1.." + std::to_string(npts) + "; fix the index");
  return static_cast<std::uint32_t>(v - 1);
}

// What a .mesh file holds: MeshData's vertices, tets and triangles, and the quadrilaterals
// and source lines a surface domain needs.
struct MeditFile {
  MeshData mesh;
  std::vector<std::size_t> vertex_lines, triangle_lines;
  std::vector<std::array<std::uint32_t, 4>> quads;
  std::vector<int> quad_refs;
  std::vector<std::size_t> quad_lines;
  std::vector<std::uint32_t> high_order;  // nodes used as P2 mid-edge nodes
  std::size_t skipped = 0;
};

MeditFile parse(TextScanner& s) {
  MeditFile file;
  MeshData& mesh = file.mesh;
  bool have_version = false, have_dim = false, have_vertices = false, ended = false;
  std::uint32_t idx[10];
  while (!ended) {
    const std::string_view kw = s.token_any();
    if (kw.empty()) break;
    if (keyword_is(kw, "MeshVersionFormatted")) {
      const int v = next_number<int>(s, "the mesh version");
      if (v < 1 || v > 4) s.fail("mesh version " + std::to_string(v) + " is not supported");
      have_version = true;
    } else if (keyword_is(kw, "Dimension")) {
      const int d = next_number<int>(s, "the dimension");
      if (d != 3) s.fail("dimension " + std::to_string(d) + " is not supported; pdr reads 3-D "
                         "meshes");
      have_dim = true;
    } else if (keyword_is(kw, "Vertices")) {
      if (have_vertices) s.fail("a second Vertices section is not supported; merge them");
      const std::size_t n = next_count(s, "the number of vertices", 4);
      mesh.points.reserve(n);
      mesh.point_markers.reserve(n);
      for (std::size_t i = 0; i < n; ++i) {
        Point p;
        p[0] = next_number<double>(s, "a vertex x coordinate");
        file.vertex_lines.push_back(s.line());
        p[1] = next_number<double>(s, "a vertex y coordinate");
        p[2] = next_number<double>(s, "a vertex z coordinate");
        mesh.points.push_back(p);
        mesh.point_markers.push_back(next_number<int>(s, "a vertex ref"));
      }
      have_vertices = true;
    } else if (keyword_is(kw, "Tetrahedra") || keyword_is(kw, "TetrahedraP2") ||
               keyword_is(kw, "Triangles") || keyword_is(kw, "TrianglesP2") ||
               keyword_is(kw, "Quadrilaterals")) {
      const bool tet = std::tolower(static_cast<unsigned char>(kw[1])) == 'e';  // "Te..."
      const bool quad = std::tolower(static_cast<unsigned char>(kw[0])) == 'q';
      const bool p2 = kw.back() == '2';
      const int corners = tet || quad ? 4 : 3;
      const int nodes = p2 ? (tet ? 10 : 6) : corners;
      if (!have_vertices) s.fail(std::string(kw) + " before Vertices; put Vertices first");
      const std::size_t n = next_count(s, "the number of elements", nodes + 1);
      for (std::size_t e = 0; e < n; ++e) {
        std::size_t line = 0;
        for (int k = 0; k < nodes; ++k) {
          idx[k] = next_index(s, mesh.points.size(), "a node");
          if (k == 0) line = s.line();
        }
        const int ref = next_number<int>(s, "an element ref");
        file.high_order.insert(file.high_order.end(), idx + corners, idx + nodes);
        if (tet) {
          mesh.tets.push_back({idx[0], idx[1], idx[2], idx[3]});
          mesh.tet_regions.push_back(ref);
        } else if (quad) {
          file.quads.push_back({idx[0], idx[1], idx[2], idx[3]});
          file.quad_refs.push_back(ref);
          file.quad_lines.push_back(line);
        } else {
          mesh.faces.push_back({idx[0], idx[1], idx[2]});
          mesh.face_markers.push_back(ref);
          file.triangle_lines.push_back(line);
        }
      }
    } else if (keyword_is(kw, "End")) {
      ended = true;
    } else {
      const Skipped* sk = std::find_if(std::begin(kSkipped), std::end(kSkipped),
                                       [&](const Skipped& k) { return keyword_is(kw, k.name); });
      if (sk == std::end(kSkipped))
        s.fail("unknown keyword '" + std::string(kw.substr(0, 40)) + "'; pdr reads "
               "Vertices, Triangles, Quadrilaterals, Tetrahedra and skips the usual others; "
               "remove it");
      const std::size_t n = next_count(s, "the number of entries", sk->tokens);
      for (std::size_t e = 0; e < n * static_cast<std::size_t>(sk->tokens); ++e)
        (void)next(s, "an entry");
      if (sk->element) file.skipped += n;
    }
  }
  if (!have_version || !have_dim)
    s.fail_at(0, "missing MeshVersionFormatted or Dimension; this is not a medit .mesh file");
  return file;
}

}  // namespace

MeshData read_medit(const std::string& path, ReadInfo* info) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  MeditFile file = parse(s);
  MeshData& mesh = file.mesh;
  const std::size_t skipped = file.skipped + file.quads.size();
  if (mesh.tets.empty() && (skipped > 0 || !mesh.faces.empty()))
    s.fail_at(0, "the file has no tetrahedra (" + std::to_string(mesh.faces.size()) +
                     " triangles, " + std::to_string(skipped) + " other elements); pdr reads "
                     "volume meshes");
  PointRoles roles(mesh.points.size());
  for (const Tet& t : mesh.tets)
    for (std::uint32_t v : t) roles.corner(v);
  for (const Tri& f : mesh.faces)
    for (std::uint32_t v : f) roles.corner(v);
  for (std::uint32_t v : file.high_order) roles.high_order(v);
  drop_if_all_zero(mesh.point_markers);
  drop_if_all_zero(mesh.face_markers);
  drop_if_all_zero(mesh.tet_regions);
  const std::size_t dropped = roles.drop_high_order_only(mesh);
  if (info) *info = ReadInfo{skipped, dropped};
  return std::move(mesh);
}

Surface read_medit_surface(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  const MeditFile file = parse(s);
  Surface surf;
  surf.source = path;
  for (std::size_t i = 0; i < file.mesh.points.size(); ++i)
    surf.add_point(file.mesh.points[i], file.vertex_lines[i], static_cast<std::int64_t>(i + 1));
  for (std::size_t f = 0; f < file.mesh.faces.size(); ++f)
    surf.add_face(file.mesh.faces[f], file.triangle_lines[f], file.mesh.face_markers[f]);
  for (std::size_t f = 0; f < file.quads.size(); ++f)
    surf.add_face(file.quads[f], file.quad_lines[f], file.quad_refs[f]);
  return surf;
}

}  // namespace pdr::io
