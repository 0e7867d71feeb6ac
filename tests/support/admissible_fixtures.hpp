// Random ADMISSIBLE domains for the mesher's properties (paper §1.1: related components
// meet at angles of at least 90 degrees; Theorem 1 then promises termination with every
// radius-edge ratio < B = 2), and a TetGen .poly writer to keep shrunk counterexamples in
// tests/regress/.
//
// Domains (coordinates multiples of a random unit, dyadic or not):
//   - voxel solids (tests/support/voxel_fixtures.hpp): unions of boxes on a grid of at most
//     4x4x3 cells, non-convex facets with holes, pinched coplanar facets, enclosed voids, optionally a
//     cubical void of half a cell suspended inside one cell (as data/cube-in-cube.poly);
//   - hexagonal prisms: a rotated regular hexagon (walls tilted in x/y, coordinates not
//     representable, angles 120 degrees) or an integer hexagon (angles >= 90 degrees),
//     extruded along z, alone, standing on a slab (the slab's top facet has a hexagonal
//     hole where the prism's walls meet it), or next to a voxel solid;
//   - walled grids: up to 3x3x3 cubes, each a region, every face a square facet (walls
//     between the cubes; three or four facet sides around their edges), the middle cube
//     of a 3x3x3 grid optionally a void.
// Shrinking removes boxes, shrinks the grid and the unit towards 1, and the kind towards a
// plain voxel solid.
#pragma once

#include <rapidcheck.h>

#include <ostream>
#include <string>

#include "mesh/plc.hpp"

namespace pdr::test {

// rounded_hexagons: also rotated regular hexagons (coordinates not representable).
rc::Gen<Plc> gen_admissible_domain(bool rounded_hexagons = true);

// Admissible domains with one small feature, where the uniform surface mesh of paper
// §2.1 is fine everywhere and the graded one is not (surface/init.hpp): a box with a small
// cubical void, a plate with a small square through-hole, two boxes a small gap apart.
// The feature is 1/2 to 1/64 of the domain's size, at a random place.
rc::Gen<Plc> gen_small_feature_domain();

// The PLC as a TetGen .poly file (1-based, coordinates with 17 significant digits: the
// reader gives back the same doubles), with `comment` as its first line(s).
std::string poly_text(const Plc& plc, const std::string& comment);

}  // namespace pdr::test

namespace pdr {
// How RapidCheck prints a counterexample domain: as its .poly text.
void showValue(const Plc& plc, std::ostream& os);
}  // namespace pdr
