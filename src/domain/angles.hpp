// Admissibility of a domain (paper §1.1): "the angle separating any two related components
// in ∂Ω be at least 90°, but no more than 270°".
//
// Related pairs and the angle pdr measures for each (v: the shared vertex, directions are
// unit vectors from v; a facet's cone at v is the set of directions from v into the facet,
// the union of the corner angles at v of its triangles):
//   SegmentSegment   two segments sharing v. The angle between them, measured inside a
//                    facet where one contains both as consecutive segments around v (the
//                    facet-interior sector, 0..360°, e.g. 270° at a re-entrant corner of an
//                    L-shaped face); otherwise the angle between the two directions.
//   FacetFacet       two facets sharing a segment: the dihedral angle through the domain,
//                    0..360°, measured for each wedge of Ω between consecutive facet sides
//                    around the segment (two sides for a manifold edge; 4, 6, ... sides
//                    give one angle per inside wedge). The sides come from the triangles of
//                    the facets on the segment.
//   FacetSegment     a facet and a segment sharing v, the segment not in the facet: the
//                    smallest angle between the segment's direction and the facet's cone
//                    (the elevation over the facet when the segment's projection falls in
//                    the cone, else the angle to the nearest boundary ray), 0..180°.
//   FacetFacetVertex two facets sharing v but no segment at v: the smallest angle between
//                    their cones (attained at a boundary ray of one of them), 0..180°.
// A pair is admissible iff its angle is in [90°, 270°]. An angle measured from one side
// (a sector or a dihedral, 0..360°) is in [90°, 270°] iff the unsigned angle between its
// two bounding directions is at least 90°; an angle defined as a minimum over directions
// (0..180°) is at least 90° iff no direction of one makes an acute angle with a direction
// of the other. Both are dot-product signs:
//   SegmentSegment   (a-v).(b-v) <= 0;
//   FacetFacet       (u x (w1-p)).(u x (w2-p)) <= 0 (cosine of the dihedral, u = q - p);
//   FacetSegment     (w-v).(g-v) <= 0 for every generator g of the cone (the far corners
//                    at v of the facet's triangles: the cone is their nonnegative span);
//   FacetFacetVertex (g-v).(h-v) <= 0 for all generators g, h of the two cones.
// Why this matches the paper: Lemma 1 relies on "the angle bounds" so that a new vertex on
// one component (a subsegment midpoint, a subfacet circumcenter) never encroaches upon a
// subsegment or subfacet of a related component. The tetrahedralization covers both sides
// of the boundary until exterior tetrahedra are removed (§2.1 step 3), so an acute angle on
// either side of two related components breaks that argument: hence the symmetric range
// [90°, 270°], reported as measured through the domain.
// These signs are exact (domain/exact.hpp), so 90° and 270° are classified exactly; the
// reported degrees are floating point (a report, not a decision). For a facet planar only
// within tolerance, the cone is that of its triangles.
// Input given in floating point bends right angles: a box rotated by a random rotation has
// angles a few ulps below 90°, and one printed with 9 significant digits a few 1e-9
// radians. The planarity tolerance (PlcOptions::planarity_tolerance, relative, 1e-9 by
// default, the one that accepts facets planar within rounding) also classifies these: it
// admits vertices known to delta = tol times the domain's diameter, or to the uncertainty of
// the coordinates' digits (io/precision.hpp) when that is more, and an angle whose exact
// cosine is positive but which moving its points (the vertex too) by at most delta opens to
// 90° (or 270°), to first order and by at most 1e-3 radians, is the right angle the input
// means, counted in Admissibility::tolerated (the bound is in angles.cpp). It classifies
// the input; the mesher never sees it.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "domain/domain.hpp"

namespace pdr::domain {

enum class AngleKind : std::uint8_t { SegmentSegment, FacetFacet, FacetSegment, FacetFacetVertex };
inline constexpr int angle_kinds = 4;
const char* angle_kind_name(AngleKind k);

struct AngleRecord {
  AngleKind kind = AngleKind::SegmentSegment;
  double degrees = 0;
  bool in_facet = false;                 // SegmentSegment measured inside facets[0]
  std::int64_t vertex = -1;              // the shared vertex; -1 for FacetFacet
  std::vector<std::array<std::uint32_t, 2>> segments;  // endpoints (a < b) of the segments
  std::vector<std::uint32_t> facets;     // facet indices (into Plc::facets)
  // Source lines, for reports: of the vertex, of the segments' ends, of the facets.
  std::size_t vertex_line = 0;
  std::vector<std::array<std::size_t, 2>> segment_lines;
  std::vector<std::size_t> facet_lines;
};

struct AngleStats {
  std::size_t pairs = 0;
  double min_degrees = std::numeric_limits<double>::infinity();
  double max_degrees = -std::numeric_limits<double>::infinity();
};

struct Admissibility {
  bool admissible = true;
  std::size_t tolerated = 0;  // signs taken as right angles within the tolerance
  std::vector<AngleRecord> violations;
  std::array<AngleStats, angle_kinds> stats{};  // indexed by AngleKind
};

Admissibility check_admissibility(const PlcDomain& dom);

// The angle classification's rule, for others that read right angles bent by rounding
// (refine/axis_zones.hpp): how far a vertex of dom is known to lie from where the input
// means it (delta above), and how far moving the vertex and the ends of two edges of
// lengths lx and ly by delta opens the angle between them, to first order and at most
// 1e-3 radians: an angle that close to 90 degrees is the right angle the input means.
double positional_uncertainty(const PlcDomain& dom);
double right_angle_opening(double lx, double ly, double delta);

}  // namespace pdr::domain
