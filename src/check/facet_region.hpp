// FacetRegion: the planar region of a PLC facet (paper §1.1: a planar, segment-bounded,
// polygonal facet, possibly with holes), projected to 2D, with exact point location and
// exact area.
//
// Semantics (those of TetGen's .poly facets): a facet is a set of polygons plus hole points
// in its plane. Polygons of three or more vertices bound cells; we require them to be
// simple and pairwise nested or interior-disjoint (they may share vertices and edges).
// The cell of a point is the innermost polygon containing it; a cell containing a facet
// hole point is removed. The region is the union of the remaining cells. Two-vertex
// polygons (segments inside the facet) and isolated points do not split cells. Crossing
// polygons are detected and reported as unsupported.
//
// Points are located exactly: a query point is the average of 1-3 doubles per coordinate
// (mesh face centroids, edge midpoints), compared by interval filters then GMP rationals.
// The projection drops one coordinate, so areas are the true areas times |n_drop| / |n|,
// the same factor for every triangle in the plane: sums compare exactly.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdr::check {

using P2 = std::array<double, 2>;

// The point (sum(x) / n, sum(y) / n), n in {1, 2, 3}.
struct Q2 {
  std::array<double, 3> x{}, y{};
  int n = 1;
  static Q2 at(const P2& p) { return {{p[0], 0, 0}, {p[1], 0, 0}, 1}; }
  static Q2 centroid(const P2& a, const P2& b, const P2& c) {
    return {{a[0], b[0], c[0]}, {a[1], b[1], c[1]}, 3};
  }
};

enum class Where : std::uint8_t { Inside, Outside, Boundary };

Where locate_in_polygon(const std::vector<P2>& polygon, const Q2& q);

// A polygon's edges bucketed by horizontal slabs of y, each holding a few of its vertices
// however they crowd: locate() visits only the edges of q's slabs, with the same exact
// decisions as locate_in_polygon (a polygon whose edges are the subsegment chains of a
// finely meshed facet has thousands of them).
class PolygonSlabs {
 public:
  explicit PolygonSlabs(const std::vector<P2>& polygon);
  Where locate(const std::vector<P2>& polygon, const Q2& q) const;
  // The sloped edges' listings (at most 8 per edge) and the most in one slab; horizontal
  // edges are kept apart.
  std::size_t listings() const { return edges_.size(); }
  std::size_t busiest() const;

 private:
  std::size_t slab(double y) const;
  struct Horizontal {
    double y, xmin, xmax;
    double reach = 0;  // the largest xmax of its row up to it (edges of a row may overlap)
    bool operator<(const Horizontal& o) const {
      return y != o.y ? y < o.y : xmin != o.xmin ? xmin < o.xmin : xmax < o.xmax;
    }
  };
  std::vector<Horizontal> horizontal_;  // sorted by y, xmin, xmax
  std::vector<double> bounds_;  // ascending: slab s holds y in [bounds_[s-1], bounds_[s])
  std::vector<std::size_t> start_{0, 0};
  std::vector<std::uint32_t> edges_;
};
// Twice the signed area of a polygon (shoelace), exact.
mpq_class area2(const std::vector<P2>& polygon);
// Twice the signed area of triangle abc, exact.
mpq_class area2(const P2& a, const P2& b, const P2& c);

class FacetRegion {
 public:
  FacetRegion(std::vector<std::vector<P2>> polygons, const std::vector<P2>& holes);

  bool supported() const { return supported_; }  // false: crossing polygons
  Where locate(const Q2& q) const;                // Inside/Outside the region, or Boundary
  const mpq_class& area2() const { return area2_; }  // twice the region's area (projected)

 private:
  int innermost(const Q2& q, bool& on_boundary) const;

  std::vector<std::vector<P2>> polygons_;
  std::vector<PolygonSlabs> slabs_;
  std::vector<int> parent_, depth_;
  std::vector<bool> removed_;  // cell of polygon i holds a hole point
  mpq_class area2_;
  bool supported_ = true;
};

}  // namespace pdr::check
