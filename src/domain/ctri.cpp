// Constrained triangulation of a planar straight-line graph (paper §1.1 facets); see
// domain/ctri.hpp for the method and its invariants.
#include "domain/ctri.hpp"

#include <algorithm>
#include <deque>
#include <numeric>
#include <stdexcept>

#include "geom/predicates.hpp"

namespace pdr::domain {

namespace {

// Precondition: u, v, x collinear, x != u. True when x lies on the ray from u through v.
bool on_ray(const P2& u, const P2& v, const P2& x) {
  for (int c = 0; c < 2; ++c)
    if (u[c] != v[c]) return (x[c] > u[c]) == (v[c] > u[c]) && x[c] != u[c];
  return false;
}

}  // namespace

int Ct2::index_of(const Ct2Tri& t, std::uint32_t v) {
  return t.v[0] == v ? 0 : (t.v[1] == v ? 1 : 2);
}

int Ct2::opposite(const Ct2Tri& t, std::uint32_t a, std::uint32_t b) {
  for (int i = 0; i < 3; ++i)
    if (t.v[i] != a && t.v[i] != b) return i;
  return 0;
}

void Ct2::link(std::int32_t t1, std::int32_t t2, std::uint32_t a, std::uint32_t b) {
  if (t1 >= 0) tris_[t1].n[opposite(tris_[t1], a, b)] = t2;
  if (t2 >= 0) tris_[t2].n[opposite(tris_[t2], a, b)] = t1;
}

std::int32_t Ct2::add_tri(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const auto t = static_cast<std::int32_t>(tris_.size());
  Ct2Tri tri;
  tri.v = {a, b, c};
  tris_.push_back(tri);
  vt_[a] = vt_[b] = vt_[c] = t;
  return t;
}

Ct2Outcome Ct2::build(std::vector<P2> points,
                      const std::vector<std::array<std::uint32_t, 2>>& constraints) {
  pts_ = std::move(points);
  tris_.clear();
  vt_.assign(pts_.size(), -1);
  std::vector<std::uint32_t> ord(pts_.size());
  std::iota(ord.begin(), ord.end(), 0u);
  std::sort(ord.begin(), ord.end(), [&](std::uint32_t a, std::uint32_t b) {
    return pts_[a] < pts_[b] || (pts_[a] == pts_[b] && a < b);
  });
  for (std::size_t i = 1; i < ord.size(); ++i)
    if (pts_[ord[i - 1]] == pts_[ord[i]])
      return {Ct2Status::Duplicate, ord[i - 1], ord[i], 0, 0};
  if (!hull_sweep(ord)) return {Ct2Status::Collinear, 0, 0, 0, 0};
  for (const auto& c : constraints) {
    if (c[0] == c[1]) continue;
    const Ct2Outcome r = insert_constraint(c[0], c[1]);
    if (r.status != Ct2Status::Ok) return r;
  }
  make_delaunay();
  return {};
}

bool Ct2::hull_sweep(const std::vector<std::uint32_t>& ord) {
  const std::size_t n = ord.size();
  if (n < 3) return false;
  std::size_t k = 2;
  while (k < n && orient(ord[0], ord[1], ord[k]) == Sign::Zero) ++k;
  if (k == n) return false;
  // Fan over the collinear prefix ord[0..k-1] from ord[k].
  const bool ccw = orient(ord[0], ord[1], ord[k]) == Sign::Positive;
  const std::uint32_t ok = ord[k];
  std::vector<std::uint32_t> next(pts_.size()), prev(pts_.size());
  std::vector<std::int32_t> owner(pts_.size(), -1);  // triangle holding hull edge a->next[a]
  auto hull_edge = [&](std::uint32_t a, std::uint32_t b, std::int32_t t) {
    next[a] = b;
    prev[b] = a;
    owner[a] = t;
  };
  std::int32_t prev_t = -1;
  for (std::size_t i = 0; i + 1 < k; ++i) {
    const std::uint32_t a = ord[i], b = ord[i + 1];
    const std::int32_t t = ccw ? add_tri(a, b, ok) : add_tri(b, a, ok);
    if (prev_t >= 0) link(prev_t, t, a, ok);
    prev_t = t;
    if (ccw) hull_edge(a, b, t);
    else hull_edge(b, a, t);
  }
  if (ccw) {
    hull_edge(ord[k - 1], ok, prev_t);
    hull_edge(ok, ord[0], 0);
  } else {
    hull_edge(ok, ord[k - 1], prev_t);
    hull_edge(ord[0], ok, 0);
  }
  // Each later point is lexicographically largest, hence strictly outside the hull: join
  // it to the chain of hull edges it sees (orient < 0 for a counter-clockwise hull).
  for (std::size_t idx = k + 1; idx < n; ++idx) {
    const std::uint32_t p = ord[idx], last = ord[idx - 1];
    auto visible = [&](std::uint32_t a) { return orient(a, next[a], p) == Sign::Negative; };
    std::uint32_t e0 = last;
    if (!visible(e0)) e0 = prev[last];
    if (!visible(e0)) {
      for (e0 = next[last]; e0 != last && !visible(e0);) e0 = next[e0];
      if (!visible(e0)) throw std::logic_error("plc_ctri: new point sees no hull edge");
    }
    std::uint32_t s = e0, e = next[e0];
    for (std::size_t guard = 0; visible(prev[s]) && guard < n; ++guard) s = prev[s];
    for (std::size_t guard = 0; visible(e) && guard < n; ++guard) e = next[e];
    std::int32_t first_t = -1;
    prev_t = -1;
    for (std::uint32_t a = s; a != e;) {
      const std::uint32_t b = next[a];
      const std::int32_t t = add_tri(p, b, a);
      link(t, owner[a], a, b);
      if (prev_t >= 0) link(prev_t, t, p, a);
      else first_t = t;
      prev_t = t;
      a = b;
    }
    hull_edge(s, p, first_t);
    hull_edge(p, e, prev_t);
  }
  return true;
}

std::pair<std::int32_t, int> Ct2::find_edge(std::uint32_t a, std::uint32_t b) const {
  const std::int32_t t0 = vt_[a];
  if (t0 < 0) return {-1, -1};
  auto check = [&](std::int32_t t) -> int {
    const Ct2Tri& T = tris_[t];
    const int j = index_of(T, a);
    if (T.v[(j + 1) % 3] == b) return (j + 2) % 3;
    if (T.v[(j + 2) % 3] == b) return (j + 1) % 3;
    return -1;
  };
  std::int32_t t = t0;
  do {  // counter-clockwise about a: across the edge (a, v[j+2]), opposite v[j+1]
    if (const int i = check(t); i >= 0) return {t, i};
    t = tris_[t].n[(index_of(tris_[t], a) + 1) % 3];
  } while (t >= 0 && t != t0);
  if (t == t0) return {-1, -1};
  t = tris_[t0].n[(index_of(tris_[t0], a) + 2) % 3];
  while (t >= 0) {  // clockwise about a from t0
    if (const int i = check(t); i >= 0) return {t, i};
    t = tris_[t].n[(index_of(tris_[t], a) + 2) % 3];
  }
  return {-1, -1};
}

void Ct2::mark_fixed(std::uint32_t a, std::uint32_t b) {
  const auto [t, i] = find_edge(a, b);
  if (t < 0) throw std::logic_error("plc_ctri: constraint edge missing after recovery");
  tris_[t].fixed[i] = true;
  const std::int32_t u = tris_[t].n[i];
  if (u >= 0) tris_[u].fixed[opposite(tris_[u], a, b)] = true;
}

Ct2Outcome Ct2::crossing_edges(std::uint32_t u, std::uint32_t v,
                               std::vector<std::array<std::uint32_t, 2>>& out) const {
  // The triangle at u whose angle contains the direction to v: walk the star of u.
  std::vector<std::int32_t> star;
  for (std::int32_t t = vt_[u]; t >= 0;) {
    star.push_back(t);
    t = tris_[t].n[(index_of(tris_[t], u) + 1) % 3];
    if (t == vt_[u]) break;
  }
  if (star.empty() || tris_[star.back()].n[(index_of(tris_[star.back()], u) + 1) % 3] < 0)
    for (std::int32_t t = tris_[vt_[u]].n[(index_of(tris_[vt_[u]], u) + 2) % 3]; t >= 0;
         t = tris_[t].n[(index_of(tris_[t], u) + 2) % 3])
      star.push_back(t);
  std::int32_t cur = -1;
  std::uint32_t x = 0, y = 0;
  for (std::int32_t t : star) {
    const Ct2Tri& T = tris_[t];
    const int j = index_of(T, u);
    const std::uint32_t tx = T.v[(j + 1) % 3], ty = T.v[(j + 2) % 3];
    const Sign ox = orient(u, v, tx), oy = orient(u, v, ty);
    if (ox == Sign::Zero && on_ray(pts_[u], pts_[v], pts_[tx]))
      return {Ct2Status::ThroughVertex, u, v, tx, 0};
    if (oy == Sign::Zero && on_ray(pts_[u], pts_[v], pts_[ty]))
      return {Ct2Status::ThroughVertex, u, v, ty, 0};
    if (ox == Sign::Negative && oy == Sign::Positive) {
      cur = t;
      x = tx;
      y = ty;
      if (T.fixed[j]) return {Ct2Status::Crossing, u, v, x, y};
      break;
    }
  }
  if (cur < 0) throw std::logic_error("plc_ctri: no triangle at u faces v");
  out.push_back({x, y});
  for (;;) {
    const Ct2Tri& T = tris_[cur];
    const std::int32_t nb = T.n[opposite(T, x, y)];
    if (nb < 0) throw std::logic_error("plc_ctri: constraint walk left the hull");
    const Ct2Tri& N = tris_[nb];
    const std::uint32_t z = N.v[opposite(N, x, y)];
    if (z == v) break;
    const Sign oz = orient(u, v, z);
    if (oz == Sign::Zero) return {Ct2Status::ThroughVertex, u, v, z, 0};
    if (oz == Sign::Negative) {  // z is on x's side: the walk leaves through zy
      if (N.fixed[index_of(N, x)]) return {Ct2Status::Crossing, u, v, z, y};
      x = z;
    } else {
      if (N.fixed[index_of(N, y)]) return {Ct2Status::Crossing, u, v, x, z};
      y = z;
    }
    out.push_back({x, y});
    cur = nb;
  }
  return {};
}

void Ct2::flip(std::int32_t t, int i) {
  const Ct2Tri T = tris_[t];
  const std::uint32_t a = T.v[i], p1 = T.v[(i + 1) % 3], p2 = T.v[(i + 2) % 3];
  const std::int32_t t2 = T.n[i];
  const Ct2Tri U = tris_[t2];
  const int j = opposite(U, p1, p2);  // U = (b, p2, p1) from j
  const std::uint32_t b = U.v[j];
  const std::int32_t na2 = T.n[(i + 1) % 3], na1 = T.n[(i + 2) % 3];
  const bool fa2 = T.fixed[(i + 1) % 3], fa1 = T.fixed[(i + 2) % 3];
  const std::int32_t nb1 = U.n[(j + 1) % 3], nb2 = U.n[(j + 2) % 3];
  const bool fb1 = U.fixed[(j + 1) % 3], fb2 = U.fixed[(j + 2) % 3];
  tris_[t].v = {a, p1, b};
  tris_[t].n = {nb1, t2, na1};
  tris_[t].fixed = {fb1, false, fa1};
  tris_[t2].v = {b, p2, a};
  tris_[t2].n = {na2, t, nb2};
  tris_[t2].fixed = {fa2, false, fb2};
  if (nb1 >= 0) tris_[nb1].n[opposite(tris_[nb1], p1, b)] = t;
  if (na2 >= 0) tris_[na2].n[opposite(tris_[na2], p2, a)] = t2;
  vt_[a] = vt_[p1] = vt_[b] = t;
  vt_[p2] = t2;
}

void Ct2::make_delaunay() {
  std::vector<std::pair<std::int32_t, int>> stack;  // edges to test, as (triangle, index)
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (tris_[t].n[i] > static_cast<std::int32_t>(t)) stack.emplace_back(static_cast<std::int32_t>(t), i);
  while (!stack.empty()) {
    const auto [t, i] = stack.back();
    stack.pop_back();
    const Ct2Tri& T = tris_[t];
    const std::int32_t u = T.n[i];
    if (u < 0 || T.fixed[i]) continue;
    const Ct2Tri& U = tris_[u];
    const std::uint32_t d = U.v[opposite(U, T.v[(i + 1) % 3], T.v[(i + 2) % 3])];
    if (incircle(pts_[T.v[0]].data(), pts_[T.v[1]].data(), pts_[T.v[2]].data(),
                 pts_[d].data()) != Sign::Positive)
      continue;
    // d strictly inside the circumcircle of a counter-clockwise triangle across an edge:
    // the quadrilateral is strictly convex, so the flip keeps both triangles
    // counter-clockwise. Afterwards t = (a, p1, d) and u = (d, p2, a) (flip()): their
    // four outer edges are tested again.
    flip(t, i);
    stack.emplace_back(t, 0);
    stack.emplace_back(t, 2);
    stack.emplace_back(u, 0);
    stack.emplace_back(u, 2);
  }
}

Ct2Outcome Ct2::insert_constraint(std::uint32_t u, std::uint32_t v) {
  if (find_edge(u, v).first >= 0) {
    mark_fixed(u, v);
    return {};
  }
  std::vector<std::array<std::uint32_t, 2>> crossing;
  if (const Ct2Outcome r = crossing_edges(u, v, crossing); r.status != Ct2Status::Ok) return r;
  std::deque<std::array<std::uint32_t, 2>> queue(crossing.begin(), crossing.end());
  const std::size_t limit = 1000 + 10 * (queue.size() + 1) * (queue.size() + 1);
  for (std::size_t step = 0; !queue.empty(); ++step) {
    if (step > limit) throw std::logic_error("plc_ctri: edge flipping does not terminate");
    const auto [x, y] = queue.front();
    queue.pop_front();
    const auto [t, i] = find_edge(x, y);
    if (t < 0) throw std::logic_error("plc_ctri: crossing edge disappeared");
    const std::uint32_t a = tris_[t].v[i];
    const std::int32_t t2 = tris_[t].n[i];
    const std::uint32_t b = tris_[t2].v[opposite(tris_[t2], x, y)];
    if (orient(a, b, x) * orient(a, b, y) != Sign::Negative) {
      queue.push_back({x, y});  // quadrilateral not strictly convex: try later
      continue;
    }
    flip(t, i);
    if ((a == u && b == v) || (a == v && b == u)) continue;
    if (orient(u, v, a) * orient(u, v, b) == Sign::Negative &&
        orient(a, b, u) * orient(a, b, v) == Sign::Negative)
      queue.push_back({a, b});
  }
  mark_fixed(u, v);
  return {};
}

Ct2Location Ct2::locate(const P2& p) const {
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    const Ct2Tri& T = tris_[t];
    Ct2Location loc{static_cast<std::int32_t>(t), 0, -1};
    bool out = false;
    for (int i = 0; i < 3 && !out; ++i) {
      const Sign o = orient2d(pts_[T.v[(i + 1) % 3]], pts_[T.v[(i + 2) % 3]], p);
      if (o == Sign::Negative) out = true;
      else if (o == Sign::Zero) {
        ++loc.zeros;
        loc.edge = i;
      }
    }
    if (!out) return loc;
  }
  return {};
}

std::vector<Ct2Region> Ct2::regions(const std::vector<std::int32_t>& hole_seeds) const {
  std::vector<Ct2Region> r(tris_.size(), Ct2Region::Inside);
  std::vector<std::int32_t> stack;
  auto flood = [&](Ct2Region mark) {
    while (!stack.empty()) {
      const Ct2Tri& T = tris_[stack.back()];
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const std::int32_t nb = T.n[i];
        if (nb >= 0 && !T.fixed[i] && r[nb] == Ct2Region::Inside) {
          r[nb] = mark;
          stack.push_back(nb);
        }
      }
    }
  };
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (tris_[t].n[i] < 0 && !tris_[t].fixed[i] && r[t] == Ct2Region::Inside) {
        r[t] = Ct2Region::Outside;
        stack.push_back(static_cast<std::int32_t>(t));
      }
  flood(Ct2Region::Outside);
  for (std::int32_t s : hole_seeds) {
    if (s < 0 || r[s] != Ct2Region::Inside) continue;
    r[s] = Ct2Region::Hole;
    stack.push_back(s);
    flood(Ct2Region::Hole);
  }
  return r;
}

}  // namespace pdr::domain
