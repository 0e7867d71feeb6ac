// Wavefront OBJ surface reader (ASCII), as written by Blender, MeshLab, CGAL, libigl and
// most CAD and scanning tools.
//
// Read: "v x y z [w | r g b]" (the coordinates; a weight or vertex colour after them is
// ignored) and "f c1 c2 c3 ..." whose corners are "v", "v/vt", "v//vn" or "v/vt/vn": the
// vertex index, 1-based, or negative for "that many vertices back from the last one read".
// Ignored: texture and normal vertices (vt, vn, vp), groups and objects (g, o), smoothing
// groups (s), materials (mtllib, usemtl), line and point elements (l, p), and any other
// statement, so the files of every exporter read. A backslash at the end of a line
// continues the statement and is refused, in any statement (no exporter pdr knows writes
// it). An index may carry a '+'. '#' starts a comment. Faces carry no markers.
#include <string>
#include <vector>

#include "io/file_bytes.hpp"
#include "io/surface.hpp"
#include "io/text_scanner.hpp"

namespace pdr::io {

namespace {

// The vertex index of one corner ("v", "v/vt", "v//vn", "v/vt/vn") as a 0-based index.
std::uint32_t corner_index(const TextScanner& s, std::string_view tok, std::size_t nv) {
  std::string_view head = tok.substr(0, tok.find('/'));
  if (head.size() > 1 && head[0] == '+') head.remove_prefix(1);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(head.data(), head.data() + head.size(), v);
  if (ec != std::errc() || end != head.data() + head.size() || head.empty())
    s.fail("expected a face corner 'v', 'v/vt', 'v//vn' or 'v/vt/vn' with an integer vertex "
           "index, found '" + std::string(tok.substr(0, 40)) + "'");
  const auto n = static_cast<std::int64_t>(nv);
  const std::int64_t i = v > 0 ? v - 1 : n + v;  // negative: relative to the last vertex
  if (v == 0 || i < 0 || i >= n)
    s.fail("corner index " + std::to_string(v) + " is out of range: " + std::to_string(nv) +
           " vertices are defined before this face (indices 1.." + std::to_string(nv) +
           ", or -1..-" + std::to_string(nv) + " counting back); fix the index");
  return static_cast<std::uint32_t>(i);
}

}  // namespace

Surface read_obj(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  Surface surf;
  surf.source = path;
  std::vector<std::uint32_t> corners;
  const auto continued = [&s] {
    s.fail("a line continued with '\\' is not supported; join it with the next line");
  };
  // The rest of a statement's line, refused when a backslash continues it.
  const auto rest_of_statement = [&s, &continued] {
    const std::string_view rest = s.rest_of_line();
    if (!rest.empty() && rest.back() == '\\') continued();
  };
  while (s.next_line()) {
    const std::string_view kw = s.token("a statement");
    if (kw == "v") {
      Point p;
      p[0] = s.number<double>("the x coordinate");
      p[1] = s.number<double>("the y coordinate");
      p[2] = s.number<double>("the z coordinate");
      rest_of_statement();  // a weight or a colour
      surf.add_point(p, s.line(), static_cast<std::int64_t>(surf.points.size() + 1));
    } else if (kw == "f") {
      corners.clear();
      while (s.has_token()) {
        const std::string_view tok = s.token("a face corner");
        if (tok == "\\") continued();
        corners.push_back(corner_index(s, tok, surf.points.size()));
      }
      surf.add_face(corners, s.line(), 0);
    } else {
      rest_of_statement();
    }
  }
  return surf;
}

}  // namespace pdr::io
