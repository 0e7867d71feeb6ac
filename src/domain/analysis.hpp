// The domain analysis in one call: validation (domain/validate.hpp), admissibility
// (domain/angles.hpp, paper §1.1) and the distance d (domain/distance.hpp, paper §2.1).
//
// DomainReport: what the analysis found, as a value that can be printed (render_text) or
// serialised (to_json). It holds no reference to the domain: every component it names
// carries its source lines.

#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "domain/angles.hpp"
#include "domain/distance.hpp"
#include "domain/domain.hpp"
#include "mesh/plc.hpp"

namespace pdr::domain {

struct ToleranceFacet {
  std::uint32_t facet = 0;
  std::size_t line = 0;
  double deviation = 0;  // max vertex distance to the fitted plane / facet diameter
};

struct DomainReport {
  std::string source;
  std::size_t input_vertices = 0;       // points in the file
  std::size_t vertices = 0;             // boundary vertices (used by some polygon)
  std::size_t segments = 0;             // after splitting at interior vertices
  std::size_t standalone_segments = 0;  // segments on no facet
  std::size_t facets = 0;               // faces (facets with area)
  std::size_t triangles = 0;            // of the facets' triangulations
  std::size_t shells = 0;               // connected boundary surfaces
  std::size_t voids = 0;                // bounded cells outside Ω (enclosed twice, ...)
  // A facet (and its line) of each void with no volume hole point inside (read by parity,
  // from a surface file): pdr leaves it empty as every void, where TetGen meshes it as a
  // region of its own.
  std::vector<std::pair<std::uint32_t, std::size_t>> unmarked_voids;
  // Each input facet (and its line) of which all or a part bounds no region (voids or the
  // outside on both sides): that part is dropped, as TetGen drops it (PlcDomain::dropped).
  std::vector<std::pair<std::uint32_t, std::size_t>> dropped_facets;
  // A surface file with walls (PlcDomain::surface_walls): every bounded cell is a region.
  bool surface_walls = false;
  std::size_t volume_holes = 0, facet_holes = 0, regions = 0;
  Point bbox_lo{}, bbox_hi{};           // of the boundary vertices
  double planarity_tolerance = 0;
  io::PlanarityTolerance tolerance;     // with the coordinates' inferred precision
  std::vector<ToleranceFacet> tolerance_facets;  // accepted as planar within tolerance
  bool admissible = true;
  std::size_t right_within_tolerance = 0;  // angle tests read as 90° or 270° (angles.hpp)
  std::vector<AngleRecord> violations;
  std::array<AngleStats, angle_kinds> angle_stats{};
  FeatureSize feature;                  // d and the closest unrelated pair
  std::string closest;                  // that pair, in words with source lines
};

DomainReport make_report(const PlcDomain& dom, const Admissibility& adm, const FeatureSize& fs);

// When every violation lies within 1e-4 degrees of 90 or 270 (right angles bent beyond the
// planarity tolerance's reading, domain/angles.hpp): what to do, in words; else empty.
std::string bent_right_angles_hint(const DomainReport& r);

// The violations a report lists (render_text, to_json "violations"): the kListedViolations
// farthest from the admissible range 90..270 degrees, in that order (ties in the order
// found); to_json's "violation_count" counts them all. A triangulated surface violates at
// every corner of every triangle: listing a scanned bust's 300,000 made its summary 37 MB
// and took longer than its analysis.
inline constexpr std::size_t kListedViolations = 100;
std::vector<const AngleRecord*> listed_violations(const DomainReport& r);

// Multi-line human-readable summary, ending with a newline.
std::string render_text(const DomainReport& r);
nlohmann::json to_json(const DomainReport& r);

struct DomainAnalysis {
  PlcDomain domain;
  DomainReport report;
};

// Throws InputError when the PLC is not a valid polyhedral domain. An inadmissible domain
// is not an error: report.admissible is false and report.violations lists why.
DomainAnalysis analyze(const Plc& plc, const PlcOptions& options = {});
DomainReport analyze_domain(const Plc& plc, const PlcOptions& options = {});

}  // namespace pdr::domain
