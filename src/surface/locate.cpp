// Point location in a facet's triangulation; see surface/locate.hpp.
#include "surface/locate.hpp"

namespace pdr::surface {
namespace {

// Where q lies relative to live subfacet t of chart ch: the index of an edge with q
// strictly beyond it, one with a subfacet across it first (-1: none, q is in the closed
// triangle), and whether q is on a constrained edge.
int beyond_edge(const SurfaceMesh& m, const FacetChart& ch, const Subfacet& t, const Point& q,
                bool& on_constrained) {
  on_constrained = false;
  int beyond = -1;
  for (int i = 0; i < 3; ++i) {
    const Sign s = chart_orient(ch, m.point(t.v[(i + 1) % 3]), m.point(t.v[(i + 2) % 3]), q);
    if (s == Sign::Negative) {
      if (beyond < 0 || (t.nbr[beyond] < 0 && t.nbr[i] >= 0)) beyond = i;
    } else if (s == Sign::Zero && t.constrained[i]) {
      on_constrained = true;
    }
  }
  return beyond;
}

std::optional<FacetLocation> scan(const SurfaceMesh& m, std::uint32_t f, const Point& q) {
  bool on = false;
  for (const std::uint32_t t : m.facet_subfacets(f))
    if (beyond_edge(m, m.facets[f].chart, m.subfacet(t), q, on) < 0) return FacetLocation{t, on};
  return std::nullopt;
}

}  // namespace

std::optional<FacetLocation> locate_in_facet(const SurfaceMesh& m, std::uint32_t f,
                                             const Point& q, std::uint32_t from) {
  const FacetChart& ch = m.facets[f].chart;
  std::int32_t cur = -1;
  for (const std::uint32_t t : m.vertex_subfacets(from))
    if (m.subfacet(t).alive && m.subfacet(t).facet == f) {
      cur = static_cast<std::int32_t>(t);
      break;
    }
  if (cur < 0) return std::nullopt;
  const std::size_t limit = m.live_subfacets();
  bool on = false;
  for (std::size_t step = 0; step <= limit; ++step) {
    const Subfacet& t = m.subfacet(static_cast<std::uint32_t>(cur));
    const int e = beyond_edge(m, ch, t, q, on);
    if (e < 0) return FacetLocation{static_cast<std::uint32_t>(cur), on};
    if (t.nbr[e] < 0) break;  // beyond the facet's boundary here: outside, or not convex
    cur = t.nbr[e];
  }
  // The walk left the facet or cycled: test every subfacet of f.
  return scan(m, f, q);
}

}  // namespace pdr::surface
