// Mesh initialization, paper §2.1 steps 1 and 2: the surface mesh D_o.
//
//   Step 1, segment refinement: split every subsegment at its midpoint until each is
//     shorter than 2d (surface/split.hpp). Terminates for any domain: lengths halve.
//   Step 2, facet refinement: each face starts as the Delaunay triangulation of its
//     vertices (input vertices and the step 1 vertices on its segments) restricted to the
//     face (surface/build.hpp, then the step 1 splits as Bowyer-Watson insertions); then
//     circumcenters of subfacets with circumradius >= d√2 are inserted (surface/insert.hpp)
//     until every circumradius is < d√2. A circumcenter that encroaches a subsegment (or
//     falls outside the facet) is not inserted: the subsegment is split instead, in every
//     facet containing it (Fig. 2). One FIFO queue over all facets; splits may add
//     subfacets to facets already refined, which are queued too.
// Termination. After step 1 every subsegment is shorter than 2d, and the facet
// triangulations are Delaunay, so a circumcenter c of a subfacet with circumradius R >= d√2
// has no vertex closer than R. If c were in the closed diametral ball of a subsegment ab
// (a, b at distance >= R from c), then |ab|^2 = |c-a|^2 + |c-b|^2 - 2 (c-a).(c-b) >= 2R^2
// >= 4d^2: impossible. So in exact arithmetic (coplanar facet vertices, and for an
// admissible domain, where no subsegment is encroached after step 1 so the constrained
// triangulations are Delaunay) step 2 splits nothing; all vertices stay pairwise at least
// d apart, and a packing argument bounds their number by O(L / d + A / d^2) (below).
// Guard (a run never hangs, even with rounding or inadmissible input): the number of
// vertices is capped at V_input + 16 (L / d + A / d^2) + 1024 (L: total segment length,
// A: total facet area, in floating point: a resource limit, not a geometric decision), at
// what a quarter of the machine's memory holds (kSurfaceVertexBytes a vertex: a domain
// whose d is tiny beside its size would otherwise run out of memory before the cap), at
// SurfaceOptions::max_vertices when that is set and smaller, and never above 2^31 (vertex
// ids are 32-bit). Reaching it throws SurfaceCapError("surface.cap: <facet or segment>:
// ..."). A mesh whose estimate already says it cannot fit is not started: when
// estimate / kEstimateOverLeast exceeds the cap, SurfaceCapError("surface.cap:
// before refinement: ...") at once (a 10 x 10 x 0.001 plate reached the memory cap after
// 88 s and 5.6 GB before). The finished meshes hold 0.24-0.44 times the estimate (the
// data/ domains, a 100 x 1 x 1 bar, a box with a small void; uniform and graded; tested
// to hold more than twice the bound), so this stops no run that would fit. A degenerate cavity (excluded by the exact arguments for coplanar points) throws
// SurfaceError naming the facet.
// d infinite (no two unrelated components) or not positive: nothing is refined.
//
// Graded variant (issue #11: one small feature anywhere makes the uniform mesh fine
// everywhere). Each facet F is refined for its own d_F and each segment S for
// d'_S = min(d_S, d_F over the facets F containing S), where d_X is the distance from X
// to the components unrelated to X, times 1/sqrt(2) (domain::local_feature_sizes; every
// d_X >= d). (d_S alone can exceed d_F: a cube's edge is farther from a void inside than
// the cube's face is; a property test found the step 2 splits that then follow.)
// Properties 2 and 3 of §2.1 hold per element: subsegments of S shorter than 2 d'_S,
// subfacets of F of circumradius below d_F sqrt(2). What Lemma 1 takes from them still
// holds:
//   - a point on S (a subsegment midpoint) encroaches nothing unrelated to S: the
//     diametral ball of a subsegment of S' has radius below d'_S' <= dist(S', X)/sqrt(2)
//     for X unrelated to S', so it reaches no point of X (likewise for the equatorial
//     balls of subfacets of F);
//   - step 2's termination argument runs per facet: a circumcenter of a subfacet of F with
//     R >= d_F sqrt(2) encroaches no subsegment of F's boundary, each shorter than
//     2 d'_S <= 2 d_F;
//   - invariants 2-4 use h < d, and every d_X >= d.
// By position (what init_surface builds): each subsegment is refined for the larger of
// d'_S and (sqrt(2) - 1) times its midpoint's distance to the components unrelated to S or
// to a facet containing S, each subfacet for the larger of d_F and its circumcenter's
// distance to the components unrelated to F over sqrt(2)
// (SurfaceMesh::subsegment_size, subfacet_size): one small gap makes only the part of a
// facet near it fine, not the whole facet. Every size is still at least d, and each of the
// two arguments above holds for whichever term is the larger:
//   - balls: a subsegment of length l < 2 (sqrt(2) - 1) dist(m, X) has its diametral ball
//     (radius l/2 < dist(m, X)) clear of X; a subfacet with R < dist(c, X) has its
//     equatorial ball clear of X;
//   - step 2: a circumcenter c of a subfacet of F with R >= dist(c, X_F) inside the
//     diametral ball of a boundary subsegment ab (midpoint m) has R <= |ab|/sqrt(2) and
//     |c - m| <= |ab|/2, so dist(m, X_F) <= R + |ab|/2 <= |ab| (1/sqrt(2) + 1/2); and
//     |ab| < 2 (sqrt(2) - 1) dist(m, X_F) = dist(m, X_F) / (1/sqrt(2) + 1/2): impossible.
//     (Against d'_S, as before with d_F.) So step 2 still splits nothing.
// Its estimate cuts segments and the facets' first triangles into pieces no larger than the
// size at their middle and sums length / size and area / size^2.
// Not carried over: property 1's unencroached start between RELATED elements of
// different sizes (a coarse subfacet next to the fine subfacets of a facet across a
// right angle); SeqRefinement refines what T_o has encroached before anything else
// (refine/seq_refinement.hpp) and claims Theorem 1's h only when there was nothing.
// Estimates: sum over segments of length / d'_S plus sum over facets of area / d_F^2,
// against the same with d: the order of the vertices each variant adds.
#pragma once

#include <cstddef>

#include "domain/analysis.hpp"
#include "domain/domain.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::surface {

// Memory of one surface vertex with its share of subsegments, subfacets and incidence
// lists, for the memory part of the cap (measured: about 200 bytes; rounded up).
inline constexpr std::size_t kSurfaceVertexBytes = 256;
// The estimate over a lower bound of the vertices the finished mesh holds (see above).
inline constexpr double kEstimateOverLeast = 10;

// Uniform: paper §2.1 with the global d. Graded: each segment and facet with its own d
// (see above). Auto: uniform unless the graded mesh is estimated at least kGradedGain
// times smaller.
enum class SurfaceSizing { Auto, Uniform, Graded };
inline constexpr double kGradedGain = 4;

struct SurfaceOptions {
  std::size_t max_vertices = 0;  // 0: the derived cap only
  SurfaceSizing sizing = SurfaceSizing::Auto;
};

struct SurfaceStats {
  std::size_t segment_splits = 0;        // step 1
  std::size_t circumcenters = 0;         // step 2 insertions
  std::size_t encroachment_splits = 0;   // step 2 subsegment splits instead of circumcenters
  std::size_t vertex_cap = 0;            // the guard in force
  bool graded = false;                   // the sizing used
  double uniform_estimate = 0, graded_estimate = 0;  // the vertex estimates it chose by
};

struct SurfaceInit {
  SurfaceMesh mesh;
  SurfaceStats stats;
};

// d: paper §2.1 (domain::DomainReport::feature.d).
SurfaceInit init_surface(const domain::PlcDomain& dom, double d, const SurfaceOptions& options = {});
SurfaceInit init_surface(const domain::DomainAnalysis& analysis, const SurfaceOptions& options = {});

}  // namespace pdr::surface
