// Stacked unions of rotated boxes; see support/union_fixtures.hpp.
#include "support/union_fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

// Boost.Geometry's rescaling policy trips GCC 12's -Wmaybe-uninitialized at -O3 (clang
// has no such warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/geometry.hpp>
#include <boost/geometry/algorithms/point_on_surface.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "support/outside_fixtures.hpp"
#include "support/plc_fixtures.hpp"

namespace pdr::test {

namespace {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;  // clockwise outer ring, closed
using BMulti = bg::model::multi_polygon<BPolygon>;
using Ring = std::vector<P2d>;                // open: the closing point dropped

// Two points of a level closer than this are one vertex (Boolean operations may compute a
// crossing twice, a few ulps apart); a vertex this close to an edge lies on it.
constexpr double kSame = 1e-9;

BPolygon rectangle(const TurnedBox& b) {
  const double c = std::cos(b.angle), s = std::sin(b.angle);
  BPolygon p;
  for (const auto& [u, v] : {std::pair{-1, -1}, {-1, 1}, {1, 1}, {1, -1}, {-1, -1}}) {
    const double x = u * b.w / 2, y = v * b.h / 2;
    bg::append(p.outer(), BPoint(b.cx + c * x - s * y, b.cy + s * x + c * y));
  }
  bg::correct(p);
  return p;
}

BMulti profile(const UnionLayer& layer) {
  BMulti acc;
  for (const TurnedBox& b : layer.add) {
    BMulti out;
    bg::union_(acc, rectangle(b), out);
    acc = std::move(out);
  }
  for (const TurnedBox& b : layer.cut) {
    BMulti out;
    bg::difference(acc, rectangle(b), out);
    acc = std::move(out);
  }
  bg::unique(acc);
  return acc;
}

template <class R>
Ring open_ring(const R& r) {
  Ring out;
  for (const BPoint& p : r) out.push_back({p.x(), p.y()});
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

// A polygon as its rings, the outer one first.
std::vector<Ring> rings_of(const BPolygon& p) {
  std::vector<Ring> out{open_ring(p.outer())};
  for (const auto& inner : p.inners()) out.push_back(open_ring(inner));
  return out;
}

double dist(const P2d& a, const P2d& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// The parameter of p's projection on ab and p's distance to the segment.
std::pair<double, double> on_segment(const P2d& p, const P2d& a, const P2d& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return {t, dist(p, {a[0] + t * dx, a[1] + t * dy})};
}

// Every corner of r at least min_corner_deg from 0 and 360 degrees (either orientation).
bool corners_ok(const Ring& r, double min_corner_deg) {
  const std::vector<double> a = corner_angles(r);
  return std::all_of(a.begin(), a.end(), [&](double x) { return x >= min_corner_deg && x <= 360 - min_corner_deg; });
}

// One level z of the stack: its vertices (snapped), and the rings that meet there.
struct Level {
  double z = 0;
  std::vector<P2d> points;
  std::vector<std::uint32_t> ids;  // Plc point of points[i]

  std::uint32_t id(const P2d& p, std::vector<Point>& plc_points) {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (dist(points[i], p) <= kSame) return ids[i];
    points.push_back(p);
    ids.push_back(static_cast<std::uint32_t>(plc_points.size()));
    plc_points.push_back({p[0], p[1], z});
    return ids.back();
  }
};

// The level's vertices strictly inside segment ab, ordered from a to b; false when one lies
// closer than min_feature to ab without being on it.
bool inner_points(const Level& level, const P2d& a, const P2d& b, double min_feature,
                  std::vector<std::uint32_t>& out) {
  std::vector<std::pair<double, std::uint32_t>> on;
  for (std::size_t i = 0; i < level.points.size(); ++i) {
    const P2d& p = level.points[i];
    if (dist(p, a) <= kSame || dist(p, b) <= kSame) continue;
    const auto [t, d] = on_segment(p, a, b);
    if (d <= kSame) on.emplace_back(t, level.ids[i]);
    else if (d < min_feature) return false;
  }
  std::sort(on.begin(), on.end());
  out.clear();
  for (const auto& [t, id] : on) out.push_back(id);
  return true;
}

}  // namespace

Plc stacked_union(const std::vector<UnionLayer>& layers, double z0, double min_feature,
                  double min_corner_deg) {
  const std::size_t n = layers.size();
  std::vector<BMulti> prof;
  for (const UnionLayer& l : layers) {
    prof.push_back(profile(l));
    if (prof.back().empty()) return {};
  }
  // The facets of each level: the bottom, the ledges between layers, the top.
  std::vector<BMulti> caps(n + 1);
  caps[0] = prof[0];
  caps[n] = prof[n - 1];
  for (std::size_t k = 1; k < n; ++k) {
    bg::sym_difference(prof[k - 1], prof[k], caps[k]);
    bg::unique(caps[k]);
  }
  // Every ring that meets level k: the caps', and those of the layers below and above.
  std::vector<std::vector<Ring>> level_rings(n + 1);
  const auto add_rings = [](std::vector<Ring>& to, const BMulti& m) {
    for (const BPolygon& p : m)
      for (Ring& r : rings_of(p)) to.push_back(std::move(r));
  };
  for (std::size_t k = 0; k <= n; ++k) {
    add_rings(level_rings[k], caps[k]);
    if (k > 0) add_rings(level_rings[k], prof[k - 1]);
    if (k < n) add_rings(level_rings[k], prof[k]);
  }
  Plc plc;
  std::vector<Level> levels(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    levels[k].z = k == 0 ? z0 : layers[k - 1].top;
    if (k > 0 && levels[k].z <= levels[k - 1].z + min_feature) return {};
    for (const Ring& r : level_rings[k]) {
      if (r.size() < 3 || !corners_ok(r, min_corner_deg)) return {};
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (dist(r[i], r[(i + 1) % r.size()]) < min_feature) return {};
        levels[k].id(r[i], plc.points);
      }
    }
  }
  std::vector<std::uint32_t> between;
  // A ring of level k as a facet polygon, with the level's vertices on its edges.
  const auto polygon = [&](std::size_t k, const Ring& r, std::vector<std::uint32_t>& out) {
    out.clear();
    for (std::size_t i = 0; i < r.size(); ++i) {
      out.push_back(levels[k].id(r[i], plc.points));
      if (!inner_points(levels[k], r[i], r[(i + 1) % r.size()], min_feature, between)) return false;
      out.insert(out.end(), between.begin(), between.end());
    }
    return true;
  };
  for (std::size_t k = 0; k <= n; ++k)
    for (const BPolygon& p : caps[k]) {
      PlcFacet f;
      f.marker = 1;
      for (const Ring& r : rings_of(p)) {
        f.polygons.emplace_back();
        if (!polygon(k, r, f.polygons.back())) return {};
      }
      for (const auto& inner : p.inners()) {
        BPolygon hole;
        hole.outer().assign(inner.begin(), inner.end());
        bg::correct(hole);
        BPoint q;
        bg::point_on_surface(hole, q);
        f.holes.push_back({q.x(), q.y(), levels[k].z});
      }
      plc.facets.push_back(std::move(f));
    }
  // The walls of layer k over its rings' edges.
  std::vector<std::uint32_t> below, above;
  for (std::size_t k = 0; k < n; ++k)
    for (const BPolygon& p : prof[k])
      for (const Ring& r : rings_of(p))
        for (std::size_t i = 0; i < r.size(); ++i) {
          const P2d& a = r[i];
          const P2d& b = r[(i + 1) % r.size()];
          if (!inner_points(levels[k], a, b, min_feature, below) ||
              !inner_points(levels[k + 1], a, b, min_feature, above))
            return {};
          PlcFacet f;
          f.marker = 1;
          std::vector<std::uint32_t> w{levels[k].id(a, plc.points)};
          w.insert(w.end(), below.begin(), below.end());
          w.push_back(levels[k].id(b, plc.points));
          w.push_back(levels[k + 1].id(b, plc.points));
          w.insert(w.end(), above.rbegin(), above.rend());
          w.push_back(levels[k + 1].id(a, plc.points));
          f.polygons.push_back(std::move(w));
          plc.facets.push_back(std::move(f));
        }
  plc.enclosure = Enclosure::HolePoints;
  relabel(plc);
  return plc;
}

namespace {

// A stack drawn from a seeded engine by rejection (RapidCheck's draws inside a rejection
// loop would pile up): shrinking acts on the seed and the layer count.
Plc draw_stack(std::uint32_t seed, int layer_count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> centre(-0.6, 0.6), side(0.3, 1.6), small(0.1, 0.6),
      turn(0, std::numbers::pi), rise(0.2, 1.0);
  std::uniform_int_distribution<int> adds(1, 4), cuts(0, 2);
  for (;;) {
    std::vector<UnionLayer> layers(static_cast<std::size_t>(layer_count));
    double z = 0;
    for (UnionLayer& l : layers) {
      for (int i = adds(rng); i > 0; --i) l.add.push_back({centre(rng), centre(rng), side(rng), side(rng), turn(rng)});
      for (int i = cuts(rng); i > 0; --i) l.cut.push_back({centre(rng), centre(rng), small(rng), small(rng), turn(rng)});
      z += rise(rng);
      l.top = z;
    }
    Plc plc = stacked_union(layers, 0, 0.02, 8);
    if (!plc.facets.empty()) return plc;
  }
}

}  // namespace

rc::Gen<Plc> gen_stacked_union() {
  return rc::gen::exec([] {
    const int layer_count = *rc::gen::inRange(1, 4);
    Plc plc = draw_stack(static_cast<std::uint32_t>(*rc::gen::inRange(0, 1 << 30)), layer_count);
    if (*rc::gen::inRange(0, 2) == 1) {
      const auto angle = [] { return *rc::gen::inRange(0, 628) / 100.0; };
      const double a = angle(), b = angle(), c = angle();
      plc = rotated(std::move(plc), a, b, c);
      if (*rc::gen::inRange(0, 2) == 1) plc = printed(std::move(plc), *rc::gen::elementOf(std::vector<int>{17, 9, 7}));
    }
    return plc;
  });
}

}  // namespace pdr::test
