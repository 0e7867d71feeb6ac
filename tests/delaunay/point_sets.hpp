// Point sets for the Delaunay tests: random, and deliberately degenerate (grids,
// cospherical, coplanar hull facets, duplicates). Deterministic for a given seed.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "geom/point.hpp"

namespace pdr::testing {

// n points uniform in [0,1)^3.
std::vector<Point> random_cube(std::size_t n, std::uint64_t seed);
// The k x k x k integer grid {0..k-1}^3 (every cube of 8 points cospherical).
std::vector<Point> grid(int k);
// All integer points with x^2 + y^2 + z^2 == r2: exactly on one sphere, all on the hull.
std::vector<Point> sphere_lattice(int r2);
// The integer points on the surface of the cube [0,k]^3 (large coplanar hull facets),
// plus `interior` random interior points with coordinates in multiples of 1/4.
std::vector<Point> cube_surface(int k, std::size_t interior, std::uint64_t seed);
// `pts` with `copies` random points repeated (exact copies), then shuffled.
std::vector<Point> with_duplicates(std::vector<Point> pts, std::size_t copies,
                                   std::uint64_t seed);
// A permutation of pts by the given seed.
std::vector<Point> shuffled(std::vector<Point> pts, std::uint64_t seed);

// Reads a TetGen .node file (points only; attributes and markers ignored). Throws
// std::runtime_error on malformed input. For the regression corpus (tests/regress).
std::vector<Point> read_node_file(const std::string& path);

}  // namespace pdr::testing
