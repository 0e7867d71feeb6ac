// validity.overlap against a brute-force oracle: every pair of tets, all 44 separating-axis
// candidates (8 face normals, 36 edge cross products), projections compared in GMP
// rationals; no grid, no pruning by shared vertices, no sign shortcuts. Both methods of
// the checker are held to it: the degree argument (degree.cpp) and the pairwise test.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include "check_test_util.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

using Q = mpq_class;
using V = std::array<Q, 3>;

V qv(const Point& p) { return {Q(p[0]), Q(p[1]), Q(p[2])}; }
V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool interiors_intersect(const MeshData& m, const Tet& s, const Tet& t) {
  std::array<V, 4> a, b;
  for (int i = 0; i < 4; ++i) a[i] = qv(m.points[s[i]]), b[i] = qv(m.points[t[i]]);
  std::vector<V> axes;
  for (const auto* p : {&a, &b})
    for (int f = 0; f < 4; ++f) {
      std::array<V, 3> q;
      for (int k = 0, n = 0; k < 4; ++k)
        if (k != f) q[n++] = (*p)[k];
      axes.push_back(cross(sub(q[1], q[0]), sub(q[2], q[0])));
    }
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = k + 1; l < 4; ++l) axes.push_back(cross(sub(a[j], a[i]), sub(b[l], b[k])));
  for (const V& n : axes) {
    if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) continue;
    Q amin = dot(n, a[0]), amax = amin, bmin = dot(n, b[0]), bmax = bmin;
    for (int i = 1; i < 4; ++i) {
      const Q x = dot(n, a[i]), y = dot(n, b[i]);
      amin = std::min(amin, x), amax = std::max(amax, x);
      bmin = std::min(bmin, y), bmax = std::max(bmax, y);
    }
    if (amax <= bmin || bmax <= amin) return false;
  }
  return true;
}

std::uint64_t oracle_overlaps(const MeshData& m) {
  std::uint64_t n = 0;
  auto degenerate = [&](const Tet& t) {
    return exact::orient3d(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) == Sign::Zero;
  };
  for (std::size_t i = 0; i < m.tets.size(); ++i)
    for (std::size_t j = i + 1; j < m.tets.size(); ++j) {
      const Tet &s = m.tets[i], &t = m.tets[j];
      int shared = 0;
      for (auto u : s) shared += static_cast<int>(std::count(t.begin(), t.end(), u));
      if (shared >= 3 || degenerate(s) || degenerate(t)) continue;
      n += interiors_intersect(m, s, t) ? 1 : 0;
    }
  return n;
}

// A jittered Kuhn grid plus random tets on its vertices and a few free points.
RC_GTEST_PROP(Overlap, AgreesWithBruteForceSeparatingAxes, ()) {
  MeshData m = kuhn_grid(1);
  const auto jit = *rc::gen::container<std::vector<int>>(24, rc::gen::inRange(-2, 3));
  for (std::size_t i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) m.points[i][c] += jit[3 * i + static_cast<std::size_t>(c)] * 0.0625;
  const auto extra = *rc::gen::container<std::vector<int>>(9, rc::gen::inRange(-4, 13));
  for (std::size_t i = 0; i < 9; i += 3) m.points.push_back({extra[i] * 0.125, extra[i + 1] * 0.125, extra[i + 2] * 0.125});
  const auto picks = *rc::gen::container<std::vector<int>>(
      16, rc::gen::inRange(0, static_cast<int>(m.points.size())));
  for (std::size_t i = 0; i + 3 < picks.size(); i += 4) {
    Tet t = {static_cast<std::uint32_t>(picks[i]), static_cast<std::uint32_t>(picks[i + 1]),
             static_cast<std::uint32_t>(picks[i + 2]), static_cast<std::uint32_t>(picks[i + 3])};
    m.tets.push_back(t);
  }
  const Report r = run(m);
  RC_ASSERT(result(r, "validity.indices").status == Status::Pass);
  const std::uint64_t expected = oracle_overlaps(m);
  RC_CLASSIFY(expected > 0, "overlapping");
  RC_ASSERT(count(r, "validity.overlap", "overlapping_pairs") == expected);
}

// Appends mesh b to mesh a, its vertices renumbered after a's (no vertex shared).
MeshData disjoint_union(MeshData a, const MeshData& b) {
  const auto base = static_cast<std::uint32_t>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (Tet t : b.tets) {
    for (auto& v : t) v += base;
    a.tets.push_back(t);
  }
  return a;
}

// Meshes that meet the degree argument's premises (positive tets, faces shared properly)
// but may overlap: a Kuhn grid of 2^3 cubes plus a second, disjoint one-cube grid of
// random size at a random offset (nested inside, crossing, touching, coinciding,
// apart). Both methods agree with brute force and with each other.
RC_GTEST_PROP(Overlap, DegreeArgumentAgreesWithBruteForce, ()) {
  const double side = *rc::gen::element(0.25, 0.5, 1.0);
  MeshData b = kuhn_grid(1, side);
  const auto off = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-3, 9));
  for (Point& p : b.points)
    for (int c = 0; c < 3; ++c) p[c] += off[static_cast<std::size_t>(c)] * 0.25;
  MeshData m = disjoint_union(kuhn_grid(2), b);
  if (*rc::gen::arbitrary<bool>()) {
    // Rotated by (3/5, 4/5) about z then x: faces of one facet no longer coplanar in
    // doubles, so the tests in space decide instead of the axis-parallel shortcuts.
    for (Point& p : m.points) {
      const double x = 0.6 * p[0] - 0.8 * p[1], y = 0.8 * p[0] + 0.6 * p[1];
      p = {x, 0.6 * y - 0.8 * p[2], 0.8 * y + 0.6 * p[2]};
    }
  }
  RC_PRE(std::all_of(m.tets.begin(), m.tets.end(), [&](const Tet& t) {
    return exact::orient3d(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) == Sign::Positive;
  }));
  const std::uint64_t expected = oracle_overlaps(m);
  Options pairwise;
  pairwise.overlap_by_degree = false;
  const Report by_degree = run(m), by_pairs = run(m, pairwise);
  const bool decided = count(by_degree, "validity.overlap", "degree.outer_cells_probed") > 0;
  RC_CLASSIFY(decided, "decided by the degree argument");
  RC_CLASSIFY(expected > 0, "overlapping");
  RC_ASSERT(count(by_pairs, "validity.overlap", "overlapping_pairs") == expected);
  // Same verdict (touching through partially overlapping coplanar faces fails both).
  RC_ASSERT(result(by_degree, "validity.overlap").status == result(by_pairs, "validity.overlap").status);
  if (decided && expected > 0) RC_ASSERT(count(by_degree, "validity.overlap", "degree.covered_probes") > 0);
  if (decided && count(by_degree, "validity.overlap", "degree.covered_probes") == 0)
    RC_ASSERT(result(by_pairs, "validity.overlap").status == Status::Pass);
}

TEST(Overlap, DegreeArgumentSeesANestedMeshThatNoBoundaryCrosses) {
  // A unit cube's mesh inside a 4^3 grid, vertices apart: the two boundaries are disjoint,
  // so only the probe just outside the inner surface (covered by the grid) finds it.
  MeshData inner = kuhn_grid(1, 0.5);
  for (Point& p : inner.points)
    for (double& x : p) x += 1.25;
  const Report r = run(disjoint_union(kuhn_grid(4), inner));
  EXPECT_EQ(result(r, "validity.overlap").status, Status::Fail);
  EXPECT_EQ(count(r, "validity.overlap", "degree.outer_cells_probed"), 2u);
  EXPECT_GT(count(r, "validity.overlap", "degree.covered_probes"), 0u);
  EXPECT_GT(count(r, "validity.overlap", "overlapping_pairs"), 0u);
  // Apart, the same two meshes pass, decided by the argument alone.
  for (Point& p : inner.points) p[0] += 10;
  const Report apart = run(disjoint_union(kuhn_grid(4), inner));
  EXPECT_EQ(result(apart, "validity.overlap").status, Status::Pass);
  EXPECT_EQ(count(apart, "validity.overlap", "degree.outer_cells_probed"), 2u);
  EXPECT_EQ(count(apart, "validity.overlap", "pairs_examined"), 0u);
}

TEST(Overlap, StructuredGridHasNoOverlapAndManyTouchingPairs) {
  Options pairwise;
  pairwise.overlap_by_degree = false;
  const Report r = run(kuhn_grid(4), pairwise);
  EXPECT_EQ(result(r, "validity.overlap").status, Status::Pass);
  EXPECT_EQ(count(r, "validity.overlap", "exact_evaluations"), 0u);  // ties go to integers
}

}  // namespace
}  // namespace pdr::check::test
