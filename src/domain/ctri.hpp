// A constrained triangulation of a planar straight-line graph, decided by orient2d alone.
//
// Used to triangulate each facet of the domain in its projection (paper §1.1: facets are
// "not necessarily convex planar, segment-bounded polygonal" regions, possibly with holes,
// interior segments and isolated vertices), so that every later test on a facet is a test
// on triangles with input vertices as corners.
//
// Construction: a lexicographic sweep builds a triangulation of the convex hull (each new
// point is outside the current hull, so it is joined to the hull edges it sees); then each
// constraint is recovered by flipping the edges that cross it (Sloan 1993: some crossing
// edge is always flippable, and the walk that collects the crossing edges detects a
// constraint through a vertex or across another constraint). Then Lawson's flips (exact
// incircle) make it the constrained Delaunay triangulation: a flip replaces an
// unconstrained edge whose quadrilateral's fourth vertex lies strictly inside a triangle's
// circumcircle, and the flips end (Lawson 1977: each lowers the triangulation on the
// lifting paraboloid). Why Delaunay: a facet read from a rotated part has straight sides
// whose vertices are collinear only to a few ulps; a triangulation that joins three of them
// in a sliver has a chord that misses the middle one by ulps on the side of the
// neighbouring facet, so it crosses that facet although the input does not; the
// constrained Delaunay triangulation joins them to a vertex across the facet instead.
// Region classification floods from the hull across unconstrained edges (Outside), then
// from each hole point (Hole); the rest is Inside.
//
// Invariants after build() == Ok: every triangle is counter-clockwise (orient2d > 0);
// n[i] is the neighbour across the edge opposite v[i] (-1 on the hull) and neighbours
// agree; fixed[i] is set on both sides of every constraint edge and on no other edge.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "domain/exact.hpp"

namespace pdr::domain {

struct Ct2Tri {
  std::array<std::uint32_t, 3> v{};
  std::array<std::int32_t, 3> n{-1, -1, -1};
  std::array<bool, 3> fixed{};
};

enum class Ct2Status : std::uint8_t { Ok, Duplicate, Collinear, ThroughVertex, Crossing };

struct Ct2Outcome {
  Ct2Status status = Ct2Status::Ok;
  std::uint32_t a = 0, b = 0;  // Duplicate: the points; ThroughVertex, Crossing: the constraint
  std::uint32_t c = 0, d = 0;  // ThroughVertex: c, the vertex; Crossing: the crossed edge cd
};

enum class Ct2Region : std::uint8_t { Inside, Outside, Hole };

// Where a point lies relative to a triangulation.
struct Ct2Location {
  std::int32_t tri = -1;  // -1: outside the convex hull
  int zeros = 0;          // 0: interior of tri, 1: on its edge `edge`, 2: at a vertex
  int edge = -1;          // with zeros == 1: the index of the vertex opposite that edge
};

class Ct2 {
 public:
  Ct2Outcome build(std::vector<P2> points, const std::vector<std::array<std::uint32_t, 2>>& constraints);

  const std::vector<P2>& points() const { return pts_; }
  const std::vector<Ct2Tri>& tris() const { return tris_; }

  Ct2Location locate(const P2& p) const;
  // Outside = reachable from the hull without crossing a constraint; Hole = reachable from
  // a triangle of `hole_seeds` without crossing a constraint; Inside = the rest.
  std::vector<Ct2Region> regions(const std::vector<std::int32_t>& hole_seeds) const;

 private:
  Sign orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    return orient2d(pts_[a], pts_[b], pts_[c]);
  }
  static int index_of(const Ct2Tri& t, std::uint32_t v);
  static int opposite(const Ct2Tri& t, std::uint32_t a, std::uint32_t b);
  void link(std::int32_t t1, std::int32_t t2, std::uint32_t a, std::uint32_t b);
  std::int32_t add_tri(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  bool hull_sweep(const std::vector<std::uint32_t>& ord);
  // A triangle containing edge ab (and the index of its third vertex), or tri = -1.
  std::pair<std::int32_t, int> find_edge(std::uint32_t a, std::uint32_t b) const;
  Ct2Outcome insert_constraint(std::uint32_t u, std::uint32_t v);
  Ct2Outcome crossing_edges(std::uint32_t u, std::uint32_t v,
                            std::vector<std::array<std::uint32_t, 2>>& out) const;
  void flip(std::int32_t t, int i);
  void make_delaunay();
  void mark_fixed(std::uint32_t a, std::uint32_t b);

  std::vector<P2> pts_;
  std::vector<Ct2Tri> tris_;
  std::vector<std::int32_t> vt_;  // a triangle incident to each vertex
};

}  // namespace pdr::domain
