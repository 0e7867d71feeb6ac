// delaunay.empty_sphere: no mesh vertex lies strictly inside the circumsphere of any tet
// (paper §1.2: a Delaunay tetrahedralization; the Bowyer-Watson cavity is exactly the set
// of tets whose open circumballs contain the new vertex). Vertices exactly on a
// circumsphere are counted ("cospherical") and are not violations.
//
// Every tet is tested against *all* vertices, not only its neighbours' (local Delaunayhood
// implies the global property only for a tetrahedralization of a convex set; a mesh of a
// non-convex domain is Delaunay only if the domain's vertices outside the mesh respect it
// too). Candidates come from the vertex grid's cells that can meet an enclosure of the
// closed circumball (circumball.hpp, PointGrid::query_ball), inside its box; each candidate
// not a vertex of the tet and not provably outside the enclosure (surely_outside, a few
// flops) gets an exact insphere sign, multiplied by the tet's exact orientation so the
// verdict does not depend on the recorded vertex order. Degenerate tets are skipped
// (validity.orientation reports them). Counts: candidates (points in the box that the query
// visited: a large ball's query skips rows of cells that miss it), signs_evaluated.
#include <algorithm>

#include "check/checks.hpp"
#include "check/circumball.hpp"
#include "check/parallel.hpp"
#include "check/signs.hpp"

namespace pdr::check {

CheckResult check_empty_circumspheres(Context& c) {
  CheckResult r = make_result("delaunay.empty_sphere");
  const auto& tets = c.mesh.tets;
  const auto& pts = c.mesh.points;
  const Options& o = c.options;
  std::vector<Collector> parts(std::max(1u, o.threads), Collector(o.max_reported));
  constexpr double kSmallBall = 16;  // radius 4 top cells
  const double side2 = c.grid.frame().side() * c.grid.frame().side();
  c.circum_r2.assign(tets.size(), Interval{});
  parallel_blocks(tets.size(), o.threads, 1024, [&](unsigned w, std::size_t b, std::size_t e) {
    Collector& col = parts[w];
    const std::uint64_t before = signs::exact_evaluations();
    std::uint64_t cospherical = 0, pairs = 0, candidates = 0, tested = 0, skipped = 0;
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
    col.counts["exact_evaluations"] += signs::exact_evaluations() - before;
  });
  merge_into(parts, r, o.max_reported);
  conclude(r);
  return r;
}

}  // namespace pdr::check
