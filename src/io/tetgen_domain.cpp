// TetGen domain readers: .poly, .smesh and bare .node point sets. See tetgen.hpp for the
// formats; every index is converted to 0-based and every entity keeps its source line.
#include <string>

#include "io/file_bytes.hpp"
#include "io/tetgen.hpp"
#include "io/tetgen_sections.hpp"

namespace pdr::io {

namespace {

// "<#facets> [<0|1 markers>]"; returns the facet count.
std::size_t read_facet_header(TextScanner& s, std::size_t min_bytes_per_facet) {
  s.require_line("the facet header '<#facets> <0|1 markers>'");
  const std::size_t n = s.count("the number of facets", min_bytes_per_facet);
  if (s.has_token()) {
    const int flag = s.number<int>("the facet marker flag");
    if (flag != 0 && flag != 1)
      s.fail("the facet marker flag must be 0 or 1, found " + std::to_string(flag));
  }
  s.end_line("the facet header");
  return n;
}

// One polygon line "<#corners> <v1> ... <vn>" of a .poly facet.
std::vector<std::uint32_t> read_polygon(TextScanner& s, std::uint32_t base, std::size_t npts) {
  const std::size_t nc = s.count("the number of polygon corners", 2);
  if (nc == 0) s.fail("a polygon needs at least one corner; remove the empty polygon");
  std::vector<std::uint32_t> poly;
  poly.reserve(nc);
  for (std::size_t k = 0; k < nc; ++k)
    poly.push_back(to_index(s, s.number<std::int64_t>("a polygon corner"), base, npts,
                            "polygon corner"));
  s.end_line("the polygon's corners (a polygon must be on one line)");
  return poly;
}

// The frame both domain formats share: points (or the sibling .node), the facet list, each
// facet read by `read_facet(s, index, base, #points, facet)` from its first line on, then
// the volume holes and regions.
template <class ReadFacet>
Plc read_facet_domain(const std::string& path, std::size_t min_bytes_per_facet,
                      ReadFacet read_facet) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path);
  Plc plc;
  plc.source = path;
  plc.enclosure = Enclosure::HolePoints;  // TetGen's reading: every unholed cell is meshed
  const std::uint32_t base = read_domain_points(s, path, plc);
  const std::size_t npts = plc.points.size();
  const std::size_t nf = read_facet_header(s, min_bytes_per_facet);
  plc.facets.reserve(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    s.require_line("facet " + std::to_string(f + 1) + " of " + std::to_string(nf));
    PlcFacet facet;
    facet.line = s.line();
    read_facet(s, f, base, npts, facet);
    plc.facets.push_back(std::move(facet));
  }
  read_holes_and_regions(s, plc);
  return plc;
}

}  // namespace

std::vector<Point> read_tetgen_points(const std::string& node_path) {
  return read_node_file(node_path, false).points;
}

Plc read_tetgen_node_domain(const std::string& node_path) {
  NodeSection sec = read_node_file(node_path, true);
  Plc plc;
  plc.source = node_path;
  plc.points = std::move(sec.points);
  plc.point_lines = std::move(sec.lines);
  plc.point_markers = std::move(sec.markers);
  return plc;
}

Plc read_tetgen_poly(const std::string& poly_path) {
  // A facet needs at least "1\n3 a b c\n".
  return read_facet_domain(poly_path, 10, [](TextScanner& s, std::size_t f,
                                             std::uint32_t base, std::size_t npts,
                                             PlcFacet& facet) {
    const std::size_t npoly = s.count("the number of polygons", 4);
    const std::size_t nholes = s.has_token() ? s.count("the number of facet holes", 8) : 0;
    if (s.has_token()) facet.marker = s.number<int>("the facet boundary marker");
    s.end_line("the facet header '<#polygons> [<#holes> [<marker>]]'");
    if (npoly == 0) s.fail("a facet needs at least one polygon; remove the empty facet");
    facet.polygons.reserve(npoly);
    for (std::size_t k = 0; k < npoly; ++k) {
      s.require_line("polygon " + std::to_string(k + 1) + " of facet " + std::to_string(f + 1));
      facet.polygons.push_back(read_polygon(s, base, npts));
    }
    facet.holes.reserve(nholes);
    for (std::size_t h = 0; h < nholes; ++h) {
      s.require_line("hole " + std::to_string(h + 1) + " of facet " + std::to_string(f + 1));
      const Point p = read_indexed_point(s, "facet hole");
      s.end_line("the facet hole's coordinates");
      facet.holes.push_back(p);
    }
  });
}

Plc read_tetgen_smesh(const std::string& smesh_path) {
  // A facet line holds at least "1 a\n".
  return read_facet_domain(smesh_path, 4, [](TextScanner& s, std::size_t, std::uint32_t base,
                                             std::size_t npts, PlcFacet& facet) {
    const std::size_t nc = s.count("the number of facet corners", 2);
    if (nc == 0) s.fail("a facet needs at least one corner; remove the empty facet");
    std::vector<std::uint32_t> poly;
    poly.reserve(nc);
    for (std::size_t k = 0; k < nc; ++k)
      poly.push_back(
          to_index(s, s.number<std::int64_t>("a facet corner"), base, npts, "facet corner"));
    if (s.has_token()) facet.marker = s.number<int>("the facet boundary marker");
    s.end_line("the facet's corners and marker");
    facet.polygons.push_back(std::move(poly));
  });
}

}  // namespace pdr::io
