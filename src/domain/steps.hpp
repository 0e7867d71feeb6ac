// The steps of build_domain (domain/validate.hpp), one per source file, and the wording of
// their diagnostics. Internal to src/refine.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "domain/domain.hpp"
#include "mesh/plc.hpp"

namespace pdr::domain::detail {

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

// Step 1 and 2 (domain/build.cpp).
void check_points(const Plc& plc);
std::vector<FacetPolys> check_polygons(const Plc& plc);
// Step 3 (domain/split.cpp); uncertainty: the coordinates' (io/precision.hpp), 0 for exact
// classification.
void split_edges(const Plc& plc, double uncertainty, std::vector<FacetPolys>& polys);
// "1.5e-10": a figure in a diagnostic (domain/coplanar.cpp).
std::string number(double x);
// A face's vertices (its loops, 2-vertex polygons and points), sorted, each once.
std::vector<std::uint32_t> face_vertices(const FacetPolys& fp);
// Step 4a (domain/coplanar.cpp): fills facets[f].plane, .plane_group, .is_face;
// tolerance_facets.
void fit_planes(const std::vector<FacetPolys>& polys, PlcDomain& dom);
// Step 4 (domain/facets.cpp): fills facets[f].tris.
void triangulate_faces(const std::vector<FacetPolys>& polys, PlcDomain& dom);
// Segments, incidences and vertex lists (domain/build.cpp).
void build_structure(const std::vector<FacetPolys>& polys, PlcDomain& dom);
// Step 5 (domain/crossing.cpp).
void check_crossings(const PlcDomain& dom);
// Step 6 (domain/build.cpp); a surface with walls is then read as a .poly without hole
// points (surface_walls).
void check_closed(PlcDomain& dom);
// Cells, orientation and step 7: volume hole and region points (domain/orient.cpp).
void orient_boundary(PlcDomain& dom);

}  // namespace pdr::domain::detail
