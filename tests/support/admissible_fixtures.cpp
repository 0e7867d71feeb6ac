// Random admissible domains and the .poly writer; see tests/support/admissible_fixtures.hpp.
#include "support/admissible_fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "support/plc_fixtures.hpp"
#include "support/voxel_fixtures.hpp"

namespace pdr::test {

namespace {

rc::Gen<GridBox> gen_grid_box(std::array<int, 3> n) {
  return rc::gen::exec([n] {
    GridBox b;
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = *rc::gen::inRange(0, n[a]);
      b.hi[a] = b.lo[a] + *rc::gen::inRange(1, n[a] - b.lo[a] + 1);
    }
    return b;
  });
}

// A voxel solid of at most 4x4x3 cells and 4 boxes, and its grid's x extent in units.
Plc voxel_solid(double unit, int& width) {
  const std::array<int, 3> n{*rc::gen::inRange(1, 5), *rc::gen::inRange(1, 5),
                             *rc::gen::inRange(1, 4)};
  const auto boxes = *rc::gen::resize(
      3, rc::gen::nonEmpty(rc::gen::container<std::vector<GridBox>>(gen_grid_box(n))));
  VoxelSet s = voxels_of(n, boxes);
  make_well_composed(s);
  width = n[0];
  Plc plc = voxel_plc(s, unit);
  if (*rc::gen::inRange(0, 3) == 0) {  // a cube of half a cell suspended in a cell
    std::vector<std::array<int, 3>> full;
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x)
          if (s.at({x, y, z})) full.push_back({x, y, z});
    const auto& c = full[*rc::gen::inRange<std::size_t>(0, full.size())];
    auto at = [&](double q) { return Point{unit * (c[0] + q), unit * (c[1] + q), unit * (c[2] + q)}; };
    plc = merge(plc, box(at(0.25), at(0.75)));
    plc.holes.push_back(at(0.5));
    relabel(plc);
  }
  return plc;
}

// A hexagon with every angle >= 90 degrees, counter-clockwise, in units.
std::vector<P2d> hexagon(double unit, bool rounded) {
  std::vector<P2d> h;
  if (!rounded || *rc::gen::inRange(0, 2) == 0) {
    // Integer: angles 180 - atan(hh/b) and 2 atan(hh/b) > 90 (b < hh: not exactly 90,
    // which a non-dyadic unit would round either way).
    const int a = *rc::gen::inRange(1, 3), hh = *rc::gen::inRange(2, 4);
    const int b = *rc::gen::inRange(1, hh);
    h = {{0, 0}, {2.0 * a, 0}, {2.0 * a + b, double(hh)}, {2.0 * a, 2.0 * hh}, {0, 2.0 * hh},
         {-double(b), double(hh)}};
  } else {  // regular, rotated: 120 degrees, coordinates rounded
    static const double turns[] = {0.0, 0.3, 0.7, 1.1};
    const double r = *rc::gen::inRange(1, 4), t = turns[*rc::gen::inRange(0, 4)];
    for (int k = 0; k < 6; ++k) {
      const double phi = t + k * std::acos(-1.0) / 3;
      h.push_back({r * std::cos(phi), r * std::sin(phi)});
    }
  }
  double x0 = h[0][0], y0 = h[0][1];
  for (const P2d& p : h) {
    x0 = std::min(x0, p[0]);
    y0 = std::min(y0, p[1]);
  }
  for (P2d& p : h) p = {(p[0] - x0) * unit, (p[1] - y0) * unit};  // into the first quadrant
  return h;
}

// The hexagon (in the first quadrant) shifted by (dx, dy), extruded over [z0, z1].
Plc hex_prism(std::vector<P2d> h, double dx, double dy, double z0, double z1) {
  for (P2d& p : h) p = {p[0] + dx, p[1] + dy};
  return prism(h, z0, z1);
}

// The hexagonal prism standing on a slab that surrounds its footprint by `margin` units.
Plc hex_on_slab(double unit, bool rounded) {
  const std::vector<P2d> h = hexagon(unit, rounded);
  const double margin = *rc::gen::inRange(1, 3) * unit;
  const double t = *rc::gen::inRange(1, 3) * unit, top = t + *rc::gen::inRange(1, 4) * unit;
  double w = 0, d = 0;
  for (const P2d& p : h) {
    w = std::max(w, p[0]);
    d = std::max(d, p[1]);
  }
  w += 2 * margin;
  d += 2 * margin;
  Plc plc = box({0, 0, 0}, {w, d, t});  // facet 1 is the top z = t, vertices 4..7
  Plc hex = hex_prism(h, margin, margin, t, top);
  hex.facets.erase(hex.facets.begin());  // the bottom cap is inside the union
  plc = merge(plc, hex);
  // The slab's top: its rectangle and the hexagon (vertices 8..13 after the merge).
  Poly ring;
  for (std::uint32_t k = 0; k < 6; ++k) ring.push_back(8 + k);
  PlcFacet& top_facet = plc.facets[1];
  top_facet.polygons.push_back(ring);
  double cx = 0, cy = 0;
  for (const P2d& p : h) {
    cx += (p[0] + margin) / 6;
    cy += (p[1] + margin) / 6;
  }
  top_facet.holes.push_back({cx, cy, t});
  relabel(plc);
  return plc;
}

}  // namespace

// nx x ny x nz cubes of side `unit`, each a region of its own: every face of every cube a
// square facet (walls between cubes, three or four facet sides around their edges), read as
// TetGen reads a .poly. The cubes flagged in `voids` (by index i + nx (j + ny k)) are voids,
// each marked by a hole point: a face between two voids, or a void and the outside, bounds
// no region and is dropped, as TetGen drops it.
Plc walled_grid(double unit, int nx, int ny, int nz, const std::vector<bool>& voids) {
  const auto id = [&](int i, int j, int k) { return static_cast<std::uint32_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  std::vector<Point> p;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) p.push_back({i * unit, j * unit, k * unit});
  std::vector<FacetSpec> f;
  for (int k = 0; k <= nz; ++k)  // faces normal to z
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) f.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k)}});
  for (int j = 0; j <= ny; ++j)  // normal to y
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) f.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j, k + 1), id(i, j, k + 1)}});
  for (int i = 0; i <= nx; ++i)  // normal to x
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) f.push_back({{id(i, j, k), id(i, j + 1, k), id(i, j + 1, k + 1), id(i, j, k + 1)}});
  Plc plc = make_plc(p, f);
  plc.enclosure = Enclosure::HolePoints;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const auto c = static_cast<std::size_t>(i + nx * (j + ny * k));
        if (c < voids.size() && voids[c]) plc.holes.push_back({(i + 0.5) * unit, (j + 0.5) * unit, (k + 0.5) * unit});
      }
  relabel(plc);
  return plc;
}

rc::Gen<Plc> gen_admissible_domain(bool rounded_hexagons) {
  return rc::gen::exec([rounded_hexagons] {
    static const double units[] = {1.0, 0.5, 0.3, 1.25, 0.1};
    const double unit = units[*rc::gen::inRange(0, 5)];
    const int kind = *rc::gen::inRange(0, 5);
    int width = 0;
    if (kind == 0) return voxel_solid(unit, width);
    if (kind == 4) {
      const auto n = [] { return *rc::gen::inRange(1, 4); };
      const int nx = n(), ny = n(), nz = n();
      // Each cube a void one time in four, one at least kept.
      std::vector<bool> voids;
      for (int c = 0; c < nx * ny * nz; ++c) voids.push_back(*rc::gen::inRange(0, 4) == 0);
      voids[static_cast<std::size_t>(*rc::gen::inRange(0, nx * ny * nz))] = false;
      return walled_grid(unit, nx, ny, nz, voids);
    }
    const double z1 = *rc::gen::inRange(1, 4) * unit;
    if (kind == 1) return hex_prism(hexagon(unit, rounded_hexagons), 0, 0, 0, z1);
    if (kind == 2) return hex_on_slab(unit, rounded_hexagons);
    const Plc solid = voxel_solid(unit, width);
    return merge(solid, hex_prism(hexagon(unit, rounded_hexagons), (width + 1) * unit, 0, 0, z1));
  });
}

rc::Gen<Plc> gen_small_feature_domain() {
  return rc::gen::exec([] {
    const int kind = *rc::gen::inRange(0, 3);
    const double w = 4 + *rc::gen::inRange(0, 5), dep = 2 + *rc::gen::inRange(0, 4);
    const double small = w / std::exp2(*rc::gen::inRange(1, 7));  // w/2 .. w/64
    // A position in [lo, hi - size] on a grid of eighths.
    const auto place = [](double lo, double hi, double size) {
      return lo + (hi - size - lo) * *rc::gen::inRange(1, 8) / 8.0;
    };
    if (kind == 0) {  // a box with a small cubical void
      const double h = std::max(dep, small * 1.5);
      const Point lo{place(0, w, small), place(0, dep, std::min(small, dep / 2)),
                     place(0, h, small)};
      const double sy = std::min(small, dep / 2);
      Plc plc = merge(box({0, 0, 0}, {w, dep, h}),
                      box(lo, {lo[0] + small, lo[1] + sy, lo[2] + small}));
      plc.holes.push_back({lo[0] + small / 2, lo[1] + sy / 2, lo[2] + small / 2});
      relabel(plc);
      return plc;
    }
    if (kind == 1) {  // a plate with a small square through-hole
      const double t = 0.5 + *rc::gen::inRange(0, 4) * 0.25;
      const double x0 = place(0, w, small), y0 = place(0, dep, std::min(small, dep / 2));
      const double x1 = x0 + small, y1 = y0 + std::min(small, dep / 2);
      std::vector<Point> p;
      for (const double z : {0.0, t})
        for (const P2d& q : std::vector<P2d>{{0, 0}, {w, 0}, {w, dep}, {0, dep}, {x0, y0},
                                             {x1, y0}, {x1, y1}, {x0, y1}})
          p.push_back({q[0], q[1], z});
      std::vector<FacetSpec> f{{{0, 1, 2, 3}, {4, 5, 6, 7}}, {{8, 9, 10, 11}, {12, 13, 14, 15}}};
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t j = (i + 1) % 4;
        f.push_back({{i, j, 8 + j, 8 + i}});
        f.push_back({{4 + i, 4 + j, 12 + j, 12 + i}});
      }
      Plc plc = make_plc(p, f);
      plc.facets[0].holes.push_back({(x0 + x1) / 2, (y0 + y1) / 2, 0});
      plc.facets[1].holes.push_back({(x0 + x1) / 2, (y0 + y1) / 2, t});
      return plc;
    }
    // two boxes a small gap apart
    return merge(box({0, 0, 0}, {w, dep, dep}), box({w + small, 0, 0}, {2 * w, dep, dep}));
  });
}

std::string poly_text(const Plc& plc, const std::string& comment) {
  std::ostringstream s;
  s.precision(17);
  auto point = [&](std::size_t i, const Point& p) {
    s << i << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  };
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) s << "# " << line << '\n';
  s << plc.points.size() << " 3 0 0\n";
  for (std::size_t i = 0; i < plc.points.size(); ++i) point(i + 1, plc.points[i]);
  s << plc.facets.size() << " 1\n";
  for (const PlcFacet& f : plc.facets) {
    s << f.polygons.size() << ' ' << f.holes.size() << ' ' << f.marker << '\n';
    for (const auto& poly : f.polygons) {
      s << poly.size();
      for (const auto v : poly) s << ' ' << v + 1;
      s << '\n';
    }
    for (std::size_t h = 0; h < f.holes.size(); ++h) point(h + 1, f.holes[h]);
  }
  s << plc.holes.size() << '\n';
  for (std::size_t h = 0; h < plc.holes.size(); ++h) point(h + 1, plc.holes[h]);
  s << "0\n";
  return s.str();
}

}  // namespace pdr::test

namespace pdr {
void showValue(const Plc& plc, std::ostream& os) { os << test::poly_text(plc, "domain"); }
}  // namespace pdr
