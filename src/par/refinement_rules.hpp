// RefinementRules: Fig. 2's step for a tet of a submesh, decided on the root's store
// (par/step_rules.hpp). Every submesh holds the subsegments and subfacets of D on its
// tets as labels (paper §4 items 1-2: label() below; they travel with the tets, Submesh
// M4).
//
// A tet is wanted when it is bad (refine/quality.hpp, exact: ratio >= B, or above the size
// bounds). Its step inserts its circumcenter p. On the complete cavity of p (accept()):
//   - p in the closed diametral ball of a subsegment that is an edge of a closure tet:
//     with `splits`, Refine(s): the subsegment's midpoint m is searched and committed as
//     a step of its own (accept_split(), below), and the tet is tried again after it;
//     without, the step is deferred;
//   - else the step is committed only when it is Fig. 2's "insert p" case: every conflict
//     tet lies inside Ω (so p does); p in no closed equatorial ball of a subfacet that is
//     a face of a closure tet (the same exact predicates as the sequential step,
//     refine/closure.hpp); no subsegment that is an edge of a conflict tet, and no
//     subfacet that is a face of one, disappears.
// Otherwise the step is deferred: the tet stays, and the sequential completion on rank 0
// (docs/parallel.md) takes it up with Fig. 2's Refine(f), the guards and the conformity
// rules, as the sequential mesher would.
//
// Refine(s) in the parallel phase (accept_split, commit). Every tet with edge ab holds
// the midpoint m in its circumsphere (a chord's midpoint lies inside every sphere
// through its ends), so the whole star of ab is in m's cavity, local at the root once the
// cavity is complete, and so is every subfacet m changes: a subfacet whose circumcircle
// holds m (a point of its plane) has both its tets in conflict. From the labels: the
// subfacets removed are the labelled faces inside the cavity; in each facet F they form
// a region whose boundary edges xy (edges of one removed subfacet only), ab excepted,
// give F's new subfacets (m, x, y), faces of the new tets since xy lies on the cavity's
// boundary; ab gives (a, m) and (m, b). The split is committed only when this holds
// exactly: ab is removed and no other subsegment is; the subfacets removed are of facets
// containing ab's segment; each boundary edge xy is an edge of the cavity's boundary; the
// new tets' inside flags (each the flag of its old neighbour, toggled across a subfacet
// of a facet with Ω on one side, as refine/volume_mesh.hpp commit_point) change across
// a new face exactly when it is a new subfacet of such a facet. Otherwise (rounding off
// exact geometry) the split is refused, remembered, and later tets whose points encroach
// that subsegment are deferred: the completion splits it with the sequential kernel.
// This is Fig. 2's Refine(s) for domains without acute angles, where the midpoint is
// the split point (refine/split.hpp: no guard); the caller enables it only there. The
// splits are recorded (splits()) so that rank 0 makes the same changes to its D after
// the assembly.
// Every committed step is thus a step the sequential mesher may take, on a closure no
// other commit shares (Lemma 2), so the sequential completion continues a valid run of
// Fig. 2 and Theorem 2's argument holds.
#pragma once

#include <array>
#include <cstdint>
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
  std::uint64_t split_refused = 0;  // splits whose change of D was not exact (above)
};

// A subsegment split committed in the parallel phase: the global ids of its ends and of
// the midpoint's vertex, and the midpoint.
struct SplitRecord {
  Gid a = kNoGid, b = kNoGid, m = kNoGid;
  Point p{};
};

class RefinementRules final : public StepRules {
 public:
  // m0: the mesh that was partitioned (its D and its vertex ids); it must outlive this.
  // `splits`: Refine(s) in the parallel phase (only where every split is the midpoint:
  // a domain without acute angles).
  RefinementRules(const refine::VolumeMesh& m0, const refine::TetBounds& bounds,
                  bool splits = false);

  bool wants(const Submesh& s, TetId t) const override;
  Point point(const Submesh& s, TetId t) const override;
  Verdict accept(const Submesh& s, const Cavity& c) override;
  bool accept_split(const Submesh& s, const Cavity& c, Gid a, Gid b) override;
  VertexId commit(Submesh& s, const Cavity& c) override;
  // A committed circumcenter is off ∂Ω (a step that would put one on it is deferred).
  std::uint8_t new_vertex_tag() const override { return kInterior; }

  const std::vector<SplitRecord>& splits() const { return splits_; }
  // The subsegments (their ends' global ids, smaller first) whose split was refused.
  const std::set<std::pair<Gid, Gid>>& refused_splits() const { return refused_; }
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
  refine::MaybeId subsegment(const Submesh& s, VertexId a, VertexId b) const;
  refine::MaybeId subfacet(const Submesh& s, VertexId a, VertexId b, VertexId c) const;
  // False: no edge of the tet with vertices v (of s) is a subsegment and no face a
  // subfacet, since at most one of its vertices may lie on ∂Ω (most tets).
  static bool may_touch_d(const Submesh& s, const VertexId* v) {
    int n = 0;
    for (int i = 0; i < 4; ++i) n += s.tag(v[i]) != kInterior;
    return n >= 2;
  }

 private:
  // The subsegment edge of real tet t whose closed diametral ball holds p, or nothing.
  std::optional<std::array<VertexId, 2>> encroached_subsegment(const Submesh& s, TetId t,
                                                               const Point& p) const;
  bool encroaches_subfacet(const Submesh& s, TetId t, const Point& p) const;

  static constexpr std::uint8_t kInterior = 1 + static_cast<int>(refine::VertexClass::Interior);
  static constexpr std::uint8_t kSegment = 1 + static_cast<int>(refine::VertexClass::Segment);
  bool separates(std::uint32_t facet) const { return m0_.surf.facets[facet].separates; }
  static bool may_be(std::uint8_t tag, std::uint8_t want) { return tag == 0 || tag == want; }

  const refine::VolumeMesh& m0_;
  const refine::TetBounds bounds_;
  std::vector<std::uint8_t> tags_;  // per M_o vertex
  DeferCounts deferred_;
  std::vector<std::pair<VertexId, VertexId>> kept_;  // accept(): the boundary's edges
  const bool splits_enabled_;
  // Subsegments whose split was refused, by their ends' global ids (smaller first).
  std::set<std::pair<Gid, Gid>> refused_;
  // accept_split() -> commit(): the split's change of D (local vertex ids).
  struct SplitPlan {
    bool active = false;
    VertexId a = kNoVertex, b = kNoVertex;
    std::uint32_t segment = 0;
    std::vector<std::array<VertexId, 3>> removed;                      // subfacets
    std::vector<std::pair<std::array<VertexId, 2>, std::uint32_t>> fan;  // edge xy, facet
  } plan_;
  std::vector<SplitRecord> splits_;
};

}  // namespace pdr::par
