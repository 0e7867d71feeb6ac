// Sections shared by the TetGen readers (internal to pdr_io): the node section of
// .node/.poly/.smesh files and the hole and region lists that end .poly/.smesh files.
// See tetgen.hpp for the formats and the index-base rule.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/text_scanner.hpp"
#include "mesh/plc.hpp"

namespace pdr::io {

struct NodeSection {
  std::vector<Point> points;
  std::vector<int> markers;              // empty unless the header's marker flag is 1
  std::vector<std::size_t> lines;        // filled when asked for
  std::uint32_t base = 0;                // index of the first point: 0 or 1
  std::size_t header_line = 0;
};

// Reads the node header and its points, positioned before the header line.
NodeSection read_node_section(TextScanner& s, bool keep_lines);

// The node section of a .node file on its own.
NodeSection read_node_file(const std::string& path, bool keep_lines);

// Converts a file index to 0-based, throwing when outside [base, base + n).
std::uint32_t to_index(TextScanner& s, std::int64_t index, std::uint32_t base, std::size_t n,
                       const char* what);

// Reads "<#holes>" + hole lines, then the optional "<#regions>" + region lines, into plc.
// Both lists may be missing at the end of the file.
// Reads "<index> <x> <y> <z>" of a `what` ("hole", "region", "facet hole"); the index
// is ignored, the line is not ended (a region has more fields).
Point read_indexed_point(TextScanner& s, const std::string& what);

void read_holes_and_regions(TextScanner& s, Plc& plc);

// The points of a .poly/.smesh: its own node section, or the sibling .node file when that
// section declares 0 points. Fills plc.points/point_lines/point_markers; returns the base.
std::uint32_t read_domain_points(TextScanner& s, const std::string& path, Plc& plc);

}  // namespace pdr::io
