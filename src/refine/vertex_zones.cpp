// Protecting balls around acute input vertices; see refine/vertex_zones.hpp.
#include "refine/vertex_zones.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geom/filter_kit.hpp"

namespace pdr::refine {
namespace {

using filter::dot;
using filter::sub;

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Point unit(Point x) {
  const double n = std::sqrt(dot(x, x));
  if (n > 0)
    for (double& c : x) c /= n;
  return x;
}

// The angle between unit vectors, well conditioned at 0 and pi.
double angle(const Point& a, const Point& b) {
  const Point c = cross(a, b);
  return std::atan2(std::sqrt(dot(c, c)), dot(a, b));
}

// The power of two closest to x > 0.
double nearest_power_of_two(double x) {
  const double lo = std::exp2(std::floor(std::log2(x)));
  return x - lo <= 2 * lo - x ? lo : 2 * lo;
}

// Where piece [t0, t1] of an arc of length `length` is split (sample_arcs).
double split_angle(double t0, double t1, double length) {
  const bool at0 = t0 == 0, at1 = t1 == length;
  if (at0 && !at1) return nearest_power_of_two(t1 / 2);
  if (at1 && !at0) return length - nearest_power_of_two((length - t0) / 2);
  return (t0 + t1) / 2;
}

constexpr double kMargin = 1e-9;
constexpr double kMaxPiece = std::numbers::pi / 6;  // 30 degrees: fans stay well shaped
constexpr std::size_t kSampleCap = 512;
constexpr int kRounds = 60;

}  // namespace

Point SphereArc::at(double t) const {
  const double c = std::cos(t), s = std::sin(t);
  return {c * e1[0] + s * e2[0], c * e1[1] + s * e2[1], c * e1[2] + s * e2[2]};
}

std::optional<std::vector<std::vector<double>>> sample_arcs(const std::vector<SphereArc>& arcs,
                                                            const std::vector<Point>& points,
                                                            double max_piece, std::size_t cap) {
  std::vector<std::vector<double>> t(arcs.size());
  std::size_t total = 0;
  for (std::size_t a = 0; a < arcs.size(); ++a) {
    t[a] = {0.0, arcs[a].length};
    total += 2;
  }
  // Each round splits every piece found encroached; a sampling that needs more rounds
  // than kRounds (pieces 2^-60 of the longest) is given up like one past the cap.
  for (int round = 0;; ++round) {
    bool changed = false;
    // An arc's ends are no samples of their own: the shell vertex there is its segment's
    // (VertexZones::shell), whose direction is in `points`. The arc's end is that direction
    // projected onto the facet's chart, which on a facet printed with few digits lies 1e-7
    // radians off it, along another facet's arc, whose end pieces it then encroached at
    // every size (a slot's apex printed with 7 digits: samples 1e-11 of the radius apart).
    std::vector<Point> all = points;
    for (std::size_t a = 0; a < arcs.size(); ++a)
      for (std::size_t i = 1; i + 1 < t[a].size(); ++i) all.push_back(arcs[a].at(t[a][i]));
    for (std::size_t a = 0; a < arcs.size(); ++a) {
      std::vector<double> next{t[a].front()};
      for (std::size_t i = 0; i + 1 < t[a].size(); ++i) {
        const double t0 = t[a][i], t1 = t[a][i + 1], half = (t1 - t0) / 2;
        bool split = t1 - t0 > max_piece;
        if (!split) {
          const Point mid = arcs[a].at(t0 + half);
          const Point p0 = arcs[a].at(t0), p1 = arcs[a].at(t1);
          for (const Point& s : all) {
            if (angle(s, p0) <= kMargin * half || angle(s, p1) <= kMargin * half) continue;
            if (angle(s, mid) < (1 - kMargin) * half) {
              split = true;
              break;
            }
          }
        }
        if (split) {
          if (++total > cap) return std::nullopt;
          next.push_back(split_angle(t0, t1, arcs[a].length));
          changed = true;
        }
        next.push_back(t1);
      }
      t[a] = std::move(next);
    }
    if (!changed) return t;
    if (round == kRounds) return std::nullopt;
  }
}

void VertexZones::add(const surface::SurfaceMesh& m, std::uint32_t v, double bound) {
  Zone z;
  z.vertex = v;
  z.v = m.point(v);
  z.r = z.r0 = std::exp2(std::floor(std::log2(bound)));
  // The segments at v, in index order: those of its subsegments (an input vertex ends
  // every segment it lies on; a scan of all segments per vertex was quadratic, 8% of a
  // scanned model's run).
  std::vector<std::uint32_t> at_v;
  for (const std::uint32_t g : m.vertex_subsegments(v)) at_v.push_back(m.subsegment(g).segment);
  std::sort(at_v.begin(), at_v.end());
  at_v.erase(std::unique(at_v.begin(), at_v.end()), at_v.end());
  for (const std::uint32_t s : at_v) {
    const surface::SurfaceSegment& g = m.segments[s];
    if (g.a != v && g.b != v) continue;
    z.segments.emplace_back(s, unit(sub(m.point(g.a == v ? g.b : g.a), z.v)));
  }
  // The facets at v: the subfacets there, grouped by facet; each facet's wedges lie between
  // its segments through v, sorted by angle about its normal.
  std::vector<std::uint32_t> facets;
  for (const std::uint32_t t : m.vertex_subfacets(v)) facets.push_back(m.subfacet(t).facet);
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  for (const std::uint32_t f : facets) {
    const Point n = unit(m.facets[f].chart.normal);
    std::vector<std::pair<double, std::uint32_t>> dirs;  // angle, index into z.segments
    Point e1{};
    for (std::uint32_t i = 0; i < z.segments.size(); ++i) {
      const auto& fs = m.segments[z.segments[i].first].facets;
      if (!std::binary_search(fs.begin(), fs.end(), f)) continue;
      const Point u = z.segments[i].second;
      if (dirs.empty()) e1 = unit(sub(u, Point{n[0] * dot(u, n), n[1] * dot(u, n), n[2] * dot(u, n)}));
      const Point e2 = cross(n, e1);
      double phi = std::atan2(dot(u, e2), dot(u, e1));
      if (phi < 0) phi += 2 * std::numbers::pi;
      dirs.emplace_back(dirs.empty() ? 0.0 : phi, i);
    }
    if (dirs.size() < 2) return;  // v inside the facet, or on a dangling segment: no wedge
    std::sort(dirs.begin(), dirs.end());
    const Point e2 = cross(n, e1);
    std::vector<std::uint8_t> inside(dirs.size(), 0);
    for (const std::uint32_t t : m.vertex_subfacets(v)) {
      const surface::Subfacet& x = m.subfacet(t);
      if (x.facet != f) continue;
      Point bis{};
      for (const std::uint32_t w : x.v)
        if (w != v) {
          const Point u = unit(sub(m.point(w), z.v));
          for (int k = 0; k < 3; ++k) bis[k] += u[k];
        }
      double phi = std::atan2(dot(bis, e2), dot(bis, e1));
      if (phi < 0) phi += 2 * std::numbers::pi;
      std::size_t gap = dirs.size() - 1;  // past the last direction: the wrap-around gap
      for (std::size_t i = 0; i + 1 < dirs.size(); ++i)
        if (phi > dirs[i].first && phi < dirs[i + 1].first) gap = i;
      inside[gap] = 1;
    }
    for (std::size_t i = 0; i < dirs.size(); ++i) {
      if (!inside[i]) continue;
      const std::size_t j = (i + 1) % dirs.size();
      double len = dirs[j].first - dirs[i].first;
      if (j == 0) len += 2 * std::numbers::pi;
      Arc arc;
      arc.facet = f;
      const double a0 = dirs[i].first;
      for (int k = 0; k < 3; ++k) {
        arc.geometry.e1[k] = std::cos(a0) * e1[k] + std::sin(a0) * e2[k];
        arc.geometry.e2[k] = -std::sin(a0) * e1[k] + std::cos(a0) * e2[k];
      }
      arc.geometry.length = len;
      arc.first = dirs[i].second;
      arc.last = dirs[j].second;
      z.arcs.push_back(std::move(arc));
    }
  }
  std::vector<SphereArc> geometry;
  for (const Arc& a : z.arcs) geometry.push_back(a.geometry);
  std::vector<Point> points;
  for (const auto& s : z.segments) points.push_back(s.second);
  const auto samples = sample_arcs(geometry, points, kMaxPiece, kSampleCap);
  if (!samples) return;
  for (std::size_t a = 0; a < z.arcs.size(); ++a) {
    z.arcs[a].angles = (*samples)[a];
    z.arcs[a].vertices.assign(z.arcs[a].angles.size(), kNone);
  }
  z.segment_vertex.assign(z.segments.size(), kNone);
  zones_.push_back(std::move(z));
}

std::uint64_t VertexZones::key(const Point& p, int dx, int dy, int dz) const {
  const auto c = [&](double x, int d) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x / cell_)) + d) &
           0x1FFFFF;
  };
  return c(p[0], dx) << 42 | c(p[1], dy) << 21 | c(p[2], dz);
}

void VertexZones::index() {
  cell_ = 0;
  for (const Zone& z : zones_) cell_ = std::max(cell_, z.r);
  grid_.clear();
  for (std::uint32_t i = 0; i < zones_.size(); ++i) grid_.emplace_back(key(zones_[i].v, 0, 0, 0), i);
  std::sort(grid_.begin(), grid_.end());
}

std::optional<std::uint32_t> VertexZones::holding(const Point& p) const {
  if (zones_.empty()) return std::nullopt;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const std::uint64_t k = key(p, dx, dy, dz);
        auto it = std::lower_bound(grid_.begin(), grid_.end(), std::pair{k, std::uint32_t{0}});
        for (; it != grid_.end() && it->first == k; ++it) {
          const Zone& z = zones_[it->second];
          const Point d = sub(p, z.v);
          if (dot(d, d) < z.r * z.r) return it->second;
        }
      }
  return std::nullopt;
}

std::vector<VertexZones::ShellPoint> VertexZones::shell(std::uint32_t zi) const {
  const Zone& z = zones_[zi];
  std::vector<ShellPoint> out;
  for (std::uint32_t i = 0; i < z.segments.size(); ++i) {
    ShellPoint s;
    s.segment = z.segments[i].first;
    s.sample = i;
    for (int k = 0; k < 3; ++k) s.p[k] = z.v[k] + z.r * z.segments[i].second[k];
    out.push_back(s);
  }
  for (std::uint32_t a = 0; a < z.arcs.size(); ++a)
    for (std::uint32_t i = 1; i + 1 < z.arcs[a].angles.size(); ++i) {
      ShellPoint s;
      s.facet = z.arcs[a].facet;
      s.arc = a;
      s.sample = i;
      const Point u = z.arcs[a].geometry.at(z.arcs[a].angles[i]);
      for (int k = 0; k < 3; ++k) s.p[k] = z.v[k] + z.r * u[k];
      out.push_back(s);
    }
  return out;
}

void VertexZones::record(std::uint32_t zi, const ShellPoint& s, std::uint32_t vertex) {
  if (s.segment != kNone)
    record_segment(zi, s.segment, vertex);
  else
    zones_[zi].arcs[s.arc].vertices[s.sample] = vertex;
}

void VertexZones::record_segment(std::uint32_t zi, std::uint32_t segment, std::uint32_t vertex) {
  Zone& z = zones_[zi];
  for (std::uint32_t i = 0; i < z.segments.size(); ++i) {
    if (z.segments[i].first != segment) continue;
    z.segment_vertex[i] = vertex;
    for (Arc& a : z.arcs) {
      if (a.first == i) a.vertices.front() = vertex;
      if (a.last == i) a.vertices.back() = vertex;
    }
  }
}

std::optional<std::pair<std::uint32_t, std::uint32_t>> VertexZones::find_piece(
    std::uint32_t zi, std::uint32_t f, std::uint32_t a, std::uint32_t b) const {
  const Zone& z = zones_[zi];
  if (!z.filled) return std::nullopt;
  for (std::uint32_t k = 0; k < z.arcs.size(); ++k) {
    const Arc& arc = z.arcs[k];
    if (arc.facet != f) continue;
    for (std::uint32_t i = 0; i + 1 < arc.vertices.size(); ++i) {
      const std::uint32_t x = arc.vertices[i], y = arc.vertices[i + 1];
      if (x != kNone && y != kNone && ((x == a && y == b) || (x == b && y == a)))
        return std::pair{k, i};
    }
  }
  return std::nullopt;
}

bool VertexZones::has_piece(std::uint32_t zi, std::uint32_t f, std::uint32_t a,
                            std::uint32_t b) const {
  return find_piece(zi, f, a, b).has_value();
}

std::optional<VertexZones::ShellPoint> VertexZones::split_piece(std::uint32_t zi, std::uint32_t f,
                                                                std::uint32_t a, std::uint32_t b) {
  const auto piece = find_piece(zi, f, a, b);
  if (!piece) return std::nullopt;
  const auto [k, i] = *piece;
  Zone& z = zones_[zi];
  Arc& arc = z.arcs[k];
  const double t = split_angle(arc.angles[i], arc.angles[i + 1], arc.geometry.length);
  if (!(t > arc.angles[i] && t < arc.angles[i + 1])) return std::nullopt;
  arc.angles.insert(arc.angles.begin() + i + 1, t);
  arc.vertices.insert(arc.vertices.begin() + i + 1, kNone);
  ShellPoint s;
  s.facet = f;
  s.arc = k;
  s.sample = i + 1;
  const Point u = arc.geometry.at(t);
  for (int c = 0; c < 3; ++c) s.p[c] = z.v[c] + z.r * u[c];
  return s;
}

void VertexZones::activate(std::uint32_t zi, double bound) {
  Zone& z = zones_[zi];
  if (!z.active) ++active_;
  z.active = true;
  if (bound > 0 && bound < z.r) z.r = std::exp2(std::floor(std::log2(bound)));
}

bool VertexZones::shrink(std::uint32_t zi, double floor) {
  Zone& z = zones_[zi];
  if (z.r / 2 < floor || z.r / 2 < 0x1p-40 * z.r0) return false;
  z.r /= 2;
  z.filled = false;
  std::fill(z.segment_vertex.begin(), z.segment_vertex.end(), kNone);
  for (Arc& a : z.arcs) std::fill(a.vertices.begin(), a.vertices.end(), kNone);
  return true;
}

}  // namespace pdr::refine
