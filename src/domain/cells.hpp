// The cells of a domain (paper §1.1: "a closed polyhedral domain, possibly having holes
// and voids"): the open regions its facets cut space into, and exact point location
// among them. domain/orient.cpp builds them to validate the domain and decide which cells
// form Ω; the refinement locates tets in them for regional volume bounds.
//
// How the cells are found:
//   1. the facet sides around each segment are sorted by angle about a->b
//      (domain/orient.cpp, before the cells are built);
//   2. every triangle has two sides, front (where (v1-v0)x(v2-v0) points) and back. Sides
//      are joined within a facet (its triangles are oriented alike) and across each wedge
//      between consecutive facets around a segment: the wedge from side x to the next side
//      y (positive rotation about a->b) is bounded by x's side facing the rotation (front
//      iff x runs a->b) and y's side facing back (a free edge, with one side, joins the
//      facet's two sides). A connected set of sides ("component")
//      lies in the closure of one cell. Its one-sided triangles (those whose other side
//      is another component) form a surface closed mod 2: each wedge adds two sides of a
//      segment, and a triangle with both sides in it cancels. (Within a facet, sides are
//      not joined across a segment lying in it: the wedges around it do that.);
//   3. each component is seeded by an exact ray leaving a rational point inside one of its
//      one-sided triangles on its side, along the axis of that triangle's largest normal
//      component, counting crossings per component (orient3d / orient2d of the rational
//      point, domain/exact.hpp: a floating-point filter, then GMP); the ray's origin is
//      moved symbolically off every edge line it meets, so one ray always decides, whatever
//      the input's symmetry. An odd count of its own surface means the component's cell
//      lies inside that surface: it is the cell's outer boundary ("outer"), and each
//      bounded cell has exactly one. Otherwise the component bounds a cavity of the cell
//      around it: the innermost outer surface enclosing the seed point (the outer surfaces
//      nest like the cells they bound; depth orders them).
// A facet wall splitting a region (a segment with three facet sides) gives two cells with
// the wall between them; a closed shell inside another, a cell inside a cell. A point is
// located with one axis ray from it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "domain/bvh.hpp"
#include "domain/domain.hpp"
#include "domain/exact.hpp"

namespace pdr::domain {

struct TriRef {
  std::uint32_t facet, tri;
};

// The domain's triangles numbered g = offset[facet] + tri, in a box hierarchy, and exact
// axis rays against them.
class RayCaster {
 public:
  explicit RayCaster(const PlcDomain& dom);
  const std::vector<TriRef>& tris() const { return tris_; }
  const FacetTri& tri(const TriRef& r) const { return dom_.facets[r.facet].tris[r.tri]; }
  const Bvh& bvh() const { return bvh_; }
  // hit(g) for every triangle g the ray from o along dir * e_axis crosses, o symbolically
  // moved off every line and plane it lies on, skipping triangle `skip`. Precondition: o
  // lies in no triangle but the skipped one.
  template <class Hit>
  void cast_axis(const RatPoint& o, int axis, int dir, std::int64_t skip, Hit&& hit) const {
    auto keep = [&](const Box& b) {
      for (int j = 0; j < 3; ++j) {
        if (j == axis) continue;
        if (o.d[j] + o.err < b.lo[j] || o.d[j] - o.err > b.hi[j]) return false;
      }
      return dir > 0 ? o.d[axis] - o.err <= b.hi[axis] : o.d[axis] + o.err >= b.lo[axis];
    };
    bvh_.for_each_kept(keep, [&](std::uint32_t i) {
      if (static_cast<std::int64_t>(i) != skip && crosses(o, axis, dir, i)) hit(i);
    });
  }

 private:
  bool crosses(const RatPoint& o, int axis, int dir, std::uint32_t i) const;

  const PlcDomain& dom_;
  std::vector<TriRef> tris_;
  Bvh bvh_;
};

// The components of step 2, their seeds and nesting (step 3), and the cells. Needs the
// sides around each segment sorted (DomainSegment::sides); keeps a reference to dom.
class Cells {
 public:
  explicit Cells(const PlcDomain& dom);

  const RayCaster& rays() const { return rays_; }
  std::size_t count() const { return outer_.size(); }  // bounded cells
  int cell_of_side(std::uint32_t facet, std::uint32_t tri, int side) const;
  // Whether the seed ray of cell c's outer boundary crosses the triangles an odd number
  // of times: the cell is enclosed by an odd number of closed surfaces (meaningful when
  // the boundary is closed mod 2).
  bool seed_parity(int c) const { return seed_total_[outer_[c]] % 2 == 1; }
  // The cell holding p (off every facet): -1 for the unbounded one. `total` gets the ray's
  // crossings with every triangle.
  int locate(const RatPoint& p, int* total = nullptr) const;

 private:
  void join_sides();
  int cast(const RatPoint& o, int axis, int dir, std::int64_t skip, std::vector<int>& odd) const;
  void seed_components();
  int innermost(const std::vector<int>& odd) const;
  void number_cells();

  const PlcDomain& dom_;
  RayCaster rays_;
  std::vector<std::size_t> offset_;      // first triangle number of each facet
  std::vector<int> comp_;                // per side node: its component
  std::size_t comps_ = 0;
  std::vector<std::vector<int>> odd_;    // per component: components its seed ray crossed oddly
  std::vector<int> seed_total_;          // per component: its seed ray's crossings, all triangles
  std::vector<std::uint8_t> is_outer_;   // per component: the outer boundary of its cell
  std::vector<int> depth_;               // per outer component: outer components around it
  std::vector<int> cell_;                // per component: its cell (-1: unbounded)
  std::vector<int> outer_;               // per cell: its outer component
};

// Regional volume bounds: a region record's volume (TetGen's -a without a number) bounds
// the tets of the cell its point lies in; the smallest bound wins where several points
// share a cell. A tet lies in the cell of its centroid (exact: a tet of a conforming mesh
// crosses no facet, so its interior lies in one cell).
class RegionVolumes {
 public:
  // Null when no region record of dom gives a volume bound. Keeps a copy of dom.
  static std::shared_ptr<const RegionVolumes> of(const PlcDomain& dom);
  double smallest() const { return smallest_; }
  // The bound of the cell holding the centroid of abcd; 0 when that cell has none.
  double bound(const Point& a, const Point& b, const Point& c, const Point& d) const;

 private:
  explicit RegionVolumes(const PlcDomain& dom);
  PlcDomain dom_;
  Cells cells_;
  std::vector<double> bound_;  // per cell; 0: none
  double smallest_ = 0;
};

}  // namespace pdr::domain
