// RapidCheck properties of the Delaunay kernel, with shrinking:
//   - the result passes every brute-force oracle (oracle.hpp);
//   - two random insertion orders give the identical canonical tet set (uniqueness of the
//     SoS-Delaunay tetrahedralization, docs/design.md §5);
//   - degenerate inputs (collinear, coplanar, too few) are reported, and only then.
// Generators favour degeneracy: small integer grids (cospherical, coplanar and collinear
// subsets everywhere, duplicates), lattice points of one sphere, and dyadic doubles of
// mixed magnitudes. A shrunk counterexample is kept in tests/regress/delaunay-*.node and
// replayed by regress_test.cpp.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <random>

#include "delaunay/bulk.hpp"
#include "delaunay/oracle.hpp"
#include "delaunay/point_sets.hpp"
#include "geom/exact.hpp"

namespace pdr {
namespace {

using testing::canonical_tets;
using testing::check_all;

rc::Gen<Point> grid_point(int k) {
  return rc::gen::map(rc::gen::tuple(rc::gen::inRange(0, k + 1), rc::gen::inRange(0, k + 1),
                                     rc::gen::inRange(0, k + 1)),
                      [](const std::tuple<int, int, int>& t) {
                        return Point{double(std::get<0>(t)), double(std::get<1>(t)),
                                     double(std::get<2>(t))};
                      });
}

// Dyadic doubles m * 2^e, |m| < 2^20, e in [-30, 10]: exact-friendly but of mixed scale.
rc::Gen<Point> dyadic_point() {
  auto coord = rc::gen::map(
      rc::gen::pair(rc::gen::inRange(-(1 << 20), 1 << 20), rc::gen::inRange(-30, 11)),
      [](const std::pair<int, int>& me) { return std::ldexp(double(me.first), me.second); });
  return rc::gen::map(rc::gen::tuple(coord, coord, coord),
                      [](const std::tuple<double, double, double>& t) {
                        return Point{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
                      });
}

// Exact classification of a point set, by brute force: 0 = fewer than 2 distinct
// points, 1 = collinear, 2 = coplanar, 3 = spans space.
int affine_dimension(const std::vector<Point>& p) {
  const std::size_t n = p.size();
  std::size_t b = n, c = n;
  for (std::size_t i = 1; i < n && b == n; ++i)
    if (p[i] != p[0]) b = i;
  if (b == n) return 0;
  for (std::size_t i = 0; i < n && c == n; ++i)
    for (int k = 0; k < 3 && c == n; ++k) {
      const int x = k, y = (k + 1) % 3;
      const double pa[2] = {p[0][x], p[0][y]}, pb[2] = {p[b][x], p[b][y]},
                   pc[2] = {p[i][x], p[i][y]};
      if (exact::orient2d(pa, pb, pc) != Sign::Zero) c = i;
    }
  if (c == n) return 1;
  for (std::size_t i = 0; i < n; ++i)
    if (exact::orient3d(p[0], p[b], p[c], p[i]) != Sign::Zero) return 3;
  return 2;
}

int expected_dimension(BulkStatus s) {
  switch (s) {
    case BulkStatus::TooFewPoints: return 0;
    case BulkStatus::AllCollinear: return 1;
    case BulkStatus::AllCoplanar: return 2;
    case BulkStatus::Ok: return 3;
  }
  return -1;
}

void require_none(const std::vector<std::string>& violations) {
  if (!violations.empty())
    RC_FAIL(std::to_string(violations.size()) + " violations, first: " + violations.front());
}

// The property every generator feeds: valid, and independent of the insertion order.
void check_point_set(const std::vector<Point>& pts, std::uint64_t seed) {
  Delaunay a(pts);
  BulkOptions sorted;
  sorted.seed = seed;
  sorted.min_round = 8;
  const BulkResult ra = bulk_insert(a, sorted);
  RC_ASSERT(expected_dimension(ra.status) == affine_dimension(pts));
  if (ra.status != BulkStatus::Ok) return;
  const auto va = check_all(a);
  require_none(va);

  Delaunay b(testing::shuffled(pts, seed ^ 0xABCDEF));
  BulkOptions plain;
  plain.spatial_sort = false;
  RC_ASSERT(bulk_insert(b, plain).status == BulkStatus::Ok);
  const auto vb = check_all(b);
  require_none(vb);
  RC_ASSERT(canonical_tets(a) == canonical_tets(b));
}

RC_GTEST_PROP(DelaunayProperty, SmallIntegerGridSets, ()) {
  const int k = *rc::gen::inRange(1, 5);
  const auto pts = *rc::gen::container<std::vector<Point>>(
      *rc::gen::inRange<std::size_t>(4, 40), grid_point(k));
  check_point_set(pts, *rc::gen::arbitrary<std::uint64_t>());
}

RC_GTEST_PROP(DelaunayProperty, DyadicSets, ()) {
  const auto pts = *rc::gen::container<std::vector<Point>>(
      *rc::gen::inRange<std::size_t>(4, 30), dyadic_point());
  check_point_set(pts, *rc::gen::arbitrary<std::uint64_t>());
}

RC_GTEST_PROP(DelaunayProperty, CosphericalSubsets, ()) {
  static const std::vector<Point> sphere = testing::sphere_lattice(101);
  const auto picks = *rc::gen::container<std::vector<std::size_t>>(
      *rc::gen::inRange<std::size_t>(4, 40), rc::gen::inRange<std::size_t>(0, sphere.size()));
  std::vector<Point> pts;
  for (std::size_t i : picks) pts.push_back(sphere[i]);
  // Optionally the centre too: then every tet touching it is degenerate-cospherical.
  if (*rc::gen::arbitrary<bool>()) pts.push_back({0, 0, 0});
  check_point_set(pts, *rc::gen::arbitrary<std::uint64_t>());
}

// One point at a time through insert(), from a random hint each time, auditing the
// topology after every step and the whole oracle at the end.
RC_GTEST_PROP(DelaunayProperty, IncrementalFromRandomHints, ()) {
  // A first tet (0..3) spanning the grid's corner, then grid points (with duplicates of
  // them and of each other, on its faces and outside it).
  std::vector<Point> pts{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}};
  const auto more = *rc::gen::container<std::vector<Point>>(
      *rc::gen::inRange<std::size_t>(0, 30), grid_point(3));
  pts.insert(pts.end(), more.begin(), more.end());
  const std::array<std::size_t, 4> init{0, 1, 2, 3};
  Delaunay dt(pts);
  dt.init(VertexId(init[0]), VertexId(init[1]), VertexId(init[2]), VertexId(init[3]));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (std::find(init.begin(), init.end(), i) != init.end()) continue;
    const std::size_t slots = dt.store().slots();
    TetId hint = TetId(*rc::gen::inRange<std::size_t>(0, slots));
    while (!dt.store().is_alive(hint)) hint = TetId((hint + 1) % slots);
    dt.insert(VertexId(i), hint);
    const auto v = dt.check_topology();
    require_none(v);
  }
  const auto v = check_all(dt);
  require_none(v);
  Delaunay whole(pts);
  RC_ASSERT(bulk_insert(whole).status == BulkStatus::Ok);
  RC_ASSERT(canonical_tets(dt) == canonical_tets(whole));
}

}  // namespace
}  // namespace pdr
