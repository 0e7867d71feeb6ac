// Random valid domains OUTSIDE the theory (related components meeting below 90 or above 270
// degrees), for the property of issue #11: `pdr mesh` ends in exit 0 or 3 with a valid,
// Delaunay, conforming mesh, whatever the angles.
//
// Families (each optionally turned by a random rotation, coordinates rounded, so the walls
// are tilted and planar only within the reader's tolerance):
//   - star prisms: a star-shaped polygon of 4..9 corners at random angles and radii,
//     extruded along z by a random height (thin slabs included): acute and reflex corners;
//   - walled star prisms: a star prism cut into regions by facet walls from its axis (the
//     star's centre) to two or more of its corners, read as TetGen reads a .poly (each
//     sector a region, the walls internal facets, three facet sides where a wall meets
//     the caps and the sides);
//   - tees after the paper's Fig. 8(b): a web and a flange whose undersides taper down from
//     the web to the tips, so the web/underside edges are re-entrant above 270 degrees and
//     the tips acute, extruded along z.
// A rotated star prism or tee is, half the time, read back as a surface file of another
// tool would give it: its polygons as faces, coordinates printed with 17, 9 or 7 digits,
// through the surface reader (io/surface.hpp: faces non-planar beyond the tolerance split
// into triangles, near-coplanar ones merged).
// min_corner_deg bounds the corners of the profiles from below (and reflex ones from above
// by 360 - min_corner_deg). With the protecting cylinders (refine/split.hpp) 400 cases at
// 5 degrees end conforming (seed 77); the suite runs 15.
// Shrinking moves the corners, heights and rotations towards simpler values.
#pragma once

#include <rapidcheck.h>

#include <vector>

#include "mesh/plc.hpp"
#include "support/plc_fixtures.hpp"

namespace pdr::test {

// The interior angles (degrees) of a simple counter-clockwise polygon.
std::vector<double> corner_angles(const std::vector<P2d>& polygon);

// A tee profile: web half-width w, web height yj, flange half-width f > w, top y = top,
// tips dropping to yt < yj (re-entrant edges above 270 degrees).
std::vector<P2d> tee_profile(double w, double yj, double f, double top, double yt);

// p turned by the rotation with Euler angles (a, b, c) (radians), rounded to doubles.
Plc rotated(Plc plc, double a, double b, double c);
// p's points as a text file written with printf's %.<digits>g gives them back (an STL or
// OFF writer of another tool: 9 digits for a float, fewer by hand).
Plc printed(Plc plc, int digits);
// plc's facets (one polygon each, no holes) as the faces of a closed surface, through
// io::surface_to_plc; plc itself if a facet has several polygons or holes, or the domain
// has holes or regions.
Plc through_surface(const Plc& plc);

// The prism over a star-shaped profile (about the origin) cut by walls from the axis to the
// corners `walls` (sorted, at least two): caps split into sectors, Enclosure::HolePoints.
Plc walled_prism(const std::vector<P2d>& profile, const std::vector<std::uint32_t>& walls, double z0,
                 double z1);

rc::Gen<Plc> gen_outside_domain(double min_corner_deg);

// A box [-1,2] x [-1,1.5] x [-1,0] whose top has a triangular hole abc (a = (0,0,0),
// b = (1,0,0), c = (cx,0.5,0)) covered by a flap (a, b, v) folded back onto the top across
// ab, v = (vx,-off,h) just above it, and two covers (b, c, v), (c, a, v): the flap meets
// the top at atan(h / off) and the covers meet the flap at about as little. Scanned
// surfaces have such folds where a cap triangle lies upside down on its neighbours (the
// repairs of the subfacets there went below the old repair floor, NOT CONFORMING). The
// top is four facets around the hole, so every segment has two facets.
Plc tucked_flap(double cx, double vx, double off, double h);
// Such flaps, folds of 0.8 to 3 degrees, turned by a random rotation or not.
rc::Gen<Plc> gen_tucked_flap();

// A crumpled top: the box [0,1]^2 x [-0.5,0] whose top is an n x n grid of triangles (each
// cell split along a random diagonal), its inner vertices at heights in [-0.02, 0.02] and,
// with probability `push`, moved past a neighbour by 1 to 1.3 cells and raised, so the top
// folds onto itself; the sides are one polygon each. Many such tops cross themselves
// (build_domain refuses them: callers discard those).
Plc crumpled_top(int n, double push, std::uint32_t seed);

// A spiky star-shaped polyhedron: a latitude-longitude sphere of nlat bands and nlon
// meridians (poles single vertices), its vertices at jittered angles and random radii in
// [rmin, 1] (one radius per direction from the origin, so the surface never crosses
// itself), each quad split along a random diagonal: triangle facets at every angle, sharp
// spikes and pits, acute vertices everywhere.
Plc spiky(int nlat, int nlon, double rmin, std::uint32_t seed);
// Such polyhedra, nlat in [3, 8], nlon in [4, 12], rmin in [0.1, 0.7], turned by a random
// rotation.
rc::Gen<Plc> gen_spiky();

// A torus of n x m planar quads (ring radius 3, tube radius r), each quad given as two
// triangle facets, as a triangulated surface from a CAD or scanning tool writes it: facets
// across each diagonal are coplanar (exactly before a rotation, within rounding after),
// corners of the triangles 7 to 80 degrees, every input vertex acute.
Plc torus_of_triangles(int n, int m, double r);
// Such tori, n in [6, 16], m in [4, 8], r in [0.45, 1.5], turned by a random rotation and
// printed with 17, 9 or 7 significant digits: the triangles of a quad are then coplanar to
// within rounding, within the planarity tolerance (one plane group) or beyond it (two
// facets at a dihedral a hair from 180 degrees).
rc::Gen<Plc> gen_rotated_torus_of_triangles();

// A pyramid over the regular n-gon of circumradius 1, apex at `height` above its centre:
// facets meeting at a sharp apex (every angle there small for a tall one).
Plc pyramid(int n, double height);
// A prism over the regular n-gon of circumradius 1, `height` tall, its top turned by
// `twist` radians in `layers` steps; the sides are triangle facets (two per quad, skinny
// for a large twist, nearly coplanar for a small one), as a CAD tool exports a twisted part.
Plc twisted_prism(int n, double twist, int layers, double height);
// Such pyramids (n in [3, 12], height 0.5 to 20) and twisted prisms (n in [3, 6], twist 0 to
// 1.2, 1 to 8 layers, height 0.5 to 5), half of them turned by a random rotation, and half
// of those read back as a surface file printed with 17, 9 or 7 digits (through_surface).
rc::Gen<Plc> gen_pyramid_or_twisted_prism();

}  // namespace pdr::test
