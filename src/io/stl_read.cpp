// STL surface reader, ASCII and binary (as written by Gmsh, meshio, CAD systems and 3-D
// scanners).
//
// Binary: an 80-byte header, a little-endian uint32 triangle count n, then n records of 50
// bytes: the normal and three corners as little-endian float32, and a uint16 attribute
// (both ignored). A file whose size is exactly 84 + 50 n is binary, even when its header
// begins with "solid" (many binary writers put that there).
// ASCII: one or more "solid [name]" ... "endsolid [name]" blocks of
//   facet normal <nx> <ny> <nz> / outer loop / vertex <x> <y> <z> (3 or more) / endloop /
//   endfacet
// with each keyword line on its own line, keywords in any case; the normal is ignored.
// STL stores every corner with each triangle; surface_to_plc merges the equal ones. Faces
// carry no markers; messages name a face by its number (and, in ASCII, its line).
#include <bit>
#include <cctype>
#include <string>

#include "io/byte_reader.hpp"
#include "io/file_bytes.hpp"
#include "io/surface.hpp"
#include "io/text_scanner.hpp"

namespace pdr::io {

namespace {

bool is_keyword(std::string_view tok, std::string_view kw) {
  if (tok.size() != kw.size()) return false;
  for (std::size_t i = 0; i < tok.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(tok[i])) != kw[i]) return false;
  return true;
}

void expect_line(TextScanner& s, std::string_view first, std::string_view second,
                 const std::string& where) {
  const std::string what = std::string(first) + (second.empty() ? "" : " ") +
                           std::string(second);
  s.require_line("'" + what + "' of " + where);
  const std::string_view tok = s.token("a keyword");
  if (!is_keyword(tok, first) ||
      (!second.empty() && !is_keyword(s.token("a keyword"), second)))
    s.fail("expected '" + what + "' of " + where + ", found '" +
           std::string(tok.substr(0, 40)) + "'; fix the STL file");
  s.end_line(what);
}

Surface read_ascii(const std::string& bytes, const std::string& path) {
  TextScanner s(bytes, path, '\0');
  Surface surf;
  surf.source = path;
  if (!s.next_line() || !is_keyword(s.token("the keyword solid"), "solid"))
    s.fail("an ASCII STL file starts with 'solid'; this is neither ASCII nor binary STL "
           "(a binary STL file is 84 + 50 x <#triangles> bytes long)");
  (void)s.rest_of_line();  // the solid's name
  std::vector<std::uint32_t> corners;
  while (s.next_line()) {
    const std::string_view tok = s.token("a keyword");
    if (is_keyword(tok, "endsolid")) {
      (void)s.rest_of_line();
      if (!s.next_line()) break;
      if (!is_keyword(s.token("a keyword"), "solid"))
        s.fail("expected 'solid' or the end of the file after 'endsolid'; fix the STL file");
      (void)s.rest_of_line();
      continue;
    }
    const std::string face = "face " + std::to_string(surf.face_count() + 1);
    if (!is_keyword(tok, "facet"))
      s.fail("expected 'facet' or 'endsolid', found '" + std::string(tok.substr(0, 40)) +
             "'; fix the STL file");
    const std::size_t line = s.line();
    if (s.has_token()) {
      if (!is_keyword(s.token("normal"), "normal"))
        s.fail("expected 'facet normal <nx> <ny> <nz>'; fix the STL file");
      for (int k = 0; k < 3; ++k) (void)s.number<double>("a normal component");
    }
    s.end_line("the facet's normal");
    expect_line(s, "outer", "loop", face);
    corners.clear();
    for (;;) {
      s.require_line("'vertex <x> <y> <z>' or 'endloop' of " + face);
      const std::string_view kw = s.token("a keyword");
      if (is_keyword(kw, "endloop")) break;
      if (!is_keyword(kw, "vertex"))
        s.fail("expected 'vertex <x> <y> <z>' or 'endloop' of " + face + ", found '" +
               std::string(kw.substr(0, 40)) + "'; fix the STL file");
      Point p;
      p[0] = s.number<double>("the x coordinate");
      p[1] = s.number<double>("the y coordinate");
      p[2] = s.number<double>("the z coordinate");
      s.end_line("the vertex's coordinates");
      corners.push_back(static_cast<std::uint32_t>(surf.points.size()));
      surf.add_point(p, s.line(), -1);
    }
    s.end_line("endloop");
    expect_line(s, "endfacet", "", face);
    surf.add_face(corners, line, 0);
  }
  return surf;
}

Surface read_binary(const std::string& bytes, const std::string& path, std::uint32_t n) {
  ByteReader b(bytes, 84, path);
  Surface surf;
  surf.source = path;
  surf.points.reserve(3 * static_cast<std::size_t>(n));
  std::uint32_t corners[3];
  for (std::uint32_t f = 0; f < n; ++f) {
    b.skip(12, "a triangle's normal");
    for (std::uint32_t& c : corners) {
      Point p;
      for (double& x : p) x = b.get_in<float>(std::endian::little, "a corner coordinate");
      if (!(p[0] - p[0] == 0 && p[1] - p[1] == 0 && p[2] - p[2] == 0))
        throw InputError(path, 0, "face " + std::to_string(f + 1) + ": a corner has a "
                                  "coordinate that is not a finite number; fix the file");
      c = static_cast<std::uint32_t>(surf.points.size());
      surf.add_point(p, 0, -1);
    }
    b.skip(2, "a triangle's attribute");
    surf.add_face(corners, 0, 0);
  }
  return surf;
}

}  // namespace

Surface read_stl(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  std::size_t i = 0;
  while (i < bytes.size() && is_blank(bytes[i])) ++i;
  const bool says_solid = is_keyword(std::string_view(bytes).substr(i, 5), "solid");
  if (bytes.size() >= 84) {
    const auto n = ByteReader(bytes, 80, path).get_in<std::uint32_t>(std::endian::little,
                                                                     "the triangle count");
    const std::uint64_t want = 84 + 50 * static_cast<std::uint64_t>(n);
    if (bytes.size() == want) return read_binary(bytes, path, n);
    if (!says_solid)
      throw InputError(path, 0, "binary STL: the header declares " + std::to_string(n) +
                                    " triangles, so the file should have 84 + 50 x " +
                                    std::to_string(n) + " = " + std::to_string(want) +
                                    " bytes, but it has " + std::to_string(bytes.size()) +
                                    "; the file is truncated or not STL, export it again");
  }
  return read_ascii(bytes, path);
}

}  // namespace pdr::io
