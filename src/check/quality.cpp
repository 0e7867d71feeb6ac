// quality.*: the two properties of Theorem 1 (paper §3), decided exactly.
//   quality.ratio          every tet's radius-edge ratio R / lmin < B, i.e. in rationals
//                          R^2 < B^2 lmin^2 (B the given double, taken exactly);
//                          Theorem 1 (2) with B = 2. The largest ratio is reported (double,
//                          for display only).
//   quality.shortest_edge  every mesh edge longer than h: l^2 > h^2 exactly; Theorem 1 (1).
// Interval filters decide almost every element; GMP (geom/exact.hpp) decides the rest.
// Degenerate tets are skipped (validity.orientation reports them). Without B (or h) the
// check is Skipped but the extreme value is still reported.
#include <algorithm>
#include <cmath>

#include <gmpxx.h>

#include "check/checks.hpp"
#include "check/circumball.hpp"
#include "check/parallel.hpp"
#include "check/signs.hpp"
#include "geom/exact.hpp"

namespace pdr::check {
namespace {

double mid(const Interval& x) { return 0.5 * x.lo + 0.5 * x.hi; }

}  // namespace

CheckResult check_radius_edge_ratio(const Context& c) {
  CheckResult r = make_result("quality.ratio");
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  const Options& o = c.options;
  const bool bounded = o.ratio_bound && std::isfinite(*o.ratio_bound) && *o.ratio_bound > 0;
  const double B = bounded ? *o.ratio_bound : 0.0;
  const Interval B2 = square(Interval(B));
  struct Extreme {
    double ratio = -1;
    std::uint64_t tet = kNoId;
  };
  std::vector<Extreme> ext(std::max(1u, o.threads));
  std::vector<Collector> parts(std::max(1u, o.threads), Collector(o.max_reported));
  parallel_blocks(tets.size(), o.threads, 4096, [&](unsigned w, std::size_t b, std::size_t e) {
    Collector& col = parts[w];
    std::uint64_t exact = 0, skipped = 0;
    for (std::size_t t = b; t < e; ++t) {
      if (c.orientation[t] == Sign::Zero) {
        ++skipped;
        continue;
      }
      ++col.checked;
      const Tet& k = tets[t];
      const std::array<const Point*, 4> p = {&pts[k[0]], &pts[k[1]], &pts[k[2]], &pts[k[3]]};
      // The minimum of the six squared lengths lies in [min of lows, min of highs].
      Interval l2 = squared_distance(*p[0], *p[1]);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          const Interval x = squared_distance(*p[i], *p[j]);
          l2 = {std::min(l2.lo, x.lo), std::min(l2.hi, x.hi)};
        }
      const Interval R2 = t < c.circum_r2.size() ? c.circum_r2[t]
                                                 : circumball(*p[0], *p[1], *p[2], *p[3]).r2;
      const double ratio = std::sqrt(mid(R2) / mid(l2));
      if (ratio > ext[w].ratio || (ratio == ext[w].ratio && t < ext[w].tet)) ext[w] = {ratio, t};
      if (!bounded) continue;
      bool bad;
      if (const auto s = interval_sign(B2 * l2 - R2)) {
        bad = *s == Sign::Negative;
      } else {
        ++exact;
        mpq_class lmin = exact::squared_distance(*p[0], *p[1]);
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) lmin = std::min(lmin, exact::squared_distance(*p[i], *p[j]));
        const mpq_class qb(B);
        bad = !(exact::circumradius2(*p[0], *p[1], *p[2], *p[3]) < qb * qb * lmin);
      }
      if (!bad) continue;
      if (!col.wants(t)) {
        col.violation(t);
        continue;
      }
      Finding f = tet_finding(c.mesh, t, "quality.ratio: tet " + std::to_string(t) +
                                             " has radius-edge ratio " + std::to_string(ratio) +
                                             " >= " + std::to_string(B));
      f.value = ratio;
      col.violation(t, std::move(f));
    }
    col.counts["exact_evaluations"] += exact;
    col.counts["degenerate_skipped"] += skipped;
  });
  merge_into(parts, r, o.max_reported);
  Extreme best;
  for (const Extreme& x : ext)
    if (x.ratio > best.ratio || (x.ratio == best.ratio && x.tet < best.tet)) best = x;
  if (best.tet != kNoId) {
    r.values["max_ratio"] = best.ratio;
    r.values["max_ratio_tet"] = static_cast<double>(best.tet);
  }
  if (bounded) {
    r.values["bound"] = B;
    conclude(r);
  } else {
    r.reason = o.ratio_bound ? "ratio bound must be finite and positive"
                             : "no ratio bound given (--ratio); max_ratio reported";
  }
  return r;
}

CheckResult check_shortest_edge(const Context& c) {
  CheckResult r = make_result("quality.shortest_edge");
  const auto& pts = c.mesh.points;
  const Options& o = c.options;
  const bool bounded = o.min_edge && std::isfinite(*o.min_edge) && *o.min_edge >= 0;
  const double h = bounded ? *o.min_edge : 0.0;
  const Interval h2 = square(Interval(h));
  double shortest = INFINITY;
  std::uint64_t shortest_edge = kNoId;
  std::uint64_t exact = 0;
  const auto& edges = c.topology.edges;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto u = static_cast<std::uint32_t>(edges[i] >> 32), v = static_cast<std::uint32_t>(edges[i]);
    ++r.checked;
    const Interval l2 = squared_distance(pts[u], pts[v]);
    const double len = std::sqrt(mid(l2));
    if (len < shortest) shortest = len, shortest_edge = i;
    if (!bounded) continue;
    bool bad;
    if (const auto s = interval_sign(l2 - h2)) {
      bad = *s == Sign::Negative;
    } else {
      ++exact;
      const mpq_class qh(h);
      bad = !(exact::squared_distance(pts[u], pts[v]) > qh * qh);
    }
    if (!bad) continue;
    ++r.violations;
    if (r.findings.size() < o.max_reported) {
      Finding f = make_finding(c.mesh, "edge", i, {u, v},
                               "quality.shortest_edge: edge (" + std::to_string(u) + "," +
                                   std::to_string(v) + ") has length " + std::to_string(len) +
                                   " <= " + std::to_string(h));
      f.value = len;
      r.findings.push_back(std::move(f));
    }
  }
  r.counts["exact_evaluations"] = exact;
  if (shortest_edge != kNoId) {
    r.values["min_edge"] = shortest;
    const std::uint64_t e = edges[shortest_edge];
    r.values["min_edge_u"] = static_cast<double>(e >> 32);
    r.values["min_edge_v"] = static_cast<double>(e & 0xffffffffu);
  }
  if (bounded) {
    r.values["bound"] = h;
    conclude(r);
  } else {
    r.reason = o.min_edge ? "edge bound must be finite and non-negative"
                          : "no edge bound given (--h); min_edge reported";
  }
  return r;
}

}  // namespace pdr::check
