// FacetRegion: exact point location and area of a projected facet (see facet_region.hpp).
#include "check/facet_region.hpp"

#include <optional>

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

Where locate_in_polygon(const std::vector<P2>& poly, const Q2& q) {
  bool inside = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2& a = poly[i];
    const P2& b = poly[(i + 1) % poly.size()];
    const Sign ya = compare(q, a[1], 1), yb = compare(q, b[1], 1);
    const bool y_between = to_int(ya) * to_int(yb) <= 0;
    if (y_between) {
      const Sign o = orient(a, b, q);
      if (o == Sign::Zero) {
        const Sign xa = compare(q, a[0], 0), xb = compare(q, b[0], 0);
        if (to_int(xa) * to_int(xb) <= 0) return Where::Boundary;
      }
      // Half-open rule: the edge spans the line y = q.y when exactly one end is above it.
      const bool a_above = ya == Sign::Negative, b_above = yb == Sign::Negative;
      if (a_above != b_above) {
        const bool crosses_right = b_above ? o == Sign::Positive : o == Sign::Negative;
        if (crosses_right) inside = !inside;
      }
    }
  }
  return inside ? Where::Inside : Where::Outside;
}

FacetRegion::FacetRegion(std::vector<std::vector<P2>> polygons, const std::vector<P2>& holes)
    : polygons_(std::move(polygons)) {
  const std::size_t n = polygons_.size();
  // contains[i][j]: polygon j lies inside polygon i.
  std::vector<std::vector<bool>> contains(n, std::vector<bool>(n, false));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      bool in = false, out = false;
      for (const P2& v : polygons_[j]) {
        const Where w = locate_in_polygon(polygons_[i], Q2::at(v));
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
    const Where w = locate_in_polygon(polygons_[i], q);
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
