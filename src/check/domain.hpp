// DomainMap: the input domain (paper §1.1) as seen in a mesh. Which mesh vertex each input
// vertex is; which mesh vertices lie on each segment, in order (they define its
// subsegments); which mesh faces lie in each facet (its subfacets).
//
// Input classification, the only tolerance in pdr_check. Meshers compute vertices on
// tilted segments and facets in floating point, so they are rarely exactly collinear or
// coplanar with the input. A mesh vertex p counts as on the line of segment AB if it is
// exactly collinear, or if dist(p, line AB) <= tol * |AB| + r; on the plane of an exactly
// planar facet F (all its vertices on the plane of a spanning triple a, b, c) if it is
// exactly coplanar with a, b, c, or if dist(p, plane abc) <= tol * diam(F) + r; on a facet
// planar only within tolerance if dist(p, P) <= tol' * diam(F) + r, P the least-squares
// plane of F's distinct vertices (diam: the diagonal of F's bounding box; for a domain
// written with fewer digits, max(tol' diam(F), 32 u), u = Options::coordinate_uncertainty), tol =
// Options::relative_tolerance, tol' = Options::inexact_facet_tolerance, r = 4 ulps of the
// largest coordinate of AB (of F's box): the rounding of a vertex computed there, which
// far from the origin exceeds tol |AB| (tol = 0: exact only, no r either). A facet planar
// within T (pdr mesh's classification) has its vertices within T diam(F) of P, and so,
// the slab being convex, its whole hull; pdr mesh puts new vertices on the plane of three
// of them, within 7T diam(F) of P over the facet (surface/chart.hpp), and tol' = 8T
// accepts them. (The plane through three corners of a quad whose corners deviate
// alternately by +-h lies 4h off the fourth corner, 3h off P there: no plane of a triple
// serves as the reference for such a facet.)
// The distances are computed in double (this classifies input; it decides nothing about
// the mesh). Everything after the classification is exact: the order of vertices along a
// segment, whether they lie between its ends, face centroids in the facet region, areas.
// How many vertices needed the tolerance is reported ("tolerance_vertices").
// A mesh face lies in facet F if its three vertices are on F's plane and in F's closed
// region, and its centroid lies inside the region (facet_region.hpp). In a conforming mesh
// no face straddles a segment, so the centroid decides for a face in the facet; the corners
// keep out the faces of a sliver across a segment between two facets a hair from coplanar
// (each corner within tolerance of both planes), which would otherwise stack on F's
// subfacets and count twice. Facets meet only along their boundaries, so a face lies in at
// most one: when several facets take it (the two walls of a thin notch near its edge, each
// within the other's tolerance and region there), it counts in the one whose plane (P, or
// abc) lies nearest its farthest corner; a face claimed wrongly leaves that facet covered
// more and its own less, which the exact areas still see. F's region is built from its polygons with the
// mesh vertices found on each edge inserted in order: when the tolerance was needed, the
// mesh faces tile that polygon exactly (and not the input one), so areas still compare
// exactly; with exact vertices the two polygons coincide.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "check/check.hpp"
#include "check/facet_region.hpp"
#include "check/grid.hpp"
#include "check/topology.hpp"

namespace pdr::check {

// Dropped: a segment the domain analysis dropped whose ends the mesher left out.
enum class ItemStatus : std::uint8_t { Ok, MissingVertex, Degenerate, NonPlanar, Unsupported, Dropped };

struct SegmentMap {
  std::uint32_t a = 0, b = 0;              // input vertex ids
  ItemStatus status = ItemStatus::Ok;
  std::vector<std::uint32_t> vertices;     // mesh vertices on it, from a to b
  std::vector<std::uint8_t> dropped;       // per pair of consecutive vertices: a dropped
                                           // piece (Options::dropped_segments); empty: none
  std::uint64_t tolerance_vertices = 0;    // of those, not exactly collinear
};

struct FacetMap {
  ItemStatus status = ItemStatus::Ok;
  std::optional<FacetRegion> region;       // when status is Ok
  int drop = 2;                            // coordinate dropped by the projection
  std::vector<std::uint32_t> on_plane;     // mesh vertices on its plane (sorted)
  std::vector<std::uint32_t> faces;        // topology face ids lying in the facet
  std::vector<std::vector<P2>> dropped;    // its dropped triangles (Options::dropped_tris),
                                           // projected through the mesh vertices on their
                                           // segment edges: faces there are not in the facet
  std::uint64_t tolerance_vertices = 0;    // on_plane vertices not exactly coplanar
  std::uint64_t ambiguous_faces = 0;       // on-plane faces with a centroid on an edge
  Point plane_origin{};                    // the plane its vertices are measured against,
  std::array<double, 3> plane_normal{};    // unit normal: a face that several facets would
                                           // take goes to the one it lies nearest
};

struct DomainMap {
  std::vector<std::optional<std::uint32_t>> mesh_vertex;  // of each input vertex
  std::vector<SegmentMap> segments;                        // distinct polygon edges
  std::vector<FacetMap> facets;                            // one per input facet
  std::vector<std::uint8_t> face_in_facet;                 // per topology face
  std::vector<std::uint32_t> subfacets;                    // distinct faces in facets
};

// Preconditions: the mesh passed validity.indices and validity.coordinates.
DomainMap map_domain(const Plc& domain, const MeshView& mesh, const Topology& topo,
                     const PointGrid& grid, const Options& options);

// The 2D projection used for a facet: drop coordinate `drop`, keep the next two cyclically.
inline P2 project(const Point& p, int drop) {
  return {p[(drop + 1) % 3], p[(drop + 2) % 3]};
}

}  // namespace pdr::check
