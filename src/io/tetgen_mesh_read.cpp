// TetGen mesh reader: PREFIX.node + PREFIX.ele (+ PREFIX.face). See tetgen.hpp for the
// layout, the index-base rule and the orientation mapping (faces: swap b and c on read).
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "io/file_bytes.hpp"
#include "io/mesh_assembly.hpp"
#include "io/tetgen.hpp"
#include "io/tetgen_sections.hpp"

namespace pdr::io {

namespace {

// Checks the element index sequence: the first is 0 or 1, the rest consecutive.
void check_sequence(TextScanner& s, std::int64_t index, std::size_t i, std::int64_t& first,
                    const char* what) {
  if (i == 0) {
    if (index != 0 && index != 1)
      s.fail(std::string("the first ") + what + " index must be 0 or 1, found " +
             std::to_string(index) + "; renumber the " + what + "s");
    first = index;
  } else if (index != first + static_cast<std::int64_t>(i)) {
    s.fail(std::string(what) + " index " + std::to_string(index) + " is out of sequence, "
           "expected " + std::to_string(first + static_cast<std::int64_t>(i)) +
           "; number the " + what + "s consecutively");
  }
}

void read_ele(const std::string& path, std::uint32_t base, MeshData& mesh, PointRoles& roles) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  const std::size_t npts = mesh.points.size();
  s.require_line("the .ele header '<#tets> <4|10> <#attributes>'");
  const std::size_t header_line = s.line();
  const std::size_t n = s.count("the number of tets", 10);  // "i a b c d\n"
  std::size_t nodes = 4;
  if (s.has_token()) {
    nodes = s.count("the number of nodes per tet", 0);
    if (nodes != 4 && nodes != 10)
      s.fail("tets with " + std::to_string(nodes) + " nodes are not supported; TetGen writes "
             "4 (linear) or 10 (-o2) nodes per tet");
  }
  const std::size_t nattr = s.has_token() ? s.count("the number of attributes", 2 * n) : 0;
  s.end_line("the .ele header");

  mesh.tets.reserve(n);
  std::vector<int> regions;
  bool regions_ok = nattr > 0;
  if (regions_ok) regions.reserve(n);
  std::int64_t first = 0;
  for (std::size_t i = 0; i < n; ++i) {
    s.require_line("tet " + std::to_string(i + 1) + " of " + std::to_string(n));
    check_sequence(s, s.number<std::int64_t>("the tet index"), i, first, "tet");
    Tet t;
    for (std::uint32_t& v : t) {
      v = to_index(s, s.number<std::int64_t>("a tet vertex"), base, npts, "tet vertex");
      roles.corner(v);
    }
    for (std::size_t k = 4; k < nodes; ++k)
      roles.high_order(
          to_index(s, s.number<std::int64_t>("a tet mid-edge node"), base, npts, "tet node"));
    for (std::size_t a = 0; a < nattr; ++a) {
      const double attr = s.number<double>("a tet attribute");
      if (a == 0 && regions_ok) {
        if (attr == std::floor(attr) && attr >= std::numeric_limits<int>::min() &&
            attr <= std::numeric_limits<int>::max())
          regions.push_back(static_cast<int>(attr));
        else
          regions_ok = false;  // real-valued attributes are not region numbers
      }
    }
    s.end_line("the tet's nodes and attributes");
    mesh.tets.push_back(t);
  }
  if (s.next_line())
    s.fail("unexpected content after the last tet; the tet count in the header (line " +
           std::to_string(header_line) + ") is too small");
  if (regions_ok) mesh.tet_regions = std::move(regions);
}

void read_face(const std::string& path, std::uint32_t base, MeshData& mesh, PointRoles& roles) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  const std::size_t npts = mesh.points.size();
  s.require_line("the .face header '<#faces> <0|1 markers>'");
  const std::size_t header_line = s.line();
  const std::size_t n = s.count("the number of faces", 8);  // "i a b c\n"
  int flag = 0;
  if (s.has_token()) {
    flag = s.number<int>("the face marker flag");
    if (flag != 0 && flag != 1)
      s.fail("the face marker flag must be 0 or 1, found " + std::to_string(flag));
  }
  s.end_line("the .face header");

  mesh.faces.reserve(n);
  if (flag) mesh.face_markers.reserve(n);
  std::int64_t first = 0;
  std::array<std::string_view, 10> tok;
  for (std::size_t i = 0; i < n; ++i) {
    s.require_line("face " + std::to_string(i + 1) + " of " + std::to_string(n));
    check_sequence(s, s.number<std::int64_t>("the face index"), i, first, "face");
    std::size_t k = 0;
    while (s.has_token()) {
      if (k == tok.size()) s.end_line("the face's nodes, marker and neighbours");
      tok[k++] = s.token("face data");
    }
    // Nodes (3, or 6 with -o2), then the marker when flagged, then 2 neighbours with -nn.
    std::size_t nodes = 0;
    if (flag) nodes = (k == 4 || k == 6) ? 3 : (k == 7 || k == 9) ? 6 : 0;
    else nodes = (k == 3 || k == 5) ? 3 : (k == 6 || k == 8) ? 6 : 0;
    if (nodes == 0)
      s.fail("a face line holds " + std::to_string(k) + " values after its index; expected "
             "3 or 6 nodes" + std::string(flag ? ", a marker" : "") +
             " and optionally 2 neighbour tets");
    Tri f;
    for (std::size_t j = 0; j < nodes; ++j) {
      std::int64_t v = 0;
      if (!parse_number(tok[j], v))
        s.fail("expected an integer face node, found '" + std::string(tok[j]) + "'");
      const std::uint32_t idx = to_index(s, v, base, npts, "face node");
      if (j < 3) {
        f[j] = idx;
        roles.corner(idx);
      } else {
        roles.high_order(idx);
      }
    }
    if (flag) {
      int m = 0;
      if (!parse_number(tok[nodes], m))
        s.fail("expected an integer face marker, found '" + std::string(tok[nodes]) + "'");
      mesh.face_markers.push_back(m);
    }
    std::swap(f[1], f[2]);  // TetGen's face normals point into the mesh; pdr's out
    mesh.faces.push_back(f);
  }
  if (s.next_line())
    s.fail("unexpected content after the last face; the face count in the header (line " +
           std::to_string(header_line) + ") is too small");
}

}  // namespace

MeshData read_tetgen_mesh(const std::string& prefix, ReadInfo* info) {
  NodeSection nodes = read_node_file(prefix + ".node", false);
  MeshData mesh;
  mesh.points = std::move(nodes.points);
  mesh.point_markers = std::move(nodes.markers);
  PointRoles roles(mesh.points.size());
  read_ele(prefix + ".ele", nodes.base, mesh, roles);
  const std::string face_path = prefix + ".face";
  if (is_regular_file(face_path)) read_face(face_path, nodes.base, mesh, roles);
  const std::size_t dropped = roles.drop_high_order_only(mesh);
  if (info) *info = ReadInfo{0, dropped};
  return mesh;
}

}  // namespace pdr::io
