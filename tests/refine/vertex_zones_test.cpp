// Protecting balls around acute vertices (refine/vertex_zones.hpp): the sampling of a
// vertex's arcs on the unit sphere, and the lemma the balls rest on. On random cones of
// facets around a vertex (spherical polygons with face angles down to half a degree and
// sharp dihedrals), sample_arcs ends within its cap, every piece is at most 30 degrees,
// and no sample lies strictly inside the diametral cap of another arc's piece (checked
// with dot products, not the sampler's own angle function). Arcs that share an end get
// the same first split from it (concentric shells on the sphere). Then the lemma, with
// exact predicates: with the samples put on a sphere of radius r around v, the equatorial
// ball of a fan triangle (v, a, b) holds a shell vertex exactly when the vertex's
// direction is in the piece's cap (so none with these samples), and it does hold points
// inside the sphere along the piece (the ball's invariant keeps those empty): what makes
// the fans faces of the Delaunay tetrahedralization whatever lies outside the sphere's
// thin lens.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "domain/analysis.hpp"
#include "geom/encroach.hpp"
#include "refine/vertex_zones.hpp"
#include "support/outside_fixtures.hpp"
#include "surface/init.hpp"

namespace pdr::refine {
namespace {

constexpr double kPi = std::numbers::pi;

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point unit(Point x) {
  const double n = std::sqrt(dot(x, x));
  for (double& c : x) c /= n;
  return x;
}
double angle(const Point& a, const Point& b) {
  return std::acos(std::clamp(dot(unit(a), unit(b)), -1.0, 1.0));
}

// The arc from direction a to direction b the short way (a != -b).
SphereArc arc(const Point& a, const Point& b) {
  SphereArc s;
  s.e1 = unit(a);
  const double t = dot(unit(b), s.e1);
  s.e2 = unit({b[0] - t * s.e1[0], b[1] - t * s.e1[1], b[2] - t * s.e1[2]});
  s.length = angle(a, b);
  return s;
}

// A cone of facets around a vertex: n edge directions around the z axis, at polar angles
// `polar[i]` and azimuths increasing; the arcs join consecutive ones (a pyramid's apex,
// crumpled when the azimuths crowd and the polar angles differ).
struct Cone {
  std::vector<Point> dirs;
  std::vector<SphereArc> arcs;
};

rc::Gen<Cone> gen_cone() {
  return rc::gen::exec([] {
    const int n = *rc::gen::inRange(4, 9);
    // Gaps in azimuth: some crowded down to a fraction of a degree, the short arcs going
    // around the axis (every gap below 170 degrees), so that they do not cross.
    std::vector<double> gap;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const bool crowd = *rc::gen::inRange(0, 3) == 0;
      gap.push_back(crowd ? *rc::gen::inRange(1, 40) / 1000.0 : *rc::gen::inRange(300, 1000) / 1000.0);
      sum += gap.back();
    }
    std::vector<double> az{0};
    for (int i = 0; i < n; ++i) {
      gap[i] *= 2 * kPi / sum;
      RC_PRE(gap[i] < 170 * kPi / 180);
      if (i + 1 < n) az.push_back(az.back() + gap[i]);
    }
    Cone c;
    for (int i = 0; i < n; ++i) {
      const double polar = *rc::gen::inRange(5, 80) * kPi / 180;
      c.dirs.push_back({std::sin(polar) * std::cos(az[i]), std::sin(polar) * std::sin(az[i]),
                        std::cos(polar)});
    }
    for (int i = 0; i < n; ++i) c.arcs.push_back(arc(c.dirs[i], c.dirs[(i + 1) % n]));
    return c;
  });
}

RC_GTEST_PROP(SampleArcs, PiecesAreShortAndNoSampleIsInAnotherPiecesCap, ()) {
  const Cone c = *gen_cone();
  const auto t = sample_arcs(c.arcs, c.dirs, kPi / 6, 1024);
  RC_ASSERT(t.has_value());
  std::vector<Point> all = c.dirs;
  for (std::size_t a = 0; a < c.arcs.size(); ++a) {
    RC_ASSERT((*t)[a].front() == 0.0);
    RC_ASSERT((*t)[a].back() == c.arcs[a].length);
    for (const double x : (*t)[a]) all.push_back(c.arcs[a].at(x));
  }
  for (std::size_t a = 0; a < c.arcs.size(); ++a)
    for (std::size_t i = 0; i + 1 < (*t)[a].size(); ++i) {
      const double t0 = (*t)[a][i], t1 = (*t)[a][i + 1];
      RC_ASSERT(t1 > t0);
      RC_ASSERT(t1 - t0 <= kPi / 6);
      const Point p0 = c.arcs[a].at(t0), p1 = c.arcs[a].at(t1), mid = c.arcs[a].at((t0 + t1) / 2);
      const double half = (t1 - t0) / 2;
      for (const Point& s : all) {
        if (angle(s, p0) < 1e-7 * half || angle(s, p1) < 1e-7 * half) continue;
        RC_ASSERT(angle(s, mid) >= half * (1 - 1e-6));
      }
    }
}

TEST(SampleArcs, ArcsSharingAnEndGetTheSameAnglesFromIt) {
  // Two facets along one segment (direction z) at a 5-degree dihedral, of face angles 20
  // and 45 degrees at the vertex: the longer arc's middle encroaches the shorter's piece,
  // and the first splits from the shared end go to the same power of two on both.
  const double dihedral = 5 * kPi / 180;
  const Point s{0, 0, 1};
  const auto at = [&](double phi, double polar) {
    return Point{std::sin(polar) * std::cos(phi), std::sin(polar) * std::sin(phi), std::cos(polar)};
  };
  const Point a = at(0, 20 * kPi / 180), b = at(dihedral, 45 * kPi / 180);
  const auto t = sample_arcs({arc(s, a), arc(s, b)}, {s, a, b}, kPi / 6, 1024);
  ASSERT_TRUE(t.has_value());
  ASSERT_GT((*t)[0].size(), 2u);
  ASSERT_GT((*t)[1].size(), 2u);
  EXPECT_EQ((*t)[0][1], (*t)[1][1]);
  EXPECT_EQ((*t)[0][1], std::exp2(std::round(std::log2((*t)[0][1]))));
}

TEST(SampleArcs, AnArcsEndOffItsSegmentDoesNotCrowdTheOtherArc) {
  // Two facets at right angles along one segment (direction z). The second facet is
  // printed with few digits: its chart's plane misses the segment by 1e-7 radians, so its
  // arc starts at the segment's direction projected onto that plane, 1e-7 along the first
  // arc. The shell vertex at that end is the segment's (direction z), not the projection:
  // the projection must not encroach the first arc's end piece (it did, and the pieces
  // there split down to 1e-11 of the shell's radius: a slot's apex printed with 7 digits,
  // tests/regress/outside-slot-triangle-walls-rotated-7-digits-runaway.poly).
  const Point s{0, 0, 1};
  const auto at = [&](double phi, double polar) {
    return Point{std::sin(polar) * std::cos(phi), std::sin(polar) * std::sin(phi), std::cos(polar)};
  };
  const Point a = at(0, 60 * kPi / 180), b = at(kPi / 2, 45 * kPi / 180);
  const Point s_off = at(0, 1e-7);
  const auto t = sample_arcs({arc(s, a), arc(s_off, b)}, {s, a, b}, kPi / 6, 1024);
  ASSERT_TRUE(t.has_value());
  EXPECT_LE((*t)[0].size(), 8u);
  EXPECT_LE((*t)[1].size(), 8u);
  EXPECT_GT((*t)[0][1], 1e-3);  // no sample crowding the shared end
}

// The lemma: with the shell vertices v + r u (u the samples), a shell vertex is strictly
// inside the equatorial ball of the fan triangle (v, a, b) exactly when its direction is
// strictly inside the piece's diametral cap (the ball meets the sphere in that cap), so
// with the sampler's samples none is; and a point inside the sphere along the piece's
// middle is inside the ball (an intruder there would take the fan out of T).
RC_GTEST_PROP(VertexZones, FanTrianglesHaveEmptyEquatorialBalls, ()) {
  const Cone c = *gen_cone();
  const auto t = sample_arcs(c.arcs, c.dirs, kPi / 6, 1024);
  RC_ASSERT(t.has_value());
  const Point v{0.5, -1.75, 2.25};
  const double r = std::exp2(-*rc::gen::inRange(0, 20));
  const auto on_shell = [&](const Point& u) {
    return Point{v[0] + r * u[0], v[1] + r * u[1], v[2] + r * u[2]};
  };
  std::vector<Point> shell;
  for (std::size_t a = 0; a < c.arcs.size(); ++a)
    for (const double x : (*t)[a]) shell.push_back(on_shell(c.arcs[a].at(x)));
  for (std::size_t a = 0; a < c.arcs.size(); ++a)
    for (std::size_t i = 0; i + 1 < (*t)[a].size(); ++i) {
      const double t0 = (*t)[a][i], t1 = (*t)[a][i + 1];
      const Point pa = on_shell(c.arcs[a].at(t0)), pb = on_shell(c.arcs[a].at(t1));
      const Point m = c.arcs[a].at((t0 + t1) / 2);
      const Point inner{v[0] + 0.9 * r * m[0], v[1] + 0.9 * r * m[1], v[2] + 0.9 * r * m[2]};
      RC_ASSERT(in_equatorial_ball(v, pa, pb, inner) == Sign::Positive);
      const double half = (t1 - t0) / 2;
      for (std::size_t k = 0; k < shell.size(); ++k) {
        // The cap's rim, where rounding decides, is left out: the sampler keeps samples
        // off it by a relative 1e-9 only (a vertex there is a lens vertex, which splits
        // the piece). Shared ends are the piece's own vertices.
        const Point u{(shell[k][0] - v[0]) / r, (shell[k][1] - v[1]) / r, (shell[k][2] - v[2]) / r};
        const double d = angle(u, m);
        if (d < half * (1 - 1e-6))
          RC_ASSERT(in_equatorial_ball(v, pa, pb, shell[k]) == Sign::Positive);
        else if (d > half * (1 + 1e-6))
          RC_ASSERT(in_equatorial_ball(v, pa, pb, shell[k]) == Sign::Negative);
      }
    }
}

// A zone on a real surface mesh: the apex of a pyramid (n triangle facets meeting there, a
// sharp apex when tall), turned and moved to negative coordinates. The ball holds what is
// within its radius (a power of two below the bound) and nothing beyond; every shell point
// lies on the sphere, on its facet's plane and inside its facet (the wedge); a piece
// between consecutive shell vertices of a facet splits on the sphere between them, a pair
// that is no piece does not; shrinking halves the radius and empties the shell.
RC_GTEST_PROP(VertexZones, ShellsOfAPyramidsApexLieOnTheSphereInTheirFacets, ()) {
  const int n = *rc::gen::inRange(3, 8);
  const double height = *rc::gen::inRange(5, 80) / 10.0;
  Plc plc = pdr::test::rotated(pdr::test::pyramid(n, height), *rc::gen::inRange(0, 628) / 100.0,
                               *rc::gen::inRange(0, 628) / 100.0, *rc::gen::inRange(0, 628) / 100.0);
  for (Point& p : plc.points) p = {p[0] - 7.25, p[1] - 3.5, p[2] - 11};
  const domain::DomainAnalysis an = domain::analyze(plc);
  const surface::SurfaceMesh m = surface::init_surface(an).mesh;
  const auto apex = static_cast<std::uint32_t>(n);
  VertexZones zones(m, {apex}, [](std::uint32_t) { return 0.01; });
  RC_ASSERT(zones.size() == 1u);
  const double r = zones.radius(0);
  RC_ASSERT(r == 0x1p-7);
  const Point a = m.point(apex);
  const auto off = [&](double t) {
    const Point e = unit({1, 2, 3});
    return Point{a[0] + t * e[0], a[1] + t * e[1], a[2] + t * e[2]};
  };
  RC_ASSERT(zones.holding(off(0.9 * r)) == std::optional<std::uint32_t>(0));
  RC_ASSERT(!zones.holding(off(1.1 * r)).has_value());
  RC_ASSERT(!zones.holding(m.point(0)).has_value());
  const auto shell = zones.shell(0);
  std::uint32_t id = 100000;
  std::vector<std::pair<VertexZones::ShellPoint, std::uint32_t>> recorded;
  for (const auto& sp : shell) {
    const Point d{sp.p[0] - a[0], sp.p[1] - a[1], sp.p[2] - a[2]};
    RC_ASSERT(std::abs(std::sqrt(dot(d, d)) - r) <= 1e-12 * r);
    if (sp.facet != VertexZones::kNone) {
      // Inside facet sp.facet = triangle (i, i + 1, apex): on its plane, within its wedge.
      const surface::SurfaceFacet& f = m.facets[sp.facet];
      const Point nrm = unit(f.chart.normal);
      RC_ASSERT(std::abs(dot(nrm, d)) <= 1e-9 * r);
      std::vector<Point> sides;
      for (const std::uint32_t g : f.segments) {
        const auto& seg = m.segments[g];
        if (seg.a == apex || seg.b == apex) {
          const Point& o = m.point(seg.a == apex ? seg.b : seg.a);
          sides.push_back(unit({o[0] - a[0], o[1] - a[1], o[2] - a[2]}));
        }
      }
      RC_ASSERT(sides.size() == 2u);
      const double whole = angle(sides[0], sides[1]);
      RC_ASSERT(std::abs(angle(sides[0], d) + angle(d, sides[1]) - whole) <= 1e-9);
    }
    zones.record(0, sp, id);
    recorded.emplace_back(sp, id++);
  }
  zones.set_filled(0);
  // The samples of the first facet with inner samples, in angle from one of its sides.
  for (const auto& [sp, vid] : recorded) {
    if (sp.facet == VertexZones::kNone) continue;
    std::vector<std::pair<double, std::uint32_t>> order;  // angle from the first side, id
    std::vector<std::pair<Point, std::uint32_t>> ends;
    for (const auto& [q, qid] : recorded)
      if (q.segment != VertexZones::kNone &&
          std::binary_search(m.segments[q.segment].facets.begin(), m.segments[q.segment].facets.end(), sp.facet))
        ends.emplace_back(q.p, qid);
    RC_ASSERT(ends.size() == 2u);
    const Point s0{ends[0].first[0] - a[0], ends[0].first[1] - a[1], ends[0].first[2] - a[2]};
    for (const auto& [q, qid] : recorded)
      if (q.facet == sp.facet || qid == ends[0].second || qid == ends[1].second)
        order.emplace_back(angle(s0, {q.p[0] - a[0], q.p[1] - a[1], q.p[2] - a[2]}), qid);
    std::sort(order.begin(), order.end());
    const auto piece = zones.split_piece(0, sp.facet, order[0].second, order[1].second);
    RC_ASSERT(piece.has_value());
    const Point d{piece->p[0] - a[0], piece->p[1] - a[1], piece->p[2] - a[2]};
    RC_ASSERT(std::abs(std::sqrt(dot(d, d)) - r) <= 1e-12 * r);
    RC_ASSERT(angle(s0, d) > order[0].first && angle(s0, d) < order[1].first);
    RC_ASSERT(!zones.split_piece(0, sp.facet, order.front().second, order.back().second));
    break;
  }
  RC_ASSERT(zones.shrink(0, 0));
  RC_ASSERT(zones.radius(0) == r / 2);
  RC_ASSERT(!zones.filled(0));
  RC_ASSERT(!zones.holding(off(0.6 * r)).has_value());
}

}  // namespace
}  // namespace pdr::refine
