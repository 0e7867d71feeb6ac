// pdr_check: an exact oracle for tetrahedral Delaunay meshes (the public API).
//
// Given a mesh as plain arrays (points, tets, optionally boundary faces) and optionally the
// input domain (a Plc), check_mesh() decides, exactly, the invariants that the paper
// (Nave, Chrisochoides, Chew 2002) guarantees of its output, and returns them as data.
// Independent of the mesher on purpose: its filters, exact stages and measures
// (check/signs.hpp, check/circumball.hpp, ...) are its own copies, not the kernel's
// geom/predicates.hpp or geom/filter_kit.hpp, so that a fault in one is not repeated in the
// other; it shares only the GMP reference (geom/exact.hpp) and, for displayed measures,
// the floating-point constructions (geom/construct.hpp).
// One CheckResult per check, always all of them, in this order:
//
//   validity.indices          every vertex index < #points
//   validity.coordinates      every coordinate finite (else all later checks are Skipped)
//   validity.orientation      orient3d(t0,t1,t2,t3) > 0 for every tet (zero volume fails)
//   validity.duplicate_vertices   no two vertices with equal coordinates
//   validity.unreferenced_vertices   vertices in no tet: Warn only, never Fail
//   validity.face_sharing     a face is in <= 2 tets, whose 4th vertices lie strictly on
//                             opposite sides of it
//   validity.boundary_closed  faces in one tet, oriented outward, use every edge equally
//                             often in both directions
//   validity.faces            MeshData.faces (if any) = the boundary faces, plus optionally
//                             interior faces (internal facets); inward orientation: Warn
//   validity.overlap          tets have disjoint interiors; coplanar faces of two tets
//                             overlap only if they are the same face
//   delaunay.empty_sphere     no vertex strictly inside any tet's circumsphere (all
//                             vertices, not only neighbours); on-sphere counted, not failed
//   quality.ratio             R^2 < B^2 lmin^2 per tet (Theorem 1 (2)); Skipped without B
//   quality.shortest_edge     l^2 > h^2 per edge (Theorem 1 (1)); Skipped without h
//   conformity.vertices       every input vertex is a mesh vertex (equal coordinates)
//   conformity.segments       the mesh vertices on each segment, in order, are joined by
//                             mesh edges (its subsegments)
//   conformity.facets         the mesh faces in each facet cover it: projected areas sum
//                             exactly to its projected area (its subfacets)
//   conformity.volume         boundary faces lie in facets, hole points in no tet, region
//                             points in some tet
//   encroachment.subsegments  no vertex strictly inside a subsegment's diametral sphere
//   encroachment.subfacets    no vertex strictly inside a subfacet's equatorial sphere
//                             (paper §1.1; Lemma 1, invariant 1); on-sphere counted
//
// The conformity and encroachment checks are Skipped without a domain. The files named in
// each result's invariant text (src/check/*.cpp) give the exact criteria and arguments.
//
// Every decision is exact (signs of polynomials in the input doubles, taken as rationals):
// floating-point filters with proven error bounds run first, GMP rationals (geom/exact.hpp)
// decide what they cannot. The only tolerance is Options::relative_tolerance, which only
// classifies imprecise input vertices as lying on a facet plane or a segment line (see
// check/domain.hpp); how many vertices needed it is reported ("tolerance_vertices").
// Nothing here prints; nothing depends on the thread count (findings are the first ones by
// element id).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "geom/point.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/plc.hpp"

namespace pdr::check {

// A read-only view of a mesh. faces may be empty (then only the computed boundary is used).
struct MeshView {
  std::span<const Point> points;
  std::span<const Tet> tets;
  std::span<const Tri> faces;
};

MeshView view_of(const MeshData& mesh);

// Parameters, passed by value (docs/design.md §14).
struct Options {
  std::optional<double> ratio_bound;  // B: quality.ratio requires R < B * lmin
  std::optional<double> min_edge;     // h: quality.shortest_edge requires lmin > h
  std::size_t max_reported = 20;      // findings kept per check (the first ones by id)
  unsigned threads = 2;               // worker threads for the per-tet loops (>= 1)
  // Input classification only (conformity, encroachment): a mesh vertex within
  // relative_tolerance * (facet diameter) of an exactly planar facet's plane, or within
  // relative_tolerance * |AB| of a segment AB's line, counts as lying on it (new vertices
  // there are rounded, a few ulps off).
  double relative_tolerance = 1e-10;
  // The same for a facet whose input vertices are not exactly coplanar, against the
  // least-squares plane of its vertices: 8T, T the domain analysis's default planarity
  // tolerance (1e-9). Such a facet's vertices lie within T diameters of that plane, and
  // pdr mesh puts new vertices on the plane of three of them, within 7T (surface/chart.hpp).
  double inexact_facet_tolerance = 8e-9;
  // The uncertainty of the domain's coordinates when they are written with fewer digits
  // (io/precision.hpp; 0: none): a facet planar only within tolerance then has its
  // vertices within max(T diameters, 4 u) of its least-squares plane, and the new ones
  // within 7 times that, so vertices within max(inexact_facet_tolerance * diameter, 32 u)
  // count as on it.
  double coordinate_uncertainty = 0;
  // Pieces of the domain that bound no region (a facet, or a part of one, with voids or the
  // outside on both sides, and the segments only such pieces hold): TetGen drops them, and
  // so does pdr's domain analysis (domain::PlcDomain::dropped). The mesh need not hold
  // them. Input vertex ids; `facet` indexes the domain's facets.
  struct DroppedTri {
    std::uint32_t facet = 0;
    std::array<std::uint32_t, 3> v{};
  };
  std::vector<DroppedTri> dropped_tris;
  std::vector<std::array<std::uint32_t, 2>> dropped_segments;
  std::vector<std::uint32_t> dropped_vertices;  // on dropped pieces only: may be left out
  bool check_overlap = true;          // validity.overlap (the costliest validity check)
  // validity.overlap first tries the degree argument (degree.cpp), which looks at the
  // boundary surface only; off, every pair of tets with meeting boxes is tested.
  bool overlap_by_degree = true;
  // Called as each phase starts ("orientation", "topology", "overlap", ...): a progress
  // line. May be empty; not called from worker threads.
  std::function<void(std::string_view phase)> on_phase;
};

// Pass: no violation. Warn: no failure, but something was flagged or not judged (reason
// says what). Fail: violations (counted in `violations`). Skipped: not run (reason says why).
enum class Status { Pass, Warn, Fail, Skipped };
std::string_view to_string(Status s);

// The ids of all checks, in report order.
const std::vector<std::string_view>& check_ids();

inline constexpr std::uint64_t kNoId = std::numeric_limits<std::uint64_t>::max();

// One offending element (or pair of elements) of a check.
struct Finding {
  std::string kind;                     // "tet", "vertex", "face", "edge", "segment",
                                        // "subsegment", "facet", "subfacet", "hole", ...
  std::uint64_t id = kNoId;             // its index in its array (tet id, facet id, ...)
  std::vector<std::uint32_t> vertices;  // mesh vertices involved (offender last)
  std::vector<Point> points;            // their coordinates (or input coordinates)
  std::optional<double> value;          // a measured value (ratio, length, ...), display only
  std::string message;                  // begins with the check id
};

struct CheckResult {
  std::string id;         // stable id, e.g. "delaunay.empty_sphere"
  std::string invariant;  // the paper's definition/lemma it encodes
  Status status = Status::Skipped;
  std::string reason;     // why skipped or warned; empty otherwise
  std::uint64_t checked = 0;     // elements examined
  std::uint64_t violations = 0;  // elements violating the invariant
  std::map<std::string, std::uint64_t> counts;  // e.g. "cospherical", "tolerance_vertices"
  std::map<std::string, double> values;         // e.g. "max_ratio" (display only)
  std::vector<Finding> findings;                // the first max_reported violations
};

struct Report {
  static constexpr int kSchemaVersion = 1;
  std::uint64_t points = 0, tets = 0, boundary_faces = 0;
  bool has_domain = false;
  Options options;
  std::vector<CheckResult> checks;
  std::map<std::string, double> seconds;  // wall time per phase; not reproducible, not in JSON
                                          // unless asked
  // delaunay.empty_sphere's pairs of a tet and a vertex exactly on its circumsphere (tet
  // index, vertex), sorted: every such pair when on_sphere_complete, which needs the check
  // to have run and found at most kMaxOnSphere of them. The order check (src/app) decides
  // from them which tets the symbolic perturbation keeps. Not in JSON.
  static constexpr std::size_t kMaxOnSphere = std::size_t{1} << 20;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> on_sphere;
  bool on_sphere_complete = false;

  bool ok() const;  // no check failed (warnings and skips allowed)
  const CheckResult* find(std::string_view id) const;
};

// Runs every check. Preconditions: none (a corrupt mesh yields failed checks, not UB).
Report check_mesh(const MeshView& mesh, Options options = {});
Report check_mesh(const MeshView& mesh, const Plc& domain, Options options = {});

// For other meshers' tests: xyz holds 3 doubles per point, tets 4 indices per tet,
// faces (optional) 3 per face. The arrays are copied.
Report check_arrays(std::span<const double> xyz, std::span<const std::uint32_t> tets,
                    std::span<const std::uint32_t> faces = {}, const Plc* domain = nullptr,
                    Options options = {});

std::string to_text(const Report& report);        // each failed check named first
nlohmann::json to_json(const Report& report, bool with_timing = false);  // "schema_version"

}  // namespace pdr::check
