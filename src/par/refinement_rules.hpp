// RefinementRules: Fig. 2's step for a tet of a submesh, decided on the root's store
// (par/step_rules.hpp). Every submesh holds the subsegments and subfacets of D on its
// tets as labels (paper §4 items 1-2: label() below; they travel with the tets, Submesh
// M4).
//
// A tet is wanted when it is bad (refine/quality.hpp, exact: ratio >= B, or above the size
// bounds). Its step inserts its circumcenter p. On the complete cavity of p (accept()),
// as Fig. 2, with the same exact predicates as the sequential step (refine/closure.hpp):
//   - p in the closed diametral ball of a subsegment that is an edge of a closure tet:
//     Refine(s), its midpoint;
//   - else p in the closed equatorial ball of a subfacet that is a face of a closure tet:
//     Refine(f) for the largest such subfacet (exact comparison, refine/closure.hpp's
//     rule), its circumcenter placed on the facet's plane as the sequential kernel
//     places it (surface/insert.hpp);
//   - else the step is committed when every conflict tet lies inside Ω (so p does) and
//     no subsegment that is an edge of a conflict tet, and no subfacet that is a face of
//     one, disappears; otherwise it is deferred.
// With `surface_steps` (a domain whose constructions on ∂Ω are exact: below), Refine(s)
// and Refine(f) are steps of their own: the new point is searched and committed like a
// circumcenter (accept_surface()), and the tet is tried again after it; a subfacet
// circumcenter that encroaches a subsegment of its closure refines that subsegment
// instead (Fig. 2). Without, they are deferred: the tet stays, marked, and the sequential
// completion on rank 0 (docs/parallel.md) takes it up with the guards and conformity
// rules of the sequential mesher.
//
// A step on ∂Ω changes D, and every change lies in its cavity, so it is local at the root
// once the cavity is complete. A midpoint m of subsegment ab lies in the circumsphere of
// every tet with edge ab (a chord's midpoint is inside every sphere through its ends), so
// ab's star is in the cavity; a subfacet whose circumcircle holds the new point q (a
// point of its plane) has both its tets in conflict. From the labels: the subfacets
// removed are the labelled faces inside the cavity; in each facet they form a region
// whose boundary edges xy (edges of one removed subfacet only; for a split, ab excepted)
// give the facet's new subfacets (q, x, y), faces of the new tets since xy lies on the
// cavity's boundary; a split turns ab into (a, m) and (m, b). The step is committed only
// when this holds exactly: for a split ab is removed and no other subsegment is, the
// subfacets removed are of facets containing ab's segment; for a subfacet's circumcenter
// no subsegment is removed, the subfacet is, and every subfacet removed is of its facet;
// each boundary edge xy is an edge of the cavity's boundary; and the new tets' inside
// flags (each the flag of its old neighbour, toggled across a subfacet of a facet with Ω
// on one side, as refine/volume_mesh.hpp commit_point) change across a new face exactly
// when it is a new subfacet of such a facet. Otherwise (rounding, off exact geometry) the
// step is refused, the element remembered, and later tets whose points need it are
// deferred to the completion. The caller enables these steps only for domains where
// every construction on ∂Ω is exact (RefineOptions::exact_theory: admissible, so every
// split is the midpoint, refine/split.hpp, and every facet parallel to a coordinate
// plane). The steps are recorded (surface_steps()) so that rank 0 makes the same
// changes to its D after the assembly (par/assembly.hpp).
// Every committed step is thus a step the sequential mesher may take, on a closure no
// other commit shares (Lemma 2), so the sequential completion continues a valid run of
// Fig. 2 and Theorem 2's argument holds. One difference in time: a step on ∂Ω is
// committed on the mesh as it is when its own cavity is complete, its element still
// there (accept_surface() drops it otherwise), while the tet whose point encroached the
// element may be gone by then. Lemma 1's bounds on a refined element (a subsegment longer
// than 2h, a subfacet of circumradius above h√2) are facts about the element and the
// encroaching point at the time of encroachment, and the element has not changed since,
// so they hold all the same; Fig. 2's subsegment rule for a subfacet's circumcenter is
// applied on the mesh at commit.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <set>
#include <utility>
#include <vector>

#include "par/step_rules.hpp"
#include "refine/quality.hpp"
#include "refine/volume_mesh.hpp"

namespace pdr::par {

struct DeferCounts {
  std::uint64_t outside = 0;     // a conflict tet outside Ω
  std::uint64_t subsegment = 0;  // p encroaches a subsegment of the closure
  std::uint64_t subfacet = 0;    // p encroaches a subfacet of the closure
  std::uint64_t removed = 0;     // the cavity would remove a subsegment or subfacet
  std::uint64_t refused = 0;     // steps on ∂Ω whose change of D was not exact (above)
  std::uint64_t cap = 0;         // the rank's share of the vertex cap was spent
};

// A step on ∂Ω committed in the parallel phase: a subsegment split (c = kNoGid) or a
// subfacet's circumcenter in facet `facet`, by the global ids of the element's vertices
// and of the new vertex, and the new point.
struct SurfaceStep {
  Gid a = kNoGid, b = kNoGid, c = kNoGid, m = kNoGid;
  Point p{};
  std::uint32_t facet = 0;
};

class RefinementRules final : public StepRules {
 public:
  // m0: the mesh that was partitioned (its D and its vertex ids); it must outlive this.
  // `surface_steps`: Refine(s) and Refine(f) in the parallel phase (above).
  RefinementRules(const refine::VolumeMesh& m0, const refine::TetBounds& bounds,
                  bool surface_steps = false);

  bool wants(const Submesh& s, TetId t) const override;
  Point point(const Submesh& s, TetId t) const override;
  Verdict accept(const Submesh& s, const Cavity& c) override;
  // Without surface steps every verdict but Commit is Defer: a conflict tet outside Ω, or
  // one with a subsegment edge or subfacet face that p encroaches, defers the step. With
  // surface steps there is no early deferral (Fig. 2's order needs the whole closure). The
  // reason is that of the first such tet the search meets (accept() takes Fig. 2's order
  // over the whole closure), counted by count_early_deferral().
  bool defers_early() const override { return !surface_steps_enabled_; }
  // Its reasons: 1 outside Ω, 2 an encroached subsegment, 3 an encroached subfacet.
  std::uint8_t defers_at(const Submesh& s, TetId u, const Point& p) override;
  void count_early_deferral(std::uint8_t reason) override;
  Verdict accept_surface(const Submesh& s, const Cavity& c, Gid a, Gid b, Gid cc) override;
  VertexId commit(Submesh& s, const Cavity& c) override;
  // A committed circumcenter is off ∂Ω (a step that would put one on it is deferred).
  std::uint8_t new_vertex_tag() const override { return kInterior; }

  // The vertex cap (refine::VertexBudget): this rank commits at most `points` points in
  // the phase (its share of the cap over M_o's vertices); past it every step is deferred
  // (reason `cap`), and the completion, which tests the cap, stops and says so.
  void set_point_budget(std::uint64_t points) { points_left_ = points; }

  const std::vector<SurfaceStep>& surface_steps() const { return steps_; }
  // The elements (their vertices' global ids, sorted; kNoGid last for a subsegment) whose
  // step was refused.
  const std::set<std::array<Gid, 3>>& refused() const { return refused_; }
  const DeferCounts& deferred() const { return deferred_; }

  // The tags to extract the submeshes with (Submesh::extract): 1 + M_o's vertex class
  // (refine::VertexClass). A vertex with tag 0 (none given, or made in the parallel
  // phase) is looked up in D like any other.
  std::span<const std::uint8_t> vertex_tags() const { return tags_; }

  // Labels submesh s (extracted from M_o) with the elements of D whose vertices it holds:
  // a subsegment's label is its segment, a subfacet's its facet (Submesh M4).
  void label(Submesh& s) const;

  // D as seen from submesh s (vertices local to s): the segment of subsegment {a, b}, the
  // facet of subfacet {a, b, c}; both filter by the vertices' tags first, then read the
  // submesh's labels.
  static refine::MaybeId subsegment(const Submesh& s, VertexId a, VertexId b);
  static refine::MaybeId subfacet(const Submesh& s, VertexId a, VertexId b, VertexId c);
  // Whether a vertex made in the phase with this tag lies on ∂Ω (a subsegment midpoint or
  // a subfacet circumcenter; commit() tags them so).
  static bool made_on_d(std::uint8_t tag) { return tag == kSegment || tag == kFacet; }
  // How many of the tet's vertices v (of s) may lie on ∂Ω (a tag other than interior).
  static int may_lie_on_d(const Submesh& s, const VertexId* v) {
    int n = 0;
    for (int i = 0; i < 4; ++i) n += s.tag(v[i]) != kInterior;
    return n;
  }
  // False: no edge of the tet with vertices v (of s) is a subsegment and no face a
  // subfacet, since at most one of its vertices may lie on ∂Ω (most tets).
  static bool may_touch_d(const Submesh& s, const VertexId* v) { return may_lie_on_d(s, v) >= 2; }
  // False: no face of the tet is a subfacet, since at most two of its vertices may lie on ∂Ω.
  static bool may_have_subfacet(const Submesh& s, const VertexId* v) {
    return may_lie_on_d(s, v) >= 3;
  }

 private:
  using Key = std::array<Gid, 3>;
  // The subsegment edge of a real tet of `tets` whose closed diametral ball holds p.
  // A subsegment edge of the tet with vertices v whose closed diametral ball holds p.
  std::optional<std::array<VertexId, 2>> encroached_edge(const Submesh& s, const VertexId* v,
                                                         const Point& p) const;
  std::optional<std::array<VertexId, 2>> encroached_subsegment(
      const Submesh& s, std::initializer_list<const std::vector<TetId>*> tets,
      const Point& p) const;
  // Refine(s) or Refine(f) for the element with local vertices v (v[2] kNoVertex for a
  // subsegment), found on closure tet `near`; deferred (counted) when disabled or refused.
  Verdict refine_element(const Submesh& s, std::array<VertexId, 3> v, TetId near);
  Key key(const Submesh& s, std::array<VertexId, 3> v) const;
  Point facet_point(const Submesh& s, const std::array<VertexId, 3>& v,
                    std::uint32_t facet) const;
  // The change of D of a surface step on cavity c (above) into plan_; false: not exact.
  bool plan(const Submesh& s, const Cavity& c, std::optional<std::array<VertexId, 2>> split,
            std::span<const std::uint32_t> facets, const std::array<VertexId, 3>* subfacet);

  static constexpr std::uint8_t kInterior = 1 + static_cast<int>(refine::VertexClass::Interior);
  static constexpr std::uint8_t kSegment = 1 + static_cast<int>(refine::VertexClass::Segment);
  static constexpr std::uint8_t kFacet = 1 + static_cast<int>(refine::VertexClass::Facet);
  bool separates(std::uint32_t facet) const { return m0_.surf.facets[facet].separates; }
  static bool may_be(std::uint8_t tag, std::uint8_t want) { return tag == 0 || tag == want; }

  const refine::VolumeMesh& m0_;
  const refine::TetBounds bounds_;
  std::vector<std::uint8_t> tags_;  // per M_o vertex
  DeferCounts deferred_;
  std::vector<std::pair<VertexId, VertexId>> kept_;  // accept(): the boundary's edges
  const bool surface_steps_enabled_;
  std::uint64_t points_left_ = ~std::uint64_t{0};
  std::set<Key> refused_;
  // accept_surface() -> commit(): the step's change of D (local vertex ids). One rules
  // object serves every actor of a rank: the actor calls commit() right after the accept
  // that planned it, in the same handler (par/insertion_actor.cpp complete()).
  struct Plan {
    enum class Kind : std::uint8_t { None, Split, Facet } kind = Kind::None;
    Key element{};  // global ids, as the step named it
    VertexId a = kNoVertex, b = kNoVertex;
    std::uint32_t label = 0;  // the segment split, or the facet
    std::vector<std::array<VertexId, 3>> removed;                      // subfacets
    std::vector<std::pair<std::array<VertexId, 2>, std::uint32_t>> fan;  // edge xy, facet
  } plan_;
  std::vector<SurfaceStep> steps_;
  // plan()'s buffers, reused from step to step.
  std::vector<std::pair<VertexId, VertexId>> plan_edges_;
  std::vector<std::pair<std::pair<VertexId, VertexId>, std::uint8_t>> plan_flags_;
  std::vector<std::pair<std::array<VertexId, 3>, std::uint32_t>> plan_removed_;
  std::vector<std::pair<std::uint32_t, std::pair<VertexId, VertexId>>> plan_region_;
};

}  // namespace pdr::par
