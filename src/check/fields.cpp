// Per-tet fields of a report (fields.hpp): the tets each finding names, counted per check.
#include "check/fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gmpxx.h>

#include "check/signs.hpp"
#include "geom/construct.hpp"
#include "geom/exact.hpp"

namespace pdr::check {

namespace {

bool indices_ok(const MeshView& mesh, const Tet& k) {
  return std::all_of(k.begin(), k.end(), [&](std::uint32_t v) { return v < mesh.points.size(); });
}

double squared_length(const Point& a, const Point& b) {
  double s = 0;
  for (int i = 0; i < 3; ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return s;
}

// R / lmin for display; NaN when undefined.
double tet_ratio(const MeshView& mesh, const Tet& k) {
  if (!indices_ok(mesh, k)) return std::numeric_limits<double>::quiet_NaN();
  const Point &a = mesh.points[k[0]], &b = mesh.points[k[1]], &c = mesh.points[k[2]],
              &d = mesh.points[k[3]];
  if (signs::orient3d(a, b, c, d) == Sign::Zero) return std::numeric_limits<double>::quiet_NaN();
  return tet_measures(a, b, c, d).ratio;
}

std::size_t named_prefix(const std::string& kind, std::size_t n) {
  if (kind == "face" || kind == "subfacet") return std::min<std::size_t>(3, n);
  if (kind == "edge" || kind == "subsegment") return std::min<std::size_t>(2, n);
  return 0;
}

}  // namespace

TetMeasures tet_measures(const Point& a, const Point& b, const Point& c, const Point& d) {
  const std::array<const Point*, 4> p{&a, &b, &c, &d};
  bool in_range = true;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      for (int k = 0; k < 3; ++k)
        in_range = in_range && signs::entry_in_range((*p[i])[k] - (*p[j])[k]);
  TetMeasures m;
  if (in_range) {
    double l2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) l2 = std::min(l2, squared_length(*p[i], *p[j]));
    const double r2 = construct::circumradius2(a, b, c, d);
    m.circumcenter = construct::circumcenter(a, b, c, d);
    m.circumradius = std::sqrt(r2);
    m.shortest_edge = std::sqrt(l2);
    m.ratio = std::sqrt(r2 / l2);
    return m;
  }
  mpq_class l2;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const mpq_class q = exact::squared_distance(*p[i], *p[j]);
      if ((i == 0 && j == 1) || q < l2) l2 = q;
    }
  const mpq_class r2 = exact::circumradius2(a, b, c, d);
  const auto o = exact::circumcenter(a, b, c, d);
  for (int k = 0; k < 3; ++k) m.circumcenter[k] = o[k].get_d();
  m.circumradius = std::sqrt(r2.get_d());
  m.shortest_edge = std::sqrt(l2.get_d());
  const mpq_class q = r2 / l2;  // scale-free: a normal double whatever the coordinates
  m.ratio = std::sqrt(q.get_d());
  return m;
}

std::vector<std::vector<std::uint32_t>> vertex_tets(const MeshView& mesh) {
  std::vector<std::vector<std::uint32_t>> inc(mesh.points.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (std::uint32_t v : mesh.tets[t])
      if (v < inc.size() && (inc[v].empty() || inc[v].back() != t))
        inc[v].push_back(static_cast<std::uint32_t>(t));
  return inc;
}

std::vector<std::uint64_t> tets_named_by(const Finding& f,
                                         const std::vector<std::vector<std::uint32_t>>& incident,
                                         const MeshView& mesh) {
  std::vector<std::uint64_t> out;
  if (f.kind == "tet") {
    if (f.id < mesh.tets.size()) out.push_back(f.id);
    return out;
  }
  std::vector<std::uint32_t> need;
  if (f.kind == "vertex" && !f.vertices.empty()) {
    need.push_back(f.vertices.back());
  } else {
    const std::size_t n = named_prefix(f.kind, f.vertices.size());
    need.assign(f.vertices.begin(), f.vertices.begin() + static_cast<std::ptrdiff_t>(n));
  }
  if (need.empty() || need[0] >= incident.size()) return out;
  for (std::uint32_t t : incident[need[0]]) {
    const Tet& k = mesh.tets[t];
    const bool all = std::all_of(need.begin(), need.end(), [&](std::uint32_t v) {
      return std::find(k.begin(), k.end(), v) != k.end();
    });
    if (all) out.push_back(t);
  }
  return out;  // incident lists are increasing, so out is sorted and unique
}

std::vector<TetField> tet_fields(const MeshView& mesh, const Report& report) {
  const std::size_t n = mesh.tets.size();
  std::vector<TetField> fields;
  TetField ratio{"ratio", std::vector<double>(n)};
  for (std::size_t t = 0; t < n; ++t) ratio.values[t] = tet_ratio(mesh, mesh.tets[t]);
  fields.push_back(std::move(ratio));
  fields.push_back({"failed_checks", std::vector<double>(n, 0.0)});

  const auto incident = vertex_tets(mesh);
  for (const CheckResult& r : report.checks) {
    if (r.status != Status::Fail) continue;
    std::vector<double> mark(n, 0.0);
    bool any = false;
    for (const Finding& f : r.findings)
      for (std::uint64_t t : tets_named_by(f, incident, mesh)) {
        mark[t] = 1.0;
        any = true;
      }
    if (!any) continue;
    for (std::size_t t = 0; t < n; ++t) fields[1].values[t] += mark[t];
    fields.push_back({"fail:" + r.id, std::move(mark)});
  }
  return fields;
}

}  // namespace pdr::check
