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

// Slabs: edge i is listed in every slab its y-range [min, max] meets. Slab of y:
// floor((y - y0) * inv) clamped, monotone in y (as the grids of grid.hpp), so an edge whose
// closed y-range holds q.y is in q.y's slab; the others do nothing in edge_step.
PolygonSlabs::PolygonSlabs(const std::vector<P2>& poly) {
  const std::size_t n = poly.size();
  if (n == 0) return;
  double lo = poly[0][1], hi = poly[0][1];
  for (const P2& p : poly) lo = std::min(lo, p[1]), hi = std::max(hi, p[1]);
  y0_ = lo;
  auto range = [&](std::size_t i) {
    const double ya = poly[i][1], yb = poly[(i + 1) % n][1];
    return std::pair{slab(std::min(ya, yb)), slab(std::max(ya, yb))};
  };
  // About one slab per two edges, halved until the edges' listings number at most 8 per
  // edge (long edges, as in a comb, span many slabs): memory stays linear in the polygon.
  for (slabs_ = static_cast<int>(std::clamp<std::size_t>(n / 2, 1, 1 << 16));; slabs_ /= 2) {
    inv_ = hi > lo ? slabs_ / (hi - lo) : 0.0;
    std::size_t listed = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto [s0, s1] = range(i);
      listed += static_cast<std::size_t>(s1 - s0) + 1;
    }
    if (slabs_ == 1 || listed <= 8 * n) break;
  }
  start_.assign(static_cast<std::size_t>(slabs_) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [s0, s1] = range(i);
    for (int s = s0; s <= s1; ++s) ++start_[s + 1];
  }
  for (int s = 0; s < slabs_; ++s) start_[s + 1] += start_[s];
  edges_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [s0, s1] = range(i);
    for (int s = s0; s <= s1; ++s) edges_[fill[s]++] = static_cast<std::uint32_t>(i);
  }
}

int PolygonSlabs::slab(double y) const {
  const double t = std::floor((y - y0_) * inv_);
  if (!(t > 0)) return 0;  // also NaN
  if (t >= slabs_ - 1) return slabs_ - 1;
  return static_cast<int>(t);
}

Where PolygonSlabs::locate(const std::vector<P2>& poly, const Q2& q) const {
  if (poly.empty()) return Where::Outside;
  // An interval holding q.y = sum / n: each division rounds to nearest, and down/up reach
  // past the neighbouring doubles.
  const Interval sum = isum(q.y, q.n);
  if (!sum.finite()) return locate_in_polygon(poly, q);
  const int s0 = slab(interval_detail::down(sum.lo / q.n)), s1 = slab(interval_detail::up(sum.hi / q.n));
  // q.y within a few ulps of a slab boundary (vertices of an axis-aligned dyadic facet):
  // the slabs around it, each edge once (in the first of them it is listed in).
  if (s1 - s0 > 2) return locate_in_polygon(poly, q);
  bool inside = false;
  const std::size_t n = poly.size();
  for (int s = s0; s <= s1; ++s)
    for (std::size_t k = start_[s]; k < start_[s + 1]; ++k) {
      const std::uint32_t i = edges_[k];
      const P2& a = poly[i];
      const P2& b = poly[(i + 1) % n];
      if (s > s0 && slab(std::min(a[1], b[1])) < s) continue;  // listed in slab s - 1 too
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
