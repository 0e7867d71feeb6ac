// RefinementRules: Fig. 2's step for a tet of a submesh, decided on the root's store
// (par/step_rules.hpp), while the surface mesh D stays as it was when the mesh was
// distributed (paper §4 items 1-2: every submesh starts with the subsegments and
// subfacets of its tets, label() below; they travel with the tets, Submesh M4).
//
// A tet is wanted when it is bad (refine/quality.hpp, exact: ratio >= B, or above the size
// bounds). Its step inserts its circumcenter p. On the complete cavity of p, the step is
// committed only when it is Fig. 2's "insert p" case:
//   - every conflict tet lies inside Ω (so p does);
//   - p lies in no closed diametral ball of a subsegment that is an edge of a closure tet,
//     and in no closed equatorial ball of a subfacet that is a face of one (the same exact
//     predicates as the sequential step, refine/closure.hpp);
//   - no subsegment that is an edge of a conflict tet, and no subfacet that is a face of
//     one, disappears (it stays an edge or a face of the cavity's boundary).
// Otherwise the step is deferred: the tet stays, and the sequential completion on rank 0
// (docs/parallel.md) takes it up with Fig. 2's Refine(s)/Refine(f), the guards and the
// conformity rules, as the sequential mesher would. Every committed step is thus a step
// the sequential mesher may take, on a closure no other commit shares (Lemma 2), so the
// sequential completion continues a valid run of Fig. 2 and Theorem 2's argument holds.
// New vertices are never on ∂Ω, so the elements of D are the labelled edges and faces of
// M_o's vertices, and a committed step labels nothing.
#pragma once

#include <cstdint>
#include <span>
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
};

class RefinementRules final : public StepRules {
 public:
  // m0: the mesh that was partitioned (its D and its vertex ids); it must outlive this.
  RefinementRules(const refine::VolumeMesh& m0, const refine::TetBounds& bounds);

  bool wants(const Submesh& s, TetId t) const override;
  Point point(const Submesh& s, TetId t) const override;
  bool accept(const Submesh& s, const Cavity& c) override;
  // A committed point is off ∂Ω (a step that would put one on it is deferred).
  std::uint8_t new_vertex_tag() const override { return kInterior; }

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
  bool encroaches(const Submesh& s, TetId t, const Point& p);

  static constexpr std::uint8_t kInterior = 1 + static_cast<int>(refine::VertexClass::Interior);
  static constexpr std::uint8_t kSegment = 1 + static_cast<int>(refine::VertexClass::Segment);
  static bool may_be(std::uint8_t tag, std::uint8_t want) { return tag == 0 || tag == want; }

  const refine::VolumeMesh& m0_;
  const refine::TetBounds bounds_;
  std::vector<std::uint8_t> tags_;  // per M_o vertex
  DeferCounts deferred_;
  std::vector<std::pair<VertexId, VertexId>> kept_;  // accept(): the boundary's edges
};

}  // namespace pdr::par
