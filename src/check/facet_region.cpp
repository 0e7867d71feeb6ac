// FacetRegion: exact point location and area of a projected facet (see facet_region.hpp).
#include "check/facet_region.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "check/interval.hpp"

namespace pdr::check {
namespace {

using Q = mpq_class;

Sign qsign(const Q& x) { return pdr::sign_of(sgn(x)); }

Interval isum(const std::array<double, 3>& v, int n) {
  Interval s(v[0]);
  for (int i = 1; i < n; ++i) s = s + Interval(v[i]);
  return s;
}
Q qsum(const std::array<double, 3>& v, int n) {
  Q s(v[0]);
  for (int i = 1; i < n; ++i) s += Q(v[i]);
  return s;
}

// sign(q.c - a), c = 0 (x) or 1 (y).
Sign compare(const Q2& q, double a, int c) {
  const auto& v = c == 0 ? q.x : q.y;
  if (auto s = interval_sign(isum(v, q.n) - Interval(q.n) * Interval(a))) return *s;
  return qsign(qsum(v, q.n) - q.n * Q(a));
}

// orient2d(a, b, q): sign of (b - a) x (q - a), times n > 0.
Sign orient(const P2& a, const P2& b, const Q2& q) {
  {
    const Interval n(q.n);
    const Interval sx = isum(q.x, q.n) - n * Interval(a[0]);
    const Interval sy = isum(q.y, q.n) - n * Interval(a[1]);
    const Interval d = (Interval(b[0]) - Interval(a[0])) * sy - (Interval(b[1]) - Interval(a[1])) * sx;
    if (auto s = interval_sign(d)) return *s;
  }
  const Q sx = qsum(q.x, q.n) - q.n * Q(a[0]), sy = qsum(q.y, q.n) - q.n * Q(a[1]);
  return qsign((Q(b[0]) - Q(a[0])) * sy - (Q(b[1]) - Q(a[1])) * sx);
}

}  // namespace

Q area2(const P2& a, const P2& b, const P2& c) {
  return (Q(b[0]) - Q(a[0])) * (Q(c[1]) - Q(a[1])) - (Q(b[1]) - Q(a[1])) * (Q(c[0]) - Q(a[0]));
}

Q area2(const std::vector<P2>& poly) {
  Q s = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2& a = poly[i];
    const P2& b = poly[(i + 1) % poly.size()];
    s += Q(a[0]) * Q(b[1]) - Q(b[0]) * Q(a[1]);
  }
  return s;
}

namespace {

// Edge a -> b of a polygon against the horizontal ray from q to the right: whether q lies
// on the edge (Boundary), else toggles `inside` when the edge crosses the ray (half-open
// rule: it spans the line y = q.y when exactly one end is above it). An edge with both ends
// strictly above or strictly below q does nothing.
bool edge_step(const P2& a, const P2& b, const Q2& q, bool& inside) {
  const Sign ya = compare(q, a[1], 1), yb = compare(q, b[1], 1);
  if (to_int(ya) * to_int(yb) > 0) return false;
  const Sign o = orient(a, b, q);
  if (o == Sign::Zero) {
    const Sign xa = compare(q, a[0], 0), xb = compare(q, b[0], 0);
    if (to_int(xa) * to_int(xb) <= 0) return true;
  }
  const bool a_above = ya == Sign::Negative, b_above = yb == Sign::Negative;
  if (a_above != b_above) {
    const bool crosses_right = b_above ? o == Sign::Positive : o == Sign::Negative;
    if (crosses_right) inside = !inside;
  }
  return false;
}

}  // namespace

Where locate_in_polygon(const std::vector<P2>& poly, const Q2& q) {
  bool inside = false;
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (edge_step(poly[i], poly[(i + 1) % poly.size()], q, inside)) return Where::Boundary;
  return inside ? Where::Inside : Where::Outside;
}

// Slabs: edge i is listed in every slab its y-range [min, max] meets. The slabs' bounds are
// every step-th of the polygon's distinct vertex y's, so each slab holds about `step`
// vertices however they crowd (a subsegment chain refined toward a sharp corner puts
// thousands of vertices in a millionth of the facet's height, where slabs of equal height
// listed them all in one). Slab of y: the number of bounds at or below it, monotone in y
// (as the grids of grid.hpp), so an edge whose closed y-range holds q.y is in a slab
// between those of q.y's lower and upper bounds; the others do nothing in edge_step.
PolygonSlabs::PolygonSlabs(const std::vector<P2>& poly) {
  const std::size_t n = poly.size();
  if (n == 0) return;
  std::vector<double> ys;
  ys.reserve(n);
  for (const P2& p : poly) ys.push_back(p[1]);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  auto range = [&](std::size_t i) {
    const double ya = poly[i][1], yb = poly[(i + 1) % n][1];
    return std::pair{slab(std::min(ya, yb)), slab(std::max(ya, yb))};
  };
  // Horizontal edges never toggle the ray's parity (both ends on one side of q.y, or both
  // on it): they only say Boundary, and are kept apart, by y and then x.
  std::vector<std::size_t> sloped;
  for (std::size_t i = 0; i < n; ++i) {
    const P2& a = poly[i];
    const P2& b = poly[(i + 1) % n];
    if (a[1] == b[1])
      horizontal_.push_back({a[1], std::min(a[0], b[0]), std::max(a[0], b[0])});
    else
      sloped.push_back(i);
  }
  std::sort(horizontal_.begin(), horizontal_.end());
  for (std::size_t k = 0; k < horizontal_.size(); ++k)
    horizontal_[k].reach = k > 0 && horizontal_[k - 1].y == horizontal_[k].y
                               ? std::max(horizontal_[k - 1].reach, horizontal_[k].xmax)
                               : horizontal_[k].xmax;
  // Two vertices per slab, the step doubled until the edges' listings number at most 8 per
  // edge (long edges, as in a comb, span many slabs): memory stays linear in the polygon.
  for (std::size_t step = 2;; step *= 2) {
    bounds_.clear();
    for (std::size_t k = step; k < ys.size(); k += step) bounds_.push_back(ys[k]);
    std::size_t listed = 0;
    for (const std::size_t i : sloped) {
      const auto [s0, s1] = range(i);
      listed += static_cast<std::size_t>(s1 - s0) + 1;
    }
    if (bounds_.empty() || listed <= 8 * n) break;
  }
  const std::size_t slabs = bounds_.size() + 1;
  start_.assign(slabs + 1, 0);
  for (const std::size_t i : sloped) {
    const auto [s0, s1] = range(i);
    for (std::size_t s = s0; s <= s1; ++s) ++start_[s + 1];
  }
  for (std::size_t s = 0; s < slabs; ++s) start_[s + 1] += start_[s];
  edges_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (const std::size_t i : sloped) {
    const auto [s0, s1] = range(i);
    for (std::size_t s = s0; s <= s1; ++s) edges_[fill[s]++] = static_cast<std::uint32_t>(i);
  }
}

std::size_t PolygonSlabs::busiest() const {
  std::size_t most = 0;
  for (std::size_t s = 0; s + 1 < start_.size(); ++s) most = std::max(most, start_[s + 1] - start_[s]);
  return most;
}

std::size_t PolygonSlabs::slab(double y) const {
  return static_cast<std::size_t>(std::upper_bound(bounds_.begin(), bounds_.end(), y) -
                                  bounds_.begin());
}

Where PolygonSlabs::locate(const std::vector<P2>& poly, const Q2& q) const {
  if (poly.empty()) return Where::Outside;
  // An interval holding q.y = sum / n: each division rounds to nearest, and down/up reach
  // past the neighbouring doubles.
  const Interval sum = isum(q.y, q.n);
  if (!sum.finite()) return locate_in_polygon(poly, q);
  const double ylo = interval_detail::down(sum.lo / q.n), yhi = interval_detail::up(sum.hi / q.n);
  // On a horizontal edge: its y is q.y exactly, and q.x lies between its ends. The edges at
  // one y are sorted by their left ends: the candidates start at or left of q.x and reach
  // it (interior-disjoint edges, as a simple polygon's: the last one or two).
  const Interval xsum = isum(q.x, q.n);
  if (!xsum.finite()) return locate_in_polygon(poly, q);
  const double xhi = interval_detail::up(xsum.hi / q.n), xlo = interval_detail::down(xsum.lo / q.n);
  auto h = std::lower_bound(horizontal_.begin(), horizontal_.end(), Horizontal{ylo, -HUGE_VAL, -HUGE_VAL});
  while (h != horizontal_.end() && h->y <= yhi) {
    const double y = h->y;
    const auto row_end = std::upper_bound(h, horizontal_.end(), Horizontal{y, HUGE_VAL, HUGE_VAL});
    if (compare(q, y, 1) == Sign::Zero) {
      auto c = std::upper_bound(h, row_end, Horizontal{y, xhi, HUGE_VAL});
      while (c != h) {
        --c;
        if (c->reach < xlo) break;
        if (to_int(compare(q, c->xmin, 0)) * to_int(compare(q, c->xmax, 0)) <= 0)
          return Where::Boundary;
      }
    }
    h = row_end;
  }
  const std::size_t s0 = slab(ylo), s1 = slab(yhi);
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t s = s0; s <= s1; ++s)
    for (std::size_t k = start_[s]; k < start_[s + 1]; ++k) {
      const std::uint32_t i = edges_[k];
      const P2& a = poly[i];
      const P2& b = poly[(i + 1) % n];
      if (s > s0 && slab(std::min(a[1], b[1])) < s) continue;  // met in an earlier slab
      if (edge_step(a, b, q, inside)) return Where::Boundary;
    }
  return inside ? Where::Inside : Where::Outside;
}

FacetRegion::FacetRegion(std::vector<std::vector<P2>> polygons, const std::vector<P2>& holes)
    : polygons_(std::move(polygons)) {
  const std::size_t n = polygons_.size();
  for (const auto& poly : polygons_) slabs_.emplace_back(poly);
  // contains[i][j]: polygon j lies inside polygon i.
  std::vector<std::vector<bool>> contains(n, std::vector<bool>(n, false));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      bool in = false, out = false;
      for (const P2& v : polygons_[j]) {
        const Where w = slabs_[i].locate(polygons_[i], Q2::at(v));
        in = in || w == Where::Inside;
        out = out || w == Where::Outside;
      }
      if (in && out) supported_ = false;  // crossing polygons
      contains[i][j] = in && !out;
    }
  parent_.assign(n, -1);
  depth_.assign(n, 0);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i)
      if (contains[i][j]) ++depth_[j];
  }
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      if (contains[i][j] && (parent_[j] < 0 || depth_[i] > depth_[parent_[j]]))
        parent_[j] = static_cast<int>(i);
  removed_.assign(n, false);
  for (const P2& h : holes) {
    bool boundary = false;
    const int c = innermost(Q2::at(h), boundary);
    if (c >= 0 && !boundary) removed_[c] = true;
  }
  area2_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (removed_[i]) continue;
    area2_ += abs(check::area2(polygons_[i]));
    for (std::size_t j = 0; j < n; ++j)
      if (parent_[j] == static_cast<int>(i)) area2_ -= abs(check::area2(polygons_[j]));
  }
}

int FacetRegion::innermost(const Q2& q, bool& on_boundary) const {
  int best = -1;
  on_boundary = false;
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    const Where w = slabs_[i].locate(polygons_[i], q);
    if (w == Where::Boundary) on_boundary = true;
    if (w == Where::Inside && (best < 0 || depth_[i] > depth_[best])) best = static_cast<int>(i);
  }
  return best;
}

Where FacetRegion::locate(const Q2& q) const {
  bool boundary = false;
  const int c = innermost(q, boundary);
  if (boundary) return Where::Boundary;
  return (c >= 0 && !removed_[c]) ? Where::Inside : Where::Outside;
}

}  // namespace pdr::check
