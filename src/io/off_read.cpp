// OFF surface reader (Geomview's Object File Format, ASCII), as written by meshio, CGAL,
// MeshLab and TetGen's -O tools.
//
// Layout: the keyword "OFF" (or "COFF", "NOFF", "CNOFF": vertex colours or normals follow
// the coordinates and are ignored), optionally followed on the same line by the counts;
// then "<#vertices> <#faces> [<#edges>]"; #vertices lines "x y z [...]"; #faces lines
// "<n> <v1> ... <vn> [colour]" with 0-based vertex indices. '#' starts a comment; every
// vertex and face is on its own line. Binary OFF and the 4-D / n-D variants are rejected.
// Faces carry no markers.
#include <string>

#include "io/file_bytes.hpp"
#include "io/surface.hpp"
#include "io/text_scanner.hpp"

namespace pdr::io {

Surface read_off(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  Surface surf;
  surf.source = path;
  if (!s.next_line()) s.fail_at(0, "the file is empty; an OFF file starts with 'OFF'");
  const std::string_view kw = s.token("the OFF keyword");
  if (kw != "OFF" && kw != "COFF" && kw != "NOFF" && kw != "CNOFF")
    s.fail("expected the keyword OFF (or COFF, NOFF, CNOFF), found '" +
           std::string(kw.substr(0, 40)) + "'; binary and n-dimensional OFF files are not "
           "supported, save the surface as ASCII OFF");
  if (!s.has_token()) s.require_line("the counts '<#vertices> <#faces> <#edges>'");
  const std::size_t nv = s.count("the number of vertices", 6);
  const std::size_t nf = s.count("the number of faces", 8);
  if (s.has_token()) (void)s.count("the number of edges", 0);
  s.end_line("the counts");
  surf.points.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    s.require_line("vertex " + std::to_string(i) + " of " + std::to_string(nv));
    Point p;
    p[0] = s.number<double>("the x coordinate");
    p[1] = s.number<double>("the y coordinate");
    p[2] = s.number<double>("the z coordinate");
    (void)s.rest_of_line();  // colour or normal
    surf.add_point(p, s.line(), static_cast<std::int64_t>(i));
  }
  std::vector<std::uint32_t> corners;
  for (std::size_t f = 0; f < nf; ++f) {
    s.require_line("face " + std::to_string(f + 1) + " of " + std::to_string(nf));
    const std::size_t n = s.count("the number of corners", 2);
    corners.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const auto v = s.number<std::int64_t>("a corner index");
      if (v < 0 || static_cast<std::uint64_t>(v) >= nv)
        s.fail("corner index " + std::to_string(v) + " is out of range: the vertices are "
               "numbered 0.." + std::to_string(nv == 0 ? 0 : nv - 1) + "; fix the index");
      corners.push_back(static_cast<std::uint32_t>(v));
    }
    (void)s.rest_of_line();  // colour
    surf.add_face(corners, s.line(), 0);
  }
  if (s.next_line())
    s.fail("unexpected '" + std::string(s.token("a token").substr(0, 40)) +
           "' after the last face; the counts line declares " + std::to_string(nf) +
           " faces, fix it");
  return surf;
}

}  // namespace pdr::io
