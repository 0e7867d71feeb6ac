// bulk_insert (bulk.hpp).
#include "delaunay/bulk.hpp"

#include <numeric>

#include "delaunay/spatial_sort.hpp"
#include "geom/predicates.hpp"
#include "mesh/huge_pages.hpp"

namespace pdr {

namespace {

bool same_point(const Point& a, const Point& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Exact: a, b, c on one line iff all three coordinate projections are degenerate.
bool collinear(const Point& a, const Point& b, const Point& c) {
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    if (orient2d(pa, pb, pc) != Sign::Zero) return false;
  }
  return true;
}

}  // namespace

BulkResult bulk_insert(Delaunay& dt, const BulkOptions& options) {
  BulkResult result;
  const std::size_t n = dt.num_points();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  if (options.spatial_sort)
    order = brio_order(std::move(order), dt.points(), options.seed, options.min_round);
  if (options.renumber) {
    std::vector<Point> sorted;
    sorted.reserve(n);
    advise_huge_pages(sorted.data(), n * sizeof(Point));
    for (std::size_t i = 0; i < n; ++i) sorted.push_back(dt.point(order[i]));
    dt.set_points(std::move(sorted));
    result.input_index = std::move(order);
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
  } else {
    result.input_index.resize(n);
    std::iota(result.input_index.begin(), result.input_index.end(), 0u);
  }
  const auto pts = dt.points();

  // The first tet: positions ia < ib < ic < id in `order`.
  const std::size_t none = n;
  std::size_t ia = 0, ib = none, ic = none, id = none;
  if (n > 0) {
    for (std::size_t i = 1; i < n && ib == none; ++i)
      if (!same_point(pts[order[i]], pts[order[ia]])) ib = i;
    for (std::size_t i = ib + 1; ib != none && i < n && ic == none; ++i)
      if (!collinear(pts[order[ia]], pts[order[ib]], pts[order[i]])) ic = i;
    for (std::size_t i = ic + 1; ic != none && i < n && id == none; ++i)
      if (orient3d(pts[order[ia]], pts[order[ib]], pts[order[ic]], pts[order[i]]) !=
          Sign::Zero)
        id = i;
  }
  if (id == none) {
    if (ib == none) {
      result.status = BulkStatus::TooFewPoints;
      result.message = "too-few-points: fewer than two distinct points";
    } else if (ic == none) {
      result.status = BulkStatus::AllCollinear;
      result.message = "all-collinear: every point lies on one line";
    } else {
      result.status = BulkStatus::AllCoplanar;
      result.message = "all-coplanar: every point lies on one plane";
    }
    return result;
  }
  // Roughly 6.7 tets per point for uniform points; more is reallocated as needed.
  dt.reserve(n, 7 * n + 64);
  dt.init(order[ia], order[ib], order[ic], order[id]);
  TetId hint = dt.last_tet();
  for (std::size_t i = 0; i < n; ++i) {
    if (i == ia || i == ib || i == ic || i == id) continue;
    const InsertResult r = dt.insert(order[i], hint);
    if (r.outcome == Outcome::Duplicate)
      result.duplicates.push_back({result.input_index[order[i]], result.input_index[r.vertex]});
    hint = r.tet;
  }
  return result;
}

}  // namespace pdr
