// validity.overlap: the tets have pairwise disjoint interiors, and two tets touching along a
// plane do so through a common face (no coplanar faces partially overlapping). Together
// with validity.orientation and validity.face_sharing this makes the tets a simplicial
// tetrahedralization of their union (the paper's T(Omega), §1.1), up to lower-dimensional
// non-conforming contacts (an edge crossing an edge, a vertex on an edge), which are not
// tested.
//
// Why not a volume identity: for positive tets whose shared faces have their fourth
// vertices on opposite sides, sum of tet volumes == volume enclosed by the boundary faces
// (divergence theorem) holds *identically*, interior faces cancelling, even when tets
// overlap (an extra tet inside the mesh adds its volume to both sides). It cannot detect
// multiple covering; a pairwise test can.
//
// Exact test. Two tets (convex, full-dimensional) have disjoint interiors iff some plane
// weakly separates them, and one can be found among (Minkowski-difference facets): the
// face planes of either tet, and the planes through an edge e of one tet spanned by e and
// an edge e' of the other (e x e' != 0). Each candidate is decided with exact signs
// (signs.hpp); "weakly" means both closed half-spaces, so touching tets are separated.
// Candidate pairs: a uniform grid over the tets' bounding boxes (grid.hpp); a pair is
// examined in the one cell holding the low corner of the boxes' intersection. Pairs sharing
// a face are left to validity.face_sharing; degenerate tets to validity.orientation.
#include <algorithm>
#include <array>

#include "check/checks.hpp"
#include "check/parallel.hpp"
#include "check/signs.hpp"

namespace pdr::check {
namespace {

enum class Contact { Separated, Overlap, CoplanarOverlap };

struct Tet4 {
  std::array<std::uint32_t, 4> id;  // positively ordered
  std::array<const Point*, 4> p;
};

constexpr std::array<std::array<int, 2>, 6> kEdges = {{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// 2D overlap of the relative interiors of triangles a and b lying in one plane.
bool coplanar_overlap(const Tet4& s, int fs, const Tet4& t, const std::array<int, 3>& ft) {
  std::array<std::uint32_t, 3> ia, ib;
  std::array<const Point*, 3> pa, pb;
  for (int i = 0; i < 3; ++i) {
    ia[i] = s.id[kFaceVertices[fs][i]];
    pa[i] = s.p[kFaceVertices[fs][i]];
    ib[i] = t.id[ft[i]];
    pb[i] = t.p[ft[i]];
  }
  int drop = 0;
  Sign oa = Sign::Zero;
  for (; drop < 3; ++drop)
    if ((oa = signs::orient2d(*pa[0], *pa[1], *pa[2], drop)) != Sign::Zero) break;
  if (drop == 3) return false;
  const Sign ob = signs::orient2d(*pb[0], *pb[1], *pb[2], drop);
  if (ob == Sign::Zero) return false;
  if (oa == Sign::Negative) std::swap(ia[1], ia[2]), std::swap(pa[1], pa[2]);
  if (ob == Sign::Negative) std::swap(ib[1], ib[2]), std::swap(pb[1], pb[2]);
  auto separates = [&](const auto& i1, const auto& p1, const auto& i2, const auto& p2) {
    for (int e = 0; e < 3; ++e) {
      const int f = (e + 1) % 3;
      bool all = true;
      for (int k = 0; k < 3 && all; ++k) {
        if (i2[k] == i1[e] || i2[k] == i1[f]) continue;
        all = signs::orient2d(*p1[e], *p1[f], *p2[k], drop) != Sign::Positive;
      }
      if (all) return true;
    }
    return false;
  };
  return !separates(ia, pa, ib, pb) && !separates(ib, pb, ia, pa);
}

// Face planes of s against the vertices of t.
std::optional<Contact> by_faces(const Tet4& s, const Tet4& t) {
  for (int f = 0; f < 4; ++f) {
    const auto& fv = kFaceVertices[f];
    bool separated = true;
    std::array<int, 3> on{};
    int n_on = 0;
    for (int k = 0; k < 4 && separated; ++k) {
      const std::uint32_t q = t.id[k];
      Sign side;
      if (q == s.id[fv[0]] || q == s.id[fv[1]] || q == s.id[fv[2]])
        side = Sign::Zero;
      else if (q == s.id[f])
        side = Sign::Negative;
      else
        side = signs::orient3d(*s.p[fv[0]], *s.p[fv[1]], *s.p[fv[2]], *t.p[k]);
      if (side == Sign::Negative) separated = false;
      if (side == Sign::Zero && n_on < 3) on[n_on++] = k;
    }
    if (!separated) continue;
    if (n_on == 3) {
      std::array<std::uint32_t, 3> a = {s.id[fv[0]], s.id[fv[1]], s.id[fv[2]]};
      std::array<std::uint32_t, 3> b = {t.id[on[0]], t.id[on[1]], t.id[on[2]]};
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a != b && coplanar_overlap(s, f, t, on)) return Contact::CoplanarOverlap;
    }
    return Contact::Separated;
  }
  return std::nullopt;
}

bool by_edges(const Tet4& s, const Tet4& t) {
  for (const auto& es : kEdges)
    for (const auto& et : kEdges) {
      const Point& e0 = *s.p[es[0]];
      const Point& e1 = *s.p[es[1]];
      const Point& g0 = *t.p[et[0]];
      const Point& g1 = *t.p[et[1]];
      auto side = [&](std::uint32_t id, const Point& x) {
        if (id == s.id[es[0]] || id == s.id[es[1]]) return 0;
        return to_int(signs::det3(e0, e1, g0, g1, e0, x));
      };
      int lo_s = 0, hi_s = 0, lo_t = 0, hi_t = 0;
      bool any_s = false;
      for (int k = 0; k < 4; ++k) {
        if (k == es[0] || k == es[1]) continue;
        const int v = side(s.id[k], *s.p[k]);
        lo_s = std::min(lo_s, v), hi_s = std::max(hi_s, v);
        any_s = any_s || v != 0;
      }
      if (!any_s) continue;  // e parallel to e': no axis
      for (int k = 0; k < 4; ++k) {
        const int v = side(t.id[k], *t.p[k]);
        lo_t = std::min(lo_t, v), hi_t = std::max(hi_t, v);
      }
      if ((hi_s <= 0 && lo_t >= 0) || (lo_s >= 0 && hi_t <= 0)) return true;
    }
  return false;
}

Contact contact(const Tet4& s, const Tet4& t) {
  if (auto c = by_faces(s, t)) return *c;
  if (auto c = by_faces(t, s)) return *c;
  return by_edges(s, t) ? Contact::Separated : Contact::Overlap;
}

int shared(const Tet& a, const Tet& b) {
  int n = 0;
  for (std::uint32_t u : a)
    for (std::uint32_t v : b) n += u == v ? 1 : 0;
  return n;
}

}  // namespace

CheckResult check_overlap(const Context& c) {
  CheckResult r = make_result("validity.overlap");
  if (!c.options.check_overlap) {
    r.reason = "disabled by options";
    return r;
  }
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  std::vector<Box> boxes(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    Box& b = boxes[t];
    b.lo = b.hi = pts[tets[t][0]];
    for (int k = 1; k < 4; ++k)
      for (int i = 0; i < 3; ++i) {
        b.lo[i] = std::min(b.lo[i], pts[tets[t][k]][i]);
        b.hi[i] = std::max(b.hi[i], pts[tets[t][k]][i]);
      }
  }
  const BoxGrid grid(boxes, static_cast<double>(tets.size()) / 2);
  auto make = [&](std::uint32_t t) {
    Tet4 x{tets[t], {&pts[tets[t][0]], &pts[tets[t][1]], &pts[tets[t][2]], &pts[tets[t][3]]}};
    if (c.orientation[t] == Sign::Negative) std::swap(x.id[1], x.id[2]), std::swap(x.p[1], x.p[2]);
    return x;
  };
  const Options& o = c.options;
  std::vector<Collector> parts(std::max(1u, o.threads), Collector(o.max_reported));
  parallel_blocks(grid.cells(), o.threads, 256, [&](unsigned w, std::size_t b, std::size_t e) {
    Collector& col = parts[w];
    const std::uint64_t before = signs::exact_evaluations();
    for (std::size_t cell = b; cell < e; ++cell) {
      const auto ids = grid.in_cell(cell);
      for (std::size_t i = 0; i < ids.size(); ++i) {
        const std::uint32_t s = ids[i];
        if (c.orientation[s] == Sign::Zero) continue;
        for (std::size_t j = i + 1; j < ids.size(); ++j) {
          const std::uint32_t t = ids[j];
          if (c.orientation[t] == Sign::Zero) continue;
          const Box &bs = boxes[s], &bt = boxes[t];
          Point corner;
          bool meet = true;
          for (int k = 0; k < 3; ++k) {
            meet = meet && bs.lo[k] <= bt.hi[k] && bt.lo[k] <= bs.hi[k];
            corner[k] = std::max(bs.lo[k], bt.lo[k]);
          }
          if (!meet) continue;
          const auto cc = grid.frame().cell_of(corner);
          if (grid.frame().index(cc[0], cc[1], cc[2]) != cell) continue;
          if (shared(tets[s], tets[t]) >= 3) continue;
          ++col.checked;
          const Contact k = contact(make(s), make(t));
          if (k == Contact::Separated) continue;
          const std::uint32_t lo = std::min(s, t), hi = std::max(s, t);
          const std::uint64_t key = (std::uint64_t{lo} << 32) | hi;
          ++col.counts[k == Contact::Overlap ? "overlapping_pairs" : "coplanar_overlaps"];
          if (!col.wants(key)) {
            col.violation(key);
            continue;
          }
          std::vector<std::uint32_t> vs(tets[lo].begin(), tets[lo].end());
          vs.insert(vs.end(), tets[hi].begin(), tets[hi].end());
          Finding f = make_finding(c.mesh, "tet", lo, vs,
                                   "validity.overlap: tets " + std::to_string(lo) + " and " +
                                       std::to_string(hi) +
                                       (k == Contact::Overlap ? " overlap"
                                                              : " touch through partially overlapping coplanar faces"));
          f.value = static_cast<double>(hi);
          col.violation(key, std::move(f));
        }
      }
    }
    col.counts["exact_evaluations"] += signs::exact_evaluations() - before;
  });
  merge_into(parts, r, o.max_reported);
  r.counts["pairs_examined"] = r.checked;
  conclude(r);
  return r;
}

}  // namespace pdr::check
