// explain_tet: one tet described in full, for `pdr check --explain T` and for tests.
//
// Where the report gives the first offenders of each check, this gives everything about
// one tet T: its vertices and their coordinates, its exact orientation, its circumcenter
// and circumradius, its shortest edge, its radius-edge ratio and the exact verdict
// R^2 < B^2 lmin^2 (Theorem 1 (2)), every vertex strictly inside or on its circumsphere
// (all vertices of the mesh, exact insphere times the exact orientation, as
// delaunay.empty_sphere decides), and every finding of the report that names T.
// Coordinates, radii and ratios are floating-point constructions (display only); every
// verdict is an exact sign. Cost: O(#points) predicates plus a few GMP operations.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "check/check.hpp"

namespace pdr::check {

struct TetExplanation {
  std::uint64_t tet = 0;
  bool indices_valid = false;  // all four indices < #points (else nothing else is filled)
  Tet vertices{};
  std::array<Point, 4> points{};
  Sign orientation = Sign::Zero;           // exact orient3d as recorded
  std::optional<Point> circumcenter;       // absent for a zero-volume tet
  std::optional<double> circumradius;
  double shortest_edge = 0;
  std::optional<double> ratio;             // R / lmin
  std::optional<bool> ratio_below_bound;   // exact R^2 < B^2 lmin^2, with a bound B
  std::vector<std::uint32_t> inside;       // vertices strictly inside (first max_listed)
  std::uint64_t inside_total = 0;
  std::vector<std::uint32_t> cospherical;  // vertices on the sphere, not of T (first ones)
  std::uint64_t cospherical_total = 0;
  std::vector<std::pair<std::string, Finding>> findings;  // (check id, finding) naming T
};

// Precondition: tet < mesh.tets.size() (std::out_of_range otherwise). `report` supplies
// the ratio bound and the findings; pass the one check_mesh returned for this mesh.
TetExplanation explain_tet(const MeshView& mesh, const Report& report, std::uint64_t tet,
                           std::size_t max_listed = 20);

std::string to_text(const TetExplanation& e);
nlohmann::json to_json(const TetExplanation& e);

}  // namespace pdr::check
