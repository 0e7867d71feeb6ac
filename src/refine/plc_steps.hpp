// The steps of build_domain (plc_validate.hpp), one per source file, and the wording of
// their diagnostics. Internal to src/refine.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/plc.hpp"
#include "refine/plc_domain.hpp"

namespace pdr::refine::detail {

// A facet's polygons by kind, after the checks of step 2 (and after splitting, step 3).
struct FacetPolys {
  std::vector<std::vector<std::uint32_t>> loops;      // polygons of >= 3 vertices
  std::vector<std::array<std::uint32_t, 2>> segs;     // 2-vertex polygons (split)
  std::vector<std::uint32_t> points;                  // 1-vertex polygons
  std::vector<std::size_t> loop_index;                // polygon number of each loop
};

// "vertex 7 (line 12)"; "facet 3 (line 40)" (0-based indices into the Plc).
std::string vertex_name(const Plc& plc, std::uint32_t v);
std::string facet_name(const Plc& plc, std::size_t f);
[[noreturn]] void fail(const Plc& plc, std::size_t line, const std::string& message);

// Step 1 and 2 (plc_build.cpp).
void check_points(const Plc& plc);
std::vector<FacetPolys> check_polygons(const Plc& plc);
// Step 3 (plc_split.cpp).
void split_edges(const Plc& plc, std::vector<FacetPolys>& polys);
// Step 4 (plc_facets.cpp): fills facets[f].plane, .tris, .is_face; tolerance_facets.
void triangulate_faces(const std::vector<FacetPolys>& polys, PlcDomain& dom);
// Segments, incidences and vertex lists (plc_build.cpp).
void build_structure(const std::vector<FacetPolys>& polys, PlcDomain& dom);
// Step 5 (plc_crossing.cpp).
void check_crossings(const PlcDomain& dom);
// Step 6 (plc_build.cpp).
void check_closed(const PlcDomain& dom);
// Orientation and step 7 (plc_orient.cpp).
void orient_boundary(PlcDomain& dom);
void check_volume_holes(const PlcDomain& dom);

}  // namespace pdr::refine::detail
