// Domains for the tests of the domain analysis; see tests/support/plc_fixtures.hpp.
#include "support/plc_fixtures.hpp"

#include "domain/validate.hpp"
#include "io/error.hpp"
#include "io/tetgen.hpp"

namespace pdr::test {

void relabel(Plc& plc) {
  plc.source = "test.poly";
  plc.point_lines.resize(plc.points.size());
  for (std::size_t i = 0; i < plc.points.size(); ++i) plc.point_lines[i] = kPointLine + i;
  for (std::size_t f = 0; f < plc.facets.size(); ++f) plc.facets[f].line = kFacetLine + f;
  plc.hole_lines.resize(plc.holes.size());
  for (std::size_t h = 0; h < plc.holes.size(); ++h) plc.hole_lines[h] = kHoleLine + h;
}

Plc make_plc(std::vector<Point> points, std::vector<FacetSpec> facets, std::vector<Point> holes) {
  Plc plc;
  plc.points = std::move(points);
  for (auto& f : facets) {
    PlcFacet facet;
    facet.polygons = std::move(f);
    facet.marker = 1;
    plc.facets.push_back(std::move(facet));
  }
  plc.holes = std::move(holes);
  relabel(plc);
  return plc;
}

Plc box(const Point& lo, const Point& hi) {
  std::vector<Point> p{{lo[0], lo[1], lo[2]}, {hi[0], lo[1], lo[2]}, {hi[0], hi[1], lo[2]},
                       {lo[0], hi[1], lo[2]}, {lo[0], lo[1], hi[2]}, {hi[0], lo[1], hi[2]},
                       {hi[0], hi[1], hi[2]}, {lo[0], hi[1], hi[2]}};
  return make_plc(p, {{{0, 1, 2, 3}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}}, {{1, 2, 6, 5}},
                      {{2, 3, 7, 6}}, {{3, 0, 4, 7}}});
}

Plc prism(const std::vector<P2d>& profile, double z0, double z1) {
  const auto n = static_cast<std::uint32_t>(profile.size());
  std::vector<Point> p;
  for (const P2d& q : profile) p.push_back({q[0], q[1], z0});
  for (const P2d& q : profile) p.push_back({q[0], q[1], z1});
  std::vector<FacetSpec> f(2);
  for (std::uint32_t i = 0; i < n; ++i) {
    f[0].resize(1);
    f[1].resize(1);
    f[0][0].push_back(i);
    f[1][0].push_back(n + i);
  }
  for (std::uint32_t i = 0; i < n; ++i) f.push_back({{i, (i + 1) % n, n + (i + 1) % n, n + i}});
  return make_plc(p, f);
}

Plc walled_box(std::uint32_t n) {
  std::vector<Point> p;
  for (std::uint32_t i = 0; i <= n; ++i) {
    const double x = i;
    for (const P2d& yz : {P2d{0, 0}, P2d{1, 0}, P2d{1, 1}, P2d{0, 1}}) p.push_back({x, yz[0], yz[1]});
  }
  std::vector<FacetSpec> f;
  for (std::uint32_t i = 0; i <= n; ++i) f.push_back({{4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3}});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t a = 4 * i, b = 4 * i + 4;
    f.push_back({{a, b, b + 1, a + 1}});          // bottom, z = 0
    f.push_back({{a + 3, b + 3, b + 2, a + 2}});  // top, z = 1
    f.push_back({{a, b, b + 3, a + 3}});          // front, y = 0
    f.push_back({{a + 1, b + 1, b + 2, a + 2}});  // back, y = 1
  }
  Plc plc = make_plc(p, f);
  plc.enclosure = Enclosure::HolePoints;
  return plc;
}

Plc merge(const Plc& a, const Plc& b) {
  Plc m = a;
  const auto off = static_cast<std::uint32_t>(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  for (PlcFacet f : b.facets) {
    for (auto& poly : f.polygons)
      for (auto& v : poly) v += off;
    m.facets.push_back(f);
  }
  m.holes.insert(m.holes.end(), b.holes.begin(), b.holes.end());
  relabel(m);
  return m;
}

Plc read_data(const std::string& name) { return io::read_tetgen_poly(std::string(PDR_DATA_DIR) + "/" + name); }

std::string error_of(const Plc& plc, const domain::PlcOptions& options) {
  try {
    (void)build_domain(plc, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace pdr::test
