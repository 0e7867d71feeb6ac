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
  const std::string bytes = read_file_bytes(poly_path);
  TextScanner s(bytes, poly_path);
  Plc plc;
  plc.source = poly_path;
  const std::uint32_t base = read_domain_points(s, poly_path, plc);
  const std::size_t npts = plc.points.size();

  // A facet needs at least "1\n3 a b c\n".
  const std::size_t nf = read_facet_header(s, 10);
  plc.facets.reserve(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    s.require_line("facet " + std::to_string(f + 1) + " of " + std::to_string(nf));
    PlcFacet facet;
    facet.line = s.line();
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
      (void)s.number<std::int64_t>("the facet hole index");
      Point p;
      p[0] = s.number<double>("the facet hole's x coordinate");
      p[1] = s.number<double>("the facet hole's y coordinate");
      p[2] = s.number<double>("the facet hole's z coordinate");
      s.end_line("the facet hole's coordinates");
      facet.holes.push_back(p);
    }
    plc.facets.push_back(std::move(facet));
  }
  read_holes_and_regions(s, plc);
  return plc;
}

Plc read_tetgen_smesh(const std::string& smesh_path) {
  const std::string bytes = read_file_bytes(smesh_path);
  TextScanner s(bytes, smesh_path);
  Plc plc;
  plc.source = smesh_path;
  const std::uint32_t base = read_domain_points(s, smesh_path, plc);
  const std::size_t npts = plc.points.size();

  // A facet line holds at least "1 a\n".
  const std::size_t nf = read_facet_header(s, 4);
  plc.facets.reserve(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    s.require_line("facet " + std::to_string(f + 1) + " of " + std::to_string(nf));
    PlcFacet facet;
    facet.line = s.line();
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
    plc.facets.push_back(std::move(facet));
  }
  read_holes_and_regions(s, plc);
  return plc;
}

}  // namespace pdr::io
