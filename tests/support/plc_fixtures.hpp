// Domains for the tests of the domain analysis (paper §1.1, §2.1): PLCs built in code,
// with fake but distinct source lines so that diagnostics can be checked, and the files
// under data/.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "domain/domain.hpp"
#include "mesh/plc.hpp"

namespace pdr::test {

using Poly = std::vector<std::uint32_t>;
using FacetSpec = std::vector<Poly>;
using P2d = std::array<double, 2>;

// Source "test.poly"; vertex i has line 100 + i, facet f line 200 + f, volume hole h line
// 300 + h (call relabel() after editing a Plc by hand).
inline constexpr std::size_t kPointLine = 100, kFacetLine = 200, kHoleLine = 300;
void relabel(Plc& plc);
Plc make_plc(std::vector<Point> points, std::vector<FacetSpec> facets,
             std::vector<Point> holes = {});
Plc box(const Point& lo, const Point& hi);
// A prism over a simple polygon in the xy plane (any orientation), z in [z0, z1]: facet 0
// the bottom cap, 1 the top cap, 2 + i the wall over profile edge i -> i+1.
Plc prism(const std::vector<P2d>& profile, double z0, double z1);
// The box [0,n]x[0,1]x[0,1] cut into n unit cubes by walls, read as TetGen reads a .poly
// (Enclosure::HolePoints: each cube a region): facet i (0 <= i <= n) is the square at x = i
// (walls for 0 < i < n), then per cube i the bottom, top, front (y = 0) and back (y = 1),
// facets n + 1 + 4i ... n + 4 + 4i.
Plc walled_box(std::uint32_t n);
// Disjoint union: b's vertices are renumbered after a's, holes concatenated.
Plc merge(const Plc& a, const Plc& b);
// A file of data/ read by the TetGen reader.
Plc read_data(const std::string& name);
// build_domain's InputError message, or "" when the PLC is accepted.
std::string error_of(const Plc& plc, const domain::PlcOptions& options = {});

}  // namespace pdr::test
