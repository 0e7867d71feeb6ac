// SeqRefinement (paper §3, Fig. 2) over the tets of T inside Ω. The parts, one file each:
// seq_refinement.cpp (the loop, Refine(t), Refine(f), Refine(s)), work_queue.hpp (the bad
// tets), budget.hpp (resolution and vertex cap), closure.hpp (Fig. 2's encroachment tests
// on the closure), guard.hpp and split.hpp (the guards outside the theory), flat.hpp (the
// rounding repairs on tilted facets), audit.hpp (Lemma 1), leftovers.hpp (what is left).
//
// A tet is bad when ratio >= B (refine/quality.hpp, exact), or, with size control, its
// circumradius exceeds L or its volume exceeds V. Bad tets wait in a FIFO work queue
// (work_queue.hpp). Refine(t):
//   p = circumcenter(t) (double: where only); the tet containing p is located from t and
//   the cavity of p built read-only from it;
//   1. p in the CLOSED diametral ball of a subsegment that is an edge of a closure tet:
//      split that subsegment instead (refine/split.hpp: the midpoint; outside the theory,
//      near an acute input vertex, at a power-of-two distance from it: concentric shells);
//      return;
//   2. p in the closed equatorial ball of subfacets that are faces of closure tets: refine
//      the one of largest circumradius at its circumcenter q in the facet (Fig. 2); q may
//      encroach a subsegment (on the facet cavity's boundary, or an edge of q's closure in
//      T): split that instead; return;
//   3. p outside Ω (the tet containing it is outside, or p is outside the hull): there
//      must have been an encroached element; if not, the tet is refused with that reason;
//   4. commit: T gains p, the new tets get their flags (refine/volume_mesh.hpp) and are queued
//      when bad.
// After 1 or 2, t may still be alive (the split's cavity missed it): it is queued again.
// Every step inserts a vertex or refuses (a refused tet is not queued again unless it is
// destroyed and rebuilt), and the number of vertices is capped, so a run never hangs.
// Guards for domains outside the theory (angles < 90°; RefineOptions::admissible false):
//   - encroachment pass (refine/guard.hpp): Lemma 1 no longer keeps D unencroached, so
//     encroached subsegments and subfacets are found exactly (strictly inside the ball, as
//     the checker) among the tets of T_o once, then among the star of every new vertex,
//     and refined before any tet: subsegments first (Refine(s)), then subfacets
//     (Refine(f), step 2's circumcenter with its subsegment fallback);
//   - concentric shells at the acute vertices (RefineOptions::acute_vertices from the
//     domain analysis, refine/split.hpp);
//   - protected length (resolution / 64, the resolution being the smallest of d/2, L/2,
//     cbrt(V), with d the element's own: the d the surface mesh sized it for, local when
//     it is graded): on segments and facets at an acute vertex nothing is split below it; the
//     tet (or encroached element) whose refinement needed that split is refused, with the
//     reason (repairs of rounding, refine/flat.hpp, and of conformity are not held);
//   - the vertex cap (RefineOptions::max_vertices, else derived from the input size,
//     the domain's bounding box and the resolution) stops the loop with stop_reason set.
// Conformity (refine/conformity.hpp): an element of D that an insertion would take out of
// T makes a tet circumcenter refine it instead; one that another insertion (or T_o) leaves
// out of T is refined before anything else, and the flags of the tets made meanwhile are
// recomputed once T conforms again. A guard refusing such a refinement leaves T
// non-conforming there: counted (conformity_refused) and reported.
// After the loop every inside tet with ratio >= B is listed (leftovers) with the reason,
// and every encroached element the guards refused is listed (unsplit); the exact checker
// on the output reports any encroachment left (pdr mesh then exits 3).
// Lemma 1 audit (RefineOptions::audit): after each insertion, refine/audit.hpp checks
// invariants 1-4 on what it touched and throws RefineError("lemma1.invariantK: ...").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "refine/quality.hpp"
#include "refine/volume_mesh.hpp"

#include "domain/analysis.hpp"

namespace pdr::refine {

struct RefineOptions {
  double ratio = 2.0;                 // B
  std::optional<double> size;         // L: circumradius bound
  std::optional<double> max_volume;   // V
  // Regional volume bounds (region records with a volume; set_domain), when any.
  std::shared_ptr<const domain::RegionVolumes> region_volumes;
  bool audit = false;
  std::size_t max_vertices = 0;       // 0: derived cap
  double d = 0;                       // paper §2.1 d (for the derived cap and the audit)
  // Called every 1024 refinement steps with the vertex count (a progress line); may be empty.
  std::function<void(std::size_t vertices)> on_progress;
  bool admissible = true;             // false: the audit records its first failure
                                      // (audit_note) instead of stopping: Lemma 1 is
                                      // not expected to hold outside the theory; and
                                      // the guards below are on
  // The bounds of tets with no vertex on ∂Ω, when they differ (the parallel run's coarse
  // mesh M_o: the boundary layer refined to the final bounds, the interior coarser, so the
  // parallel phase rarely meets D: app/parallel.hpp).
  std::optional<TetBounds> interior;
  // The domain meets Theorem 1's hypotheses exactly (theorem_applies below): the audit then
  // holds every new edge to the theorem's a-priori h (RefineStats::h_theorem) rather than to
  // the smallest size the run refined.
  bool exact_theory = false;
  std::vector<std::uint32_t> acute_vertices;  // inadmissible: acute_vertices(report)
                                              // (refine/split.hpp); empty: every input
                                              // vertex
  std::vector<double> cylinders;  // inadmissible: protecting_cylinders(analysis)
                                  // (refine/split.hpp); empty: none
  // How far an input vertex may lie from where the input means it (the domain analysis'
  // delta, domain/angles.hpp; 0 for exactly planar input): classifies the right angles
  // that bound a sharp axis's strip (refine/axis_zones.hpp) as the analysis does.
  double vertex_uncertainty = 0;
  // Given: the only tets that may need a step at the start, every other inside tet being
  // known to meet the bounds (the parallel run's completion: the steps its parallel phase
  // deferred, app/parallel.hpp); the run queues these instead of testing every tet. A bad
  // tet missing here is never refined, and the leftovers list it ("never refined").
  std::optional<std::vector<TetId>> start_tets;
  // Given: the run resumes refinement of a mesh that Fig. 2's steps made from T_o, with T_o
  // meeting Theorem 1's hypotheses exactly (the parallel run's completion on a domain whose
  // constructions on ∂Ω are exact, app/parallel.hpp): Theorem 1's h of T_o under this
  // run's bounds (theorem_h). The run takes it as its h_theorem, rather than one computed
  // from the mesh it starts from (whose shortest edge every edge trivially exceeds), and
  // skips the scan of every tet for encroached elements at the start: the caller has
  // made sure none is (a tet's circumcenter goes in only where it encroaches no element
  // of its closure, and an element a point encroaches is an element of a tet around that
  // point, refine/guard.hpp; the points on ∂Ω, held to no such test, encroach nothing by
  // Lemma 1, which the caller checks around them).
  std::optional<double> resumed_h;
};

// Theorem 1's h for a run from a mesh whose shortest inside edge is `shortest_edge`: the
// smallest of that edge, L/2 and the radius bound that V implies, lowered by 2^-30
// relative (seq_refinement.cpp says why each).
double theorem_h(double shortest_edge, const RefineOptions& o);
// The shortest edge of an inside tet of m.
double shortest_inside_edge(const VolumeMesh& m);

// The smallest volume bound of the run: V and the regional bounds; none when neither.
std::optional<double> smallest_volume(const RefineOptions& o);

// Theorem 1's hypotheses hold, and the refinement's constructions on ∂Ω are exact:
// admissible, with no angle read as 90 or 270 degrees within tolerance, no facet accepted
// as planar within tolerance, and every facet parallel to a coordinate plane (so every
// subfacet circumcenter and segment midpoint keeps the facet's constant coordinate; on a
// tilted facet they are rounded off it by ulps, and the repairs of refine/flat.hpp, which
// are no step of Fig. 2, may refine elements below the a-priori bound).
bool theorem_applies(const domain::DomainAnalysis& an);

// Sets what the domain's analysis decides in the options: d, admissible, exact_theory and
// the guards' acute vertices and protecting cylinders (refine/split.hpp).
void set_domain(RefineOptions& o, const domain::DomainAnalysis& an);

struct Leftover {
  TetId tet = kNoTet;
  std::array<VertexId, 4> v{};
  std::array<Point, 4> p{};
  double ratio = 0;  // display only
  std::string reason;
};

struct RefineStats {
  std::size_t tet_circumcenters = 0;
  std::size_t subfacet_circumcenters = 0;
  std::size_t axis_copies = 0;  // rotation copies near sharp axes (refine/axis_zones.hpp)
  std::size_t axis_copies_dropped = 0;  // copies outside their facet, on a vertex, refused
  std::size_t ball_zones = 0;     // protecting balls activated (refine/vertex_zones.hpp)
  std::size_t ball_fills = 0;     // shells filled (each after the first: the ball halved)
  std::size_t ball_vertices = 0;  // vertices of shells and of their pieces' splits
  std::size_t subsegment_splits = 0;
  std::size_t refused = 0;
  std::size_t vertex_cap = 0;
  std::size_t encroached_splits = 0;    // elements the encroachment guard refined
  std::size_t encroached_refused = 0;   // ... and those it could not (unsplit)
  std::size_t conformity_breaks = 0;    // insertions after which D was not in T
  std::size_t conformity_splits = 0;    // refinements of elements missing from T
  std::size_t conformity_refused = 0;   // ... that a guard refused: T does not conform
  std::size_t flat_left = 0;            // flat tets on a facet (refine/flat.hpp rule 1) left
                                        // inside: the cap stopped their repair, or it was
                                        // refused (slivers; T still conforms)
  std::size_t flat_repairs = 0;         // refinements asked by refine/flat.hpp rule 1 (a flat
                                        // tet on a facet), inserted or refused
  std::size_t face_repairs = 0;         // ... by rule 2 (a subfacet face with its tet's apex
                                        // in its equatorial ball: rounding or geometry)
  std::size_t flag_repairs = 0;         // surface insertions whose star's flags disagreed
                                        // with D: every flag recomputed (conformity.hpp)
  std::size_t flag_conflicts = 0;       // faces where parity across D disagreed at the end
  double h = 0;  // min over refinements of (l/2, R_f/√2, R_t/2): the largest h the run met
  // Theorem 1's h, a priori (from T_o and the size bounds, before any refinement; see
  // theorem_h in seq_refinement.cpp), when the hypotheses hold (B >= 2,
  // RefineOptions::exact_theory and T_o conforms), else 0: the audit holds every new edge
  // to it, and `pdr mesh` checks that every final edge is longer.
  double h_theorem = 0;
  std::size_t audit_failures = 0;  // inadmissible domains only (else the first throws)
  std::string audit_note;          // the first of them
};

struct RefineResult {
  RefineStats stats;
  std::vector<Leftover> leftovers;  // inside tets with ratio >= B at the end
  std::vector<std::string> unsplit;  // why encroached elements were not refined (first 50)
  std::string stop_reason;          // empty unless the vertex cap stopped the loop
  // The run had start tets and added no vertex and changed no inside flag: its tets are
  // those it started from (and only the start tets were tested for leftovers).
  bool tets_unchanged = false;
};

RefineResult refine(VolumeMesh& m, const RefineOptions& options);

}  // namespace pdr::refine
