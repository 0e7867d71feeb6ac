// Per-tet fields of a report, for a visual inspection of the offenders (ParaView):
// `pdr check --vtu OUT.vtu` writes them as VTK cell data.
//
//   ratio           R / lmin of each tet (display only: floating point where every
//                   coordinate difference is in the filters' range, else from the exact
//                   rationals, rounded; NaN for a tet with invalid indices or zero volume)
//   failed_checks   how many failed checks name the tet
//   fail:<id>       1 where check <id> names the tet, else 0; one field per failed check
//                   that names at least one tet
//
// A finding names the tets it is about: kind "tet" its own id; "face"/"subfacet" the tets
// having its first three vertices as a face; "edge"/"subsegment" the tets having its first
// two vertices; "vertex" the tets having its last vertex. Other kinds (segment, facet,
// hole, region) name no tet. Only the findings in the report are seen: for complete
// fields, run check_mesh with Options::max_reported at least the number of tets.
#pragma once

#include <string>
#include <vector>

#include "check/check.hpp"

namespace pdr::check {

struct TetField {
  std::string name;
  std::vector<double> values;  // one per tet
};

std::vector<TetField> tet_fields(const MeshView& mesh, const Report& report);

// Display measures of one tet, valid for any finite coordinates: in floating point when
// every coordinate difference is in the filters' range (signs::entry_in_range), else
// computed exactly and rounded once (a tet with edges of 1e-110 gets its true ratio, not
// an underflowed one). Precondition: the tet is not flat (exact orient3d != 0).
struct TetMeasures {
  Point circumcenter{};
  double circumradius = 0;
  double shortest_edge = 0;
  double ratio = 0;  // circumradius / shortest_edge
};
TetMeasures tet_measures(const Point& a, const Point& b, const Point& c, const Point& d);

// The tets a finding names (rules above), sorted, without duplicates. `incident` lists
// the tets of each vertex (as vertex_tets returns).
std::vector<std::uint64_t> tets_named_by(const Finding& f,
                                         const std::vector<std::vector<std::uint32_t>>& incident,
                                         const MeshView& mesh);
std::vector<std::vector<std::uint32_t>> vertex_tets(const MeshView& mesh);

}  // namespace pdr::check
