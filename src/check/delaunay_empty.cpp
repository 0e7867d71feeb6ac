// delaunay.empty_sphere: no mesh vertex lies strictly inside the circumsphere of any tet
// (paper §1.2: a Delaunay tetrahedralization; the Bowyer-Watson cavity is exactly the set
// of tets whose open circumballs contain the new vertex). Vertices exactly on a
// circumsphere are counted ("cospherical", pairs of a tet and a vertex) and are not
// violations.
//
// The vertex query. Candidates for a tet come from the vertex grid's cells that can meet
// an enclosure of the closed circumball (circumball.hpp, PointGrid::query_ball), inside its
// box; each candidate not a vertex of the tet and not provably outside the enclosure
// (surely_outside, a few flops) gets an exact insphere sign, multiplied by the tet's exact
// orientation so the verdict does not depend on the recorded vertex order. Degenerate tets
// are skipped (validity.orientation reports them). Every vertex is a candidate, not only
// the neighbours': a mesh of a non-convex domain is Delaunay only if the vertices across a
// gap or a notch respect every sphere too.
//
// The Delaunay lemma spares most tets that query. Premises: (P1) every tet has a nonzero
// orientation; (P2) every face is held by one tet (a boundary face) or by two on its
// opposite sides; (P3) every vertex is a vertex of some tet; (P4) the tets' interiors are
// disjoint (validity.overlap). Let every interior face be locally Delaunay: the apex of one
// holder is not strictly inside the other's circumsphere (one exact insphere per face).
// Claim: a tet t whose closed circumball B has an enclosing box that meets the box of no
// boundary face has no vertex strictly inside B; and none on its sphere either unless one
// of t's faces is a tie (its other holder's apex on t's sphere).
// Proof. Let v be a vertex in the open ball B, not a vertex of t, and pow_s(x) = |x - c_s|^2
// - r_s^2 the power of x for the sphere of tet s. Walk along a segment from a point p
// inside t to v, p chosen so that the segment meets no mesh edge and no mesh vertex before
// v (the p to avoid lie on finitely many planes, each through v and an edge not collinear
// with v; a line through v and an edge meets the segment only at v). The segment lies in
// the closed ball (convex), so it touches no boundary face: it leaves a tet only through
// the interior of an interior face f, into f's other holder t', which lies beyond f (P2).
// Across f, pow_t - pow_t' is affine, zero on f's plane, and at the apex of t' equals
// pow_t(apex) >= 0 (f locally Delaunay), so it is >= 0 on the far side, where v lies (the
// segment crosses f's plane once); > 0 if the apex is strictly outside. A convex tet is
// crossed once by a segment, so the walk ends, in a tet s whose closure holds v. Say v is
// not a vertex of s. If v lies inside s, or inside a face of s (an interior one: no
// boundary face meets the ball), tets cover a neighbourhood of v. If v lies inside an edge
// e of s, every face at e is interior, so the tets around e go round it in cycles whose
// dihedral angles add up to a multiple of 2 pi and cover a neighbourhood of v too. If v
// lies at a vertex of s (a duplicate point), that vertex's star has no boundary face and
// covers its neighbourhood. Either way v's own tets (P3) would overlap one of them
// (against P4). So v is a vertex of s, pow_s(v) = 0, and along the walk pow_t(v) >= ... >=
// pow_s(v) = 0: v is not strictly inside B. If the first face crossed is not a tie,
// pow_t(v) > pow_t1(v) >= 0: v is not on the sphere either. []
// So: one insphere per interior face; a face that is not locally Delaunay, or a premise
// P1-P3 that fails, sends every tet to the query (the counts and findings are then the
// query's, exactly); otherwise only the tets at a tie face or near the boundary (their
// ball's box meets a boundary face's, looked up in the grid's top frame) are queried.
// The boundary faces' boxes are looked up in a BoxCells over the vertex grid's top frame
// (grid.hpp). P4 is validity.overlap's, decided beside this check: check.cpp runs this
// check again with every tet queried when that fails (used_lemma), and without the lemma
// when the overlap check is off. Counts: local_faces (interior
// faces tested), queried_tets, lemma (1 when the lemma was used), candidates (points in a
// queried box), signs_evaluated. The pairs of a tet and a vertex on its sphere are kept
// too (Context::on_sphere, up to Report::kMaxOnSphere): the order check decides from them.
#include <algorithm>
#include <atomic>
#include <optional>

#include "check/checks.hpp"
#include "check/circumball.hpp"
#include "check/parallel.hpp"
#include "check/signs.hpp"

namespace pdr::check {
namespace {

// The interior faces' verdict: ok when P2 holds and every one is locally Delaunay; the
// holders of faces whose apex is on the other holder's sphere.
struct LocalFaces {
  bool ok = true;
  std::uint64_t tested = 0;
  std::vector<std::uint32_t> tied;
};

LocalFaces local_faces(const Context& c) {
  const Topology& topo = c.topology;
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  const unsigned threads = std::max(1u, c.options.threads);
  std::vector<LocalFaces> parts(threads);
  std::atomic<bool> failed{false};
  parallel_blocks(topo.faces.size(), threads, 1 << 14, [&](unsigned w, std::size_t b, std::size_t e) {
    if (failed.load(std::memory_order_relaxed)) return;
    LocalFaces& part = parts[w];
    for (std::size_t f = b; f < e; ++f) {
      const auto h = topo.holders(f);
      if (h.size() == 1) continue;
      if (h.size() != 2 || apex_side(c, h[0]) == apex_side(c, h[1])) {
        failed.store(true, std::memory_order_relaxed);
        return;
      }
      const Tet& k = tets[h[0].tet];
      const Point& apex = pts[tets[h[1].tet][h[1].local]];
      ++part.tested;
      const Sign in =
          signs::insphere(pts[k[0]], pts[k[1]], pts[k[2]], pts[k[3]], apex) * c.orientation[h[0].tet];
      if (in == Sign::Positive) {
        failed.store(true, std::memory_order_relaxed);
        return;
      }
      if (in == Sign::Zero) {
        part.tied.push_back(h[0].tet);
        part.tied.push_back(h[1].tet);
      }
    }
  });
  LocalFaces all;
  all.ok = !failed.load();
  for (LocalFaces& p : parts) {
    all.tested += p.tested;
    all.tied.insert(all.tied.end(), p.tied.begin(), p.tied.end());
  }
  return all;
}

// P1 and P3.
bool tets_and_vertices_qualify(const Context& c) {
  for (Sign s : c.orientation)
    if (s == Sign::Zero) return false;
  std::vector<std::uint8_t> used(c.mesh.points.size(), 0);
  for (const Tet& t : c.mesh.tets)
    for (std::uint32_t v : t) used[v] = 1;
  return std::find(used.begin(), used.end(), std::uint8_t{0}) == used.end();
}

}  // namespace

bool used_lemma(const CheckResult& r) {
  const auto it = r.counts.find("lemma");
  return it != r.counts.end() && it->second != 0;
}

CheckResult check_empty_circumspheres(Context& c, bool by_lemma) {
  CheckResult r = make_result("delaunay.empty_sphere");
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  const Options& o = c.options;
  std::vector<Collector> parts(std::max(1u, o.threads), Collector(o.max_reported));
  constexpr double kSmallBall = 16;  // radius 4 top cells
  const double side2 = c.grid.frame().side() * c.grid.frame().side();
  c.circum_r2.assign(tets.size(), Interval{});
  c.on_sphere.assign(std::max(1u, o.threads), {});
  std::atomic<std::size_t> on_sphere_claimed{0};  // one cap over every worker's list
  LocalFaces local;
  local.ok = by_lemma && tets_and_vertices_qualify(c);
  if (local.ok) local = local_faces(c);
  const bool lemma = local.ok;
  std::vector<std::uint8_t> tied;
  std::optional<BoxCells> near;  // the boundary faces' boxes
  if (lemma) {
    tied.assign(tets.size(), 0);
    for (std::uint32_t t : local.tied) tied[t] = 1;
    std::vector<Box> boundary;
    boundary.reserve(c.topology.boundary.size());
    for (std::uint32_t f : c.topology.boundary) boundary.push_back(box_of<3>(pts, c.topology.faces[f]));
    near.emplace(c.grid.frame(), std::move(boundary));
  }
  parallel_blocks(tets.size(), o.threads, 1024, [&](unsigned w, std::size_t b, std::size_t e) {
    Collector& col = parts[w];
    const std::uint64_t before = signs::exact_evaluations();
    std::uint64_t cospherical = 0, pairs = 0, candidates = 0, tested = 0, skipped = 0, queried = 0;
    for (std::size_t t = b; t < e; ++t) {
      const Sign s = c.orientation[t];
      if (s == Sign::Zero) {
        ++skipped;
        continue;
      }
      ++col.checked;
      const Tet& k = tets[t];
      const Point &pa = pts[k[0]], &pb = pts[k[1]], &pc = pts[k[2]], &pd = pts[k[3]];
      const BallEnclosure ball = circumball(pa, pb, pc, pd);
      c.circum_r2[t] = ball.r2;
      const Box box = enclosing_box(ball);
      if (lemma && !tied[t] && !near->meets(box)) continue;  // the lemma answers for it
      ++queried;
      std::int64_t first = -1;
      std::uint64_t inside = 0;
      const auto visit = [&](std::uint32_t v, const Point& p) {
        if (v == k[0] || v == k[1] || v == k[2] || v == k[3]) return;
        for (int i = 0; i < 3; ++i)
          if (p[i] < box.lo[i] || p[i] > box.hi[i]) return;
        ++candidates;
        if (surely_outside(ball, p)) return;
        ++tested;
        const Sign in = signs::insphere(pa, pb, pc, pd, p) * s;
        if (in == Sign::Zero) {
          ++cospherical;
          if (on_sphere_claimed.fetch_add(1, std::memory_order_relaxed) < Report::kMaxOnSphere)
            c.on_sphere[w].emplace_back(t, v);
        } else if (in == Sign::Positive) {
          ++inside;
          if (first < 0 || v < first) first = v;
        }
      };
      // A ball a few cells wide: its box's cells (pruning rows would cost more than it
      // saves); a larger one, a flat tet's: the cells near the ball.
      if (ball.r2.hi <= kSmallBall * side2)
        c.grid.query(box, visit);
      else
        c.grid.query_ball(ball.center, ball.r2.hi, visit);
      if (inside == 0) continue;
      pairs += inside;
      if (!col.wants(t)) {
        col.violation(t);
        continue;
      }
      std::vector<std::uint32_t> vs(k.begin(), k.end());
      vs.push_back(static_cast<std::uint32_t>(first));
      Finding f = make_finding(c.mesh, "tet", t, vs,
                               "delaunay.empty_sphere: vertex " + std::to_string(first) +
                                   " is strictly inside the circumsphere of tet " + std::to_string(t) +
                                   (inside > 1 ? " (and " + std::to_string(inside - 1) + " more)" : ""));
      f.value = static_cast<double>(inside);
      col.violation(t, std::move(f));
    }
    col.counts["cospherical"] += cospherical;
    col.counts["violating_pairs"] += pairs;
    col.counts["candidates"] += candidates;
    col.counts["signs_evaluated"] += tested;
    col.counts["degenerate_skipped"] += skipped;
    col.counts["queried_tets"] += queried;
    col.counts["exact_evaluations"] += signs::exact_evaluations() - before;
  });
  c.on_sphere_overflow = on_sphere_claimed.load() > Report::kMaxOnSphere;
  if (c.on_sphere_overflow) c.on_sphere.clear();  // an incomplete list decides nothing
  merge_into(parts, r, o.max_reported);
  r.counts["local_faces"] = lemma ? local.tested : 0;  // (an early stop's count depends on timing)
  r.counts["lemma"] = lemma ? 1 : 0;
  conclude(r);
  return r;
}

}  // namespace pdr::check
