// SeqRefinement (paper §3, Fig. 2); see refine/seq_refinement.hpp. The main loop and
// Refine(t), Refine(f), Refine(s) are here; beside them: the work queue (work_queue.hpp),
// the vertex budget (budget.hpp), the guards outside the theory (guard.hpp, split.hpp),
// the closure encroachment tests (closure.hpp), the rounding repairs (flat.hpp), the
// rotation copies of conformity repairs near sharp axes (axis_zones.hpp), the Lemma 1
// audit (audit.hpp) and the leftovers (leftovers.hpp).
#include "refine/seq_refinement.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>

#include "delaunay/conflict.hpp"
#include "domain/angles.hpp"
#include "domain/distance.hpp"
#include "geom/construct.hpp"
#include "geom/predicates.hpp"
#include "geom/point_text.hpp"
#include "mesh/tables.hpp"
#include "refine/audit.hpp"
#include "refine/axis_zones.hpp"
#include "refine/budget.hpp"
#include "refine/closure.hpp"
#include "refine/conformity.hpp"
#include "refine/flat.hpp"
#include "refine/guard.hpp"
#include "refine/leftovers.hpp"
#include "refine/quality.hpp"
#include "refine/split.hpp"
#include "refine/vertex_zones.hpp"
#include "refine/work_queue.hpp"
#include "surface/insert.hpp"
#include "surface/locate.hpp"
#include "surface/split.hpp"

namespace pdr::refine {
namespace {

class Refiner {
 public:
  Refiner(VolumeMesh& m, const RefineOptions& o)
      : m_(m), o_(o), budget_(m.dt.points(), o) {}

  // Fig. 2: while some tet is bad, Refine(t). Outside the theory the encroached elements
  // the guards found come first (subsegments, then subfacets); the budget ends the loop.
  RefineResult run() {
    res_.stats.vertex_cap = budget_.cap();
    const std::size_t points_at_start = m_.dt.num_points();
    res_.stats.h = std::numeric_limits<double>::infinity();
    // The theorem's h where its hypotheses hold: B >= 2 (its proof needs a refined tet's
    // shortest edge below half its circumradius), exactly, with T_o holding every subsegment
    // and subfacet of D (§2.1 property 1) and none of them encroached (invariant 1 at the
    // start, the base case of Lemma 1). Rounded input can miss either by an ulp (a vertex a
    // hair inside an equatorial ball it should lie on); the repairs that follow are no step
    // of Fig. 2, and the a-priori bound is then not claimed.
    // Admissible domains: what T_o has encroached (rounding, or a graded D_o between
    // related elements of different sizes, surface/init.hpp) is refined first, as the
    // guards' pass does outside the theory.
    EncroachedLists at_start;
    if (o_.admissible && !o_.resumed_h) encroached_at_start(at_start);
    if (o_.resumed_h)
      res_.stats.h_theorem = *o_.resumed_h;
    else if (o_.admissible && o_.exact_theory && o_.ratio >= 2 && m_.missing_subfacets.empty() &&
             m_.missing_subsegments.empty() && at_start.subsegments.empty() &&
             at_start.subfacets.empty())
      res_.stats.h_theorem = theorem_h(shortest_inside_edge(m_), o_);
    const TetStore& s = m_.dt.store();
    // Then the stars of the new vertices are searched for encroachment as outside the
    // theory (a half of a split element can still be encroached by the same vertex), and
    // the Lemma 1 audit, whose base case failed, notes instead of throwing.
    watch_encroachment_ = !o_.admissible || !at_start.subsegments.empty() ||
                          !at_start.subfacets.empty();
    if (!o_.admissible)
      start_guards();
    else
      enc_ = std::move(at_start);
    if (!m_.missing_subfacets.empty() || !m_.missing_subsegments.empty()) {
      ++res_.stats.conformity_breaks;  // T_o (refine/initial.hpp)
      conformity_.start(m_);
    }
    const auto seed = [&](TetId t) {
      if (t < s.slots() && s.is_alive(t) && !s.is_ghost(t) && m_.is_inside(t)) consider(t);
    };
    if (o_.start_tets)
      for (const TetId t : *o_.start_tets) seed(t);
    else
      for (TetId t = 0; t < s.slots(); ++t) seed(t);
    for (;;) {
      if (const auto done = refine_encroached()) {
        if (!*done) break;  // the budget is spent
        continue;
      }
      QueuedTet e;
      if (!queue_.pop(e)) {  // no bad tet left
        if (final_reflag()) continue;
        break;
      }
      if (!WorkQueue::current(s, e) || !m_.is_inside(e.t)) continue;  // reflagged outside
      if (at_cap()) break;
      const std::size_t before = m_.dt.num_points();
      refine_tet(e.t);
      // An encroached element split on t's behalf may leave t alive: it waits again.
      if (m_.dt.num_points() > before && WorkQueue::current(s, e)) queue_.push(e);
      if (o_.on_progress && (++steps_ & 0x3FF) == 0) o_.on_progress(m_.dt.num_points());
    }
    abandon_missing();
    refused_.seal();
    // From given start tets, with no vertex added and no flag changed since, the tets are
    // those of the start, and only the start tets may miss the bounds
    // (RefineOptions::start_tets).
    res_.tets_unchanged = o_.start_tets && m_.dt.num_points() == points_at_start &&
                          res_.stats.flag_repairs == 0 && res_.stats.conformity_breaks == 0;
    res_.leftovers = collect_leftovers(m_, o_.ratio, refused_, res_.stop_reason,
                                       res_.tets_unchanged ? &*o_.start_tets : nullptr);
    return std::move(res_);
  }

 private:
  VolumeMesh& m_;
  const RefineOptions o_;
  const VertexBudget budget_;
  RefineResult res_;
  WorkQueue queue_;
  std::uint64_t steps_ = 0;
  Cavity cav_, cav2_;
  ClosureScan scan_;  // outside the theory: refine_tet's one-pass closure test
  std::vector<TetId> star_;
  // The vertices of the current insertion step (after_insert), each with what it refined;
  // a star of one of them.
  std::vector<std::pair<VertexId, const char*>> step_;
  std::vector<TetId> around_;
  RefusedTets refused_;
  SplitGuard guard_;     // empty for admissible domains (midpoints)
  AxisZones zones_;      // rotation copies around sharp axes (inadmissible domains only)
  VertexZones balls_;    // protecting balls around acute vertices (inadmissible domains only)
  bool filling_ = false;  // a zone's shell is going in (zone_repair)
  bool watch_encroachment_ = false;  // new stars searched for encroachment (run())
  EncroachedLists enc_;  // the encroachment guard's work (inadmissible domains only)
  ConformityTracker conformity_;  // refine/conformity.hpp

  const Point& pt(VertexId v) const { return m_.dt.point(v); }

  bool at_cap() { return budget_.reached(m_.dt.num_points(), res_.stop_reason); }

  // Outside the theory: refines the next encroached element the guards found (subsegments
  // first, then subfacets: Fig. 2's order). nullopt when none is waiting; false when the
  // budget is spent.
  std::optional<bool> refine_encroached() {
    if (const auto done = restore_missing()) return done;
    while (!enc_.subsegments.empty()) {
      const Encroached e = enc_.subsegments.back();
      enc_.subsegments.pop_back();
      if (!still_subsegment(m_.surf, e)) continue;
      if (at_cap()) return false;
      ++res_.stats.encroached_splits;
      if (auto why = split(e.id, hint(e.tet))) unsplit(std::move(*why));
      return true;
    }
    while (!enc_.subfacets.empty()) {
      const Encroached e = enc_.subfacets.back();
      enc_.subfacets.pop_back();
      if (!still_subfacet(m_.surf, e)) continue;
      if (at_cap()) return false;
      ++res_.stats.encroached_splits;
      refine_subfacet(e.id, hint(e.tet), kNoTet);
      return true;
    }
    return std::nullopt;
  }

  // Repairs of a missing subfacet go below the protected lengths, down to this fraction of
  // them: a bound, not what ends a cascade of repairs (at dihedrals below 70.53 degrees
  // around one axis the repairs of two facets took each other's subfacets out of T in turn,
  // each level half the size of the last; the rotation copies of refine/axis_zones.hpp end
  // that). What is still missing at the floor is listed (exit 3, NOT CONFORMING). Repairs
  // that end by themselves can go deep: a scanned surface with cap triangles folded onto
  // their neighbours at 1 to 3 degrees needed 2^-11.5 of its protected length (2^-10 left
  // it NOT CONFORMING), so the floor leaves 12 more levels of halving than that.
  static constexpr double kRepairFloor = 0x1p-24;
  // ...and never below what doubles can place: a circumcenter of a subfacet of circumradius
  // r among coordinates of magnitude X is computed with an error of a few ulps of X, so r
  // must keep about 2^-40 of X (12 bits of the 52 left for the position within r); the
  // same for a piece of a subsegment a repair splits.
  static constexpr double kPrecisionFloor = 0x1p-40;

  // The largest absolute coordinate of the points.
  static double magnitude(std::initializer_list<Point> pts) {
    double mag = 0;
    for (const Point& p : pts)
      for (int k = 0; k < 3; ++k) mag = std::max(mag, std::abs(p[k]));
    return mag;
  }

  // Why a repair of subfacet f may not go in: below the repair floor, or below what doubles
  // can place; empty when it may.
  std::string refuse_repair(std::uint32_t f) const {
    const surface::Subfacet& x = m_.surf.subfacet(f);
    const Point &a = m_.surf.point(x.v[0]), &b = m_.surf.point(x.v[1]),
                &c = m_.surf.point(x.v[2]);
    // In a protecting ball the zone's rules bound the repairs (refine/vertex_zones.hpp).
    if (in_active_ball(construct::triangle_circumcenter(a, b, c))) return {};
    if (std::string why = guard_.refuse_subfacet(m_.surf, f, kRepairFloor); !why.empty())
      return why;
    return below_precision(f);
  }

  // Why subfacet f's circumcenter cannot be placed in doubles (kPrecisionFloor); empty
  // when it can.
  std::string below_precision(std::uint32_t f) const {
    const surface::Subfacet& x = m_.surf.subfacet(f);
    const Point &a = m_.surf.point(x.v[0]), &b = m_.surf.point(x.v[1]),
                &c = m_.surf.point(x.v[2]);
    const double mag = magnitude({a, b, c});
    const double r = std::sqrt(construct::triangle_circumradius2(a, b, c));
    if (r >= kPrecisionFloor * mag) return {};
    std::ostringstream os;
    os.precision(6);
    os << "refine.precision: subfacet (" << x.v[0] << ", " << x.v[1] << ", " << x.v[2]
       << ") of " << m_.surf.facet_name(x.facet) << " has circumradius " << r
       << ", below 2^-40 of its coordinates' magnitude " << mag
       << ": its circumcenter cannot be placed in doubles";
    return os.str();
  }

  // Conformity first (refine/conformity.hpp): refines the next element of D missing from T
  // (Refine(s), then Refine(f)); once none is, recomputes the flags of the tets made
  // meanwhile. nullopt when nothing was missing; false when the budget is spent.
  std::optional<bool> restore_missing() {
    if (const auto n = conformity_.next(m_.surf)) {
      if (at_cap()) {
        conformity_.wait_again(*n);
        return false;
      }
      ++res_.stats.conformity_splits;
      const std::size_t before = m_.dt.num_points();
      if (n->subsegment) {
        if (auto why = split(n->e.id, kNoTet, /*below_floor=*/true)) unsplit(std::move(*why));
      } else if (std::string why = refuse_repair(n->e.id); !why.empty()) {
        unsplit("volume.conformity: a repair " + why);  // a cascade of repairs
      } else {
        // Rotation copies only for repairs below the protected length: above it a repair
        // is bounded like any refinement there, and copies there only leave tets next to
        // the sharp edge unrefined (the paper's tee at V = 0.008: 2).
        const bool deep = !guard_.refuse_subfacet(m_.surf, n->e.id).empty();
        refine_subfacet(n->e.id, kNoTet, kNoTet, /*below_floor=*/true, /*copies=*/deep);
      }
      if (m_.dt.num_points() == before)
        ++res_.stats.conformity_refused;
      else if (!n->subsegment && still_subfacet(m_.surf, n->e))
        conformity_.wait_again(*n);  // Refine(f) split a subsegment instead
      return true;
    }
    if (!conformity_.broken()) return std::nullopt;
    for (const TetId t : conformity_.restore(m_))
      if (m_.is_inside(t)) consider(t);
    return true;
  }

  // Once the queue is empty, in a run that had to repair flags or restore conformity:
  // every flag by parity from the hull (refine/conformity.hpp), a net under the
  // per-insertion repair; true when that queued bad tets. Idempotent, so the loop ends.
  // Runs without either keep every flag by construction (commit_point with the star
  // checked after each surface insertion) and skip this O(n) pass.
  bool final_reflag() {
    if (conformity_.broken() ||
        res_.stats.flag_repairs + res_.stats.conformity_breaks == 0)
      return false;
    std::size_t conflicts = 0;
    bool queued = false;
    for (const TetId t : reflag_all(m_, conflicts))
      if (m_.is_inside(t) && bad(t)) {
        queue_.push(m_.dt.store(), t);
        queued = true;
      }
    if (conflicts > 0 && res_.stats.flag_conflicts == 0)
      unsplit("volume.flags: across " + std::to_string(conflicts) +
              " faces of T the inside flags cannot follow D (T does not separate the domain "
              "along its facets there)");
    res_.stats.flag_conflicts = conflicts;
    return queued;
  }

  // The budget ended with elements of D missing from T: each is listed. Flat tets on a
  // facet still inside (refine/flat.hpp rule 1: their repair waited in the queue when the
  // cap stopped the run, or was refused) are counted: they leave T conforming (their faces
  // that are subfacets are faces of T and the inside flags follow them; their other faces
  // lie in the facet's slab without being in the facet), slivers of the facet's rounding.
  void abandon_missing() {
    for (const auto& n : conformity_.abandon(m_)) {
      ++res_.stats.conformity_refused;
      unsplit(std::string("volume.conformity: ") + (n.subsegment ? "subsegment " : "subfacet ") +
              std::to_string(n.e.id) + " is not in T (" + res_.stop_reason + ")");
    }
    // Flat tets need a facet a few ulps off its plane: not with the exact theory's facets.
    if (o_.admissible && o_.exact_theory) return;
    const TetStore& s = m_.dt.store();
    for (TetId t = 0; t < s.slots(); ++t)
      if (s.is_alive(t) && !s.is_ghost(t) && m_.is_inside(t) && flat_subfacet_face(m_, t))
        ++res_.stats.flat_left;
  }

  // Commits cavity c (p becomes D's vertex sv, kNone: off ∂Ω) and records the elements of
  // D that are not in T afterwards; `doomed_known`: conformity_.doomed(c) was just taken.
  VertexId insert(const Cavity& c, std::uint32_t sv, bool doomed_known = false) {
    if (!doomed_known) conformity_.doomed(m_, c);
    const VertexId v = commit_point(m_, c, sv, star_);
    const bool broke = conformity_.committed(m_, v, star_);
    // A surface update the cavity did not mirror (refine/conformity.hpp reflag_all).
    if (sv != kNone && !conformity_.broken() && !star_flags_consistent(m_, star_)) {
      ++res_.stats.flag_repairs;
      repair_flags();
    }
    if (broke) {
      ++res_.stats.conformity_breaks;
      if (o_.audit)
        audited([&] {
          throw RefineError("volume.conformity: after inserting " + point_text(pt(v)) +
                            ", an element of D at it or in its cavity is not in T");
        });
    }
    return v;
  }

  // The star's flags disagree across its faces. First from the tets around the star: when
  // every other flag was right, that is enough and the star then agrees with D across
  // every face. Else every flag by parity from the hull (reflag_all, linear in T). A pass
  // that finds faces where the parity cannot follow D (an element of D whose repair was
  // refused is not in T, so T does not separate the domain there) cannot make the flags
  // agree, and neither can the next ones until that changes: after such a pass the next
  // 1, 2, 4, ... flag repairs that the star alone cannot make skip the global pass (a
  // thin notch printed with 7 digits ran reflag_all at each of 1,135 flag repairs, 80% of
  // its run); one that finds none resets the count. final_reflag makes every flag follow
  // the parity at the end.
  void repair_flags() {
    for (const TetId t : reflag(m_, star_))
      if (m_.is_inside(t)) consider(t);
    if (star_flags_consistent(m_, star_)) return;
    if (reflag_skip_ > 0) {
      --reflag_skip_;
      return;
    }
    std::size_t conflicts = 0;
    for (const TetId t : reflag_all(m_, conflicts))
      if (m_.is_inside(t)) consider(t);
    reflag_interval_ = conflicts == 0 ? 0 : std::max<std::size_t>(1, 2 * reflag_interval_);
    reflag_skip_ = reflag_interval_;
  }
  std::size_t reflag_interval_ = 0, reflag_skip_ = 0;

  // Inadmissible domains: shells and protected lengths at the acute vertices (every input
  // vertex when the caller gave none), and the encroachment pre-pass over T_o.
  void start_guards() {
    std::vector<std::uint32_t> acute = o_.acute_vertices;
    if (acute.empty())
      for (std::uint32_t v = 0; v < m_.surf.vertex_count(); ++v)
        if (m_.surf.home(v).kind == HomeKind::Input) acute.push_back(v);
    // The cylinders are no wider than the element size asked for (refine/split.hpp).
    double cap = std::numeric_limits<double>::infinity();
    if (o_.size) cap = std::min(cap, *o_.size);
    if (const auto v = smallest_volume(o_)) cap = std::min(cap, std::cbrt(*v));
    guard_ = SplitGuard(
        m_.surf, acute, [b = budget_](double d) { return b.resolution_at(d) / 64; }, o_.cylinders, cap);
    zones_ = AxisZones(m_.surf, o_.cylinders, cap, o_.vertex_uncertainty);
    {
      const std::vector<double> near = nearest_at_start();
      balls_ = VertexZones(m_.surf, acute, [&](std::uint32_t v) {
        double d = std::numeric_limits<double>::infinity();
        for (const std::uint32_t g : m_.surf.vertex_subsegments(v))
          d = std::min(d, m_.surf.subsegment_size(g));
        return std::min(budget_.resolution_at(d) / 64, near[v] / 2);
      });
    }
    const TetStore& s = m_.dt.store();
    std::vector<TetId> all;
    for (TetId t = 0; t < s.slots(); ++t)
      if (s.is_alive(t) && !s.is_ghost(t)) all.push_back(t);
    find_encroached(m_, all, enc_);
  }
  TetId hint(TetId t) const {
    const TetStore& s = m_.dt.store();
    return t < s.slots() && s.is_alive(t) ? t : kNoTet;
  }
  // An encroached element the guards would not split.
  void unsplit(std::string why) {
    if (res_.stats.encroached_refused++ < 50) res_.unsplit.push_back(std::move(why));
  }

  std::array<VertexId, 4> verts(TetId t) const {
    const VertexId* v = m_.dt.store().vertices(t);
    return {v[0], v[1], v[2], v[3]};
  }

  bool bad(TetId t) const {
    const VertexId* v = m_.dt.store().vertices(t);
    TetBounds b{o_.ratio, o_.size, o_.max_volume, o_.region_volumes.get()};
    if (o_.interior && std::all_of(v, v + 4, [&](VertexId u) {
          return m_.vertex_class(u) == VertexClass::Interior;
        }))
      b = *o_.interior;
    return is_bad(pt(v[0]), pt(v[1]), pt(v[2]), pt(v[3]), b) ||
           subfacet_to_refine(m_, t).has_value();  // issue #3: refine/flat.hpp
  }
  void consider(TetId t) {
    if (bad(t)) queue_.push(m_.dt.store(), t);
  }
  void queue_star() {
    const TetStore& s = m_.dt.store();
    for (const TetId t : star_)
      if (!s.is_ghost(t) && m_.is_inside(t)) consider(t);
  }

  void refuse(TetId t, std::string why) {
    ++res_.stats.refused;
    refused_.add(verts(t), std::move(why));
  }

  // Locates p from `hint` and builds its cavity into `c`; false when p is a vertex.
  bool plan(const Point& p, TetId hint, Cavity& c, bool& outside) {
    const Location loc = m_.dt.locate(p, hint);
    if (loc.kind == Location::Kind::OnVertex) return false;
    outside = loc.kind == Location::Kind::OutsideHull || !m_.is_inside(loc.tet);
    m_.dt.build_cavity(p, loc.tet, c);
    return true;
  }

  // Outside the theory: t's circumcenter p's cavity into cav_, given up at the first tet
  // that shows an element of D that p encroaches or the cavity would take out of T (`hit`;
  // else the whole cavity's first such element, or none); false when p is a vertex. The
  // search grows from t itself when t conflicts with p (it does but for rounding): a
  // sliver's circumcenter can lie far outside, where the tets around p are many and fine,
  // and the nearest subfacet the cavity crosses is the one next to t (a crumpled top's
  // layers made cavities of 30,000 tets and more, built from p, for each refused tet).
  // Then no hit means no conflict tet across a subfacet from t, so p is outside Ω exactly
  // when a conflict tet is (only a non-conforming T can have one).
  bool plan_scanned(const Point& p, TetId t, bool& outside, std::optional<ClosureScan::Hit>& hit) {
    const TetStore& s = m_.dt.store();
    const bool from_t = seeds_cavity(s, m_.dt.points(), t, p);
    TetId seed = t;
    if (!from_t) {
      const Location loc = m_.dt.locate(p, t);
      if (loc.kind == Location::Kind::OnVertex) return false;
      outside = loc.kind == Location::Kind::OutsideHull || !m_.is_inside(loc.tet);
      seed = loc.tet;
    }
    hit.reset();
    const bool whole = m_.dt.build_cavity_until(p, seed, cav_, [&](TetId from, int f, TetId u) {
      hit = scan_.joins(m_, from, f, u, p);
      return hit.has_value();
    });
    if (whole) hit = scan_.first(m_, cav_, p, /*conflict_seen=*/true);
    if (from_t && whole && !hit)
      outside = std::any_of(cav_.conflict.begin(), cav_.conflict.end(),
                            [&](TetId u) { return s.is_ghost(u) || !m_.is_inside(u); });
    return true;
  }

  // A Lemma 1 audit check: it throws on admissible domains whose T_o is unencroached;
  // otherwise (outside the theory, or Lemma 1's base case failed) the first failure is
  // noted.
  template <class Check>
  void audited(Check check) {
    if (!watch_encroachment_) {
      check();
      return;
    }
    try {
      check();
    } catch (const RefineError& e) {
      if (res_.stats.audit_failures++ == 0) res_.stats.audit_note = e.what();
    }
  }

  // The current star of step_[i]'s vertex into around_ (star_ while the step has one).
  void step_star(std::size_t i) {
    if (step_.size() == 1) {
      around_ = star_;
      return;
    }
    const Location loc = m_.dt.locate(pt(step_[i].first), m_.dt.last_tet());
    vertex_star(m_, step_[i].first, loc.tet, around_);
  }

  // Some subsegment or subfacet of D has a vertex strictly inside its ball in T_o.
  void encroached_at_start(EncroachedLists& found) const {
    const TetStore& s = m_.dt.store();
    std::vector<TetId> all;
    for (TetId t = 0; t < s.slots(); ++t)
      if (s.is_alive(t) && !s.is_ghost(t)) all.push_back(t);
    find_encroached(m_, all, found);
  }

  // Rounding repair at step_[i]'s vertex (issue #3, refine/flat.hpp rule 2): refines a
  // subfacet face of a tet of its star whose fourth vertex lies strictly inside the
  // subfacet's equatorial ball, as the bad-tet queue would. True when that added a vertex.
  bool repair(std::size_t i) {
    step_star(i);
    const TetStore& s = m_.dt.store();
    for (const TetId t : around_) {
      if (s.is_ghost(t)) continue;
      const auto f = encroached_subfacet_face(m_, t);
      if (!f) continue;
      const std::size_t before = m_.dt.num_points();
      ++res_.stats.face_repairs;
      refine_subfacet(*f, t, t);  // its vertex joins step_ (no recursion)
      if (m_.dt.num_points() > before) return true;
    }
    return false;
  }

  // After each commit: invariants 2-4 on the new edges, the new tets queued. The step's
  // first call then repairs rounding encroachment at once at each vertex of the step (the
  // repairs' vertices join the step; the vertex cap bounds them) and only then audits
  // invariant 1 on each one's current star: every tet the step created holds one of them.
  void after_insert(VertexId v, const char* what, double size2) {
    // The theorem's h where its hypotheses hold exactly; else the run's own (outside the
    // theory Lemma 1 is not expected to hold: the audit only records its first failure).
    const double h = res_.stats.h_theorem > 0 ? res_.stats.h_theorem : res_.stats.h;
    if (o_.audit) audited([&] { audit_edges(m_, v, star_, what, size2, h); });
    queue_star();
    if (watch_encroachment_) find_encroached(m_, star_, enc_);
    step_.emplace_back(v, what);
    if (step_.size() > 1) return;  // a repair's vertex, or a rotation copy
    if (!pending_copies_.empty() && pt(v) == pending_point_) {
      const std::vector<AxisZones::Copy> copies = std::move(pending_copies_);
      pending_copies_.clear();
      for (const AxisZones::Copy& c : copies) insert_copy(c, pending_size2_);
    }
    for (std::size_t i = 0; i < step_.size() && !at_cap();)
      if (!repair(i)) ++i;
    if (o_.audit)
      for (std::size_t i = 0; i < step_.size(); ++i) {
        step_star(i);
        audited([&] { audit_encroachment(m_, step_[i].first, around_, step_[i].second); });
      }
    step_.clear();
  }

  // Fig. 2 Refine(s) (refine/split.hpp: where); the reason when the guard refuses.
  // In a protecting ball only a repair goes on, by the zone's rules.
  std::optional<std::string> split(std::uint32_t sub, TetId hint, bool below_floor = false) {
    const SplitGuard::Plan where = guard_.plan(m_.surf, sub, below_floor);
    if (!where.ok) return where.reason;
    if (const auto z = ball_for(where.p, below_floor))
      return below_floor ? zone_repair(*z, kNone, where.p) : ball_refusal(*z, where.p);
    return split_at(sub, where.p, hint, below_floor);
  }

  // Splits subsegment sub at p (on it up to rounding); the reason when it cannot.
  std::optional<std::string> split_at(std::uint32_t sub, const Point& p, TetId hint,
                                      bool below_floor) {
    const Subsegment& x = m_.surf.subsegment(sub);
    const Point a = m_.surf.point(x.v[0]), b = m_.surf.point(x.v[1]);
    double piece2 = std::numeric_limits<double>::infinity();
    for (const Point& e : {a, b}) {
      double l2 = 0;
      for (int k = 0; k < 3; ++k) l2 += (e[k] - p[k]) * (e[k] - p[k]);
      piece2 = std::min(piece2, l2);
    }
    // A repair's split below what doubles can place (kPrecisionFloor; the pieces of a
    // shell split are not halves, so the shorter one is what counts).
    if (below_floor && std::sqrt(piece2) < kPrecisionFloor * magnitude({a, b})) {
      std::ostringstream os;
      os.precision(6);
      os << "refine.precision: splitting subsegment (" << x.v[0] << ", " << x.v[1] << ") of "
         << m_.surf.segment_name(x.segment) << " would leave a piece of length "
         << std::sqrt(piece2) << ", below 2^-40 of its coordinates' magnitude "
         << magnitude({a, b}) << ": doubles cannot place the split point";
      return os.str();
    }
    // T's cavity first, D's split second: the step decides before it changes anything
    // (docs/parallel.md: a step that must fetch tets from another submesh is dropped).
    bool outside = false;
    if (!plan(p, hint, cav_, outside))
      throw RefineError("refine.split: the split point " + point_text(p) + " of " +
                        m_.surf.segment_name(x.segment) + " is already a vertex");
    // Outside the theory a repair's split deep in a cascade can meet a subfacet whose apex
    // is a vertex of the same segment, collinear with it but for rounding: p is then on
    // neither side of that edge and the facet's cavity is not star-shaped. Nothing has
    // changed; the split is refused and listed (exit 3, NOT CONFORMING when it was a
    // repair), not an internal error.
    const surface::SplitPlan sp = surface::plan_split(m_.surf, sub, p);
    if (!sp.failure.empty())
      return "refine.precision: " + sp.failure + " (the split point is within rounding of a subfacet's edge)";
    res_.stats.h = std::min(res_.stats.h, std::sqrt(piece2));
    const surface::SplitResult r = surface::commit_split(m_.surf, sub, sp);
    const VertexId v = insert(cav_, r.vertex);
    ++res_.stats.subsegment_splits;
    after_insert(v, "subsegment", piece2);
    return std::nullopt;
  }

  // Tet t cannot be refined (kNoTet: an encroached element could not be split).
  void give_up(TetId t, std::string why) {
    if (t == kNoTet)
      unsplit(std::move(why));
    else
      refuse(t, std::move(why));
  }

  // Fig. 2 Refine(f) for a subfacet f, on behalf of tet t (kNoTet: f is encroached);
  // `hint` locates its circumcenter. With `copies` (a conformity repair below the protected
  // length) near a sharp axis, the circumcenter's rotation copies follow it
  // (refine/axis_zones.hpp).
  void refine_subfacet(std::uint32_t f, TetId hint, TetId t, bool below_floor = false,
                       bool copies = false) {
    if (std::string why = below_floor ? std::string() : guard_.refuse_subfacet(m_.surf, f);
        !why.empty()) {
      give_up(t, std::move(why));
      return;
    }
    const Subfacet& x = m_.surf.subfacet(f);
    const double r2 = construct::triangle_circumradius2(
        m_.surf.point(x.v[0]), m_.surf.point(x.v[1]), m_.surf.point(x.v[2]));
    surface::FacetCavity fc = plan_circumcenter(m_.surf, f);
    // In a zone every facet vertex goes to the zone's grid, copies or not: a circumcenter
    // of a subfacet that mirrors another wall's (up to rounding) then lands on that wall's
    // copy instead of ulps from it. The snapped cavity is used only when it is as good.
    if (!zones_.empty() && fc.status == surface::CavityStatus::Ok) {
      AxisZones::Placed placed = zones_.place(m_.surf, x.facet, fc.p);
      if (placed.own != fc.p) {
        surface::FacetCavity snapped =
            surface::build_facet_cavity(m_.surf, x.facet, placed.own, {f}, std::nullopt);
        if (snapped.status == surface::CavityStatus::Ok) fc = std::move(snapped);
      }
      // The copies join this step (after_insert) before its repairs look at the star.
      if (copies && fc.p == placed.own) {
        pending_copies_ = std::move(placed.copies);
        pending_point_ = fc.p;
        pending_size2_ = r2;
      }
    }
    // A repair of a subfacet with a shell piece (a, b) for an edge goes by the zone's rules
    // also when its circumcenter encroaches a subsegment: the fan triangle (v, a, b) always
    // encroaches its radial subsegments (its angle at v is below 90 degrees), and so can a
    // triangle (a, b, c) just outside the shell; the split of (v, a) that Fig. 2 makes
    // instead shrank the ball where the piece (a, b) is to be split on the sphere (slots
    // of 1 degree turned and printed with 17 digits halved an apex's ball 18 to 30 times,
    // down to 1e-12: NOT CONFORMING, or vertices 1e-9 from a segment).
    const auto has_piece = [&](std::uint32_t z) {
      for (int i = 0; i < 3; ++i)
        if (balls_.has_piece(z, x.facet, x.v[(i + 1) % 3], x.v[(i + 2) % 3])) return true;
      return false;
    };
    // (The circumcenter of such a repair is not inserted: it turns no dormant ball on.)
    const bool ok = fc.status == surface::CavityStatus::Ok;
    if (ok || (below_floor && fc.status == surface::CavityStatus::Encroaches))
      if (const auto z = ok ? ball_for(fc.p, below_floor) : active_ball_of(fc.p);
          z && (ok || has_piece(*z))) {
        pending_copies_.clear();
        if (!below_floor) {
          give_up(t, ball_refusal(*z, fc.p));
          return;
        }
        auto why = zone_repair(*z, f, fc.p);
        if (!why) return;
        // Nothing went in: an encroached subsegment is still split as Fig. 2 would.
        if (ok) {
          give_up(t, std::move(*why));
          return;
        }
      }
    insert_on_facet(fc, hint, t, below_floor, r2, f);
    pending_copies_.clear();  // not inserted: no copies
  }

  // Rotation copies waiting for their point's step (refine_subfacet, after_insert): the
  // point may still give way to a subsegment split, whose step must not take them.
  std::vector<AxisZones::Copy> pending_copies_;
  Point pending_point_{};
  double pending_size2_ = 0;

  enum class OnFacet { Inserted, SplitInstead, Failed };

  // Inserts the point of facet cavity fc (Fig. 2's Refine(f) once the point is chosen), or
  // splits the subsegment it encroaches. `of`: the subfacet whose circumcenter it is, a
  // failure given up on t's behalf; kNone: a rotation copy, whose failure is only counted
  // by the caller. `size2`: the squared size of the element refined.
  OnFacet insert_on_facet(const surface::FacetCavity& fc, TetId hint, TetId t, bool below_floor,
                          double size2, std::uint32_t of) {
    const bool quiet = of == kNone;
    const auto what = [&] { return "circumcenter of subfacet " + std::to_string(of); };
    const auto fail = [&](std::string why) {
      if (!quiet) give_up(t, std::move(why));
      return OnFacet::Failed;
    };
    const auto split_instead = [&](std::uint32_t sub) {
      if (auto why = split(sub, hint, below_floor)) return fail(std::move(*why));
      return OnFacet::SplitInstead;
    };
    if (fc.status == surface::CavityStatus::Encroaches && !fc.encroached.empty())
      return split_instead(fc.encroached.front());
    if (fc.status != surface::CavityStatus::Ok)
      return fail("refine.subfacet: the " + what() + " of " + m_.surf.facet_name(fc.facet) +
                  " cannot be inserted (" + cavity_status_name(fc.status) + ")");
    bool outside = false;
    if (!plan(fc.p, hint, cav2_, outside))
      return fail("refine.subfacet: " + what() + " " + point_text(fc.p) + " is already a vertex");
    if (const auto s = closure_encroached_subsegment(m_, {cav2_.conflict, cav2_.ring}, fc.p))
      return split_instead(*s);
    res_.stats.h = std::min(res_.stats.h, std::sqrt(size2 / 2));
    const std::uint32_t sv = m_.surf.add_vertex(fc.p, {HomeKind::Facet, fc.facet});
    commit_facet_cavity(m_.surf, fc, sv);
    const VertexId v = insert(cav2_, sv);
    if (!quiet) ++res_.stats.subfacet_circumcenters;
    after_insert(v, "subfacet", size2);
    return OnFacet::Inserted;
  }

  // A rotation copy of a facet vertex near a sharp axis (refine/axis_zones.hpp), with
  // Fig. 2's rule: a subsegment it encroaches is split first (below the protected lengths,
  // as a repair), then the copy is tried again. Nothing is reported when it cannot go in
  // (outside its facet, on a vertex): the refinement goes on without it.
  void insert_copy(const AxisZones::Copy& c, double size2) {
    // The walk starts at the axis vertex nearest the copy (it stays one after splits).
    std::uint32_t from = 0;
    double best = std::numeric_limits<double>::infinity();
    for (const std::uint32_t v : m_.surf.chain(c.axis))
      if (const double d2 = domain::dist2_point_point(m_.surf.point(v), c.p); d2 < best) {
        best = d2;
        from = v;
      }
    // The copy lies in its wall: the facet through the axis (tried first), or, when the
    // wall lies exactly on one plane, another of its facets at an end of the axis.
    std::vector<std::uint32_t> order{c.facet};
    if (zones_.exact_wall(c.facet))
      for (const std::uint32_t g : zones_.wall(c.facet))
        if (g != c.facet) order.push_back(g);
    for (int attempt = 0; attempt < 4 && !at_cap(); ++attempt) {
      // Only a ball's shell goes in an active protecting ball, and a split the last
      // attempt made instead can have turned one on.
      if (in_active_ball(c.p)) break;
      std::optional<surface::FacetLocation> loc;
      std::uint32_t facet = c.facet;
      for (const std::uint32_t g : order) {
        std::uint32_t start = from;
        if (g != c.facet) {
          const surface::SurfaceSegment& axis = m_.surf.segments[c.axis];
          const auto holds = [&](std::uint32_t v) {
            for (const std::uint32_t sg : m_.surf.facets[g].segments)
              if (m_.surf.segments[sg].a == v || m_.surf.segments[sg].b == v) return true;
            return false;
          };
          start = holds(axis.a) ? axis.a : axis.b;
          if (!holds(start)) continue;
        }
        loc = surface::locate_in_facet(m_.surf, g, c.p, start);
        if (loc) {
          facet = g;
          break;
        }
      }
      if (!loc || loc->on_subsegment) break;
      const surface::FacetCavity fc =
          surface::build_facet_cavity(m_.surf, facet, c.p, {loc->subfacet}, std::nullopt);
      const TetId hint = m_.dt.last_tet();
      const OnFacet r = insert_on_facet(fc, hint, kNoTet, /*below_floor=*/true, size2, kNone);
      if (r == OnFacet::Inserted) {
        ++res_.stats.axis_copies;
        return;
      }
      if (r != OnFacet::SplitInstead) break;
    }
    ++res_.stats.axis_copies_dropped;
  }

  // The protecting balls around acute vertices (refine/vertex_zones.hpp).

  // Per input vertex of D, the distance to its nearest other vertex in T (one pass over
  // T's edges). A ball's first radius is at most the protected length at its vertex (the
  // local d of its subsegments, as the split guard's) and half this, so it holds its vertex
  // alone.
  std::vector<double> nearest_at_start() const {
    std::vector<double> near2(m_.surf.vertex_count(), std::numeric_limits<double>::infinity());
    const TetStore& s = m_.dt.store();
    const auto input = [&](VertexId v) {
      const std::uint32_t sv = m_.d2s[v];
      return sv != kNone && m_.surf.home(sv).kind == HomeKind::Input ? sv : kNone;
    };
    for (TetId t = 0; t < s.slots(); ++t) {
      if (!s.is_alive(t) || s.is_ghost(t)) continue;
      for (const auto& e : tables::kEdgeVertex) {
        const VertexId a = s.vertex(t, e[0]), b = s.vertex(t, e[1]);
        const double d2 = domain::dist2_point_point(pt(a), pt(b));
        for (const std::uint32_t sv : {input(a), input(b)})
          if (sv != kNone) near2[sv] = std::min(near2[sv], d2);
      }
    }
    for (double& x : near2) x = std::sqrt(x);
    return near2;
  }

  // Half the distance from D's vertex v to its nearest vertex in T (one of its neighbours
  // there); 0 when v is not in T.
  double half_nearest(std::uint32_t v) {
    const VertexId tv = v < m_.s2d.size() ? m_.s2d[v] : kNone;
    if (tv == kNone) return 0;
    const Location loc = m_.dt.locate(pt(tv), m_.dt.last_tet());
    if (loc.kind != Location::Kind::OnVertex) return 0;
    vertex_star(m_, tv, loc.tet, around_);
    const TetStore& s = m_.dt.store();
    double best = std::numeric_limits<double>::infinity();
    for (const TetId t : around_)
      for (int i = 0; i < 4; ++i) {
        const VertexId w = s.vertex(t, i);
        if (w == tv || w == kGhostVertex) continue;
        best = std::min(best, domain::dist2_point_point(pt(w), pt(tv)));
      }
    return std::sqrt(best) / 2;
  }

  // The ball whose open ball holds p, dormant or active.
  std::optional<std::uint32_t> ball_of(const Point& p) const {
    if (balls_.empty()) return std::nullopt;
    return balls_.holding(p);
  }
  // The active ball holding p (none is looked up while no ball is on: most runs).
  std::optional<std::uint32_t> active_ball_of(const Point& p) const {
    if (!balls_.any_active()) return std::nullopt;
    const auto z = balls_.holding(p);
    return z && balls_.active(*z) ? z : std::nullopt;
  }
  bool in_active_ball(const Point& p) const { return active_ball_of(p).has_value(); }

  // The active ball holding p, the point of a step. A repair's point in a dormant ball
  // activates it (its radius then at most half the distance from its vertex to the nearest
  // other, so that it holds its vertex alone: the first deep repair there comes before any
  // vertex near it), and p counts only if it is still inside.
  std::optional<std::uint32_t> ball_for(const Point& p, bool repair) {
    const auto z = ball_of(p);
    if (!z || balls_.active(*z)) return z;
    if (!repair) return std::nullopt;
    const std::uint32_t v = balls_.vertex(*z);
    const double bound = std::min(half_nearest(v), unrelated_distance(v) / 2);
    if (!(bound > 0)) return std::nullopt;  // v not found in T: the ball stays dormant
    balls_.activate(*z, bound);
    ++res_.stats.ball_zones;
    return ball_of(p);
  }

  // The distance from input vertex v to the subsegments of segments not through v and to
  // the subfacets of facets not containing it: a ball no wider than half of it meets only
  // wedges of the facets through v (a scan of D, once per ball turned on).
  double unrelated_distance(std::uint32_t v) const {
    const Point& x = m_.surf.point(v);
    std::vector<std::uint8_t> at_v(m_.surf.facets.size(), 0);
    std::vector<std::uint8_t> seg_at_v(m_.surf.segments.size(), 0);
    for (std::uint32_t s = 0; s < m_.surf.segments.size(); ++s) {
      const surface::SurfaceSegment& g = m_.surf.segments[s];
      if (g.a != v && g.b != v) continue;
      seg_at_v[s] = 1;
      for (const std::uint32_t f : g.facets) at_v[f] = 1;
    }
    double best = std::numeric_limits<double>::infinity();
    for (const Subsegment& g : m_.surf.subsegments())
      if (!seg_at_v[g.segment])
        best = std::min(best, domain::dist2_point_segment(x, m_.surf.point(g.v[0]),
                                                          m_.surf.point(g.v[1])));
    for (const Subfacet& t : m_.surf.subfacets())
      if (t.alive && !at_v[t.facet])
        best = std::min(best, domain::dist2_point_triangle(x, m_.surf.point(t.v[0]),
                                                           m_.surf.point(t.v[1]),
                                                           m_.surf.point(t.v[2])));
    return std::sqrt(best);
  }

  std::string ball_refusal(std::uint32_t z, const Point& p) const {
    std::ostringstream os;
    os.precision(6);
    os << "refine.ball: " << point_text(p) << " lies in the protecting ball of acute input vertex "
       << balls_.vertex(z) << " (radius " << balls_.radius(z)
       << "), where only the ball's shell goes in";
    return os.str();
  }

  // A repair whose point p falls in ball z, for subfacet f (kNone: a subsegment's split):
  // the zone's rules. The reason when nothing can go in.
  std::optional<std::string> zone_repair(std::uint32_t z, std::uint32_t f, const Point& p) {
    if (filling_) return ball_refusal(z, p);  // the shell's own repairs wait for it
    const std::size_t before = m_.dt.num_points();
    const auto none_went_in = [&]() -> std::optional<std::string> {
      if (m_.dt.num_points() > before) return std::nullopt;
      return "refine.ball: no vertex of the shell of the protecting ball of acute input vertex " +
             std::to_string(balls_.vertex(z)) + " could be inserted";
    };
    if (f != kNone) {
      const Subfacet& x = m_.surf.subfacet(f);
      for (int i = 0; i < 3; ++i)
        if (const auto piece = balls_.split_piece(z, x.facet, x.v[(i + 1) % 3], x.v[(i + 2) % 3])) {
          filling_ = true;
          insert_shell_point(z, *piece);
          filling_ = false;
          return none_went_in();
        }
    }
    if (balls_.filled(z) &&
        !balls_.shrink(z, kPrecisionFloor * magnitude({m_.surf.point(balls_.vertex(z))}))) {
      std::ostringstream os;
      os.precision(6);
      os << "refine.precision: the protecting ball of acute input vertex " << balls_.vertex(z)
         << " cannot shrink below radius " << balls_.radius(z)
         << " (2^-40 of its coordinates, or of its first radius)";
      return os.str();
    }
    filling_ = true;
    balls_.set_filled(z);
    ++res_.stats.ball_fills;
    for (const VertexZones::ShellPoint& sp : balls_.shell(z)) {
      if (at_cap()) break;
      insert_shell_point(z, sp);
    }
    filling_ = false;
    return none_went_in();
  }

  // Inserts shell point sp of ball z (on a segment: a split of the subsegment at the ball's
  // vertex; in a facet: a vertex of the facet) and records its vertex. Nothing is reported
  // when it cannot go in: the repairs that follow see what is missing.
  void insert_shell_point(std::uint32_t z, const VertexZones::ShellPoint& sp) {
    const std::uint32_t v = balls_.vertex(z);
    const TetId hint = m_.dt.last_tet();
    if (sp.segment != VertexZones::kNone) {
      for (const std::uint32_t g : m_.surf.vertex_subsegments(v)) {
        const Subsegment& x = m_.surf.subsegment(g);
        if (x.segment != sp.segment) continue;
        const std::uint32_t w = x.v[0] == v ? x.v[1] : x.v[0];
        const double l = std::sqrt(domain::dist2_point_point(m_.surf.point(w), m_.surf.point(v)));
        if (l <= balls_.radius(z) * (1 + 0x1p-20)) {  // the shell's point is already there
          balls_.record(z, sp, w);
          return;
        }
        const std::size_t before = m_.surf.vertex_count();
        if (!split_at(g, sp.p, hint, /*below_floor=*/true) && m_.surf.vertex_count() > before) {
          balls_.record(z, sp, static_cast<std::uint32_t>(before));
          ++res_.stats.ball_vertices;
        }
        return;
      }
      return;
    }
    const Point p = surface::place_on_facet(m_.surf.facets[sp.facet].chart, sp.p);
    const auto loc = surface::locate_in_facet(m_.surf, sp.facet, p, v);
    if (!loc || loc->on_subsegment) return;
    const surface::FacetCavity fc =
        surface::build_facet_cavity(m_.surf, sp.facet, p, {loc->subfacet}, std::nullopt);
    const std::size_t before = m_.surf.vertex_count();
    const double r = balls_.radius(z);
    if (insert_on_facet(fc, hint, kNoTet, /*below_floor=*/true, r * r, kNone) ==
            OnFacet::Inserted &&
        m_.surf.vertex_count() > before) {
      balls_.record(z, sp, static_cast<std::uint32_t>(before));
      ++res_.stats.ball_vertices;
    }
  }

  // An element of `holder` (a tet of p's cavity) that p encroaches, refined on behalf of t.
  bool refine_element_of(TetId holder, TetId t, const Point& p) {
    const std::span<const TetId> own(&holder, 1);
    if (const auto s = closure_encroached_subsegment(m_, {own}, p)) {
      if (auto why = split(*s, t)) refuse(t, std::move(*why));
      return true;
    }
    if (const auto f = closure_encroached_subfacet(m_, {own}, p)) {
      refine_subfacet(*f, t, t);
      return true;
    }
    return false;
  }

  // Outside the theory, before p's cavity is built: the tets a visibility walk from t
  // towards p enters while each conflicts with p are tets of p's cavity, so their elements
  // are in its closure, and one that p encroaches is refined as Fig. 2 would (the order
  // among encroached elements differs; outside the theory it carries no proof). A skinny
  // tet at a sharp angle has its circumcenter far off, beyond a facet it encroaches, and
  // its cavity spans much of T, built again for every tet a guard refuses: with a 5-degree
  // wedge that cost grew quadratically (runs past 120 s). The walk stops at a tet that
  // holds p, at one that does not conflict, at the hull, or after kPathSteps tets; the full
  // cavity then decides.
  static constexpr int kPathSteps = 64;
  bool refine_along_path(TetId t, const Point& p) {
    const TetStore& s = m_.dt.store();
    TetId cur = t;
    int entered = -1;
    for (int step = 0; step < kPathSteps; ++step) {
      if (refine_element_of(cur, t, p)) return true;
      const VertexId* v = s.vertices(cur);
      int crossed = -1;
      for (int f = 0; f < 4 && crossed < 0; ++f) {
        if (f == entered) continue;
        const auto& fv = tables::kFaceVertex[f];
        if (orient3d(pt(v[fv[0]]), pt(v[fv[1]]), pt(v[fv[2]]), p) == Sign::Positive) crossed = f;
      }
      if (crossed < 0) return false;  // cur holds p
      const HalfFace h = s.opposite(cur, crossed);
      const TetId n = tet_of(h);
      if (s.is_ghost(n) || !in_conflict(s, m_.dt.points(), n, p)) return false;
      cur = n;
      entered = face_of(h);
    }
    return false;
  }

  void refine_tet(TetId t) {
    // issue #3: refine/flat.hpp; a flat tet's repair (rule 1) is not held by the repair
    // floor, only by what doubles can place and by the facet's planarity gap (refine/flat.hpp:
    // a 3-degree notch printed with 7 digits made 72,000 flat repairs at circumradii of
    // 1e-9 to 4e-12 before this, and never ended).
    if (const SubfacetPicks f = subfacets_to_refine(m_, t); f.flat) {
      if (std::string why = below_precision(*f.flat); !why.empty()) {
        refuse(t, std::move(why));
        return;
      }
      if (std::string why = within_planarity_gap(m_.surf, *f.flat); !why.empty()) {
        refuse(t, std::move(why));
        return;
      }
      ++res_.stats.flat_repairs;
      refine_subfacet(*f.flat, t, t, /*below_floor=*/true);
      return;
    } else if (f.any) {
      ++res_.stats.face_repairs;
      refine_subfacet(*f.any, t, t);
      return;
    }
    const VertexId* v = m_.dt.store().vertices(t);
    const Point &a = pt(v[0]), &b = pt(v[1]), &c = pt(v[2]), &d = pt(v[3]);
    const Point p = construct::circumcenter(a, b, c, d);
    if (const auto z = active_ball_of(p)) {
      refuse(t, ball_refusal(*z, p));
      return;
    }
    // Outside the theory, an element that p encroaches on the way from t to p is refined
    // without building p's cavity (refine_along_path).
    if (guard_.active() && refine_along_path(t, p)) return;
    bool outside = false;
    std::optional<ClosureScan::Hit> hit;
    if (!(guard_.active() ? plan_scanned(p, t, outside, hit) : plan(p, t, cav_, outside))) {
      refuse(t, "refine.tet: circumcenter " + point_text(p) + " is already a vertex");
      return;
    }
    if (guard_.active()) {
      // Outside the theory: the first element of D in the cavity's order that p
      // encroaches or the cavity would take out of T (refine/closure.hpp ClosureScan).
      if (hit) {
        if (!hit->subsegment)
          refine_subfacet(hit->id, t, t);
        else if (auto why = split(hit->id, t))
          refuse(t, std::move(*why));
        return;
      }
    } else if (const auto s = closure_encroached_subsegment(m_, {cav_.conflict, cav_.ring}, p)) {
      if (auto why = split(*s, t)) refuse(t, std::move(*why));
      return;
    } else if (const auto f = closure_encroached_subfacet(m_, {cav_.conflict, cav_.ring}, p)) {
      refine_subfacet(*f, t, t);
      return;
    }
    // An element of D the cavity would take out of T is refined first, as if p encroached
    // it (refine/conformity.hpp); outside the theory the scan above found none.
    if (guard_.active()) {
      conformity_.doomed_none();
    } else {
      const EncroachedLists& doomed = conformity_.doomed(m_, cav_);
      if (!doomed.subsegments.empty()) {
        if (auto why = split(doomed.subsegments.front().id, t)) refuse(t, std::move(*why));
        return;
      }
      if (!doomed.subfacets.empty()) {
        refine_subfacet(doomed.subfacets.front().id, t, t);
        return;
      }
    }
    if (outside) {
      refuse(t, "refine.outside: circumcenter " + point_text(p) +
                    " lies outside the domain but encroaches no subsegment or subfacet of "
                    "its cavity's closure");
      return;
    }
    const double r2 = construct::circumradius2(a, b, c, d);
    res_.stats.h = std::min(res_.stats.h, std::sqrt(r2) / 2);
    const VertexId nv = insert(cav_, kNone, true);
    ++res_.stats.tet_circumcenters;
    after_insert(nv, "tet", r2);
  }
};

}  // namespace

void set_domain(RefineOptions& o, const domain::DomainAnalysis& an) {
  o.d = an.report.feature.d;
  o.admissible = an.report.admissible;
  o.exact_theory = theorem_applies(an);
  o.acute_vertices = acute_vertices(an.report);
  o.cylinders = protecting_cylinders(an);
  // Exactly planar input keeps the strip test's 1e-9 (refine/axis_zones.hpp).
  o.vertex_uncertainty = an.report.tolerance_facets.empty() && an.report.right_within_tolerance == 0
                             ? 0.0
                             : domain::positional_uncertainty(an.domain);
  o.region_volumes = domain::RegionVolumes::of(an.domain);
}

std::optional<double> smallest_volume(const RefineOptions& o) {
  std::optional<double> v = o.max_volume;
  if (o.region_volumes) v = std::min(v.value_or(o.region_volumes->smallest()), o.region_volumes->smallest());
  return v;
}

bool theorem_applies(const domain::DomainAnalysis& an) {
  const domain::DomainReport& r = an.report;
  if (!r.admissible || r.right_within_tolerance != 0 || !r.tolerance_facets.empty()) return false;
  const Plc& plc = an.domain.plc;
  for (const PlcFacet& f : plc.facets) {
    bool parallel = false;
    for (int k = 0; k < 3 && !parallel; ++k) {
      std::optional<double> c;
      parallel = true;
      for (const auto& polygon : f.polygons)
        for (std::uint32_t v : polygon) {
          if (!c) c = plc.points[v][k];
          parallel = parallel && plc.points[v][k] == *c;
        }
    }
    if (!parallel) return false;
  }
  return true;
}

// Theorem 1's h, a priori. The proof of Lemma 1 holds for any h such that every edge of the
// initial mesh is longer than h and every tet refined for its size has circumradius > 2h
// (the encroachment and quality steps carry the bound from there). So h is the smallest of
// the shortest edge of T_o inside Omega, L/2 for the circumradius bound L, and, for the
// volume bound V, half the smallest circumradius a tet of volume > V can have: the regular
// tet is the largest in its circumsphere (volume 8R^3/(9*sqrt(3))), so R > (9*sqrt(3)V/8)^(1/3).
// Computed in floating point, then lowered by 2^-30 relative: any smaller h is as valid.
double theorem_h(double shortest_edge, const RefineOptions& o) {
  double h = shortest_edge;
  if (o.size) h = std::min(h, *o.size / 2);
  if (const auto v = smallest_volume(o)) h = std::min(h, std::cbrt(9 * std::sqrt(3.0) * *v / 8) / 2);
  return h * (1 - 0x1p-30);
}

double shortest_inside_edge(const VolumeMesh& m) {
  const TetStore& s = m.dt.store();
  double e2 = std::numeric_limits<double>::infinity();
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t) || !m.is_inside(t)) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Point& a = m.dt.point(s.vertex(t, i));
        const Point& b = m.dt.point(s.vertex(t, j));
        const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
        e2 = std::min(e2, dx * dx + dy * dy + dz * dz);
      }
  }
  return std::sqrt(e2);
}

RefineResult refine(VolumeMesh& m, const RefineOptions& options) {
  return Refiner(m, options).run();
}

}  // namespace pdr::refine
