// Rotation copies around sharp axes; see refine/axis_zones.hpp.
#include "refine/axis_zones.hpp"

#include <algorithm>
#include <cmath>

#include "domain/angles.hpp"
#include "geom/filter_kit.hpp"
#include "geom/predicates.hpp"

#include "surface/chart.hpp"

namespace pdr::refine {
namespace {

using filter::dot;
using filter::sub;

// x without its component along unit u, normalized; {0,0,0} when x is along u.
Point perpendicular(const Point& x, const Point& u) {
  const double t = dot(x, u);
  Point w{x[0] - t * u[0], x[1] - t * u[1], x[2] - t * u[2]};
  const double n = std::sqrt(dot(w, w));
  if (n == 0) return {0, 0, 0};
  for (double& c : w) c /= n;
  return w;
}

// Whether the side e of facet f's wall along segment s holds the strip of the zone: every
// other segment of the wall (f's coplanar group, less the edges between its own facets) at
// an end of s, on that side, leaves the end at 90 degrees or more from s (an acute one cuts
// the strip off near that end, as the third side of a lone triangle facet does). The
// cosine is floating point with a margin of 1e-9, plus, for input planar only within the
// tolerance, the opening the domain analysis reads as a right angle bent by the input's
// rounding (domain/angles.hpp: moving the three vertices by `uncertainty`, to first
// order, at most 1e-3 radians): it chooses where copies go, and decides nothing about T.
bool holds_strip(const surface::SurfaceMesh& m, const std::vector<std::uint32_t>& wall,
                 std::uint32_t s, const Point& e, const Point& u, double uncertainty) {
  const surface::SurfaceSegment& axis = m.segments[s];
  const Point axis_d = sub(m.point(axis.b), m.point(axis.a));
  const double axis_length = std::sqrt(dot(axis_d, axis_d));
  const auto in_wall = [&](std::uint32_t g) {
    return std::find(wall.begin(), wall.end(), g) != wall.end();
  };
  for (const std::uint32_t f : wall)
    for (const std::uint32_t o : m.facets[f].segments) {
      if (o == s) continue;
      const surface::SurfaceSegment& g = m.segments[o];
      if (g.facets.size() >= 2 && std::all_of(g.facets.begin(), g.facets.end(), in_wall))
        continue;  // a crease between two pieces of the wall
      for (const auto& [end, sign] : {std::pair{axis.a, 1.0}, std::pair{axis.b, -1.0}}) {
        if (g.a != end && g.b != end) continue;
        Point d = sub(m.point(g.a == end ? g.b : g.a), m.point(end));
        const double n = std::sqrt(dot(d, d));
        if (n == 0) continue;
        for (double& c : d) c /= n;
        if (dot(d, e) <= 0) continue;  // on the wall's other side of s
        const double opening = domain::right_angle_opening(n, axis_length, uncertainty);
        if (sign * dot(d, u) > 1e-9 + std::sin(opening)) return false;
      }
    }
  return true;
}

}  // namespace

AxisZones::AxisZones(const surface::SurfaceMesh& m, const std::vector<double>& cylinders,
                     double cap, double uncertainty) {
  // Walls: coplanar groups. Whether each lies exactly on one plane (every corner of each
  // facet on the plane of the group's first facet): only then do copies go into its
  // facets beside the one through the axis.
  exact_.assign(m.facets.size(), 1);
  for (std::uint32_t f = 0; f < m.facets.size(); ++f) {
    if (!m.facets[f].is_face) continue;
    const surface::FacetChart& ch = m.facets[m.facets[f].plane_group].chart;
    for (const std::uint32_t s : m.facets[f].segments)
      for (const std::uint32_t v : {m.segments[s].a, m.segments[s].b})
        if (orient3d(ch.origin, ch.t1, ch.t2, m.point(v)) != Sign::Zero)
          exact_[m.facets[f].plane_group] = 0;
  }
  walls_of_.assign(m.facets.size(), {});
  group_.assign(m.facets.size(), 0);
  for (std::uint32_t f = 0; f < m.facets.size(); ++f) {
    if (!m.facets[f].is_face) continue;
    group_[f] = m.facets[f].plane_group;
    walls_of_[group_[f]].push_back(f);
  }
  for (std::uint32_t s = 0; s < cylinders.size() && s < m.segments.size(); ++s) {
    if (!(cylinders[s] > 0)) continue;
    const surface::SurfaceSegment& seg = m.segments[s];
    Zone z;
    z.segment = s;
    z.a = m.point(seg.a);
    const Point d = sub(m.point(seg.b), z.a);
    z.length = std::sqrt(dot(d, d));
    if (z.length == 0) continue;
    z.u = {d[0] / z.length, d[1] / z.length, d[2] / z.length};
    z.radius = std::min(cylinders[s], cap);
    if (!(z.radius > 0)) continue;
    // The sides of the facets along the first subsegment of the axis.
    const std::vector<std::uint32_t> chain = m.chain(s);
    if (chain.size() < 2) continue;
    bool strips = true;
    for (const std::uint32_t f : seg.facets) {
      if (!m.facets[f].is_face) continue;
      for (const std::uint32_t t : m.subfacets_on_edge(f, chain[0], chain[1])) {
        const surface::Subfacet& x = m.subfacet(t);
        for (const std::uint32_t v : x.v) {
          if (v == chain[0] || v == chain[1]) continue;
          const Point e = perpendicular(sub(m.point(v), z.a), z.u);
          if (dot(e, e) > 0) z.walls.push_back({f, e});
          strips = strips && holds_strip(m, wall(f), s, e, z.u, uncertainty);
        }
      }
    }
    if (z.walls.size() < 2 || !strips) continue;
    zones_.push_back(std::move(z));
  }
  if (zones_.empty()) return;
  facet_zones_.assign(m.facets.size(), {});
  for (std::uint32_t i = 0; i < zones_.size(); ++i)
    for (const Wall& w : zones_[i].walls)
      for (const std::uint32_t f : wall(w.facet))
        if (facet_zones_[f].empty() || facet_zones_[f].back() != i) facet_zones_[f].push_back(i);
}

const std::vector<std::uint32_t>& AxisZones::wall(std::uint32_t f) const {
  return walls_of_[group_[f]];
}

bool AxisZones::exact_wall(std::uint32_t f) const { return exact_[group_[f]] != 0; }

AxisZones::Placed AxisZones::place(const surface::SurfaceMesh& m, std::uint32_t f,
                                   const Point& p) const {
  Placed out;
  out.own = p;
  if (f >= facet_zones_.size()) return out;
  for (const std::uint32_t i : facet_zones_[f]) {
    const Zone& z = zones_[i];
    const Point x = sub(p, z.a);
    double along = dot(x, z.u);
    if (!(along > 0 && along < z.length)) continue;
    const Point w{x[0] - along * z.u[0], x[1] - along * z.u[1], x[2] - along * z.u[2]};
    double r = std::sqrt(dot(w, w));
    if (!(r > 0 && r < z.radius)) continue;
    // p's own wall: the side of f whose direction is closest to p's; none when p is not
    // on a side of f along the axis (beyond the axis line).
    const Wall* own = nullptr;
    double best = 0;
    for (const Wall& wall : z.walls)
      if (group_[wall.facet] == group_[f] && dot(wall.e, w) > best) {
        best = dot(wall.e, w);
        own = &wall;
      }
    if (own == nullptr) continue;
    const double grid = std::ldexp(1.0, std::ilogb(z.radius) - kGridBits);
    along = std::nearbyint(along / grid) * grid;
    r = std::nearbyint(r / grid) * grid;
    if (!(along > 0 && along < z.length && r > 0 && r < z.radius)) continue;
    for (const Wall& wall : z.walls) {
      Point q;
      for (int k = 0; k < 3; ++k) q[k] = z.a[k] + along * z.u[k] + r * wall.e[k];
      // p's own place is on its own facet's plane (another facet of its wall than the
      // one through the axis, when p lies there); a copy's, on the plane of the facet
      // through the axis.
      if (&wall == own)
        out.own = surface::place_on_facet(m.facets[f].chart, q);
      else
        out.copies.push_back(
            {wall.facet, surface::place_on_facet(m.facets[wall.facet].chart, q), z.segment});
    }
    return out;
  }
  return out;
}

}  // namespace pdr::refine
