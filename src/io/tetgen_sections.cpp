// Sections shared by the TetGen readers: node section, holes, regions. See tetgen.hpp.
#include "io/tetgen_sections.hpp"

#include "io/file_bytes.hpp"

namespace pdr::io {

NodeSection read_node_section(TextScanner& s, bool keep_lines) {
  NodeSection sec;
  s.require_line("the node header '<#points> 3 <#attributes> <0|1 markers>'");
  sec.header_line = s.line();
  // A point line holds at least "i x y z\n": 8 bytes.
  const std::size_t n = s.count("the number of points", 8);
  if (s.has_token()) {
    const int dim = s.number<int>("the dimension");
    if (dim != 3) s.fail("dimension " + std::to_string(dim) + " is not supported; pdr reads "
                         "3-D points, so the header must say 3");
  }
  const std::size_t nattr = s.has_token() ? s.count("the number of attributes", 2 * n) : 0;
  int has_markers = 0;
  if (s.has_token()) {
    has_markers = s.number<int>("the boundary marker flag");
    if (has_markers != 0 && has_markers != 1)
      s.fail("the boundary marker flag must be 0 or 1, found " + std::to_string(has_markers));
  }
  s.end_line("the node header");

  sec.points.reserve(n);
  if (has_markers) sec.markers.reserve(n);
  if (keep_lines) sec.lines.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.require_line("point " + std::to_string(i + 1) + " of " + std::to_string(n));
    const auto index = s.number<std::int64_t>("the point index");
    if (i == 0) {
      if (index != 0 && index != 1)
        s.fail("the first point index must be 0 or 1 (it fixes the index base), found " +
               std::to_string(index) + "; renumber the points");
      sec.base = static_cast<std::uint32_t>(index);
    } else if (index != static_cast<std::int64_t>(sec.base + i)) {
      s.fail("point index " + std::to_string(index) + " is out of sequence, expected " +
             std::to_string(sec.base + i) + "; number the points consecutively");
    }
    Point p;
    p[0] = s.number<double>("the x coordinate");
    p[1] = s.number<double>("the y coordinate");
    p[2] = s.number<double>("the z coordinate");
    for (std::size_t a = 0; a < nattr; ++a) (void)s.number<double>("a point attribute");
    if (has_markers) sec.markers.push_back(s.number<int>("the point boundary marker"));
    s.end_line(has_markers ? "the point's boundary marker"
                           : "the point's coordinates and attributes (the header declares "
                             "no boundary markers)");
    sec.points.push_back(p);
    if (keep_lines) sec.lines.push_back(s.line());
  }
  return sec;
}

NodeSection read_node_file(const std::string& path, bool keep_lines) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  NodeSection sec = read_node_section(s, keep_lines);
  if (s.next_line())
    s.fail("unexpected content after the last point; the point count in the header (line " +
           std::to_string(sec.header_line) + ") is too small");
  return sec;
}

std::uint32_t to_index(TextScanner& s, std::int64_t index, std::uint32_t base, std::size_t n,
                       const char* what) {
  // Compared before subtracting: index - base would overflow for index near -2^63.
  if (index < static_cast<std::int64_t>(base) ||
      static_cast<std::uint64_t>(index - static_cast<std::int64_t>(base)) >= n)
    s.fail(std::string(what) + " " + std::to_string(index) + " is out of range: the points "
           "are numbered " + std::to_string(base) + ".." +
           std::to_string(static_cast<std::int64_t>(base + n) - 1) + "; fix the index");
  return static_cast<std::uint32_t>(index - static_cast<std::int64_t>(base));
}

Point read_indexed_point(TextScanner& s, const std::string& what) {
  (void)s.number<std::int64_t>("the " + what + " index");
  Point p;
  p[0] = s.number<double>("the " + what + "'s x coordinate");
  p[1] = s.number<double>("the " + what + "'s y coordinate");
  p[2] = s.number<double>("the " + what + "'s z coordinate");
  return p;
}

void read_holes_and_regions(TextScanner& s, Plc& plc) {
  if (!s.next_line()) return;  // no hole list
  const std::size_t nh = s.count("the number of volume holes", 8);
  s.end_line("the number of volume holes");
  plc.holes.reserve(nh);
  plc.hole_lines.reserve(nh);
  for (std::size_t i = 0; i < nh; ++i) {
    s.require_line("volume hole " + std::to_string(i + 1) + " of " + std::to_string(nh));
    const Point p = read_indexed_point(s, "hole");
    s.end_line("the hole's coordinates");
    plc.holes.push_back(p);
    plc.hole_lines.push_back(s.line());
  }
  if (!s.next_line()) return;  // no region list
  const std::size_t nr = s.count("the number of regions", 8);
  s.end_line("the number of regions");
  plc.regions.reserve(nr);
  for (std::size_t i = 0; i < nr; ++i) {
    s.require_line("region " + std::to_string(i + 1) + " of " + std::to_string(nr));
    PlcRegion r;
    r.point = read_indexed_point(s, "region");
    r.attribute = s.number<double>("the region attribute");
    if (s.has_token()) r.max_volume = s.number<double>("the region's volume constraint");
    s.end_line("the region's volume constraint");
    r.line = s.line();
    plc.regions.push_back(r);
  }
  if (s.next_line())
    s.fail("unexpected content after the region list; remove it or fix the region count");
}

std::uint32_t read_domain_points(TextScanner& s, const std::string& path, Plc& plc) {
  NodeSection sec = read_node_section(s, true);
  if (sec.points.empty()) {
    const std::string node_path = strip_extension(path) + ".node";
    if (!is_regular_file(node_path))
      s.fail_at(sec.header_line, "the node section has 0 points and there is no " + node_path +
                                     "; list the points here or provide the .node file");
    sec = read_node_file(node_path, true);
  }
  plc.points = std::move(sec.points);
  plc.point_lines = std::move(sec.lines);
  plc.point_markers = std::move(sec.markers);
  return sec.base;
}

}  // namespace pdr::io
