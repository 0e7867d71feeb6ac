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

#include "geom/encroach.hpp"
#include "refine/vertex_zones.hpp"

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

}  // namespace
}  // namespace pdr::refine
