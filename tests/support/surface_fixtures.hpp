// Domains and helpers for the surface mesh tests (paper §2.1 steps 1-2): a RapidCheck
// generator of random admissible box-union domains (disjoint boxes, boxes with a void,
// orthogonal "skyline" prisms, unions of those), a facet with a square grid of isolated
// vertices (cocircular everywhere), a box rotated about z (tilted facets, constructed
// points a few ulps off their planes), and a brute-force SoS Delaunay oracle for a facet.
#pragma once

#include <rapidcheck.h>

#include <array>
#include <set>
#include <string>
#include <vector>

#include "domain/analysis.hpp"
#include "mesh/plc.hpp"
#include "surface/audit.hpp"
#include "surface/init.hpp"

namespace pdr::test {

// A random admissible domain whose coordinates are multiples of a random unit (dyadic or
// not), every unrelated pair at least one unit apart and at most ~8 units across.
rc::Gen<Plc> gen_box_union();

// The box [0,n]x[0,n]x[0,1] whose bottom facet also lists the interior grid points
// (i, j), 0 < i, j < n, as isolated vertices (1-vertex polygons): every grid square is
// cocircular.
Plc grid_facet_box(int n);

// A square frame (genus one): [0,4]^2 x [0,1] minus the hole [1.5,2.5]^2 x [0,1]; the caps
// are facets with two polygons and a facet hole point.
Plc frame_box();

// The box [0,3]x[0,2]x[0,1] whose top facet also holds the segment (1,1,1)-(2,1,1) as a
// 2-vertex polygon (an interior segment: the facet lies on both of its sides).
Plc box_with_interior_segment();

// The box [0,a]x[0,b]x[0,c] rotated about the z axis by the angle with cosine 3/5 (as
// doubles: the walls stay exactly vertical, hence exactly planar, but tilted).
Plc rotated_box(double a, double b, double c);

// The box [0,a]x[0,b]x[0,c] rotated by generic angles about z and x and translated, in
// double: no facet is axis-parallel and most are planar only within tolerance.
Plc tumbled_box(double a, double b, double c);

// "surface.x: ..." lines, for failure messages.
std::string describe(const surface::SurfaceAudit& a);

// Every triangle of the given vertices that is Delaunay under incircle3_sos (no other
// vertex inside its perturbed circle), as sorted triples. Precondition: the points are
// coplanar and in convex position with respect to the facet (the facet is convex).
std::set<std::array<std::uint32_t, 3>> brute_sos_delaunay(const std::vector<Point>& pts,
                                                          const std::vector<std::uint32_t>& ids);

// The live subfacets of facet f as sorted triples.
std::set<std::array<std::uint32_t, 3>> facet_triples(const surface::SurfaceMesh& m, std::uint32_t f);

}  // namespace pdr::test
