// Plc: a piecewise linear complex, the input domain of paper §1.1, as read from
// TetGen .poly/.smesh: vertices, planar polygonal facets (each a set of polygons, which
// may include segments of two vertices and isolated points, plus facet holes), volume
// holes (voids and cavities are marked by a point inside them) and regional attributes.
// Line numbers are kept so validation can report file:line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geom/point.hpp"

namespace pdr {

struct PlcFacet {
  std::vector<std::vector<std::uint32_t>> polygons;  // 0-based vertex indices
  std::vector<Point> holes;                          // points in the facet's plane
  int marker = 0;
  std::size_t line = 0;                              // source line of the facet header
};

struct PlcRegion {
  Point point{};
  double attribute = 0;
  double max_volume = -1;  // negative: no constraint
  std::size_t line = 0;
};

// Which cells of the boundary's complement are in the domain.
enum class Enclosure : std::uint8_t {
  Parity,      // those enclosed by an odd number of closed shells: a shell inside another
               // bounds a void (surface formats: a hollow part's inner surface)
  HolePoints,  // every bounded cell unless a volume hole point lies in it: a shell inside
               // another bounds a second region (TetGen's reading of a .poly or .smesh)
};

// How precisely a domain's coordinates are given (io/precision.hpp infers it from their
// values).
struct CoordinatePrecision {
  int digits = 0;          // the most significant digits of a coordinate; 0: not inferred
  bool float32 = false;    // every coordinate a float, and more than 9 digits
  double uncertainty = 0;  // how far rounding may have moved a vertex (absolute); 0: exact
};

struct Plc {
  std::string source;                  // file name, for diagnostics
  Enclosure enclosure = Enclosure::Parity;
  std::vector<Point> points;
  std::vector<std::size_t> point_lines;  // source line of each point
  std::vector<int> point_markers;      // empty or points.size()
  std::vector<PlcFacet> facets;
  std::vector<Point> holes;            // volume holes
  std::vector<std::size_t> hole_lines;
  std::vector<PlcRegion> regions;
  // How precisely the file gives the coordinates, as a surface reader inferred it from
  // every point a face uses before merging faces; digits 0: not inferred here (the domain
  // analysis infers it from `points`, which a surface's merged facets leave fewer of).
  CoordinatePrecision precision;
};

}  // namespace pdr
