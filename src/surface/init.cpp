// Mesh initialization, paper §2.1 steps 1 and 2; see surface/init.hpp.
#include "surface/init.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <memory>
#include <numbers>

#include "domain/distance.hpp"
#include "geom/construct.hpp"
#include "mesh/physical_memory.hpp"
#include "surface/build.hpp"
#include "surface/encroach.hpp"
#include "surface/insert.hpp"
#include "surface/split.hpp"

namespace pdr::surface {

namespace {

double distance(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

double triangle_area(const Point& a, const Point& b, const Point& c) {
  const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// The estimate of surface/init.hpp for the sizes m holds (segment_size, facet_size).
double size_estimate(const SurfaceMesh& m) {
  double n = 0;
  for (std::uint32_t s = 0; s < m.segments.size(); ++s)
    n += distance(m.point(m.segments[s].a), m.point(m.segments[s].b)) / m.segment_size(s);
  for (const Subfacet& t : m.subfacets())
    if (t.alive) {
      const double h = m.facet_size(t.facet);
      n += triangle_area(m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2])) / (h * h);
    }
  return n;
}

// The estimate for the mesh graded by position: the same sums, with each segment and each
// subfacet of the facets' first triangulations cut into pieces no larger than the size at
// their middle (halving a segment, quartering a triangle, at most kDepth times, and not
// where the size is within twice the segment's or facet's own d, below which it never
// goes), each piece counting length / size or area / size^2 at its middle.
double position_estimate(const SurfaceMesh& m) {
  constexpr int kDepth = 12;
  const domain::UnrelatedDistance& z = *m.sizer;
  double n = 0;
  const auto on_segment = [&](auto&& self, std::uint32_t s, const Point& a, const Point& b,
                              int depth) -> void {
    const Point mid = construct::midpoint(a, b);
    const double floor = m.segment_size(s);
    const double l = distance(a, b), h = std::max(floor, z.segment_size_at(s, mid));
    if (depth < kDepth && l > 4 * h && h > 2 * floor) {
      self(self, s, a, mid, depth + 1);
      self(self, s, mid, b, depth + 1);
      return;
    }
    n += l / h;
  };
  for (std::uint32_t s = 0; s < m.segments.size(); ++s)
    on_segment(on_segment, s, m.point(m.segments[s].a), m.point(m.segments[s].b), 0);
  const auto on_triangle = [&](auto&& self, std::uint32_t f, const Point& a, const Point& b,
                               const Point& c, int depth) -> void {
    const Point g{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
    const double area = triangle_area(a, b, c);
    const double floor = m.facet_size(f);
    const double h = std::max(floor, z.facet_size_at(f, g));
    if (depth < kDepth && area > 16 * h * h && h > 2 * floor) {
      const Point ab = construct::midpoint(a, b), bc = construct::midpoint(b, c),
                  ca = construct::midpoint(c, a);
      self(self, f, a, ab, ca, depth + 1);
      self(self, f, ab, b, bc, depth + 1);
      self(self, f, ca, bc, c, depth + 1);
      self(self, f, ab, bc, ca, depth + 1);
      return;
    }
    n += area / (h * h);
  };
  for (const Subfacet& t : m.subfacets())
    if (t.alive)
      on_triangle(on_triangle, t.facet, m.point(t.v[0]), m.point(t.v[1]), m.point(t.v[2]), 0);
  return n;
}

// Graded sizes (surface/init.hpp): d_F per facet, min(d_S, d_F of its facets) per segment.
void set_graded_sizes(SurfaceMesh& m, const domain::PlcDomain& dom) {
  const domain::LocalFeatureSizes local = domain::local_feature_sizes(dom);
  m.facet_d = local.facet_d;
  m.segment_d = local.segment_d;
  for (std::uint32_t s = 0; s < dom.segments.size(); ++s)
    for (const std::uint32_t f : dom.segments[s].facets)
      if (dom.facets[f].is_face) m.segment_d[s] = std::min(m.segment_d[s], m.facet_d[f]);
}

// The guard of surface/init.hpp (a resource limit computed in floating point).
std::size_t vertex_cap(const SurfaceMesh& m, double estimate, const SurfaceOptions& o) {
  const double derived = static_cast<double>(m.vertex_count()) + 16 * estimate + 1024;
  double limit = static_cast<double>(std::numeric_limits<std::uint32_t>::max() / 2);
  if (const double memory = physical_memory_bytes(); memory > 0)
    limit = std::min(limit, memory / 4 / static_cast<double>(kSurfaceVertexBytes));
  auto cap = static_cast<std::size_t>(std::min(derived, limit));
  if (o.max_vertices != 0) cap = std::min(cap, o.max_vertices);
  return cap;
}

class Initializer {
 public:
  Initializer(SurfaceMesh& m, double d, std::size_t cap, SurfaceStats& st)
      : m_(m), d_(d), cap_(cap), st_(st) {}

  void refine_segments() {
    std::deque<std::uint32_t> queue;
    for (std::uint32_t s = 0; s < m_.subsegments().size(); ++s) queue.push_back(s);
    while (!queue.empty()) {
      const std::uint32_t s = queue.front();
      queue.pop_front();
      if (!subsegment_too_long(m_, s, m_.subsegment_size(s))) continue;
      guard(m_.segment_name(m_.subsegment(s).segment) + " (step 1, segment refinement)");
      const SplitResult r = split_subsegment(m_, s);
      ++st_.segment_splits;
      queue.push_back(s);
      queue.push_back(r.new_subsegment);
    }
  }

  void refine_facets() {
    for (std::uint32_t t = 0; t < m_.subfacets().size(); ++t)
      if (m_.subfacet(t).alive) push(t);
    while (!queue_.empty()) {
      const auto [t, v] = queue_.front();
      queue_.pop_front();
      const Subfacet& s = m_.subfacet(t);
      if (!s.alive || s.v != v || !subfacet_too_large(m_, t, m_.subfacet_size(t))) continue;
      const std::uint32_t f = s.facet;
      guard(m_.facet_name(f) + " (step 2, facet refinement)");
      const InsertResult r = insert_circumcenter(m_, t);
      if (r.outcome == InsertOutcome::Rejected)
        throw SurfaceError("surface.insert: " + m_.facet_name(f) +
                           ": the circumcenter of subfacet (" + std::to_string(v[0]) + ", " +
                           std::to_string(v[1]) + ", " + std::to_string(v[2]) +
                           ") cannot be inserted: cavity " + cavity_status_name(r.cavity));
      if (r.outcome == InsertOutcome::Inserted) {
        ++st_.circumcenters;
        for (const std::uint32_t n : r.subfacets) push(n);
        continue;
      }
      for (const std::uint32_t g : r.encroached) {
        guard(m_.facet_name(f) + " (step 2, splitting an encroached subsegment)");
        const SplitResult sr = split_subsegment(m_, g);
        ++st_.encroachment_splits;
        for (const std::uint32_t n : sr.subfacets) push(n);
      }
      queue_.push_back({t, v});
    }
  }

 private:
  void push(std::uint32_t t) { queue_.push_back({t, m_.subfacet(t).v}); }

  void guard(const std::string& where) const {
    if (m_.vertex_count() < cap_) return;
    throw SurfaceCapError(
        "surface.cap: " + where + ": the surface mesh reached " +
        std::to_string(m_.vertex_count()) + " vertices, its cap (--max-vertices, else from the " +
        "domain's size and d = " + number(d_) + ", and a quarter of this machine's memory); " +
        (m_.sizer ? "the graded surface mesh is sized by each element's distance to the "
                    "components unrelated to it, so a small gap makes the surface near it very "
                    "fine"
                  : "the uniform surface mesh of paper §2.1 is sized by d, the smallest distance "
                    "between unrelated components (see the domain report for the pair), so a "
                    "tiny feature makes it very fine") +
        "; or refinement does not converge near an inadmissible angle. Raise --max-vertices, "
        "or enlarge the small feature");
  }

  SurfaceMesh& m_;
  double d_;
  std::size_t cap_;
  SurfaceStats& st_;
  std::deque<std::pair<std::uint32_t, std::array<std::uint32_t, 3>>> queue_;
};

}  // namespace

SurfaceInit init_surface(const domain::PlcDomain& dom, double d, const SurfaceOptions& options) {
  SurfaceInit out;
  out.mesh = build_surface(dom);
  if (!(d > 0) || !std::isfinite(d)) return out;
  out.mesh.d = d;
  out.stats.uniform_estimate = size_estimate(out.mesh);
  if (options.sizing != SurfaceSizing::Uniform) {
    set_graded_sizes(out.mesh, dom);
    out.mesh.sizer = std::make_shared<const domain::UnrelatedDistance>(dom);
    out.stats.graded_estimate = position_estimate(out.mesh);
    out.stats.graded = options.sizing == SurfaceSizing::Graded ||
                       out.stats.uniform_estimate > kGradedGain * out.stats.graded_estimate;
    if (!out.stats.graded) {
      out.mesh.segment_d.clear();
      out.mesh.facet_d.clear();
      out.mesh.sizer.reset();
    }
  }
  const double estimate = out.stats.graded ? out.stats.graded_estimate : out.stats.uniform_estimate;
  out.stats.vertex_cap = vertex_cap(out.mesh, estimate, options);
  const double least = estimate / kEstimateOverLeast;
  if (least > static_cast<double>(out.stats.vertex_cap))
    throw SurfaceCapError(
        "surface.cap: before refinement: the " +
        std::string(out.stats.graded ? "graded" : "uniform") + " surface mesh needs about " +
        number(least) + " vertices or more (the facets' areas and the segments' lengths "
        "against the sizes d gives them, d = " + number(d) + "), more than its cap of " +
        std::to_string(out.stats.vertex_cap) + " (--max-vertices, else from a quarter of this "
        "machine's memory); a thin part or a tiny gap between unrelated components (see the "
        "domain report for the pair) makes d small. Raise --max-vertices, or enlarge the "
        "small feature");
  Initializer init(out.mesh, d, out.stats.vertex_cap, out.stats);
  init.refine_segments();
  init.refine_facets();
  return out;
}

SurfaceInit init_surface(const domain::DomainAnalysis& analysis, const SurfaceOptions& options) {
  return init_surface(analysis.domain, analysis.report.feature.d, options);
}

}  // namespace pdr::surface
