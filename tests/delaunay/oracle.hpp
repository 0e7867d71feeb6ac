// Brute-force oracles for a Delaunay tetrahedralization, in exact arithmetic (GMP, via
// geom/exact.hpp, which shares no code with the adaptive predicates the kernel uses).
// Each returns violations, one line each, starting with the invariant's name; empty =
// holds. Quadratic: for small inputs only.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "delaunay/delaunay.hpp"

namespace pdr::testing {

// Everything below, in one call.
std::vector<std::string> check_all(const Delaunay& dt);

// Every finite tet is positive (exact orient3d).
std::vector<std::string> check_positive(const Delaunay& dt);
// Empty circumsphere, SoS version (hence uniqueness): for every finite tet and every
// vertex q of the triangulation not in it, insphere_sos(tet, q) is Negative; for every
// ghost tet on hull face abc, q is strictly inside (orient3d < 0) or on the plane and
// strictly outside the perturbed circle (incircle3_sos Negative).
std::vector<std::string> check_empty_spheres(const Delaunay& dt);
// The hull faces (ghost tets) form a closed, consistently oriented surface of Euler
// characteristic 2, and the finite tets fill it exactly: the sum of the tets' exact
// volumes equals the volume the hull surface encloses.
std::vector<std::string> check_hull_and_volume(const Delaunay& dt);
// Every point of dt is a vertex of some tet or equals (exactly) one that is.
std::vector<std::string> check_all_points_used(const Delaunay& dt);

// The canonical form of a tetrahedralization: each tet as its four points sorted by
// lex_less, the list sorted. Equal for equal tetrahedralizations, whatever the ids.
using CanonicalTet = std::array<Point, 4>;
std::vector<CanonicalTet> canonical_tets(const Delaunay& dt);

}  // namespace pdr::testing
