// PlcDomain: a validated polyhedral domain and its related components (paper §1.1).
//
// build_domain (domain/validate.hpp) turns a Plc into this structure or throws InputError.
// What a PlcDomain guarantees:
//   - vertices are pairwise distinct; every facet with a polygon of >= 3 vertices (a
//     "face") is planar, exactly or within the documented tolerance (domain/plane.hpp);
//   - segments are the edges of the facets' polygons, plus the 2-vertex polygons, each
//     split at every input vertex lying in its interior (so collinear overlapping edges
//     share their common pieces), unique and undirected (a < b);
//   - each face is triangulated (triangles with input vertices as corners, conforming to
//     its segments, holes removed): the facet "as the kernel sees it";
//   - every input vertex is a component: a node that no facet lists is an isolated vertex,
//     as a 1-vertex polygon is (TetGen inserts such nodes of a .poly too; the surface
//     readers list only the vertices their faces use);
//   - components meet only in shared vertices and segments (no crossing facets, segments
//     or stray vertices);
//   - every segment bounds at least two facet sides (a segment inside a face counts as
//     two), except, read as TetGen reads a .poly, a free edge of a facet inside the domain
//     (a crack, a baffle, a window in a wall: one side, the domain all round it). The facets cut space into cells (domain/orient.cpp); the domain is, by
//     plc.enclosure: the points from which a ray crosses the boundary an odd number of
//     times (every segment then bounds an even number of sides, so the boundary is closed
//     mod 2; voids are even); or, TetGen's reading, every bounded cell in which no volume
//     hole point lies, so that a closed shell inside another, or a facet wall splitting a
//     region, bounds a second region, and its facets are internal (`separates` false,
//     both sides in Ω);
//   - a facet, or a part of one, with no domain on either side (two voids, or a void and
//     the outside) is dropped (`dropped`), as TetGen drops it, with the segments only it
//     held (`dropped_segments`); the domain is never empty;
//   - every triangle knows which of its sides faces the domain (`inward`; both do on an
//     internal facet, which then reads +1), and the facet sides around each segment are
//     sorted by angle with the inside wedges marked;
//   - volume hole points lie in bounded cells, off every facet, and by parity in a void
//     (even); region points lie inside the domain, off every facet.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "domain/plane.hpp"
#include "io/precision.hpp"
#include "mesh/plc.hpp"

namespace pdr::domain {

// Parameters of the domain analysis (docs/design.md §14: one small struct, by value).
struct PlcOptions {
  // Relative planarity tolerance (domain/plane.hpp). Classification only; 0: exact
  // classification, and no uncertainty of the coordinates inferred (io/precision.hpp).
  double planarity_tolerance = 1e-9;
};

struct FacetTri {
  std::array<std::uint32_t, 3> v{};             // global vertex ids, counter-clockwise in
                                                // the facet's projection
  std::array<std::int32_t, 3> nbr{-1, -1, -1};  // triangle of this facet across the edge
                                                // opposite v[i]; -1 if none
  std::array<bool, 3> on_segment{};             // that edge is a segment
  std::int8_t inward = 0;  // +1: the domain is on the side (v1-v0)x(v2-v0) points to
};

struct DomainFacet {
  bool is_face = false;                 // has a polygon of >= 3 vertices
  FacetPlane plane;                     // valid when is_face; the face's own
  std::uint32_t plane_group = 0;        // smallest face of its coplanar group (itself when
                                        // alone): faces across an edge coplanar within the
                                        // planarity tolerance (domain/coplanar.cpp)
  std::vector<std::uint32_t> vertices;  // sorted ids: corners of tris, and 1-vertex polygons
  std::vector<FacetTri> tris;           // the facet's region (empty unless is_face)
  std::vector<std::uint32_t> segments;  // sorted ids of the segments the facet contains
  int shell = -1;                       // connected component of the boundary surface
  std::array<int, 2> cells{-1, -1};     // the cells on its front (where its triangles'
                                        // normals point) and back; -1: the unbounded one
  bool separates = true;                // Ω lies on one side only (else an internal facet
                                        // between two regions, both in Ω)
  std::int64_t part_of = -1;            // a part of that input facet, whose parts bound
                                        // different cells (domain/orient.cpp); -1: whole
};

// One side of a face along a segment: the triangle of that face on the segment.
struct HalfFacet {
  std::uint32_t facet = 0;
  std::uint32_t tri = 0;      // index into facets[facet].tris
  std::uint32_t apex = 0;     // the triangle's vertex off the segment
  std::int8_t dir = 0;        // +1 when the triangle runs a->b (its normal then points to
                              // the positive rotation about a->b), -1 for b->a
  std::int8_t inside_after = 0;  // +1 when the wedge from this side to the next one, turning
                                 // positively about a->b, lies inside the domain
};

struct DomainSegment {
  std::uint32_t a = 0, b = 0;           // a < b
  std::vector<HalfFacet> sides;         // sorted by angle about a->b (cyclic)
  std::vector<std::uint32_t> facets;    // distinct facets containing the segment, sorted
};

struct PlcDomain {
  Plc plc;                                           // the input, as given
  PlcOptions options;
  // The planarity classification: options.planarity_tolerance with the uncertainty of the
  // coordinates inferred from their values (io/precision.hpp; none when the tolerance is 0).
  io::PlanarityTolerance tolerance;
  std::vector<DomainFacet> facets;                   // parallel to plc.facets
  std::vector<DomainSegment> segments;               // sorted by (a, b)
  std::vector<std::vector<std::uint32_t>> vertex_segments;  // per vertex, sorted
  std::vector<std::vector<std::uint32_t>> vertex_facets;    // faces containing it, sorted
  std::size_t shells = 0;                            // connected boundary surfaces
  // Cells (domain/orient.cpp): the bounded open regions the facets cut space into.
  std::size_t cells = 0;
  std::vector<std::uint8_t> cell_inside;             // per cell: in Ω
  std::vector<std::uint8_t> cell_holes;              // per cell: volume hole points in it
                                                     // (saturating at 255)
  std::vector<std::uint32_t> tolerance_facets;       // faces planar only within tolerance
  // Facets, or parts of them, with no domain on either side (between voids, or a void and
  // the outside; domain/orient.cpp): dropped, as TetGen drops them. Their records stay in
  // `facets` with no triangles, vertices or segments (is_face false), and a segment that
  // only they held is gone from `segments`. Input vertex ids.
  struct Dropped {
    std::uint32_t facet = 0;                           // the input facet (part_of of a part)
    std::vector<std::array<std::uint32_t, 3>> tris;    // its dropped triangles
  };
  std::vector<Dropped> dropped;
  std::vector<std::array<std::uint32_t, 2>> dropped_segments;
  std::vector<std::uint32_t> outside_vertices;  // isolated ones in a void or outside Ω
  // Read from a surface file with walls (an edge of three or more faces): parity misreads
  // such a surface, and every bounded cell is a region, as TetGen reads it (plc.enclosure
  // is then HolePoints).
  bool surface_walls = false;

  std::optional<std::uint32_t> find_segment(std::uint32_t a, std::uint32_t b) const;
  std::size_t face_count() const;
  std::size_t vertex_count() const { return plc.points.size(); }  // every one a component
};

}  // namespace pdr::domain
