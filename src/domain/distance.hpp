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
//
// Squared Euclidean distances between points, segments and triangles, in floating point.
//
// These serve the distance d of paper §2.1, which only says how finely the boundary is
// subdivided initially; d is a report and a size, never a combinatorial decision (docs/design.md
// §6), so it is computed in double. Each result carries a relative error of a few units
// in the last place of the inputs' coordinate differences; callers that need a strict
// lower bound of the true distance may shrink d by a relative 1e-12.

#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "domain/domain.hpp"
#include "geom/point.hpp"

namespace pdr::domain {

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

// The distance of paper §2.1 per component: for each segment and each face, the minimum
// distance to the components unrelated to it (sharing no vertex with it), times 1/sqrt(2)
// (infinity when none is unrelated). The minimum over all of them is feature_size's d.
// The graded initial surface mesh (surface/init.hpp) sizes each segment and facet by it.
// Branch and bound over the same hierarchy, from each segment and each facet triangle,
// with the exact distances between the component and the primitives of the unrelated
// ones (no reduction to boundaries: each query is against whole triangles); floating
// point, like d.
struct LocalFeatureSizes {
  std::vector<double> segment_d;  // per DomainSegment
  std::vector<double> facet_d;    // per DomainFacet (infinity for a facet that is no face)
};
LocalFeatureSizes local_feature_sizes(const PlcDomain& dom);
LocalFeatureSizes local_feature_sizes_brute(const PlcDomain& dom);

// Distances from a point to the components unrelated to a segment or to a facet (sharing no
// vertex with it), by branch and bound over the same hierarchy: the sizes of the surface
// mesh graded by position (surface/init.hpp). Floating point, like d. Holds a copy of what
// it needs of the domain.
class UnrelatedDistance {
 public:
  explicit UnrelatedDistance(const PlcDomain& dom);
  ~UnrelatedDistance();
  UnrelatedDistance(const UnrelatedDistance&) = delete;
  UnrelatedDistance& operator=(const UnrelatedDistance&) = delete;
  double to_segment_unrelated(std::uint32_t s, const Point& p) const;  // infinity: none
  double to_facet_unrelated(std::uint32_t f, const Point& p) const;
  // The sizes of surface/init.hpp at p: for segment s, (sqrt(2) - 1) times p's distance to
  // what is unrelated to s or to a facet containing s; for facet f, p's distance to what is
  // unrelated to f over sqrt(2).
  double segment_size_at(std::uint32_t s, const Point& p) const;
  double facet_size_at(std::uint32_t f, const Point& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

double dist2_point_point(const Point& p, const Point& q);
double dist2_point_segment(const Point& p, const Point& a, const Point& b);
double dist2_point_triangle(const Point& p, const Point& a, const Point& b, const Point& c);
double dist2_segment_segment(const Point& p, const Point& q, const Point& r, const Point& s);
// Preconditions: the segment does not pass through the triangle, the triangles do not
// intersect (true for unrelated components of a valid domain).
double dist2_segment_triangle(const Point& p, const Point& q, const Point& a, const Point& b,
                              const Point& c);
double dist2_triangle_triangle(const Point& a, const Point& b, const Point& c, const Point& d,
                               const Point& e, const Point& f);

}  // namespace pdr::domain
