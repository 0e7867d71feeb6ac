// Parts of the kernel checked on their own: the semi-static filters against the GMP
// predicates (they may say Unsure, never a wrong sign), the hashed pairing path of the
// commit (forced by a zero dense limit), and restoring the input numbering on export.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "delaunay/bulk.hpp"
#include "delaunay/export.hpp"
#include "delaunay/oracle.hpp"
#include "delaunay/point_sets.hpp"
#include "delaunay/semistatic.hpp"
#include "geom/exact.hpp"

namespace pdr {
namespace {

Sign to_sign(Filtered f) { return static_cast<Sign>(static_cast<int>(f)); }

// Coordinates of mixed magnitude, plus near-degenerate points: a point pushed off a plane
// or sphere through three or four others by one unit in the last place.
rc::Gen<double> coordinate() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::inRange(-1000, 1001), [](int x) { return x / 16.0; }),
      rc::gen::map(rc::gen::pair(rc::gen::inRange(-(1 << 30), 1 << 30), rc::gen::inRange(-60, 40)),
                   [](const std::pair<int, int>& me) { return std::ldexp(me.first, me.second); }));
}

rc::Gen<Point> any_point() {
  return rc::gen::map(rc::gen::tuple(coordinate(), coordinate(), coordinate()),
                      [](const std::tuple<double, double, double>& t) {
                        return Point{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
                      });
}

RC_GTEST_PROP(Semistatic, Orient3dNeverContradictsExact, ()) {
  const Point a = *any_point(), b = *any_point(), c = *any_point();
  Point d = *rc::gen::element(a, b, c);
  // Near the plane abc: an affine combination, rounded, nudged by a few ulps.
  const double s = *rc::gen::inRange(-3, 4) / 2.0;
  for (int k = 0; k < 3; ++k) d[k] = a[k] + s * (b[k] - a[k]) + (1 - s) * (c[k] - a[k]);
  const int nudge = *rc::gen::inRange(-2, 3);
  d[2] = std::nextafter(d[2], nudge > 0 ? INFINITY : -INFINITY);
  for (const Point& q : {d, *any_point()}) {
    const Filtered f = semistatic::orient3d(a.data(), b.data(), c.data(), q.data());
    if (f != Filtered::Unsure) RC_ASSERT(to_sign(f) == exact::orient3d(a, b, c, q));
  }
}

RC_GTEST_PROP(Semistatic, InsphereNeverContradictsExact, ()) {
  const Point a = *any_point(), b = *any_point(), c = *any_point(), d = *any_point();
  // A fifth point next to the sphere (a vertex nudged by one ulp), or anywhere.
  Point e = *rc::gen::element(a, b, c, d);
  e[0] = std::nextafter(e[0], *rc::gen::arbitrary<bool>() ? INFINITY : -INFINITY);
  for (const Point& q : {e, *any_point()}) {
    const Filtered f = semistatic::insphere(a.data(), b.data(), c.data(), d.data(), q.data());
    if (f != Filtered::Unsure) RC_ASSERT(to_sign(f) == exact::insphere(a, b, c, d, q));
  }
}

TEST(Semistatic, DecidesEasyCasesAndDoubtsDegenerateOnes) {
  const Point o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(semistatic::orient3d(o.data(), x.data(), y.data(), z.data()), Filtered::Positive);
  EXPECT_EQ(semistatic::orient3d(o.data(), y.data(), x.data(), z.data()), Filtered::Negative);
  const Point flat{1, 1, 0};
  EXPECT_EQ(semistatic::orient3d(o.data(), x.data(), y.data(), flat.data()), Filtered::Unsure);
  const Point in{0.25, 0.25, 0.25}, out{2, 2, 2}, on{1, 1, 1};  // on: cospherical
  EXPECT_EQ(semistatic::insphere(o.data(), x.data(), y.data(), z.data(), in.data()),
            Filtered::Positive);
  EXPECT_EQ(semistatic::insphere(o.data(), x.data(), y.data(), z.data(), out.data()),
            Filtered::Negative);
  EXPECT_EQ(semistatic::insphere(o.data(), x.data(), y.data(), z.data(), on.data()),
            Filtered::Unsure);
}

TEST(Commit, HashedPairingGivesTheSameTetrahedralization) {
  for (const auto& pts : {testing::random_cube(60, 3), testing::grid(4),
                          testing::sphere_lattice(41)}) {
    KernelOptions hashed;
    hashed.dense_pairing_limit = 0;
    Delaunay a(pts, hashed), b(pts);
    ASSERT_EQ(bulk_insert(a).status, BulkStatus::Ok);
    ASSERT_EQ(bulk_insert(b).status, BulkStatus::Ok);
    const auto v = testing::check_all(a);
    EXPECT_TRUE(v.empty()) << v.front();
    EXPECT_EQ(testing::canonical_tets(a), testing::canonical_tets(b));
  }
}

TEST(Export, RestoreInputOrderUndoesTheRenumbering) {
  const std::vector<Point> pts = testing::with_duplicates(testing::grid(3), 5, 1);
  Delaunay dt(pts);
  const BulkResult r = bulk_insert(dt);
  ASSERT_EQ(r.status, BulkStatus::Ok);
  MeshData m = to_mesh_data(dt);
  restore_input_order(m, r.input_index);
  EXPECT_EQ(m.points, pts);
  for (const Tet& t : m.tets)
    EXPECT_EQ(exact::orient3d(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]), Sign::Positive);
  for (const Duplicate& d : r.duplicates) EXPECT_EQ(pts[d.id], pts[d.kept]);
  EXPECT_EQ(r.duplicates.size(), 5u);
}

}  // namespace
}  // namespace pdr
