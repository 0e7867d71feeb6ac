// The order-independence check (order_check.hpp): every mesh tet is a tet of DT(V), decided
// from the checker's report where it found the mesh Delaunay, else by DT(V) rebuilt in
// another order; a tet it lacks is a cospherical tie or a violation.
#include "app/order_check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "check/parallel.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/delaunay.hpp"
#include "geom/predicates.hpp"

namespace pdr::app {

namespace {

using Quad = std::array<std::uint32_t, 4>;

Quad sorted(Quad q) {
  std::sort(q.begin(), q.end());
  return q;
}

// For each missing tet, a vertex of DT(V) adjacent to one of its vertices that lies exactly
// on its circumsphere, or -1. `dt` holds the rebuilt tets (sorted quads, any order).
std::vector<std::int64_t> tie_vertices(const MeshData& mesh, const std::vector<Quad>& dt,
                                       const std::vector<std::size_t>& missing) {
  // The DT(V) neighbours of every vertex of a missing tet, in one pass over DT(V).
  std::vector<std::int32_t> slot(mesh.points.size(), -1);
  std::vector<std::vector<std::uint32_t>> around;
  for (std::size_t t : missing)
    for (std::uint32_t v : mesh.tets[t])
      if (slot[v] < 0) {
        slot[v] = std::int32_t(around.size());
        around.emplace_back();
      }
  for (const Quad& q : dt)
    for (std::uint32_t v : q)
      if (slot[v] >= 0)
        around[slot[v]].insert(around[slot[v]].end(), q.begin(), q.end());
  for (auto& a : around) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  std::vector<std::int64_t> out;
  out.reserve(missing.size());
  for (std::size_t t : missing) {
    const auto& m = mesh.tets[t];
    const Point &a = mesh.points[m[0]], &b = mesh.points[m[1]], &c = mesh.points[m[2]],
                &d = mesh.points[m[3]];
    std::int64_t tie = -1;
    if (orient3d(a, b, c, d) != Sign::Zero)
      for (std::uint32_t v : m) {
        for (std::uint32_t w : around[slot[v]]) {
          if (std::find(m.begin(), m.end(), w) != m.end()) continue;
          if (insphere(a, b, c, d, mesh.points[w]) == Sign::Zero) {
            tie = w;
            break;
          }
        }
        if (tie >= 0) break;
      }
    out.push_back(tie);
  }
  return out;
}

}  // namespace

RebuiltDt rebuild_dt(std::span<const Point> points, std::uint64_t seed) {
  RebuiltDt r;
  for (const Point& p : points)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return r;
  Delaunay dt(std::vector<Point>(points.begin(), points.end()));
  BulkOptions o;
  o.seed = seed;
  o.renumber = false;  // vertex ids stay the mesh's
  r.rebuilt = bulk_insert(dt, o).status == BulkStatus::Ok;
  if (!r.rebuilt) return r;
  const TetStore& s = dt.store();
  std::vector<Quad> quads;
  quads.reserve(s.live());
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t) && !s.is_ghost(t)) {
      const VertexId* v = s.vertices(t);
      quads.push_back(sorted({v[0], v[1], v[2], v[3]}));
    }
  // A counting sort by smallest vertex.
  r.first.assign(points.size() + 1, 0);
  for (const Quad& q : quads) ++r.first[q[0] + 1];
  for (std::size_t v = 0; v < points.size(); ++v) r.first[v + 1] += r.first[v];
  r.tets.resize(quads.size());
  std::vector<std::uint32_t> fill(r.first.begin(), r.first.end() - 1);
  for (const Quad& q : quads) r.tets[fill[q[0]]++] = q;
  // Each run sorted: a vertex that is the smallest of many tets (the centre of points on a
  // sphere, numbered first) is searched, not scanned, by every lookup.
  for (std::size_t v = 0; v < points.size(); ++v)
    std::sort(r.tets.begin() + r.first[v], r.tets.begin() + r.first[v + 1]);
  return r;
}

bool RebuiltDt::holds(const Quad& q) const {
  if (q[0] + std::size_t{1} >= first.size()) return false;
  return std::binary_search(tets.begin() + first[q[0]], tets.begin() + first[q[0] + 1], q);
}

bool order_implied(const check::Report& report) {
  if (report.tets == 0) return false;
  for (const char* id : {"validity.indices", "validity.coordinates", "validity.duplicate_vertices",
                         "validity.orientation", "delaunay.empty_sphere"}) {
    const check::CheckResult* r = report.find(id);
    if (!r || r->status != check::Status::Pass) return false;
  }
  return report.on_sphere_complete;
}

OrderCheck order_from_report(const MeshData& mesh, const check::Report& report, std::uint64_t seed,
                             std::size_t max_listed, unsigned threads) {
  OrderCheck r;
  r.seed = seed;
  r.rebuilt = false;
  r.tets = mesh.tets.size();
  const auto& pairs = report.on_sphere;  // sorted by tet
  // Each pair's perturbed side (an exact zero first: the costly case), on every thread.
  std::vector<std::uint8_t> inside(pairs.size(), 0);
  check::parallel_blocks(pairs.size(), threads, 1 << 10, [&](unsigned, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const auto& k = mesh.tets[pairs[i].first];
      const Point &p0 = mesh.points[k[0]], &p1 = mesh.points[k[1]], &p2 = mesh.points[k[2]],
                  &p3 = mesh.points[k[3]];
      inside[i] = insphere_sos(p0, p1, p2, p3, mesh.points[pairs[i].second]) * orient3d(p0, p1, p2, p3) ==
                  Sign::Positive;
    }
  });
  for (std::size_t i = 0; i < pairs.size();) {
    const std::uint64_t t = pairs[i].first;
    std::int64_t tie = -1;
    for (; i < pairs.size() && pairs[i].first == t; ++i)
      if (tie < 0 && inside[i]) tie = pairs[i].second;
    if (tie < 0) continue;
    ++r.missing;
    if (r.first.size() < max_listed) {
      const auto& k = mesh.tets[t];
      r.first.push_back(sorted({k[0], k[1], k[2], k[3]}));
      r.first_index.push_back(t);
      r.first_tie_vertex.push_back(tie);
    }
  }
  r.ties = r.missing;
  return r;
}

OrderCheck check_order_independence(const MeshData& mesh, std::uint64_t seed,
                                     std::size_t max_listed, bool find_ties) {
  return check_order_independence(mesh, rebuild_dt(mesh.points, seed), seed, max_listed,
                                  find_ties);
}

OrderCheck check_order_independence(const MeshData& mesh, const RebuiltDt& dt,
                                     std::uint64_t seed, std::size_t max_listed,
                                     bool find_ties, unsigned threads) {
  OrderCheck r;
  r.seed = seed;
  r.tets = mesh.tets.size();
  r.rebuilt = dt.rebuilt;
  // Each worker lists the misses of its blocks; sorted after, they are in mesh order.
  std::vector<std::vector<std::size_t>> misses(std::max(1u, threads));
  check::parallel_blocks(mesh.tets.size(), threads, 1 << 14,
                         [&](unsigned w, std::size_t b, std::size_t e) {
                           for (std::size_t i = b; i < e; ++i) {
                             const auto& t = mesh.tets[i];
                             if (!dt.holds(sorted({t[0], t[1], t[2], t[3]})))
                               misses[w].push_back(i);
                           }
                         });
  std::vector<std::size_t> missing;
  for (const auto& m : misses) missing.insert(missing.end(), m.begin(), m.end());
  std::sort(missing.begin(), missing.end());
  for (std::size_t k = 0; k < missing.size() && k < max_listed; ++k) {
    const auto& t = mesh.tets[missing[k]];
    r.first.push_back(sorted({t[0], t[1], t[2], t[3]}));
    r.first_index.push_back(missing[k]);
  }
  r.missing = missing.size();
  if (find_ties && r.rebuilt && !missing.empty()) {
    const std::vector<std::int64_t> tie = tie_vertices(mesh, dt.tets, missing);
    r.ties = std::size_t(std::count_if(tie.begin(), tie.end(), [](std::int64_t w) { return w >= 0; }));
    r.first_tie_vertex.assign(tie.begin(), tie.begin() + std::ptrdiff_t(r.first.size()));
  } else {
    r.first_tie_vertex.assign(r.first.size(), -1);
  }
  return r;
}

namespace {

check::CheckResult order_check_result(const MeshData& mesh, const check::Report& report,
                                      std::uint64_t seed) {
  check::CheckResult c;
  c.id = "order.independence";
  c.invariant =
      "Remarks 1-2, Lemma 2: the mesh is DT(V) of its own vertices (symbolically perturbed), "
      "whatever the insertion order";
  for (const char* id : {"validity.indices", "validity.coordinates",
                         "validity.duplicate_vertices"}) {
    const check::CheckResult* v = report.find(id);
    if (v && v->status != check::Status::Pass) {
      c.status = check::Status::Skipped;
      c.reason = std::string("the vertex set cannot be rebuilt (") + id + " did not pass)";
      return c;
    }
  }
  const bool implied = order_implied(report);
  if (implied) c.counts["implied"] = 1;
  // A tie is a difference of tie-breaking only on a Delaunay mesh: a tet with a vertex
  // strictly inside its sphere can have another one exactly on it.
  const check::CheckResult* empty = report.find("delaunay.empty_sphere");
  const bool delaunay = empty && empty->status == check::Status::Pass;
  const OrderCheck oc =
      implied ? order_from_report(mesh, report, seed, report.options.max_reported,
                                  report.options.threads)
              : check_order_independence(mesh, rebuild_dt(mesh.points, seed), seed,
                                         report.options.max_reported, delaunay,
                                         report.options.threads);
  if (!implied && !oc.rebuilt) {
    c.status = check::Status::Skipped;
    c.reason = "the vertices do not span space: no DT(V) to rebuild";
    return c;
  }
  const std::size_t ties = oc.ties;
  c.checked = oc.tets;
  c.violations = oc.missing;  // flagged: failures, or with status warn, ties
  c.counts["seed"] = oc.seed;
  c.counts["missing"] = oc.missing;
  c.counts["cospherical_ties"] = ties;
  for (std::size_t k = 0; k < oc.first.size(); ++k) {
    check::Finding f;
    f.kind = "tet";
    f.id = oc.first_index[k];
    const auto& t = mesh.tets[oc.first_index[k]];
    f.vertices.assign(t.begin(), t.end());
    const bool tie = oc.first_tie_vertex[k] >= 0;
    if (tie) f.vertices.push_back(std::uint32_t(oc.first_tie_vertex[k]));
    for (std::uint32_t v : f.vertices) f.points.push_back(mesh.points[v]);
    f.message = "order.independence: tet " + std::to_string(oc.first_index[k]) +
                (implied ? " is not a tet of DT(V): the symbolic perturbation puts a vertex "
                           "on its sphere inside"
                         : " is not a tet of DT(V) rebuilt in another order") +
                (tie ? " (a cospherical tie: its last vertex lies on the tet's circumsphere)"
                     : "");
    c.findings.push_back(std::move(f));
  }
  if (oc.missing == 0) {
    c.status = check::Status::Pass;
  } else if (ties == oc.missing) {
    c.status = check::Status::Warn;
    c.reason = std::to_string(ties) +
               " tets differ from DT(V) only where vertices are cospherical: a Delaunay "
               "tetrahedralization, with ties broken unlike pdr's symbolic perturbation";
  } else {
    c.status = check::Status::Fail;
  }
  return c;
}

}  // namespace

void add_order_check(check::Report& report, const MeshData& mesh, std::uint64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  check::CheckResult c = order_check_result(mesh, report, seed);
  report.checks.push_back(std::move(c));
  report.seconds["order"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace pdr::app
