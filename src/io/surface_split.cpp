// Step 0b of surface_to_plc (surface.hpp): faces of four or more corners that are not
// planar within the planarity tolerance (a quad mesh from a modelling or scanning tool,
// whose quads are bilinear patches, not planar polygons) are split into triangles, as a
// user of such files expects (Gmsh, Blender and trimesh triangulate them too).
//
// How much a face is off its plane is a tolerance question (it classifies input and steers
// nothing later): the largest distance of a corner to the plane through the corners'
// centroid with the Newell normal, against kSplitShare * tolerance * (the face's
// bounding-box diagonal) or twice the coordinates' uncertainty (io/precision.hpp),
// whichever is more. A face left whole keeps a margin for the domain's least-squares test
// (domain/plane.hpp), which judges each facet with the full tolerance (and four times the
// uncertainty).
//
// The triangles are decided exactly (orient2d on the input doubles), in the projection
// that drops the axis of the face's Newell normal's largest component. A quad is split
// along the shorter of its diagonals that lie inside it in that view, or, folded so far
// that none does, along the shorter whose two triangles are not degenerate. A larger face
// is split by the triangulation of its diagonals whose smallest angle is largest (ear
// clipping, best-shaped ear first, above 96 corners). A
// face with no such triangulation (a quad with three corners on a line both ways, a larger
// face whose projection is not a simple polygon) is an error naming it.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "geom/predicates.hpp"
#include "io/surface.hpp"
#include "io/surface_topology.hpp"

namespace pdr::io {

namespace {

constexpr double kSplitShare = 0.5, kSplitUncertainty = 2;

Point newell_normal(const Surface& s, std::span<const std::uint32_t> c) {
  Point n{0, 0, 0};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point &p = s.points[c[i]], &q = s.points[c[(i + 1) % c.size()]];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

// Whether face c lies within kSplitShare * tolerance * (its bounding-box diagonal) of the
// plane through its centroid with the Newell normal n (a face with a zero normal is left to
// step 2, which names what is wrong with it).
bool planar_enough(const Surface& s, std::span<const std::uint32_t> c, const Point& n,
                   const PlanarityTolerance& tolerance) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0)) return true;
  Point centroid{0, 0, 0}, lo = s.points[c[0]], hi = s.points[c[0]];
  for (const std::uint32_t v : c)
    for (int k = 0; k < 3; ++k) {
      centroid[k] += s.points[v][k] / static_cast<double>(c.size());
      lo[k] = std::min(lo[k], s.points[v][k]);
      hi[k] = std::max(hi[k], s.points[v][k]);
    }
  double dev = 0;
  for (const std::uint32_t v : c) {
    const Point& p = s.points[v];
    dev = std::max(dev, std::fabs(n[0] * (p[0] - centroid[0]) + n[1] * (p[1] - centroid[1]) +
                                  n[2] * (p[2] - centroid[2])) / len);
  }
  const double diag = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  return dev <= std::max(kSplitShare * tolerance.relative * diag,
                         kSplitUncertainty * tolerance.uncertainty());
}

double dist2(const Point& a, const Point& b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

constexpr std::size_t kMaxOptimal = 96;

// The largest cosine of the angles of triangle abc (its smallest angle's).
double largest_cosine(const Surface& s, std::uint32_t a, std::uint32_t b, std::uint32_t d) {
  const Point* p[3] = {&s.points[a], &s.points[b], &s.points[d]};
  double worst = -1;
  for (int i = 0; i < 3; ++i) {
    const Point &o = *p[i], &u = *p[(i + 1) % 3], &v = *p[(i + 2) % 3];
    const double ux = u[0] - o[0], uy = u[1] - o[1], uz = u[2] - o[2];
    const double vx = v[0] - o[0], vy = v[1] - o[1], vz = v[2] - o[2];
    const double lu = std::sqrt(ux * ux + uy * uy + uz * uz), lv = std::sqrt(vx * vx + vy * vy + vz * vz);
    worst = std::max(worst, (ux * vx + uy * vy + uz * vz) / (lu * lv));
  }
  return worst;
}

// Ear clipping of the simple polygon c: each ear strictly convex with no other corner in
// or on it (exact), the one of largest smallest angle first; only the two neighbours of a
// clipped corner change, so each round re-tests two ears.
template <class Orient>
std::optional<std::vector<std::array<std::size_t, 3>>> ear_clipping(
    const Surface& s, std::span<const std::uint32_t> c, const Orient& orient, Sign turn) {
  std::vector<std::array<std::size_t, 3>> out;
  std::vector<std::size_t> left(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) left[i] = i;
  // The ear at position k of `left`, as its largest angle cosine, or nullopt if none.
  const auto ear = [&](std::size_t k) -> std::optional<double> {
    const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                      d = left[(k + 1) % left.size()];
    if (orient(a, b, d) != turn) return std::nullopt;
    const auto not_out = [&](Sign g) { return g == turn || g == Sign::Zero; };
    for (const std::size_t x : left) {
      if (x == a || x == b || x == d) continue;
      if (not_out(orient(a, b, x)) && not_out(orient(b, d, x)) && not_out(orient(d, a, x)))
        return std::nullopt;
    }
    return largest_cosine(s, c[a], c[b], c[d]);
  };
  std::vector<std::optional<double>> ears(left.size());
  for (std::size_t k = 0; k < left.size(); ++k) ears[k] = ear(k);
  while (left.size() > 3) {
    std::optional<std::size_t> best;
    for (std::size_t k = 0; k < left.size(); ++k)
      if (ears[k] && (!best || *ears[k] < *ears[*best])) best = k;
    if (!best) return std::nullopt;
    const std::size_t k = *best;
    out.push_back({left[(k + left.size() - 1) % left.size()], left[k], left[(k + 1) % left.size()]});
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
    ears.erase(ears.begin() + static_cast<std::ptrdiff_t>(k));
    const std::size_t before = (k + left.size() - 1) % left.size(), after = k % left.size();
    ears[before] = ear(before);
    ears[after] = ear(after);
  }
  if (orient(left[0], left[1], left[2]) != turn) return std::nullopt;
  out.push_back({left[0], left[1], left[2]});
  return out;
}

// The triangles of face c (corner indices into c), or nullopt when its projection along
// `axis`, turning with sign `turn`, has no triangulation of the kind above.
std::optional<std::vector<std::array<std::size_t, 3>>> triangles(
    const Surface& s, std::span<const std::uint32_t> c, int axis, Sign turn) {
  const auto orient = [&](std::size_t i, std::size_t j, std::size_t k) {
    const auto a = drop_axis(s.points[c[i]], axis), b = drop_axis(s.points[c[j]], axis),
               d = drop_axis(s.points[c[k]], axis);
    return orient2d(a.data(), b.data(), d.data());
  };
  std::vector<std::array<std::size_t, 3>> out;
  if (c.size() == 4) {
    // A diagonal inside the quad as seen along its normal (both triangles turn as the face
    // does; a quad concave in that view has exactly one); the shorter when both are. A
    // quad folded so far that neither is (a bow tie in that view): any diagonal whose
    // triangles are not degenerate (three corners on a line: orient2d zero in every axis
    // projection), since a quad that is not planar has its two triangles meet only along
    // the diagonal.
    const auto collinear = [&](std::size_t i, std::size_t j, std::size_t k) {
      for (int a = 0; a < 3; ++a) {
        const auto p = drop_axis(s.points[c[i]], a), q = drop_axis(s.points[c[j]], a),
                   r = drop_axis(s.points[c[k]], a);
        if (orient2d(p.data(), q.data(), r.data()) != Sign::Zero) return false;
      }
      return true;
    };
    bool d02 = orient(0, 1, 2) == turn && orient(0, 2, 3) == turn;
    bool d13 = orient(1, 2, 3) == turn && orient(1, 3, 0) == turn;
    if (!d02 && !d13) {
      d02 = !collinear(0, 1, 2) && !collinear(0, 2, 3);
      d13 = !collinear(1, 2, 3) && !collinear(1, 3, 0);
    }
    if (!d02 && !d13) return std::nullopt;
    const bool use02 = d02 && (!d13 || dist2(s.points[c[0]], s.points[c[2]]) <=
                                           dist2(s.points[c[1]], s.points[c[3]]));
    if (use02)
      out = {{0, 1, 2}, {0, 2, 3}};
    else
      out = {{1, 2, 3}, {1, 3, 0}};
    return out;
  }
  // Ear clipping needs a simple polygon: no two edges that are not neighbours meet
  // (segments meet iff neither has the other's ends strictly on one side).
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the wrap
      const std::size_t i1 = (i + 1) % n, j1 = (j + 1) % n;
      const Sign a = orient(i, i1, j), b = orient(i, i1, j1);
      const Sign d = orient(j, j1, i), e = orient(j, j1, i1);
      const bool apart = (a == b && a != Sign::Zero) || (d == e && d != Sign::Zero);
      if (!apart) {
        const bool collinear = a == Sign::Zero && b == Sign::Zero;
        if (!collinear) return std::nullopt;
        // On one line: they meet unless one lies wholly before the other along it.
        const auto pi = drop_axis(s.points[c[i]], axis), pi1 = drop_axis(s.points[c[i1]], axis);
        const auto pj = drop_axis(s.points[c[j]], axis), pj1 = drop_axis(s.points[c[j1]], axis);
        const int ax = pi[0] != pi1[0] ? 0 : 1;
        const double lo1 = std::min(pi[ax], pi1[ax]), hi1 = std::max(pi[ax], pi1[ax]);
        const double lo2 = std::min(pj[ax], pj1[ax]), hi2 = std::max(pj[ax], pj1[ax]);
        if (!(hi1 < lo2 || hi2 < lo1)) return std::nullopt;
      }
    }
  // The polygon is simple. Its triangulations are those of its diagonals: segments between
  // two corners that meet no edge and no other corner, inside the polygon at their ends
  // (exact). Among them the one whose smallest angle is largest (Klincsek's dynamic
  // programme over sub-polygons, O(n^3); the angles in floating point only choose among
  // valid triangulations): a first-found ear can be a sliver across corners nearly on one
  // line (an L face whose inner corner lies on the diagonal of its outer ones became a
  // triangle 1e-7 high there, and the segments 1e-7 apart drove the refinement to that
  // size), which this avoids whenever another triangulation does. Above kMaxOptimal
  // corners, ear clipping (best-shaped ear first) keeps the time quadratic.
  if (n > kMaxOptimal) return ear_clipping(s, c, orient, turn);
  const auto at = [&](std::size_t i) { return drop_axis(s.points[c[i % n]], axis); };
  std::vector<std::uint8_t> diagonal(n * n, 0);
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t v = u + 2; v < n; ++v) {
      if (u == 0 && v == n - 1) continue;  // an edge
      bool ok = true;
      for (std::size_t x = 0; x < n && ok; ++x) {
        const std::size_t y = (x + 1) % n;
        if (x != u && x != v && orient(u, v, x) == Sign::Zero) {
          // A corner on the line of uv: on the segment itself it blocks the diagonal.
          const auto pu = at(u), pv = at(v), px = at(x);
          const int ax = pu[0] != pv[0] ? 0 : 1;
          if (std::min(pu[ax], pv[ax]) <= px[ax] && px[ax] <= std::max(pu[ax], pv[ax])) ok = false;
        }
        if (x == u || x == v || y == u || y == v) continue;
        // Proper crossing of uv with edge xy (touching is a corner on a segment, above).
        const Sign a1 = orient(u, v, x), a2 = orient(u, v, y), b1 = orient(x, y, u), b2 = orient(x, y, v);
        if (a1 != Sign::Zero && a2 != Sign::Zero && a1 != a2 && b1 != Sign::Zero &&
            b2 != Sign::Zero && b1 != b2)
          ok = false;
      }
      if (!ok) continue;
      // Inside at u: within the interior angle between its edges.
      const std::size_t pu = (u + n - 1) % n, qu = (u + 1) % n;
      const bool left_of_next = orient(u, qu, v) == turn, left_of_prev = orient(pu, u, v) == turn;
      const bool inside = orient(pu, u, qu) == turn ? left_of_next && left_of_prev
                                                     : left_of_next || left_of_prev;
      if (inside) diagonal[u * n + v] = diagonal[v * n + u] = 1;
    }
  const auto joined = [&](std::size_t i, std::size_t j) {
    return j == i + 1 || (i == 0 && j == n - 1) || diagonal[i * n + j];
  };
  // best[i][j]: the largest smallest-angle score (minus the largest cosine) of a
  // triangulation of corners i..j, i-j an edge or diagonal; choice[i][j] its apex.
  constexpr double kNone = -3;
  std::vector<double> best(n * n, kNone);
  std::vector<std::size_t> choice(n * n, 0);
  for (std::size_t i = 0; i + 1 < n; ++i) best[i * n + i + 1] = 2;  // no triangle: no bound
  for (std::size_t len = 2; len < n; ++len)
    for (std::size_t i = 0; i + len < n; ++i) {
      const std::size_t j = i + len;
      if (!joined(i, j)) continue;
      for (std::size_t k = i + 1; k < j; ++k) {
        if (!joined(i, k) || !joined(k, j) || best[i * n + k] == kNone || best[k * n + j] == kNone)
          continue;
        if (orient(i, k, j) != turn) continue;
        const double score = std::min({-largest_cosine(s, c[i], c[k], c[j]), best[i * n + k], best[k * n + j]});
        if (score > best[i * n + j]) {
          best[i * n + j] = score;
          choice[i * n + j] = k;
        }
      }
    }
  if (best[n - 1] == kNone) return std::nullopt;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j < i + 2) continue;
    const std::size_t k = choice[i * n + j];
    out.push_back({i, k, j});
    todo.push_back({i, k});
    todo.push_back({k, j});
  }
  return out;
}

}  // namespace

std::optional<Surface> split_nonplanar_faces(const Surface& s, const PlanarityTolerance& tolerance) {
  for (const Point& p : s.points)  // step 1 names a coordinate that is not finite
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return std::nullopt;
  const std::size_t nf = s.face_count();
  std::vector<Point> normal(nf);
  bool any = false;
  for (std::size_t f = 0; f < nf; ++f) {
    if (s.face(f).size() < 4) continue;
    normal[f] = newell_normal(s, s.face(f));
    if (!planar_enough(s, s.face(f), normal[f], tolerance)) any = true;
  }
  if (!any) return std::nullopt;
  Surface out = s.points_only();
  for (std::size_t f = 0; f < nf; ++f) {
    const std::span<const std::uint32_t> c = s.face(f);
    const std::size_t number = s.face_number(f);
    if (c.size() < 4 || planar_enough(s, c, normal[f], tolerance)) {
      out.add_face(c, s.face_lines[f], s.face_markers[f]);
      out.face_numbers.push_back(number);
      continue;
    }
    const Point& n = normal[f];
    const int axis = std::fabs(n[0]) >= std::fabs(n[1]) && std::fabs(n[0]) >= std::fabs(n[2]) ? 0
                     : std::fabs(n[1]) >= std::fabs(n[2])                                   ? 1
                                                                                             : 2;
    const Sign turn = n[axis] > 0 ? Sign::Positive : Sign::Negative;
    const auto tris = triangles(s, c, axis, turn);
    if (!tris)
      face_fail(s, f,
                "planar faces: the face is not planar within the planarity tolerance and cannot "
                "be split into triangles (its projection on its plane is not a simple polygon, "
                "or corners lie on one line); split it into planar faces");
    for (const auto& t : *tris) {
      const std::uint32_t tri[3] = {c[t[0]], c[t[1]], c[t[2]]};
      out.add_face(tri, s.face_lines[f], s.face_markers[f]);
      out.face_numbers.push_back(number);
    }
  }
  return out;
}

}  // namespace pdr::io
