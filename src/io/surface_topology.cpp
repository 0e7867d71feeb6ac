// Steps 1-4 of surface_to_plc (surface.hpp): duplicate vertices, degenerate faces, closed
// surface (edges of two or more faces), consistent orientation. Every decision is exact:
// coordinates are compared with ==, collinearity and planarity with orient2d/orient3d.
#include "io/surface_topology.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "geom/point_text.hpp"
#include "geom/predicates.hpp"
#include "io/error.hpp"

namespace pdr::io {

std::string face_name(const Surface& s, std::size_t f) {
  return "face " + std::to_string(s.face_number(f));
}

std::string vertex_name(const Surface& s, const SurfaceTopology& t, std::uint32_t v) {
  const std::int64_t id = s.point_ids[t.input_of[v]];
  const std::string at = point_text(t.points[v]);
  return id < 0 ? at : "vertex " + std::to_string(id) + " " + at;
}

void face_fail(const Surface& s, std::size_t f, const std::string& problem) {
  throw InputError(s.source, s.face_lines[f], face_name(s, f) + ": " + problem);
}

namespace {

// Step 1: one point per distinct coordinate triple (-0 == 0), in first-appearance order.
void merge_duplicates(const Surface& s, SurfaceTopology& t, std::vector<std::uint32_t>& id) {
  const std::size_t n = s.points.size();
  std::vector<Point> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!(s.points[i][k] - s.points[i][k] == 0)) {
        const std::string name = s.point_ids[i] < 0 ? "a vertex" :
                                 "vertex " + std::to_string(s.point_ids[i]);
        throw InputError(s.source, s.point_lines[i],
                         "finite coordinates: " + name + " has a coordinate that is not a "
                         "finite number; fix the file");
      }
      p[i][k] = s.points[i][k] + 0.0;  // -0 becomes +0
    }
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::tie(p[a], a) < std::tie(p[b], b);
  });
  std::vector<std::uint32_t> first(n);  // input point -> first input point with its value
  for (std::size_t i = 0; i < n; ++i)
    first[order[i]] = (i > 0 && p[order[i]] == p[order[i - 1]]) ? first[order[i - 1]] : order[i];
  id.assign(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (first[i] == i) {
      id[i] = static_cast<std::uint32_t>(t.points.size());
      t.points.push_back(p[i]);
      t.input_of.push_back(i);
    } else {
      id[i] = id[first[i]];
    }
  }
}

// Step 2 for face f (its corners renumbered): at least 3 corners, distinct, not collinear;
// records a non-collinear triple and whether the face is exactly planar.
void check_face(const Surface& s, SurfaceTopology& t, std::size_t f) {
  const auto c = t.face(s, f);
  if (c.size() < 3)
    face_fail(s, f, "non-degenerate faces: the face has " + std::to_string(c.size()) +
                        " corners; a face needs at least 3, remove it");
  std::vector<std::uint32_t> sorted(c.begin(), c.end());
  std::sort(sorted.begin(), sorted.end());
  const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
  if (dup != sorted.end())
    face_fail(s, f, "non-degenerate faces: the face visits " + vertex_name(s, t, *dup) +
                        " twice (counting vertices with equal coordinates as one); remove "
                        "the repeated corner or the face");
  const Point& a = t.points[c[0]];
  const Point& b = t.points[c[1]];
  std::size_t third = 0;
  for (std::size_t k = 2; k < c.size() && third == 0; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      const auto pa = drop_axis(a, axis), pb = drop_axis(b, axis);
      const auto pk = drop_axis(t.points[c[k]], axis);
      if (orient2d(pa.data(), pb.data(), pk.data()) != Sign::Zero) {
        third = k;
        break;
      }
    }
  if (third == 0)
    face_fail(s, f, "non-degenerate faces: all corners of the face lie on one line; remove "
                    "the face or fix its corners");
  t.plane[f] = {c[0], c[1], c[third]};
  const Point& d = t.points[c[third]];
  t.planar[f] = std::all_of(c.begin(), c.end(), [&](std::uint32_t v) {
    return orient3d(a, b, d, t.points[v]) == Sign::Zero;
  });
}

struct EdgeUse {
  std::uint32_t lo, hi;   // vertices, lo < hi
  std::uint32_t face;
  std::uint32_t corner;   // position of the use in `corners`: from corner to its successor
  bool forward;           // the face runs lo -> hi
  bool operator<(const EdgeUse& o) const {
    return std::tie(lo, hi, face) < std::tie(o.lo, o.hi, o.face);
  }
};

// Step 3: every edge joins two or more faces; returns the uses of the edges of exactly two,
// in pairs (an edge of three or more, a wall or bodies touching along it, pairs no faces).
// Reports the open edge whose first face comes first in the file.
std::vector<EdgeUse> pair_edges(const Surface& s, const SurfaceTopology& t) {
  std::vector<EdgeUse> uses;
  uses.reserve(t.corners.size());
  for (std::size_t f = 0; f < s.face_count(); ++f) {
    const std::size_t b = s.face_start[f], n = s.face_start[f + 1] - b;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t u = t.corners[b + i], v = t.corners[b + (i + 1) % n];
      uses.push_back({std::min(u, v), std::max(u, v), static_cast<std::uint32_t>(f),
                      static_cast<std::uint32_t>(b + i), u < v});
    }
  }
  std::sort(uses.begin(), uses.end());
  std::size_t open = uses.size();
  std::vector<EdgeUse> pairs;
  pairs.reserve(uses.size());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    if (j - i == 1 && (open == uses.size() || uses[i].face < uses[open].face)) open = i;
    if (j - i == 2) pairs.insert(pairs.end(), uses.begin() + static_cast<std::ptrdiff_t>(i),
                                 uses.begin() + static_cast<std::ptrdiff_t>(j));
    i = j;
  }
  if (open != uses.size()) {
    const EdgeUse& e = uses[open];
    face_fail(s, e.face, "closed surface: the edge from " + vertex_name(s, t, e.lo) + " to " +
                             vertex_name(s, t, e.hi) + " belongs to no other face, so the "
                             "surface is open there; close it (every edge must join two or "
                             "more faces)");
  }
  return pairs;
}

// Step 4: reverse faces, one connected piece at a time, until the two faces of every edge
// run along it in opposite directions.
void orient(const Surface& s, SurfaceTopology& t, const std::vector<EdgeUse>& uses) {
  const std::size_t nf = s.face_count();
  std::vector<std::size_t> start(nf + 1, 0);
  for (const EdgeUse& u : uses) ++start[u.face + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  // For each face, its edges as (pair index): the pair is uses[2p], uses[2p+1].
  std::vector<std::uint32_t> pair_of(uses.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < uses.size(); ++i)
    pair_of[fill[uses[i].face]++] = static_cast<std::uint32_t>(i / 2);
  std::vector<std::int8_t> flip(nf, -1);
  std::vector<std::uint32_t> stack;
  for (std::size_t root = 0; root < nf; ++root) {
    if (flip[root] >= 0) continue;
    flip[root] = 0;
    stack.push_back(static_cast<std::uint32_t>(root));
    while (!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      for (std::size_t k = start[f]; k < start[f + 1]; ++k) {
        const EdgeUse& a = uses[2 * pair_of[k]];
        const EdgeUse& b = uses[2 * pair_of[k] + 1];
        const EdgeUse& mine = a.face == f ? a : b;
        const EdgeUse& other = a.face == f ? b : a;
        // After flipping, the two must run in opposite directions.
        const std::int8_t want = static_cast<std::int8_t>(
            (mine.forward != (flip[f] == 1)) == other.forward ? 1 : 0);
        if (flip[other.face] < 0) {
          flip[other.face] = want;
          stack.push_back(other.face);
        } else if (flip[other.face] != want) {
          face_fail(s, f, "orientable surface: the faces around the edge from " +
                              vertex_name(s, t, mine.lo) + " to " + vertex_name(s, t, mine.hi) +
                              " cannot be oriented consistently (the surface is one-sided); "
                              "fix the surface");
        }
      }
    }
  }
  t.neighbour.assign(t.corners.size(), SurfaceTopology::kNoNeighbour);
  for (std::size_t p = 0; p < uses.size(); p += 2) {
    t.neighbour[uses[p].corner] = uses[p + 1].face;
    t.neighbour[uses[p + 1].corner] = uses[p].face;
  }
  // Reverse the flipped faces: corner i becomes corner n-1-i, and the edge from corner i to
  // i+1 becomes the edge from n-2-i to n-1-i.
  for (std::size_t f = 0; f < nf; ++f) {
    if (flip[f] != 1) continue;
    const std::size_t b = s.face_start[f], n = s.face_start[f + 1] - b;
    std::reverse(t.corners.begin() + static_cast<std::ptrdiff_t>(b),
                 t.corners.begin() + static_cast<std::ptrdiff_t>(b + n));
    std::vector<std::uint32_t> nb(n);
    for (std::size_t i = 0; i < n; ++i) nb[(2 * n - 2 - i) % n] = t.neighbour[b + i];
    std::copy(nb.begin(), nb.end(), t.neighbour.begin() + static_cast<std::ptrdiff_t>(b));
  }
}

}  // namespace

SurfaceTopology build_topology(const Surface& s) {
  SurfaceTopology t;
  std::vector<std::uint32_t> id;
  merge_duplicates(s, t, id);
  t.corners.reserve(s.corners.size());
  for (std::uint32_t c : s.corners) t.corners.push_back(id[c]);
  const std::size_t nf = s.face_count();
  t.planar.assign(nf, 0);
  t.plane.assign(nf, {});
  for (std::size_t f = 0; f < nf; ++f) check_face(s, t, f);
  orient(s, t, pair_edges(s, t));
  return t;
}

}  // namespace pdr::io
