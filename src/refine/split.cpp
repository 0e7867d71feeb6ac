// surface::Subsegment split points: midpoints, concentric shells, protected lengths; see
// refine/split.hpp.
#include "refine/split.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "domain/distance.hpp"
#include "geom/construct.hpp"

namespace pdr::refine {

std::vector<std::uint32_t> acute_vertices(const domain::DomainReport& r) {
  std::vector<std::uint32_t> out;
  for (const domain::AngleRecord& a : r.violations) {
    if (a.vertex >= 0) {
      out.push_back(static_cast<std::uint32_t>(a.vertex));
      continue;
    }
    for (const auto& s : a.segments) out.insert(out.end(), s.begin(), s.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<double> protecting_cylinders(const domain::DomainAnalysis& an) {
  const domain::PlcDomain& dom = an.domain;
  std::vector<std::uint32_t> sharp;
  for (const domain::AngleRecord& a : an.report.violations) {
    // The angle, like the radius, is floating point: it sizes a guard, it decides no
    // predicate.
    if (a.kind != domain::AngleKind::FacetFacet ||
        std::min(a.degrees, 360 - a.degrees) >= kCylinderAngleDeg)
      continue;
    for (const auto& e : a.segments)
      if (const auto s = dom.find_segment(e[0], e[1])) sharp.push_back(*s);
  }
  if (sharp.empty()) return {};
  const domain::LocalFeatureSizes lfs = domain::local_feature_sizes(dom);
  std::vector<double> radius(dom.segments.size(), 0.0);
  for (const std::uint32_t s : sharp) {
    // segment_d is the distance to the unrelated components over sqrt(2); infinite when
    // every component touches the segment: then the segment's length stands for it.
    double l = lfs.segment_d[s] * std::numbers::sqrt2;
    if (!std::isfinite(l))
      l = std::sqrt(domain::dist2_point_point(dom.plc.points[dom.segments[s].a],
                                              dom.plc.points[dom.segments[s].b]));
    radius[s] = kCylinderFraction * l;
  }
  return radius;
}

SplitGuard::SplitGuard(const surface::SurfaceMesh& m, const std::vector<std::uint32_t>& acute,
                       Floor floor, const std::vector<double>& cylinders, double cylinder_cap)
    : floor_(std::move(floor)) {
  if (acute.empty()) return;
  acute_.assign(m.vertex_count(), 0);
  for (const std::uint32_t v : acute)
    if (v < acute_.size()) acute_[v] = 1;
  guarded_.assign(m.segments.size(), 0);
  for (std::size_t s = 0; s < m.segments.size(); ++s)
    guarded_[s] = static_cast<std::uint8_t>(is_acute(m.segments[s].a) || is_acute(m.segments[s].b));
  guarded_facet_.assign(m.facets.size(), 0);
  for (std::size_t f = 0; f < m.facets.size(); ++f)
    for (const std::uint32_t s : m.facets[f].segments)
      if (guarded_[s]) guarded_facet_[f] = 1;
  if (cylinders.empty()) return;
  facet_cylinders_.assign(m.facets.size(), {});
  for (std::size_t f = 0; f < m.facets.size(); ++f)
    for (const std::uint32_t s : m.facets[f].segments)
      if (s < cylinders.size() && cylinders[s] > 0)
        facet_cylinders_[f].push_back({m.point(m.segments[s].a), m.point(m.segments[s].b),
                                       std::min(cylinders[s], cylinder_cap), s});
}

std::string SplitGuard::refuse_subfacet(const surface::SurfaceMesh& m, std::uint32_t f,
                                        double scale) const {
  const surface::Subfacet& x = m.subfacet(f);
  if (!active() || !guarded_facet_[x.facet]) return {};
  const Point &a = m.point(x.v[0]), &b = m.point(x.v[1]), &c = m.point(x.v[2]);
  const double r = std::sqrt(construct::triangle_circumradius2(a, b, c));
  std::ostringstream os;
  os.precision(6);
  if (!facet_cylinders_.empty()) {
    const Point q = construct::triangle_circumcenter(a, b, c);
    for (const Cylinder& y : facet_cylinders_[x.facet]) {
      const double dist = std::sqrt(domain::dist2_point_segment(q, y.a, y.b));
      if (dist >= y.radius || r >= scale * kCylinderFloor * y.radius) continue;
      os << "refine.protected: the circumcenter of subfacet (" << x.v[0] << ", " << x.v[1]
         << ", " << x.v[2] << ") of " << m.facet_name(x.facet) << " lies " << dist << " from "
         << m.segment_name(y.segment) << ", inside its protecting cylinder of radius "
         << y.radius << " (a dihedral below 70.53 or above 289.47 deg), and its circumradius " << r
         << " is below the cylinder's protected length " << scale * kCylinderFloor * y.radius;
      return os.str();
    }
  }
  const double floor = scale * floor_(m.subfacet_size(f));
  if (r >= floor) return {};
  os << "refine.protected: subfacet (" << x.v[0] << ", " << x.v[1] << ", " << x.v[2]
     << ") of " << m.facet_name(x.facet) << " has circumradius " << r
     << " < the protected length " << floor
     << " of a facet at an acute input vertex (angle < 90 deg)";
  return os.str();
}

namespace {

double distance(const Point& a, const Point& b) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(s);
}

// The power of two closest to x > 0.
double nearest_power_of_two(double x) {
  const double lo = std::exp2(std::floor(std::log2(x)));
  return x - lo <= 2 * lo - x ? lo : 2 * lo;
}

}  // namespace

SplitGuard::Plan SplitGuard::plan(const surface::SurfaceMesh& m, std::uint32_t s,
                                  bool below_floor) const {
  const surface::Subsegment& g = m.subsegment(s);
  const Point &a = m.point(g.v[0]), &b = m.point(g.v[1]);
  Plan r;
  if (!active() || !guarded_[g.segment]) {
    r.p = construct::midpoint(a, b);
    return r;
  }
  const double l = distance(a, b);
  const bool sa = is_acute(g.v[0]), sb = is_acute(g.v[1]);
  double t = 0.5;  // fraction of the way from a to b
  if (sa != sb) {
    const double from = nearest_power_of_two(l / 2);  // in [l/3, 2l/3]
    t = sa ? from / l : 1 - from / l;
  }
  const double piece = std::min(t, 1 - t) * l;
  const double floor = below_floor ? 0.0 : floor_(m.subsegment_size(s));
  if (piece < floor) {
    std::ostringstream os;
    os.precision(6);
    os << "refine.protected: splitting subsegment (" << g.v[0] << ", " << g.v[1] << ") of "
       << m.segment_name(g.segment) << " would leave a piece of length " << piece
       << " < the protected length " << floor
       << " of a segment at an acute input vertex (angle < 90 deg)";
    r.ok = false;
    r.reason = os.str();
    return r;
  }
  if (t == 0.5) {
    r.p = construct::midpoint(a, b);
  } else {
    for (int k = 0; k < 3; ++k) r.p[k] = a[k] + t * (b[k] - a[k]);
  }
  return r;
}

}  // namespace pdr::refine
