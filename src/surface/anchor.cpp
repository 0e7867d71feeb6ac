// Placement planes anchored at sharp features; see surface/anchor.hpp.
#include "surface/anchor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace pdr::surface {

namespace {

using Vec = std::array<double, 3>;

// Features sharper than this (degrees) anchor the plane; right angles bent by rounding do
// not.
constexpr double kSharp = 80;

Vec sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& u, const Vec& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
Vec cross(const Vec& u, const Vec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// The direction from segment ab into the side's triangle, perpendicular to ab.
Vec into_side(const std::vector<Point>& pts, const domain::DomainSegment& s, const domain::HalfFacet& h) {
  const Vec e = sub(pts[s.b], pts[s.a]);
  const Vec w = sub(pts[h.apex], pts[s.a]);
  const double t = dot(w, e) / dot(e, e);
  return {w[0] - t * e[0], w[1] - t * e[1], w[2] - t * e[2]};
}

// The smallest angle (degrees) between a half-plane of facet f and one of another facet
// along segment s; 180 when no other facet holds s.
double sharpness(const domain::PlcDomain& dom, std::uint32_t f, const domain::DomainSegment& s) {
  const std::vector<Point>& pts = dom.plc.points;
  double best = 180;
  for (const domain::HalfFacet& hf : s.sides) {
    if (hf.facet != f) continue;
    const Vec u = into_side(pts, s, hf);
    for (const domain::HalfFacet& hg : s.sides) {
      if (hg.facet == f) continue;
      const Vec v = into_side(pts, s, hg);
      const double c = dot(u, v) / std::sqrt(dot(u, u) * dot(v, v));
      best = std::min(best, std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi);
    }
  }
  return best;
}

// The sharpest corner of facet f: the vertex whose angle in f (the sum of its triangles'
// angles there; 360 degrees inside f) lies closest to 0 or 360 degrees, and that distance.
std::pair<std::uint32_t, double> sharpest_corner(const std::vector<Point>& pts, const domain::DomainFacet& F) {
  std::vector<double> sum(F.vertices.size(), 0);
  for (const domain::FacetTri& t : F.tris)
    for (int i = 0; i < 3; ++i) {
      const Point& o = pts[t.v[i]];
      const Vec u = sub(pts[t.v[(i + 1) % 3]], o), v = sub(pts[t.v[(i + 2) % 3]], o);
      const double c = dot(u, v) / std::sqrt(dot(u, u) * dot(v, v));
      const auto k = std::lower_bound(F.vertices.begin(), F.vertices.end(), t.v[i]) - F.vertices.begin();
      sum[static_cast<std::size_t>(k)] += std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi;
    }
  std::pair<std::uint32_t, double> best{0, 180};
  for (std::size_t k = 0; k < sum.size(); ++k) {
    if (sum[k] == 0 || sum[k] > 359) continue;  // not a corner of a triangle, or inside f
    const double sharp = std::min(sum[k], 360 - sum[k]);
    if (sharp < best.second) best = {F.vertices[k], sharp};
  }
  return best;
}

// The largest distance of facet f's vertices from the plane through a, b, c.
double farthest_from(const std::vector<Point>& pts, const domain::DomainFacet& F, const Point& a,
                     const Point& b, const Point& c) {
  const Vec n = cross(sub(b, a), sub(c, a));
  const double len = std::sqrt(dot(n, n));
  double d = 0;
  for (const std::uint32_t v : F.vertices) d = std::max(d, std::fabs(dot(n, sub(pts[v], a))) / len);
  return d;
}

}  // namespace

domain::FacetPlane placement_plane(const domain::PlcDomain& dom, std::uint32_t f) {
  const domain::DomainFacet& F = dom.facets[f];
  domain::FacetPlane plane = F.plane;
  if (plane.exact || F.tris.empty()) return plane;
  const std::vector<Point>& pts = dom.plc.points;
  const domain::DomainSegment* sharp = nullptr;
  double angle = kSharp;
  for (const std::uint32_t s : F.segments)
    if (const double a = sharpness(dom, f, dom.segments[s]); a < angle) angle = a, sharp = &dom.segments[s];
  const auto [corner, corner_angle] = sharpest_corner(pts, F);
  // The anchor: both ends of the sharpest segment and the vertex farthest from their line,
  // or the sharpest corner, the vertex farthest from it and the one spanning the largest
  // triangle with them (the defining triple's rule, surface/chart.hpp, from another start).
  std::array<std::uint32_t, 3> t{};
  const auto widest = [&](std::uint32_t a, std::uint32_t b) {
    const Vec e = sub(pts[b], pts[a]);
    std::uint32_t c = a;
    double area = 0;
    for (const std::uint32_t v : F.vertices) {
      const Vec n = cross(e, sub(pts[v], pts[a]));
      if (const double x = dot(n, n); x > area) area = x, c = v;
    }
    return c;
  };
  if (sharp && angle <= corner_angle) {
    t = {sharp->a, sharp->b, widest(sharp->a, sharp->b)};
  } else if (corner_angle < kSharp) {
    std::uint32_t far = corner;
    double d = 0;
    for (const std::uint32_t v : F.vertices) {
      const Vec w = sub(pts[v], pts[corner]);
      if (const double x = dot(w, w); x > d) d = x, far = v;
    }
    t = {corner, far, widest(corner, far)};
  } else {
    return plane;
  }
  if (t[2] == t[0] || t[2] == t[1] || t[0] == t[1]) return plane;
  const auto& old = plane.triple;
  const double before = farthest_from(pts, F, pts[old[0]], pts[old[1]], pts[old[2]]);
  if (farthest_from(pts, F, pts[t[0]], pts[t[1]], pts[t[2]]) > 2 * before) return plane;
  const Sign o = domain::orient2d(plane.projection(pts[t[0]]), plane.projection(pts[t[1]]),
                                  plane.projection(pts[t[2]]));
  if (o == Sign::Zero) return plane;
  if (o == Sign::Negative) std::swap(t[1], t[2]);
  plane.triple = t;
  return plane;
}

}  // namespace pdr::surface
