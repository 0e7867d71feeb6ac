// Steps 5-6 of surface_to_plc (surface.hpp): exactly coplanar faces merged into facets,
// each facet's boundary loops, a hole point for each inner loop, and the vertices the
// facets leave out. The decisions are exact predicates; the one construction, a hole
// point, is an ear's centroid checked with exact orient2d before it is used.
#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "geom/predicates.hpp"
#include "io/error.hpp"
#include "io/surface.hpp"
#include "io/surface_topology.hpp"
#include "mesh/union_find.hpp"

namespace pdr::io {

namespace {

// orient2d of three points projected along `axis`.
Sign orient_along(const Point& a, const Point& b, const Point& c, int axis) {
  const auto pa = drop_axis(a, axis), pb = drop_axis(b, axis), pc = drop_axis(c, axis);
  return orient2d(pa.data(), pb.data(), pc.data());
}

// The axis of the largest normal component of the face's plane triple (a choice in double;
// orient2d along it then decides exactly). For exactly coplanar faces any axis along which
// the plane does not project to a line would do; for faces coplanar only within tolerance
// (step 5b) an axis nearly in their plane could flip one face's turn against the other's.
int projection_axis(const SurfaceTopology& t, std::size_t f) {
  const auto& [a, b, c] = t.plane[f];
  const Point &o = t.points[a], &p = t.points[b], &q = t.points[c];
  const double ux = p[0] - o[0], uy = p[1] - o[1], uz = p[2] - o[2];
  const double vx = q[0] - o[0], vy = q[1] - o[1], vz = q[2] - o[2];
  const double n[3] = {std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz),
                       std::fabs(ux * vy - uy * vx)};
  const int axis = n[0] >= n[1] && n[0] >= n[2] ? 0 : n[1] >= n[2] ? 1 : 2;
  if (orient_along(o, p, q, axis) != Sign::Zero) return axis;
  // The double normal underflowed or overflowed (coordinates near the ends of the double
  // range): any axis along which the exact projection turns will do.
  for (int k = 0; k < 3; ++k)
    if (orient_along(o, p, q, k) != Sign::Zero) return k;
  throw std::logic_error("surface_facets: a face's plane triple is collinear");
}

// The turn at the lexicographically smallest corner of a closed polygon projected along
// `axis`: its orientation when the polygon is simple (Zero: it is not).
Sign polygon_sign(const SurfaceTopology& t, std::span<const std::uint32_t> loop, int axis) {
  const std::size_t n = loop.size();
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (drop_axis(t.points[loop[i]], axis) < drop_axis(t.points[loop[m]], axis)) m = i;
  return orient_along(t.points[loop[(m + n - 1) % n]], t.points[loop[m]],
                      t.points[loop[(m + 1) % n]], axis);
}

// Step 5's merge test for face f and its neighbour g across the edge from corner i of f.
bool same_facet(const Surface& s, const SurfaceTopology& t, std::size_t f, std::size_t g,
                std::size_t i) {
  if (s.face_markers[f] != s.face_markers[g] || !t.planar[f] || !t.planar[g]) return false;
  const auto& [a, b, c] = t.plane[f];
  for (std::uint32_t v : t.face(s, g))
    if (orient3d(t.points[a], t.points[b], t.points[c], t.points[v]) != Sign::Zero) return false;
  const int axis = projection_axis(t, f);
  const Sign sf = polygon_sign(t, t.face(s, f), axis);
  const Sign sg = polygon_sign(t, t.face(s, g), axis);
  if (sf == Sign::Zero || sg == Sign::Zero)
    face_fail(s, sf == Sign::Zero ? f : g, "simple faces: the face's boundary turns back on "
                                           "itself; fix the face");
  if (sf != sg) {
    const auto fc = t.face(s, f);
    face_fail(s, f, "no folded faces: this face and " + face_name(s, g) +
                        " are coplanar and lie on the same side of their common edge from " +
                        vertex_name(s, t, fc[i]) + " to " +
                        vertex_name(s, t, fc[(i + 1) % fc.size()]) +
                        ", so they overlap; remove the doubled faces");
  }
  return true;
}

// Step 5b: regions of step 5 that are coplanar only within the planarity tolerance (the two
// triangles of a planar quad in a rotated file: their fourth corners are a few ulps off each
// other's planes; a side written with 7 digits as many small triangles). Greedy, in face
// order: a region grows across edges into neighbouring regions with the same marker, not
// folded onto it, while every distinct vertex of the union lies within
// kMergeShare * tolerance * (the union's bounding-box diagonal), or twice the coordinates'
// uncertainty (io/precision.hpp), of the union's least-squares plane. The shares leave the
// domain's least-squares test (domain/plane.hpp), which judges the merged facet with the
// full tolerance (and four times the uncertainty), a margin. (The plane of the seed face
// would not do for the uncertainty: rounding tilts a small face's plane by about u over
// its size, which over a large side exceeds any multiple of u.)
constexpr double kMergeShare = 0.125, kMergeUncertainty = 2;

class NearPlane {
 public:
  // `stamp`: one entry per point, shared by the planes of one merge (entries equal to
  // `id` mark this plane's vertices); id > 0, distinct per plane.
  NearPlane(const SurfaceTopology& t, std::vector<std::uint32_t>& stamp, std::uint32_t id)
      : t_(t), stamp_(stamp), id_(id) {}

  // Adds the vertices when the union stays within the tolerance; false (nothing added)
  // otherwise.
  bool add(std::span<const std::uint32_t> verts, const PlanarityTolerance& tolerance) {
    const std::size_t old = members_.size();
    Sums sums = sums_;
    Point lo = lo_, hi = hi_;
    for (const std::uint32_t v : verts) {
      if (stamp_[v] == id_) continue;
      stamp_[v] = id_;
      members_.push_back(v);
      const Point& p = t_.points[v];
      if (members_.size() == 1) origin_ = lo = hi = p;
      sums.add(sub(p, origin_));
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    const auto undo = [&] {
      for (std::size_t i = old; i < members_.size(); ++i) stamp_[members_[i]] = 0;
      members_.resize(old);
      return false;
    };
    const double diam = norm(sub(hi, lo));
    const double allowed = std::max(kMergeShare * tolerance.relative * diam,
                                    kMergeUncertainty * tolerance.uncertainty());
    const auto [centroid, normal] = sums.plane();
    if (!(norm(normal) > 0)) {  // (near) collinear: only the seed itself may be
      if (old > 0) return undo();
      sums_ = sums, lo_ = lo, hi_ = hi, centroid_ = centroid, normal_ = normal, max_dev_ = 0;
      return true;
    }
    // A bound on the old vertices' deviation from the new plane, from their deviation from
    // the old one; scanned exactly when the bound does not settle it.
    double dev = 0;
    if (old > 0 && norm(normal_) > 0) {
      const Point dn = sub(normal, normal_), flip = {normal[0] + normal_[0], normal[1] + normal_[1],
                                                     normal[2] + normal_[2]};
      const double turn = std::min(norm(dn), norm(flip));
      dev = max_dev_ + turn * diam + std::fabs(dot(sub(centroid, centroid_), normal));
    } else {
      dev = std::numeric_limits<double>::infinity();
    }
    for (std::size_t i = old; i < members_.size(); ++i)
      dev = std::max(dev, std::fabs(dot(sub(origin_add(members_[i]), centroid), normal)));
    if (!(dev <= allowed)) {
      dev = 0;
      for (const std::uint32_t v : members_)
        dev = std::max(dev, std::fabs(dot(sub(origin_add(v), centroid), normal)));
      if (!(dev <= allowed)) return undo();
    }
    sums_ = sums, lo_ = lo, hi_ = hi, centroid_ = centroid, normal_ = normal, max_dev_ = dev;
    return true;
  }

 private:
  static Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
  static double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static double norm(const Point& a) { return std::sqrt(dot(a, a)); }
  static Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  // Point v relative to the origin (where the sums are taken).
  Point origin_add(std::uint32_t v) const { return sub(t_.points[v], origin_); }

  // Sums over the distinct vertices (relative to the origin) for their least-squares plane.
  struct Sums {
    double n = 0;
    Point s{};
    std::array<std::array<double, 3>, 3> ss{};
    void add(const Point& p) {
      n += 1;
      for (int i = 0; i < 3; ++i) {
        s[i] += p[i];
        for (int j = 0; j < 3; ++j) ss[i][j] += p[i] * p[j];
      }
    }
    // The centroid and the unit normal of the least-squares plane (the largest cross
    // product of two rows of the centred scatter matrix: its null direction when the
    // points are near a plane); a zero normal when they are (near) collinear.
    std::pair<Point, Point> plane() const {
      const Point c{s[0] / n, s[1] / n, s[2] / n};
      std::array<Point, 3> m{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = ss[i][j] - n * c[i] * c[j];
      Point best{};
      double len = 0;
      for (const auto& [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
        const Point x = cross(m[i], m[j]);
        if (const double l = norm(x); l > len) len = l, best = x;
      }
      if (len > 0)
        for (double& x : best) x /= len;
      return {c, best};
    }
  };

  const SurfaceTopology& t_;
  std::vector<std::uint32_t>& stamp_;
  std::uint32_t id_;
  std::vector<std::uint32_t> members_;  // distinct vertices
  Point origin_{}, lo_{}, hi_{}, centroid_{}, normal_{};
  Sums sums_;
  double max_dev_ = 0;
};

// Face f and its neighbour g lie on opposite sides of their common edge (not folded onto
// each other).
bool unfolded(const Surface& s, const SurfaceTopology& t, std::size_t f, std::size_t g) {
  const int axis = projection_axis(t, f);
  const Sign sf = polygon_sign(t, t.face(s, f), axis);
  return sf != Sign::Zero && sf == polygon_sign(t, t.face(s, g), axis);
}

void merge_within_tolerance(const Surface& s, const SurfaceTopology& t,
                            const PlanarityTolerance& tolerance, UnionFind& uf) {
  const std::size_t nf = s.face_count();
  std::vector<std::vector<std::uint32_t>> members(nf);
  for (std::uint32_t f = 0; f < nf; ++f) members[uf.find(f)].push_back(f);
  std::vector<std::uint8_t> taken(nf, 0);
  std::vector<std::uint32_t> verts, stamp(t.points.size(), 0);
  auto region_vertices = [&](std::uint32_t root) {
    verts.clear();
    for (std::uint32_t f : members[root]) {
      const auto c = t.face(s, f);
      verts.insert(verts.end(), c.begin(), c.end());
    }
    return std::span<const std::uint32_t>(verts);
  };
  for (std::uint32_t seed = 0; seed < nf; ++seed) {
    if (uf.find(seed) != seed || taken[seed]) continue;
    taken[seed] = 1;
    NearPlane plane(t, stamp, seed + 1);
    // A seed not within the tolerance of its own least-squares plane (a sliver whose
    // plane rounding cannot place, or no tolerance at all) stays as it is.
    if (!plane.add(region_vertices(seed), tolerance)) continue;
    std::vector<std::uint32_t> queue{seed};  // region roots of the group
    for (std::size_t q = 0; q < queue.size(); ++q)
      for (std::uint32_t f : members[queue[q]]) {
        const std::size_t b = s.face_start[f], n = s.face_start[f + 1] - b;
        for (std::size_t i = 0; i < n; ++i) {
          const std::uint32_t g = t.neighbour[b + i];
          if (g == SurfaceTopology::kNoNeighbour) continue;
          const std::uint32_t root = uf.find(g);
          if (root == uf.find(seed) || taken[root] || s.face_markers[f] != s.face_markers[g] ||
              !unfolded(s, t, f, g) || !plane.add(region_vertices(root), tolerance))
            continue;
          taken[root] = 1;
          queue.push_back(root);
          uf.join(seed, root);
        }
      }
  }
}

struct Region {
  std::vector<std::uint32_t> faces;
};

// The boundary of a region (faces with a common orientation) as simple closed loops: the
// directed boundary edges, walked and split at every vertex a walk visits twice.
std::vector<std::vector<std::uint32_t>> boundary_loops(const Surface& s,
                                                       const SurfaceTopology& t,
                                                       const Region& r, UnionFind& uf,
                                                       std::vector<std::int32_t>& pos) {
  const std::uint32_t root = uf.find(r.faces[0]);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // (from, to)
  for (std::uint32_t f : r.faces) {
    const auto c = t.face(s, f);
    for (std::size_t i = 0; i < c.size(); ++i)
      if (const std::uint32_t g = t.neighbour[s.face_start[f] + i];
          g == SurfaceTopology::kNoNeighbour || uf.find(g) != root)
        edges.push_back({c[i], c[(i + 1) % c.size()]});
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint8_t> used(edges.size(), 0);
  auto next_edge = [&](std::uint32_t from) -> std::size_t {
    auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{from, 0u});
    for (std::size_t k = static_cast<std::size_t>(it - edges.begin());
         k < edges.size() && edges[k].first == from; ++k)
      if (!used[k]) return k;
    return edges.size();
  };
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<std::uint32_t> path;
  for (std::size_t e0 = 0; e0 < edges.size(); ++e0) {
    if (used[e0]) continue;
    path.assign(1, edges[e0].first);
    pos[edges[e0].first] = 0;
    while (!path.empty()) {
      const std::size_t k = next_edge(path.back());
      if (k == edges.size()) {
        // Boundary edges balance at every vertex, so a walk can only stop where it began.
        if (path.size() != 1) throw std::logic_error("surface_facets: unbalanced boundary");
        pos[path.back()] = -1;
        break;
      }
      used[k] = 1;
      const std::uint32_t v = edges[k].second;
      if (pos[v] < 0) {
        pos[v] = static_cast<std::int32_t>(path.size());
        path.push_back(v);
        continue;
      }
      const auto from = path.begin() + pos[v];
      loops.emplace_back(from, path.end());
      for (auto it = from + 1; it != path.end(); ++it) pos[*it] = -1;
      path.erase(from + 1, path.end());
    }
  }
  return loops;
}

// A point strictly inside the inner loop `loop` (orientation `sign` along `axis`): the
// centroid of an ear, accepted when it lies strictly inside the ear in every axis
// projection in which the ear is not degenerate (the domain projects facets along one of
// them). Returns false when no ear gives such a point.
bool hole_point(const SurfaceTopology& t, const std::vector<std::uint32_t>& loop, int axis,
                Sign sign, Point& out) {
  const std::size_t n = loop.size();
  auto P = [&](std::size_t i) -> const Point& { return t.points[loop[i % n]]; };
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = P(i + n - 1), &b = P(i), &c = P(i + 1);
    if (orient_along(a, b, c, axis) != sign) continue;
    bool ear = true;
    for (std::size_t j = 0; j < n && ear; ++j) {
      if (j == i || j == (i + 1) % n || j == (i + n - 1) % n) continue;
      const Point& w = P(j);
      ear = orient_along(a, b, w, axis) == -sign || orient_along(b, c, w, axis) == -sign ||
            orient_along(c, a, w, axis) == -sign;
    }
    if (!ear) continue;
    Point h;
    for (int k = 0; k < 3; ++k) h[k] = (a[k] + b[k] + c[k]) / 3;
    bool inside = true;
    for (int ax = 0; ax < 3 && inside; ++ax) {
      const Sign o = orient_along(a, b, c, ax);
      if (o == Sign::Zero) continue;
      inside = orient_along(a, b, h, ax) == o && orient_along(b, c, h, ax) == o &&
               orient_along(c, a, h, ax) == o;
    }
    if (inside) {
      out = h;
      return true;
    }
  }
  return false;
}

// Step 5 for one region: its facet, with the region's vertices that no loop visits in
// `inner`.
PlcFacet region_facet(const Surface& s, const SurfaceTopology& t, const Region& r,
                      UnionFind& uf, std::vector<std::int32_t>& pos,
                      std::vector<std::uint32_t>& inner) {
  const std::uint32_t f0 = r.faces[0];
  PlcFacet facet;
  facet.line = s.face_lines[f0];
  facet.marker = s.face_markers[f0];
  if (r.faces.size() == 1) {
    const auto c = t.face(s, f0);
    facet.polygons.emplace_back(c.begin(), c.end());
    return facet;
  }
  const int axis = projection_axis(t, f0);
  const Sign region_sign = polygon_sign(t, t.face(s, f0), axis);
  facet.polygons = boundary_loops(s, t, r, uf, pos);
  for (const auto& loop : facet.polygons) {
    const Sign ls = polygon_sign(t, loop, axis);
    if (ls == Sign::Zero)
      face_fail(s, f0, "simple facets: the boundary of the plane facet made of this face and "
                       "the faces coplanar with it crosses itself; the surface intersects "
                       "itself there, fix it");
    if (ls == region_sign) continue;
    Point h;
    if (!hole_point(t, loop, axis, -region_sign, h))
      face_fail(s, f0, "facet holes: no point strictly inside a hole of the plane facet made "
                       "of this face and the faces coplanar with it was found (the hole is "
                       "too thin for double precision); enlarge the hole");
    facet.holes.push_back(h);
  }
  for (const auto& loop : facet.polygons)
    for (std::uint32_t v : loop) pos[v] = 0;
  for (std::uint32_t f : r.faces)
    for (std::uint32_t v : t.face(s, f))
      if (pos[v] < 0) {
        inner.push_back(v);
        pos[v] = 0;
      }
  for (const auto& loop : facet.polygons)
    for (std::uint32_t v : loop) pos[v] = -1;
  for (std::uint32_t v : inner) pos[v] = -1;
  return facet;
}

}  // namespace

namespace {

// Step 0: a face whose corners are, as a set, those of an earlier face (a face two bodies
// of an assembly share, each giving it) is read once. Null when no face repeats.
std::optional<Surface> without_repeated_faces(const Surface& s) {
  for (const Point& p : s.points)  // step 1 names a coordinate that is not finite
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return std::nullopt;
  const std::size_t nf = s.face_count();
  std::vector<std::vector<Point>> key(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    for (const std::uint32_t c : s.face(f)) key[f].push_back(s.points[c]);
    std::sort(key[f].begin(), key[f].end());
  }
  std::vector<std::uint32_t> order(nf);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  std::vector<std::uint8_t> repeat(nf, 0);
  bool any = false;
  for (std::size_t i = 1; i < nf; ++i)
    if (key[order[i]] == key[order[i - 1]]) {
      repeat[order[i]] = 1;
      any = true;
    }
  if (!any) return std::nullopt;
  Surface out = s.points_only();
  for (std::size_t f = 0; f < nf; ++f)
    if (!repeat[f]) {
      out.add_face(s.face(f), s.face_lines[f], s.face_markers[f]);
      out.face_numbers.push_back(s.face_number(f));
    }
  return out;
}

// Step 5c: a facet whose boundary loops are an earlier facet's (a face two bodies share,
// each triangulating it its own way) is read once; its 1-vertex polygons join the kept one.
void drop_repeated_facets(Plc& plc) {
  const auto key = [](const PlcFacet& f) {
    std::vector<std::vector<std::uint32_t>> loops;
    for (std::vector<std::uint32_t> p : f.polygons) {
      if (p.size() < 2) continue;
      std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
      std::vector<std::uint32_t> back(p.rbegin(), p.rend());
      std::rotate(back.begin(), std::min_element(back.begin(), back.end()), back.end());
      loops.push_back(std::min(p, back));
    }
    std::sort(loops.begin(), loops.end());
    return loops;
  };
  std::map<std::vector<std::vector<std::uint32_t>>, std::size_t> first;
  std::vector<PlcFacet> kept;
  for (PlcFacet& f : plc.facets) {
    const auto [it, added] = first.emplace(key(f), kept.size());
    if (added) {
      kept.push_back(std::move(f));
      continue;
    }
    PlcFacet& k = kept[it->second];
    for (const auto& p : f.polygons)
      if (p.size() == 1 && std::find(k.polygons.begin(), k.polygons.end(), p) == k.polygons.end())
        k.polygons.push_back(p);
  }
  plc.facets = std::move(kept);
}

// The points some face uses: the domain keeps those alone, and infers their precision
// (io/precision.hpp) from them, so the reader does too.
std::vector<Point> used_points(const Surface& s) {
  std::vector<std::uint8_t> used(s.points.size(), 0);
  for (const std::uint32_t v : s.corners)
    if (v < used.size()) used[v] = 1;
  std::vector<Point> out;
  for (std::size_t v = 0; v < s.points.size(); ++v)
    if (used[v]) out.push_back(s.points[v]);
  return out;
}

// surface_to_plc under the tolerance inferred once for the file (removing repeated faces
// and splitting non-planar ones keeps the points the faces use).
Plc to_plc(const Surface& s, const PlanarityTolerance& tolerance) {
  if (const auto once = without_repeated_faces(s)) return to_plc(*once, tolerance);
  if (const auto split = split_nonplanar_faces(s, tolerance)) return to_plc(*split, tolerance);
  const SurfaceTopology t = build_topology(s);
  const std::size_t nf = s.face_count();
  UnionFind uf(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t b = s.face_start[f], n = s.face_start[f + 1] - b;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t g = t.neighbour[b + i];
      if (g != SurfaceTopology::kNoNeighbour && g > f && uf.find(g) != uf.find(static_cast<std::uint32_t>(f)) &&
          same_facet(s, t, f, g, i))
        uf.join(static_cast<std::uint32_t>(f), g);
    }
  }
  merge_within_tolerance(s, t, tolerance, uf);
  std::vector<Region> regions;
  std::vector<std::uint32_t> region_of(nf);
  for (std::uint32_t f = 0; f < nf; ++f) {
    const std::uint32_t root = uf.find(f);
    if (root == f) {
      region_of[f] = static_cast<std::uint32_t>(regions.size());
      regions.emplace_back();
    }
    region_of[f] = region_of[root];
    regions[region_of[f]].faces.push_back(f);
  }

  Plc plc;
  plc.source = s.source;
  std::vector<std::int32_t> pos(t.points.size(), -1);
  std::vector<std::vector<std::uint32_t>> inner(regions.size());
  std::vector<std::uint32_t> uses(t.points.size(), 0);  // facets whose polygons hold it
  for (std::size_t r = 0; r < regions.size(); ++r) {
    plc.facets.push_back(region_facet(s, t, regions[r], uf, pos, inner[r]));
    for (const auto& poly : plc.facets.back().polygons)
      for (std::uint32_t v : poly) uses[v] = 1;
  }
  // Step 6: inner vertices another facet uses stay, as 1-vertex polygons; the rest go.
  for (std::size_t r = 0; r < regions.size(); ++r)
    for (std::uint32_t v : inner[r])
      if (uses[v]) plc.facets[r].polygons.push_back({v});
  drop_repeated_facets(plc);
  std::vector<std::uint32_t> renumber(t.points.size(), 0);
  for (std::uint32_t v = 0; v < t.points.size(); ++v) {
    if (!uses[v]) continue;
    renumber[v] = static_cast<std::uint32_t>(plc.points.size());
    plc.points.push_back(t.points[v]);
    plc.point_lines.push_back(s.point_lines[t.input_of[v]]);
  }
  for (PlcFacet& facet : plc.facets)
    for (auto& poly : facet.polygons)
      for (std::uint32_t& v : poly) v = renumber[v];
  plc.precision = tolerance.precision;
  return plc;
}

}  // namespace

Plc surface_to_plc(const Surface& s, double planarity_tolerance) {
  if (s.face_count() == 0)
    throw InputError(s.source, 0, "closed surface: the file holds no faces; a domain needs a "
                                  "closed surface of triangles or polygons");
  return to_plc(s, planarity_tolerance_of(used_points(s), planarity_tolerance));
}

}  // namespace pdr::io
