// The distance d of paper §2.1: "the minimum distance between any two unrelated components
// in ∂Ω, times 1/√2".
//
// Components: the boundary vertices, the segments and the faces of a PlcDomain. Related
// (paper §1.1): two segments sharing a vertex, two facets sharing a segment, a facet and a
// segment or another facet sharing a vertex; pdr extends this to vertices in the only way
// that keeps distances positive: a vertex is related to the segments and facets that
// contain it, and two distinct vertices are unrelated. So unrelated = sharing no vertex.
//
// Fast path (feature_size): the minimum over unrelated pairs is attained by
//   vertex-vertex, vertex-segment, vertex-facet or segment-segment pairs,
// because for planar facets the closest points of a segment and a facet, or of two
// facets, can always be taken with one of them on the boundary (a vertex or a segment of
// one of the two), and the segments and vertices of a component share no vertex with a
// component it is unrelated to. One bounding-volume hierarchy over all vertices, segments
// and facet triangles is searched by branch and bound from each vertex and each segment,
// pruning boxes farther than the best distance found so far (initialised with the
// shortest segment, itself a vertex-vertex pair). Expected O(n log n) for n components of
// comparable size; no all-pairs loop.
// Reference (feature_size_brute): every pair of components of all six kinds, facets as
// unions of their triangles; O(n^2), for tests.
// For facets planar only within tolerance (triangles not exactly coplanar), the reduction
// holds up to that tolerance.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "refine/plc_domain.hpp"

namespace pdr::refine {

enum class ComponentKind : std::uint8_t { Vertex, Segment, Facet };
const char* component_kind_name(ComponentKind k);

struct FeatureSize {
  double min_distance = std::numeric_limits<double>::infinity();
  double d = std::numeric_limits<double>::infinity();  // min_distance / sqrt(2)
  // The closest unrelated pair: kinds and ids (vertex id, segment index, facet index).
  ComponentKind first_kind = ComponentKind::Vertex, second_kind = ComponentKind::Vertex;
  std::uint32_t first = 0, second = 0;
};

FeatureSize feature_size(const PlcDomain& dom);
FeatureSize feature_size_brute(const PlcDomain& dom);

}  // namespace pdr::refine
