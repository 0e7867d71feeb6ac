// Subsegment splitting at the midpoint (paper §2.1 step 1, Fig. 2); see surface/split.hpp.
#include "surface/split.hpp"

#include <algorithm>

#include "geom/construct.hpp"
#include "surface/cavity.hpp"

namespace pdr::surface {

SplitResult split_subsegment(SurfaceMesh& m, std::uint32_t s) {
  const Subsegment& g = m.subsegment(s);
  return split_subsegment_at(m, s, construct::midpoint(m.point(g.v[0]), m.point(g.v[1])));
}

SplitPlan plan_split(const SurfaceMesh& m, std::uint32_t s, const Point& p) {
  const Subsegment& g = m.subsegment(s);
  const std::uint32_t u = g.v[0], w = g.v[1];
  SplitPlan plan;
  plan.p = p;
  for (const std::uint32_t f : m.segments[g.segment].facets) {
    const std::vector<std::uint32_t> seeds = m.subfacets_on_edge(f, u, w);
    if (seeds.empty())
      throw SurfaceError("surface.conformity: subsegment (" + std::to_string(u) + ", " +
                         std::to_string(w) + ") of " + m.segment_name(g.segment) +
                         " is not an edge of " + m.facet_name(f));
    plan.cavities.push_back(build_facet_cavity(m, f, p, seeds, std::array{u, w}));
    if (plan.cavities.back().status != CavityStatus::Ok) {
      plan.failure = "surface.split: the split point of subsegment (" + std::to_string(u) +
                     ", " + std::to_string(w) + ") of " + m.segment_name(g.segment) +
                     " cannot be inserted in " + m.facet_name(f) + ": cavity " +
                     cavity_status_name(plan.cavities.back().status);
      return plan;
    }
  }
  return plan;
}

SplitResult commit_split(SurfaceMesh& m, std::uint32_t s, const SplitPlan& plan) {
  const Subsegment g = m.subsegment(s);
  SplitResult r;
  r.vertex = m.add_vertex(plan.p, {HomeKind::Segment, g.segment});
  r.new_subsegment = m.split_subsegment_record(s, r.vertex);
  for (const FacetCavity& c : plan.cavities) {
    const std::vector<std::uint32_t> made = commit_facet_cavity(m, c, r.vertex);
    r.subfacets.insert(r.subfacets.end(), made.begin(), made.end());
    r.encroached.insert(r.encroached.end(), c.encroached.begin(), c.encroached.end());
  }
  std::sort(r.encroached.begin(), r.encroached.end());
  r.encroached.erase(std::unique(r.encroached.begin(), r.encroached.end()), r.encroached.end());
  return r;
}

SplitResult split_subsegment_at(SurfaceMesh& m, std::uint32_t s, const Point& p) {
  const SplitPlan plan = plan_split(m, s, p);
  if (!plan.failure.empty()) throw SurfaceError(plan.failure);
  return commit_split(m, s, plan);
}

}  // namespace pdr::surface
