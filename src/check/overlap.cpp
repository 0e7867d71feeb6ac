// validity.overlap: the tets have pairwise disjoint interiors, and two tets touching along a
// plane do so through a common face (no coplanar faces partially overlapping). Together
// with validity.orientation and validity.face_sharing this makes the tets a simplicial
// tetrahedralization of their union (the paper's T(Omega), §1.1), up to lower-dimensional
// non-conforming contacts (an edge crossing an edge, a vertex on an edge), which are not
// tested.
//
// Two methods. First the degree argument of degree.cpp: with positive tets and faces
// shared properly, the number of tets covering a point is the winding number of the
// boundary surface about it, so a boundary that is a simplicial complex and has nothing
// covered just outside it proves the interiors disjoint, looking at the boundary faces
// and one point per boundary component (about 20 times faster on a 1M-tet mesh). When its
// premises fail, or it finds a covered point, the pairwise test below decides and names
// the pairs.
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
// an edge e' of the other (e x e' != 0). A plane separating two tets that share vertices
// holds them all (they lie in both closed sets), so only candidates holding every shared
// vertex are tried: for a shared edge, the four face planes through it (the tets' wedges
// around it are separable by one of their sides); for a shared vertex, the six face planes
// and nine edge pairs through it (the SAT candidates of the two tangent cones). Each candidate is decided with exact signs
// (signs.hpp); "weakly" means both closed half-spaces, so touching tets are separated.
// Candidate pairs: a grid over the tets' bounding boxes, nested where they crowd
// (grid.hpp); a pair is examined once, in the cell holding the low corner of the boxes'
// intersection. Boxes that
// only touch have a separating axis-parallel plane for free. Pairs sharing
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

// The outward face planes of a positive tet.
struct Planes {
  std::array<signs::Plane, 4> face;
  Planes() = default;
  explicit Planes(const Tet4& s) {
    for (int f = 0; f < 4; ++f)
      face[f] = signs::Plane(*s.p[kFaceVertices[f][0]], *s.p[kFaceVertices[f][1]], *s.p[kFaceVertices[f][2]]);
  }
};

// Face planes of s against the vertices of t.
std::optional<Contact> by_faces(const Tet4& s, const Planes& ps, const Tet4& t) {
  for (int f = 0; f < 4; ++f) {
    // A plane separating tets with a common vertex passes through it: faces of s not
    // holding every shared vertex cannot separate.
    if (std::find(t.id.begin(), t.id.end(), s.id[f]) != t.id.end()) continue;
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
        side = ps.face[f].orient(*t.p[k]);
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
  auto holds_shared = [&](const Tet4& x, const std::array<int, 2>& e, const Tet4& y) {
    for (int k = 0; k < 4; ++k)
      if (k != e[0] && k != e[1] && std::find(y.id.begin(), y.id.end(), x.id[k]) != y.id.end())
        return false;
    return true;
  };
  for (const auto& es : kEdges)
    for (const auto& et : kEdges) {
      // As in by_faces: the plane must hold every shared vertex, so both edges must.
      if (!holds_shared(s, es, t) || !holds_shared(t, et, s)) continue;
      const Point& e0 = *s.p[es[0]];
      const Point& e1 = *s.p[es[1]];
      const Point& g0 = *t.p[et[0]];
      const Point& g1 = *t.p[et[1]];
      const std::uint32_t s0 = s.id[es[0]], s1 = s.id[es[1]], t0 = t.id[et[0]], t1 = t.id[et[1]];
      // det[e1 - e0, g1 - g0, x - e0] vanishes identically when x is e0 or e1, or when x is
      // one end of e' and the other end is e0 or e1 (dependent columns).
      auto side = [&](std::uint32_t id, const Point& x) {
        if (id == s0 || id == s1) return 0;
        if ((id == t1 && (t0 == s0 || t0 == s1)) || (id == t0 && (t1 == s0 || t1 == s1))) return 0;
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

// Boxes touching on the plane x[axis] = c: the plane separates the tets; they can only
// meet improperly through two coplanar faces lying in it.
Contact touching(const Tet4& s, const Tet4& t, int axis, double c) {
  int fs = -1, ns = 0, nt = 0;
  std::array<int, 3> on{};
  for (int k = 0; k < 4; ++k) {
    if ((*s.p[k])[axis] == c)
      ++ns;
    else
      fs = k;  // the face of s in the plane is the one opposite its off-plane vertex
    if ((*t.p[k])[axis] == c && nt < 3) on[nt++] = k;
  }
  if (ns != 3 || nt != 3) return Contact::Separated;
  return coplanar_overlap(s, fs, t, on) ? Contact::CoplanarOverlap : Contact::Separated;
}

Contact contact(const Tet4& s, const Planes& ps, const Tet4& t) {
  if (auto c = by_faces(s, ps, t)) return *c;
  if (auto c = by_faces(t, Planes(t), s)) return *c;
  return by_edges(s, t) ? Contact::Separated : Contact::Overlap;
}

int shared(const Tet& a, const Tet& b) {
  int n = 0;
  for (std::uint32_t u : a)
    for (std::uint32_t v : b) n += u == v ? 1 : 0;
  return n;
}

// The pairwise test: every pair of tets whose boxes meet.
void check_pairs(const Context& c, CheckResult& r) {
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  std::vector<Box> boxes(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) boxes[t] = box_of<4>(pts, tets[t]);
  // Degenerate tets are left to validity.orientation: an empty box is never paired.
  for (std::size_t t = 0; t < tets.size(); ++t)
    if (c.orientation[t] == Sign::Zero) boxes[t] = Box{{1, 1, 1}, {0, 0, 0}};
  auto make = [&](std::uint32_t t) {
    Tet4 x{tets[t], {&pts[tets[t][0]], &pts[tets[t][1]], &pts[tets[t][2]], &pts[tets[t][3]]}};
    if (c.orientation[t] == Sign::Negative) std::swap(x.id[1], x.id[2]), std::swap(x.p[1], x.p[2]);
    return x;
  };
  const Options& o = c.options;
  const unsigned workers = std::max(1u, o.threads);
  std::vector<Collector> parts(workers, Collector(o.max_reported));
  std::vector<std::uint64_t> evaluations(workers, 0);
  // Per worker: the last tet s seen and its planes (the sweep pairs one s with many t).
  struct Cache {
    std::uint32_t s = UINT32_MAX;
    Tet4 S;
    Planes PS;
    bool has_planes = false;
  };
  std::vector<Cache> cache(workers);
  auto loop = [&](std::size_t n, auto&& body) {
    parallel_blocks(n, workers, 256, [&](unsigned w, std::size_t b, std::size_t e) {
      const std::uint64_t before = signs::exact_evaluations();
      body(w, b, e);
      evaluations[w] += signs::exact_evaluations() - before;
    });
  };
  // Cells a few times larger than a typical tet box: few boxes straddle cells, and the
  // sweep along x inside a cell prunes most non-overlapping boxes (measured best).
  for_each_box_pair(boxes, 32, loop, [&](unsigned w, std::uint32_t s, std::uint32_t t) {
    Collector& col = parts[w];
    if (shared(tets[s], tets[t]) >= 3) return;
    ++col.checked;
    const Box& bs = boxes[s];
    const Box& bt = boxes[t];
    int axis = -1;
    double plane = 0;
    for (int a = 0; a < 3 && axis < 0; ++a) {
      if (bs.hi[a] == bt.lo[a]) axis = a, plane = bs.hi[a];
      if (bt.hi[a] == bs.lo[a]) axis = a, plane = bt.hi[a];
    }
    Cache& k = cache[w];
    if (k.s != s) k.s = s, k.S = make(s), k.has_planes = false;
    const Tet4 T = make(t);
    Contact contact_kind;
    if (axis >= 0) {
      contact_kind = touching(k.S, T, axis, plane);
    } else {
      if (!k.has_planes) k.PS = Planes(k.S), k.has_planes = true;
      contact_kind = contact(k.S, k.PS, T);
    }
    if (contact_kind == Contact::Separated) return;
    const std::uint32_t lo = std::min(s, t), hi = std::max(s, t);
    const std::uint64_t key = (std::uint64_t{lo} << 32) | hi;
    ++col.counts[contact_kind == Contact::Overlap ? "overlapping_pairs" : "coplanar_overlaps"];
    if (!col.wants(key)) {
      col.violation(key);
      return;
    }
    std::vector<std::uint32_t> vs(tets[lo].begin(), tets[lo].end());
    vs.insert(vs.end(), tets[hi].begin(), tets[hi].end());
    Finding f = make_finding(c.mesh, "tet", lo, vs,
                             "validity.overlap: tets " + std::to_string(lo) + " and " + std::to_string(hi) +
                                 (contact_kind == Contact::Overlap
                                      ? " overlap"
                                      : " touch through partially overlapping coplanar faces"));
    f.value = static_cast<double>(hi);
    col.violation(key, std::move(f));
  });
  for (unsigned w = 0; w < workers; ++w) parts[w].counts["exact_evaluations"] += evaluations[w];
  merge_into(parts, r, o.max_reported);
  r.counts["pairs_examined"] = r.checked;
}

}  // namespace

CheckResult check_overlap(const Context& c) {
  CheckResult r = make_result("validity.overlap");
  if (!c.options.check_overlap) {
    r.reason = "disabled by options";
    return r;
  }
  const DegreeVerdict proved =
      c.options.overlap_by_degree ? overlap_by_degree(c, r) : DegreeVerdict::PremisesFail;
  if (proved == DegreeVerdict::Disjoint) {
    r.checked = c.mesh.tets.size();
    conclude(r);
    return r;
  }
  check_pairs(c, r);
  if (proved == DegreeVerdict::Overlap && r.violations == 0) {
    // The degree argument found a doubly covered point that no pair explains: report it
    // rather than pass (this would be a bug of one of the two tests).
    ++r.violations;
    r.findings.push_back({"mesh", kNoId, {}, {}, std::nullopt,
                          "validity.overlap: a point just outside the boundary is covered by a tet, "
                          "but no pair of tets was found to overlap"});
  }
  conclude(r);
  return r;
}

}  // namespace pdr::check
