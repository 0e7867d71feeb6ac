// validity.*: the mesh is a tetrahedralization (the objects T(Omega) of paper §1.1 are
// tetrahedra forming a simplicial mesh). Exact invariants:
//   indices           every vertex index of tets/faces < #points; #tets < 2^30
//   coordinates       every coordinate finite
//   orientation       orient3d(t0,t1,t2,t3) > 0 exactly for every tet (zero volume fails)
//   duplicate_vertices  no two vertices with exactly equal coordinates
//   unreferenced_vertices  (warning) vertices in no tet; harmless for every other check
//                     except conformity (an input vertex must be in the mesh *and* in a tet
//                     to be of use) and Delaunay emptiness (they still must lie outside
//                     every circumsphere: they are points of the mesh)
//   face_sharing      every face in at most two tets, whose fourth vertices lie strictly on
//                     opposite sides of it (decided from the exact orientations)
//   boundary_closed   the faces held by one tet, oriented outward by geometry, use every
//                     edge as often in each direction (a closed, consistently oriented surface)
//   faces             MeshData.faces, if given, lists every boundary face (in any vertex order;
//                     inward orientation is a warning) and otherwise only faces of tets
//                     (interior faces are allowed: internal facets); no face twice
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "check/checks.hpp"
#include "check/parallel.hpp"
#include "check/signs.hpp"

namespace pdr::check {
namespace {

bool same_cycle(const Tri& a, const Tri& b) {
  for (int s = 0; s < 3; ++s)
    if (a[0] == b[s] && a[1] == b[(s + 1) % 3] && a[2] == b[(s + 2) % 3]) return true;
  return false;
}

}  // namespace

CheckResult check_indices(const MeshView& mesh, const Options& o) {
  CheckResult r = make_result("validity.indices");
  const std::size_t n = mesh.points.size();
  const std::size_t max = o.max_reported;
  if (mesh.tets.size() >= (std::size_t{1} << 30)) {
    ++r.violations;
    r.findings.push_back({"mesh", kNoId, {}, {}, std::nullopt,
                          "validity.indices: more than 2^30 tets are not supported"});
  }
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    ++r.checked;
    const Tet& tet = mesh.tets[t];
    if (std::all_of(tet.begin(), tet.end(), [&](std::uint32_t v) { return v < n; })) continue;
    ++r.violations;
    if (r.findings.size() < max)
      r.findings.push_back({"tet", t, {tet.begin(), tet.end()}, {}, std::nullopt,
                            "validity.indices: tet " + std::to_string(t) + " has a vertex index >= " +
                                std::to_string(n)});
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    ++r.checked;
    const Tri& tri = mesh.faces[f];
    if (std::all_of(tri.begin(), tri.end(), [&](std::uint32_t v) { return v < n; })) continue;
    ++r.violations;
    if (r.findings.size() < max)
      r.findings.push_back({"face", f, {tri.begin(), tri.end()}, {}, std::nullopt,
                            "validity.indices: face " + std::to_string(f) + " has a vertex index >= " +
                                std::to_string(n)});
  }
  conclude(r);
  return r;
}

CheckResult check_coordinates(const MeshView& mesh, const Options& o) {
  CheckResult r = make_result("validity.coordinates");
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    ++r.checked;
    const Point& p = mesh.points[v];
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) continue;
    ++r.violations;
    if (r.findings.size() < o.max_reported)
      r.findings.push_back({"vertex", v, {static_cast<std::uint32_t>(v)}, {p}, std::nullopt,
                            "validity.coordinates: vertex " + std::to_string(v) + " is not finite"});
  }
  conclude(r);
  return r;
}

CheckResult check_orientation(const MeshView& mesh, const Options& o,
                              std::vector<Sign>& orientation) {
  CheckResult r = make_result("validity.orientation");
  orientation.assign(mesh.tets.size(), Sign::Zero);
  std::vector<Collector> parts(std::max(1u, o.threads), Collector(o.max_reported));
  parallel_blocks(mesh.tets.size(), o.threads, 4096, [&](unsigned w, std::size_t b, std::size_t e) {
    Collector& c = parts[w];
    const std::uint64_t before = signs::exact_evaluations();
    for (std::size_t t = b; t < e; ++t) {
      const Tet& k = mesh.tets[t];
      const Sign s = signs::orient3d(mesh.points[k[0]], mesh.points[k[1]], mesh.points[k[2]],
                                     mesh.points[k[3]]);
      orientation[t] = s;
      ++c.checked;
      if (s == Sign::Positive) continue;
      ++c.counts[s == Sign::Zero ? "zero_volume" : "negative"];
      if (!c.wants(t)) {
        c.violation(t);
        continue;
      }
      Finding f = tet_finding(mesh, t, std::string("validity.orientation: tet ") + std::to_string(t) +
                                           (s == Sign::Zero ? " has zero volume" : " is inverted"));
      f.value = s == Sign::Zero ? 0.0 : -1.0;
      c.violation(t, std::move(f));
    }
    c.counts["exact_evaluations"] += signs::exact_evaluations() - before;
  });
  merge_into(parts, r, o.max_reported);
  conclude(r);
  return r;
}

CheckResult check_duplicate_vertices(const Context& c) {
  CheckResult r = make_result("validity.duplicate_vertices");
  const auto& pts = c.mesh.points;
  std::vector<std::uint32_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    return lex_less(pts[x], pts[y]) || (!lex_less(pts[y], pts[x]) && x < y);
  });
  r.checked = pts.size();
  std::vector<std::pair<std::uint64_t, Finding>> found;
  for (std::size_t i = 1; i < order.size(); ++i) {
    const std::uint32_t a = order[i - 1], b = order[i];
    if (lex_less(pts[a], pts[b])) continue;
    ++r.violations;
    found.emplace_back(b, make_finding(c.mesh, "vertex", b, {a, b},
                                       "validity.duplicate_vertices: vertex " + std::to_string(b) +
                                           " has the coordinates of vertex " + std::to_string(a)));
  }
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t i = 0; i < found.size() && i < c.options.max_reported; ++i)
    r.findings.push_back(std::move(found[i].second));
  conclude(r);
  return r;
}

CheckResult check_unreferenced_vertices(const Context& c) {
  CheckResult r = make_result("validity.unreferenced_vertices");
  std::vector<bool> used(c.mesh.points.size(), false);
  for (const Tet& t : c.mesh.tets)
    for (std::uint32_t v : t) used[v] = true;
  r.checked = used.size();
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (used[v]) continue;
    ++r.violations;
    if (r.findings.size() < c.options.max_reported)
      r.findings.push_back(make_finding(c.mesh, "vertex", v, {static_cast<std::uint32_t>(v)},
                                        "validity.unreferenced_vertices: vertex " + std::to_string(v) +
                                            " is in no tet"));
  }
  r.status = r.violations == 0 ? Status::Pass : Status::Warn;
  if (r.violations) r.reason = "vertices in no tet (not a failure: they still take part in Delaunay emptiness)";
  return r;
}

CheckResult check_face_sharing(const Context& c) {
  CheckResult r = make_result("validity.face_sharing");
  const Topology& topo = c.topology;
  const Options& o = c.options;
  std::vector<Collector> parts(std::max(1u, o.threads), Collector(o.max_reported));
  const auto block = [&](unsigned w, std::size_t b, std::size_t e) {
    Collector& col = parts[w];
    for (std::size_t f = b; f < e; ++f) {
      const auto h = topo.holders(f);
      ++col.checked;
      std::string why;
      if (h.size() > 2) {
        why = " is shared by " + std::to_string(h.size()) + " tets";
      } else if (h.size() == 2) {
        const int s0 = apex_side(c, h[0]), s1 = apex_side(c, h[1]);
        if (s0 == 0 || s1 == 0) {
          ++col.counts["degenerate_skipped"];
          continue;
        }
        if (s0 != s1) continue;
        why = " has tets " + std::to_string(h[0].tet) + " and " + std::to_string(h[1].tet) +
              " on the same side";
      } else {
        continue;
      }
      if (!col.wants(f)) {
        col.violation(f);
        continue;
      }
      const Tri& k = topo.faces[f];
      col.violation(f, make_finding(c.mesh, "face", kNoId, {k[0], k[1], k[2]},
                                    "validity.face_sharing: face (" + std::to_string(k[0]) + "," +
                                        std::to_string(k[1]) + "," + std::to_string(k[2]) + ")" +
                                        why));
    }
  };
  parallel_blocks(topo.faces.size(), o.threads, 1 << 14, block);
  merge_into(parts, r, o.max_reported);
  conclude(r);
  return r;
}

std::optional<Tri> outward_boundary_face(const Context& c, std::uint32_t face) {
  const FaceRef& h = c.topology.holders(face)[0];
  const Sign s = c.orientation[h.tet];
  if (s == Sign::Zero) return std::nullopt;
  Tri f = face_of(c.mesh.tets[h.tet], h.local);
  if (s == Sign::Negative) std::swap(f[1], f[2]);
  return f;
}

CheckResult check_boundary_closed(const Context& c) {
  CheckResult r = make_result("validity.boundary_closed");
  std::vector<std::pair<std::uint64_t, int>> uses;
  for (std::uint32_t f : c.topology.boundary) {
    const auto o = outward_boundary_face(c, f);
    if (!o) {
      ++r.counts["degenerate_skipped"];
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = (*o)[i], v = (*o)[(i + 1) % 3];
      uses.emplace_back(edge_key(u, v), u < v ? 1 : -1);
    }
  }
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    int sum = 0;
    while (j < uses.size() && uses[j].first == uses[i].first) sum += uses[j++].second;
    ++r.checked;
    if (sum != 0) {
      ++r.violations;
      if (r.findings.size() < c.options.max_reported) {
        const auto u = static_cast<std::uint32_t>(uses[i].first >> 32),
                   v = static_cast<std::uint32_t>(uses[i].first);
        Finding fd = make_finding(c.mesh, "edge", kNoId, {u, v},
                                  "validity.boundary_closed: boundary edge (" + std::to_string(u) +
                                      "," + std::to_string(v) + ") is used " + std::to_string(sum) +
                                      " more times in one direction than the other");
        fd.value = sum;
        r.findings.push_back(std::move(fd));
      }
    }
    i = j;
  }
  conclude(r);
  return r;
}

CheckResult check_listed_faces(const Context& c) {
  CheckResult r = make_result("validity.faces");
  if (c.mesh.faces.empty()) {
    r.reason = "no faces listed";
    return r;
  }
  const Topology& topo = c.topology;
  std::vector<std::uint8_t> listed(topo.faces.size(), 0);
  auto report = [&](std::uint64_t id, std::vector<std::uint32_t> vs, const std::string& msg) {
    ++r.violations;
    if (r.findings.size() < c.options.max_reported)
      r.findings.push_back(make_finding(c.mesh, "face", id, std::move(vs), "validity.faces: " + msg));
  };
  for (std::size_t i = 0; i < c.mesh.faces.size(); ++i) {
    ++r.checked;
    const Tri& given = c.mesh.faces[i];
    Tri key = given;
    std::sort(key.begin(), key.end());
    const auto f = topo.find_face(key);
    const std::vector<std::uint32_t> vs(given.begin(), given.end());
    if (!f) {
      report(i, vs, "listed face " + std::to_string(i) + " is not a face of any tet");
      continue;
    }
    if (listed[*f]++) {
      report(i, vs, "listed face " + std::to_string(i) + " is listed twice");
      continue;
    }
    if (topo.holders(*f).size() != 1) {
      ++r.counts["interior_listed"];
      continue;
    }
    const auto out = outward_boundary_face(c, static_cast<std::uint32_t>(*f));
    if (out && !same_cycle(given, *out)) ++r.counts["inward"];
  }
  for (std::uint32_t f : topo.boundary) {
    if (listed[f]) continue;
    const Tri& k = topo.faces[f];
    report(kNoId, {k[0], k[1], k[2]}, "boundary face (" + std::to_string(k[0]) + "," +
                                          std::to_string(k[1]) + "," + std::to_string(k[2]) +
                                          ") is not listed");
  }
  conclude(r);
  if (r.status == Status::Pass && r.counts["inward"] > 0) {
    r.status = Status::Warn;
    r.reason = "some listed boundary faces are oriented inward (MeshData expects outward normals)";
  }
  return r;
}

}  // namespace pdr::check
