// Domains and helpers for the surface mesh tests; see tests/support/surface_fixtures.hpp.
#include "support/surface_fixtures.hpp"

#include <algorithm>
#include <cmath>

#include "geom/predicates.hpp"
#include "support/plc_fixtures.hpp"

namespace pdr::test {

namespace {

Plc box_in_cell(int cell, double unit) {
  // Cells are 8 units wide along x; a box inside one, at least one unit from its sides.
  const int lo_x = *rc::gen::inRange(1, 3), lo_y = *rc::gen::inRange(0, 3), lo_z = *rc::gen::inRange(0, 3);
  const int sx = *rc::gen::inRange(1, 5), sy = *rc::gen::inRange(1, 4), sz = *rc::gen::inRange(1, 4);
  const double x0 = (8 * cell + lo_x) * unit;
  return box({x0, lo_y * unit, lo_z * unit}, {x0 + sx * unit, (lo_y + sy) * unit, (lo_z + sz) * unit});
}

Plc box_with_void(double unit) {
  const int n = *rc::gen::inRange(4, 7);
  const int lo = *rc::gen::inRange(1, n - 2), hi = *rc::gen::inRange(lo + 1, n);
  const int hz = *rc::gen::inRange(lo + 1, n);
  Plc outer = box({0, 0, 0}, {n * unit, n * unit, n * unit});
  Plc inner = box({lo * unit, lo * unit, lo * unit}, {hi * unit, hi * unit, hz * unit});
  Plc m = merge(outer, inner);
  m.holes.push_back({(lo + 0.5) * unit, (lo + 0.5) * unit, (lo + 0.5) * unit});
  relabel(m);
  return m;
}

Plc skyline(double unit) {
  const int columns = *rc::gen::inRange(2, 5);
  std::vector<int> h;
  for (int i = 0; i < columns; ++i) {
    int x = *rc::gen::inRange(1, 4);
    if (!h.empty() && x == h.back()) x = h.back() == 3 ? 2 : h.back() + 1;  // no flat joint
    h.push_back(x);
  }
  std::vector<P2d> profile{{0, 0}, {columns * unit, 0}};
  for (int i = columns - 1; i >= 0; --i) {
    profile.push_back({(i + 1) * unit, h[i] * unit});
    profile.push_back({i * unit, h[i] * unit});
  }
  return prism(profile, 0, *rc::gen::inRange(1, 4) * unit);
}

}  // namespace

rc::Gen<Plc> gen_box_union() {
  return rc::gen::exec([] {
    static const double units[] = {1.0, 0.5, 0.3, 1.25, 0.1};
    const double unit = units[*rc::gen::inRange(0, 5)];
    const int kind = *rc::gen::inRange(0, 4);
    Plc plc;
    if (kind == 0) {
      plc = box_in_cell(0, unit);
      const int more = *rc::gen::inRange(0, 3);
      for (int c = 1; c <= more; ++c) plc = merge(plc, box_in_cell(c, unit));
    } else if (kind == 1) {
      plc = box_with_void(unit);
    } else {
      plc = skyline(unit);
      if (kind == 3) plc = merge(plc, box_in_cell(1, unit));
    }
    return plc;
  });
}

Plc grid_facet_box(int n) {
  Plc plc = box({0, 0, 0}, {double(n), double(n), 1});
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) {
      plc.facets[0].polygons.push_back({static_cast<std::uint32_t>(plc.points.size())});
      plc.points.push_back({double(i), double(j), 0});
    }
  relabel(plc);
  return plc;
}

Plc frame_box() {
  std::vector<Point> p{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 1}, {4, 0, 1},
                       {4, 4, 1}, {0, 4, 1}, {1.5, 1.5, 0}, {2.5, 1.5, 0}, {2.5, 2.5, 0},
                       {1.5, 2.5, 0}, {1.5, 1.5, 1}, {2.5, 1.5, 1}, {2.5, 2.5, 1}, {1.5, 2.5, 1}};
  Plc plc = make_plc(p, {{{0, 1, 2, 3}, {8, 9, 10, 11}},
                         {{4, 5, 6, 7}, {12, 13, 14, 15}},
                         {{0, 1, 5, 4}}, {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}},
                         {{8, 9, 13, 12}}, {{9, 10, 14, 13}}, {{10, 11, 15, 14}}, {{11, 8, 12, 15}}});
  plc.facets[0].holes.push_back({2, 2, 0});
  plc.facets[1].holes.push_back({2, 2, 1});
  return plc;
}

Plc box_with_interior_segment() {
  Plc plc = box({0, 0, 0}, {3, 2, 1});
  const auto n = static_cast<std::uint32_t>(plc.points.size());
  plc.points.push_back({1, 1, 1});
  plc.points.push_back({2, 1, 1});
  plc.facets[1].polygons.push_back({n, n + 1});
  relabel(plc);
  return plc;
}

Plc rotated_box(double a, double b, double c) {
  Plc plc = box({0, 0, 0}, {a, b, c});
  for (Point& p : plc.points) {
    const double x = p[0], y = p[1];
    p[0] = 0.6 * x - 0.8 * y;
    p[1] = 0.8 * x + 0.6 * y;
  }
  return plc;
}

Plc tumbled_box(double a, double b, double c) {
  Plc plc = box({0, 0, 0}, {a, b, c});
  const double t1 = 0.2, t2 = 0.4;
  for (Point& p : plc.points) {
    const double x1 = std::cos(t1) * p[0] - std::sin(t1) * p[1];
    const double y1 = std::sin(t1) * p[0] + std::cos(t1) * p[1];
    const double y2 = std::cos(t2) * y1 - std::sin(t2) * p[2];
    const double z2 = std::sin(t2) * y1 + std::cos(t2) * p[2];
    p = {x1 + 0.1, y2 - 0.3, z2 + 0.7};
  }
  return plc;
}

std::string describe(const surface::SurfaceAudit& a) {
  std::string s = std::to_string(a.violation_count) + " violations";
  for (const std::string& v : a.violations) s += "\n  " + v;
  return s;
}

std::set<std::array<std::uint32_t, 3>> brute_sos_delaunay(const std::vector<Point>& pts,
                                                          const std::vector<std::uint32_t>& ids) {
  std::set<std::array<std::uint32_t, 3>> out;
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::size_t j = i + 1; j < ids.size(); ++j)
      for (std::size_t k = j + 1; k < ids.size(); ++k) {
        const Point &a = pts[ids[i]], &b = pts[ids[j]], &c = pts[ids[k]];
        bool empty = true;
        for (const std::uint32_t d : ids) {
          if (d == ids[i] || d == ids[j] || d == ids[k]) continue;
          if (incircle3_sos(a, b, c, pts[d]) != Sign::Negative) {
            empty = false;
            break;
          }
        }
        if (!empty) continue;
        std::array<std::uint32_t, 3> t{ids[i], ids[j], ids[k]};
        std::sort(t.begin(), t.end());
        out.insert(t);
      }
  return out;
}

std::set<std::array<std::uint32_t, 3>> facet_triples(const surface::SurfaceMesh& m, std::uint32_t f) {
  std::set<std::array<std::uint32_t, 3>> out;
  for (const std::uint32_t t : m.facet_subfacets(f)) {
    std::array<std::uint32_t, 3> v = m.subfacet(t).v;
    std::sort(v.begin(), v.end());
    out.insert(v);
  }
  return out;
}

}  // namespace pdr::test
