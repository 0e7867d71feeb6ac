// Brute-force oracles (oracle.hpp).
#include "delaunay/oracle.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "geom/exact.hpp"

namespace pdr::testing {

namespace {

constexpr std::size_t kMaxReports = 20;

std::string tet_name(const TetStore& s, TetId t) {
  std::string out = "tet " + std::to_string(t) + " (";
  for (int i = 0; i < 4; ++i) {
    const VertexId v = s.vertex(t, i);
    out += (v == kGhostVertex ? std::string("ghost") : std::to_string(v));
    out += i < 3 ? "," : ")";
  }
  return out;
}

// exact::insphere_sos, skipping the perturbation when the plain sign is nonzero (the two
// agree then, by definition of SoS); much faster on non-degenerate input.
Sign reference_insphere_sos(const Point& a, const Point& b, const Point& c, const Point& d,
                            const Point& e) {
  const Sign plain = exact::insphere(a, b, c, d, e);
  return plain != Sign::Zero ? plain : exact::insphere_sos(a, b, c, d, e);
}

std::vector<VertexId> used_vertices(const Delaunay& dt) {
  const TetStore& s = dt.store();
  std::vector<char> used(dt.num_points(), 0);
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t)) continue;
    for (int i = 0; i < 4; ++i)
      if (s.vertex(t, i) != kGhostVertex) used[s.vertex(t, i)] = 1;
  }
  std::vector<VertexId> out;
  for (VertexId v = 0; v < used.size(); ++v)
    if (used[v]) out.push_back(v);
  return out;
}

}  // namespace

std::vector<std::string> check_positive(const Delaunay& dt) {
  std::vector<std::string> out;
  const TetStore& s = dt.store();
  for (TetId t = 0; t < s.slots() && out.size() < kMaxReports; ++t) {
    if (!s.is_alive(t) || s.is_ghost(t)) continue;
    const VertexId* v = s.vertices(t);
    if (exact::orient3d(dt.point(v[0]), dt.point(v[1]), dt.point(v[2]), dt.point(v[3])) !=
        Sign::Positive)
      out.push_back("tet-positive: " + tet_name(s, t) + " is not positively oriented");
  }
  return out;
}

std::vector<std::string> check_empty_spheres(const Delaunay& dt) {
  std::vector<std::string> out;
  const TetStore& s = dt.store();
  const std::vector<VertexId> used = used_vertices(dt);
  for (TetId t = 0; t < s.slots() && out.size() < kMaxReports; ++t) {
    if (!s.is_alive(t)) continue;
    const VertexId* v = s.vertices(t);
    for (VertexId q : used) {
      if (q == v[0] || q == v[1] || q == v[2] || q == v[3]) continue;
      const Point& a = dt.point(v[0]);
      const Point& b = dt.point(v[1]);
      const Point& c = dt.point(v[2]);
      const Point& p = dt.point(q);
      if (s.is_ghost(t)) {
        const Sign o = exact::orient3d(a, b, c, p);
        if (o == Sign::Negative) continue;
        if (o == Sign::Zero && exact::incircle3_sos(a, b, c, p) == Sign::Negative) continue;
        out.push_back("empty-sphere-hull: vertex " + std::to_string(q) +
                      " conflicts with ghost " + tet_name(s, t));
      } else if (reference_insphere_sos(a, b, c, dt.point(v[3]), p) != Sign::Negative) {
        out.push_back("empty-sphere: vertex " + std::to_string(q) + " conflicts with " +
                      tet_name(s, t));
      }
      if (out.size() >= kMaxReports) break;
    }
  }
  return out;
}

std::vector<std::string> check_hull_and_volume(const Delaunay& dt) {
  std::vector<std::string> out;
  const TetStore& s = dt.store();
  std::map<std::pair<VertexId, VertexId>, int> directed;
  std::set<VertexId> hull_vertices;
  std::size_t faces = 0;
  mpq_class hull_volume6 = 0, tet_volume6 = 0;
  const Point* origin = nullptr;
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || !s.is_ghost(t)) continue;
    const VertexId* v = s.vertices(t);
    if (origin == nullptr) origin = &dt.point(v[0]);
    ++faces;
    for (int k = 0; k < 3; ++k) {
      ++directed[{v[k], v[(k + 1) % 3]}];
      hull_vertices.insert(v[k]);
    }
    hull_volume6 += exact::volume6(*origin, dt.point(v[0]), dt.point(v[1]), dt.point(v[2]));
  }
  for (const auto& [e, n] : directed) {
    if (n != 1) out.push_back("hull-manifold: directed edge " + std::to_string(e.first) + "->" +
                              std::to_string(e.second) + " used " + std::to_string(n) + " times");
    else if (!directed.count({e.second, e.first}))
      out.push_back("hull-closed: edge " + std::to_string(e.first) + "->" +
                    std::to_string(e.second) + " has no reverse");
    if (out.size() >= kMaxReports) return out;
  }
  const long euler = static_cast<long>(hull_vertices.size()) -
                     static_cast<long>(directed.size() / 2) + static_cast<long>(faces);
  if (euler != 2) out.push_back("hull-sphere: Euler characteristic " + std::to_string(euler));
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t)) continue;
    const VertexId* v = s.vertices(t);
    tet_volume6 += exact::volume6(dt.point(v[0]), dt.point(v[1]), dt.point(v[2]), dt.point(v[3]));
  }
  // Hull faces are oriented outward, so (origin, a, b, c) has volume of sign
  // -orient3d(a,b,c,origin) >= 0 and the sum is the enclosed volume (divergence theorem).
  if (hull_volume6 != tet_volume6)
    out.push_back("volume: tets sum to " + tet_volume6.get_str() + "/6, hull encloses " +
                  hull_volume6.get_str() + "/6");
  return out;
}

std::vector<std::string> check_all_points_used(const Delaunay& dt) {
  std::vector<std::string> out;
  const std::vector<VertexId> used = used_vertices(dt);
  std::set<std::array<double, 3>> used_points;
  std::vector<char> is_used(dt.num_points(), 0);
  for (VertexId v : used) {
    used_points.insert(dt.point(v));
    is_used[v] = 1;
  }
  for (VertexId v = 0; v < dt.num_points() && out.size() < kMaxReports; ++v)
    if (!is_used[v] && !used_points.count(dt.point(v)))
      out.push_back("all-points-used: point " + std::to_string(v) + " is in no tet");
  return out;
}

std::vector<std::string> check_all(const Delaunay& dt) {
  std::vector<std::string> out = dt.check_topology();
  if (!out.empty()) return out;  // the geometric checks assume a sound store
  for (auto* check : {&check_positive, &check_empty_spheres, &check_hull_and_volume,
                      &check_all_points_used}) {
    auto v = check(dt);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

std::vector<CanonicalTet> canonical_tets(const Delaunay& dt) {
  std::vector<CanonicalTet> out;
  const TetStore& s = dt.store();
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t)) continue;
    CanonicalTet c;
    for (int i = 0; i < 4; ++i) c[i] = dt.point(s.vertex(t, i));
    std::sort(c.begin(), c.end(), [](const Point& a, const Point& b) { return lex_less(a, b); });
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace pdr::testing
