// Bowyer-Watson cavities in a facet (paper §1.2 in 2D, §2.1 step 2); see surface/cavity.hpp.
#include "surface/cavity.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "geom/encroach.hpp"

namespace pdr::surface {

namespace {

bool is_split_edge(const std::optional<std::array<std::uint32_t, 2>>& split, std::uint32_t u,
                   std::uint32_t w) {
  return split && (((*split)[0] == u && (*split)[1] == w) || ((*split)[0] == w && (*split)[1] == u));
}

bool is_split_end(const std::optional<std::array<std::uint32_t, 2>>& split, std::uint32_t v) {
  return split && ((*split)[0] == v || (*split)[1] == v);
}

// The star-shape test of surface/cavity.hpp.
bool star_shaped(const SurfaceMesh& m, const FacetCavity& c) {
  const FacetChart& ch = m.facets[c.facet].chart;
  std::unordered_map<std::uint32_t, std::size_t> start, end;
  for (std::size_t i = 0; i < c.boundary.size(); ++i) {
    const CavityEdge& e = c.boundary[i];
    if (chart_orient(ch, m.point(e.u), m.point(e.w), c.p) != Sign::Positive) return false;
    if (!start.emplace(e.u, i).second || !end.emplace(e.w, i).second) return false;
  }
  for (const std::uint32_t t : c.tris)
    for (const std::uint32_t v : m.subfacet(t).v)
      if (!start.count(v) && !end.count(v)) return false;
  if (c.boundary.empty()) return false;
  // One loop, or one path (a boundary split: from the vertex that only starts an edge).
  std::size_t first = 0;
  for (std::size_t i = 0; i < c.boundary.size(); ++i)
    if (!end.count(c.boundary[i].u)) first = i;
  std::size_t seen = 0;
  for (std::size_t i = first;;) {
    ++seen;
    const auto next = start.find(c.boundary[i].w);
    if (next == start.end() || next->second == first || seen > c.boundary.size()) break;
    i = next->second;
  }
  return seen == c.boundary.size();
}

}  // namespace

FacetCavity build_facet_cavity(const SurfaceMesh& m, std::uint32_t facet, const Point& p,
                               const std::vector<std::uint32_t>& seeds,
                               const std::optional<std::array<std::uint32_t, 2>>& split) {
  FacetCavity c;
  c.facet = facet;
  c.p = p;
  c.split = split;
  const FacetChart& ch = m.facets[facet].chart;
  auto conflicts = [&](std::uint32_t t) {
    const Subfacet& s = m.subfacet(t);
    return chart_incircle(ch, m.point(s.v[0]), m.point(s.v[1]), m.point(s.v[2]), p) ==
           Sign::Positive;
  };
  std::unordered_set<std::uint32_t> in, out;
  std::vector<std::uint32_t> stack;
  for (const std::uint32_t t : seeds) {
    if (!split && !conflicts(t)) {
      c.status = CavityStatus::SeedNotInConflict;
      return c;
    }
    if (in.insert(t).second) stack.push_back(t);
  }
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    c.tris.push_back(t);
    const Subfacet& s = m.subfacet(t);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = s.v[(i + 1) % 3], w = s.v[(i + 2) % 3];
      if (is_split_edge(split, u, w)) continue;
      const std::int32_t nb = s.nbr[i];
      const bool stop = s.constrained[i] || nb < 0;
      if (!stop) {
        const auto n = static_cast<std::uint32_t>(nb);
        if (in.count(n)) continue;
        if (!out.count(n)) {
          if (conflicts(n)) {
            in.insert(n);
            stack.push_back(n);
            continue;
          }
          out.insert(n);
        }
      }
      c.boundary.push_back({u, w, nb, s.constrained[i]});
    }
  }
  // A subsegment on the boundary that p is in the closed diametral ball of, or (a new
  // vertex inside the facet) on or beyond: Ruppert's remedy for a circumcenter that would
  // leave the facet. The exact argument of surface/cavity.hpp finds such a p in a diametral
  // ball when the subsegments are unencroached; outside the theory a facet vertex can
  // encroach one (an angle above 135 degrees opposite it) and the circumcenter then lies
  // beyond it but outside its ball.
  for (const CavityEdge& e : c.boundary)
    if (e.constrained &&
        (in_diametral_ball(m.point(e.u), m.point(e.w), p) != Sign::Negative ||
         (!split && chart_orient(ch, m.point(e.u), m.point(e.w), p) != Sign::Positive)))
      if (const auto g = m.find_subsegment(e.u, e.w)) c.encroached.push_back(*g);
  std::sort(c.encroached.begin(), c.encroached.end());
  c.encroached.erase(std::unique(c.encroached.begin(), c.encroached.end()), c.encroached.end());
  if (!split && !c.encroached.empty())
    c.status = CavityStatus::Encroaches;
  else if (!star_shaped(m, c))
    c.status = CavityStatus::NotStarShaped;
  return c;
}

std::vector<std::uint32_t> commit_facet_cavity(SurfaceMesh& m, const FacetCavity& c,
                                               std::uint32_t vertex) {
  for (const std::uint32_t t : c.tris) m.kill_subfacet(t);
  std::vector<std::uint32_t> made;
  std::unordered_map<std::uint32_t, std::uint32_t> starting, ending;  // boundary vertex -> new tri
  for (const CavityEdge& e : c.boundary) {
    Subfacet t;
    t.v = {e.u, e.w, vertex};
    t.nbr = {-1, -1, e.outer};
    t.constrained = {is_split_end(c.split, e.w), is_split_end(c.split, e.u), e.constrained};
    t.facet = c.facet;
    const std::uint32_t id = m.add_subfacet(t);
    made.push_back(id);
    starting[e.u] = id;
    ending[e.w] = id;
    if (e.outer >= 0) {
      Subfacet& o = m.subfacet_mut(static_cast<std::uint32_t>(e.outer));
      o.nbr[edge_index(o, e.u, e.w)] = static_cast<std::int32_t>(id);
    }
  }
  for (const std::uint32_t id : made) {
    Subfacet& t = m.subfacet_mut(id);
    if (const auto it = starting.find(t.v[1]); it != starting.end())
      t.nbr[0] = static_cast<std::int32_t>(it->second);  // edge (w, p)
    if (const auto it = ending.find(t.v[0]); it != ending.end())
      t.nbr[1] = static_cast<std::int32_t>(it->second);  // edge (p, u)
  }
  return made;
}

const char* cavity_status_name(CavityStatus s) {
  switch (s) {
    case CavityStatus::Ok: return "ok";
    case CavityStatus::Encroaches: return "encroaches";
    case CavityStatus::SeedNotInConflict: return "seed not in conflict";
    case CavityStatus::NotStarShaped: return "not star-shaped";
  }
  return "?";
}

}  // namespace pdr::surface
