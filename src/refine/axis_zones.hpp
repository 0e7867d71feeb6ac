// Rotation copies around sharp axes: conformity between facets that meet along one segment
// at sharp dihedrals (issue #11; outside the theory).
//
// Facets F and G contain segment s (the axis) and meet along it at the angle theta (a
// dihedral below arccos(1/3), or several walls around s: refine/split.hpp's protecting
// cylinders). A vertex inserted on F near s can lie in the equatorial ball of a subfacet of
// G, which then leaves T; its repair puts a vertex on G that does the same to F, and at a
// small theta this cascade goes down towards s without end (walls of a star prism around its
// axis: an edge of 2.5e-32 after 60,000 vertices).
//
// The identity that stops it. Let x be a point of G's half-plane at distance r from s's
// line, y a point of the same half-plane at signed distance r_y (positive on G's side), and
// R(x) x turned about the line by theta onto F. Then
//     |R(x) - y|^2 = |x - y|^2 + 2 r r_y (1 - cos theta),
// so R(x) is strictly farther from y than x whenever r > 0, r_y > 0 and theta != 0. Take y
// the centre of a subfacet g of G (its equatorial ball is centred on G's plane) and x a
// vertex of G: x is not inside g's circle (G's triangulation is Delaunay in its plane), so
// R(x) is not inside g's equatorial ball. (A wall of several facets is triangulated facet
// by facet, so a vertex x of another facet of G's wall can lie in g's circle; but then x
// is already in g's equatorial ball, and g is out of T, or encroached, with or without
// copies: the copies add nothing there.) Hence, if every vertex inserted on a wall within
// the zone of s is inserted together with its copies R(x) on every other wall of s (same
// distance along s, same distance from it), no vertex of such a set encroaches a subfacet
// of another wall whose centre lies on that wall's side of s; a centre on s or beyond it
// means the subfacet's axis edge is encroached in its own plane, which Fig. 2 splits (the
// axis, shared by every wall, splits symmetrically). What can still encroach across walls
// is a vertex without copies (the initial surface mesh, a copy that fell outside its
// facet near the ends of s, points beyond the zone): a vertex x' of G at distance
// delta from F encroaches only subfacets of F of circumradius above about delta, so the
// refinement it causes stops at that size instead of going down to s. The copies are
// inserted with Fig. 2's rule for facet vertices (one that encroaches a subsegment splits
// it first) and are not held by the protected lengths (a repair is not).
// Only conformity repairs below the protected length get copies (refine/seq_refinement.cpp):
// they are what cascades. Every other vertex is held by the protected lengths, so what it
// causes is bounded as any refinement above them, and copies of it only left tets next to
// sharp edges unrefined (of every vertex: the tee of guard_test; of every repair: 2 tets
// on the paper's tee at V = 0.008). Every facet vertex in a zone goes to the zone's grid
// (place), copies or not.
// The zone of s is its protecting cylinder (refine/split.hpp: radius kCylinderFraction times
// the local feature size of s, capped by the element size), between its two ends, and a
// zone is kept only where every wall holds the whole strip along s (no other segment of
// the wall leaves an end of s at an acute angle on that side): the argument needs every
// copy to exist. A wall is the coplanar group of a facet through s (domain/coplanar.cpp):
// a side given as two triangles holds the strip as the quadrilateral does, the edge
// between them being no boundary of it (a thin slot whose walls are triangle pairs ended
// NOT CONFORMING when each triangle was a wall of its own, since the triangle through s
// never holds the strip; tests/regress/outside-notch-3-degrees-triangle-walls-*). A point
// of the wall keeps its own facet's plane; its copies go on the plane of the facet through
// s, and, when the group lies exactly on one plane, into whichever facet of the group
// holds them. A group coplanar only within the tolerance drops the copies outside the
// facet through s: placed on the other facets' planes, a few 1e-10 radians apart, they
// left flat tets along the crease of a rotated star prism printed with 9 digits.
// A lone triangle facet never holds the strip; on a scanned surface folded to dihedrals of
// one degree (a public test model, cheburashka), zones of triangle walls made copies that
// skipped most walls and cascaded to the vertex cap (400,000 vertices in 17 s, where plain
// repairs end at 220,000). Floating point says where the copies go (place_on_facet puts
// them on the facet's plane); exact predicates decide everything about them.
#pragma once

#include <cstdint>
#include <vector>

#include "geom/point.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::refine {

class AxisZones {
 public:
  AxisZones() = default;
  // cylinders: per segment of m, the protecting cylinder's radius (0: none), capped by `cap`;
  // uncertainty: how far an input vertex may lie from where the input means it (0: exact).
  AxisZones(const surface::SurfaceMesh& m, const std::vector<double>& cylinders, double cap,
            double uncertainty = 0);

  struct Copy {
    std::uint32_t facet = 0;
    Point p{};
    std::uint32_t axis = 0;  // the segment of the zone
  };
  // Where point p of facet f goes, and its copies: for the first zone of f holding p, p's
  // distances along and from the axis rounded to the zone's grid (kGridBits below its
  // radius), placed on f (`own`) and turned onto every other wall (`copies`). Empty copies
  // and own == p when p lies in no zone of f.
  struct Placed {
    Point own{};
    std::vector<Copy> copies;
  };
  Placed place(const surface::SurfaceMesh& m, std::uint32_t f, const Point& p) const;
  // The grid makes the copies of one point the same doubles whichever wall it was found
  // on: the walls' triangulations are then the same up to the rotation, and a subfacet of
  // one wall whose circumcenter is (up to rounding) a copy's lands on that very vertex
  // instead of ulps from it.
  static constexpr int kGridBits = 30;
  bool empty() const { return zones_.empty(); }
  // The facets of f's wall, f among them: its coplanar group (domain/coplanar.cpp).
  // Precondition: f is a face of the mesh the zones were built for.
  const std::vector<std::uint32_t>& wall(std::uint32_t f) const;
  // Whether f's wall lies exactly on one plane: copies then go into any of its facets;
  // else only into the facet through the axis (refine/seq_refinement.cpp insert_copy).
  bool exact_wall(std::uint32_t f) const;

 private:
  struct Wall {
    std::uint32_t facet = 0;
    Point e{};  // unit, in the facet's plane, perpendicular to the axis, into the facet
  };
  struct Zone {
    std::uint32_t segment = 0;
    Point a{}, u{};  // the axis: its end a and unit direction
    double length = 0, radius = 0;
    std::vector<Wall> walls;  // one per side of a facet containing the axis
  };
  std::vector<Zone> zones_;
  std::vector<std::vector<std::uint32_t>> facet_zones_;  // per facet: zones it is a wall of
  std::vector<std::uint32_t> group_;                     // per facet: its wall's first facet
  std::vector<std::vector<std::uint32_t>> walls_of_;     // per wall's first facet: its facets
  std::vector<std::uint8_t> exact_;                      // per wall's first facet: one plane
};

}  // namespace pdr::refine
