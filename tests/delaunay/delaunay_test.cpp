// Delaunay kernel examples: random, grid, cospherical, coplanar-hull and duplicate-laden
// point sets, each checked by the brute-force oracles (oracle.hpp); the two-phase API;
// degenerate inputs; incremental insertion with the audit after every step.
#include <gtest/gtest.h>

#include "delaunay/bulk.hpp"
#include "delaunay/conflict.hpp"
#include "delaunay/export.hpp"
#include "delaunay/oracle.hpp"
#include "delaunay/point_sets.hpp"
#include "geom/exact.hpp"

namespace pdr {
namespace {

using testing::canonical_tets;
using testing::check_all;

std::string first(const std::vector<std::string>& v) { return v.empty() ? "" : v.front(); }

Delaunay build(std::vector<Point> pts, BulkOptions opt = {}) {
  Delaunay dt(std::move(pts));
  const BulkResult r = bulk_insert(dt, opt);
  EXPECT_EQ(r.status, BulkStatus::Ok) << r.message;
  return dt;
}

void expect_valid(const Delaunay& dt) {
  const auto v = check_all(dt);
  EXPECT_TRUE(v.empty()) << v.size() << " violations, first: " << first(v);
}

TEST(Delaunay, FourPointsMakeOneTetAndFourGhosts) {
  Delaunay dt({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}});  // negative as given
  ASSERT_EQ(bulk_insert(dt).status, BulkStatus::Ok);
  EXPECT_EQ(dt.count_finite_tets(), 1u);
  EXPECT_EQ(dt.store().live(), 5u);
  expect_valid(dt);
}

TEST(Delaunay, RandomPoints) {
  const Delaunay dt = build(testing::random_cube(80, 1));
  expect_valid(dt);
  EXPECT_EQ(dt.stats().inserted, 76u);
}

TEST(Delaunay, IntegerGrid6) {
  const Delaunay dt = build(testing::grid(6));
  expect_valid(dt);
}

TEST(Delaunay, CosphericalLattice) {
  for (int r2 : {9, 41}) {
    SCOPED_TRACE(r2);
    const Delaunay dt = build(testing::sphere_lattice(r2));
    expect_valid(dt);
  }
}

TEST(Delaunay, CoplanarHullFacets) {
  const Delaunay dt = build(testing::cube_surface(4, 30, 7));
  expect_valid(dt);
}

TEST(Delaunay, DuplicatesAreReportedNotInserted) {
  const std::vector<Point> base = testing::grid(4);
  std::vector<Point> pts = testing::with_duplicates(base, 40, 3);
  Delaunay dt(pts);
  const BulkResult r = bulk_insert(dt);
  ASSERT_EQ(r.status, BulkStatus::Ok);
  EXPECT_EQ(r.duplicates.size(), 40u);
  for (const Duplicate& d : r.duplicates) {
    EXPECT_NE(d.id, d.kept);
    EXPECT_EQ(pts[d.id], pts[d.kept]);
  }
  expect_valid(dt);
  EXPECT_EQ(canonical_tets(dt), canonical_tets(build(base)));
}

TEST(Delaunay, InsertionOrderDoesNotMatter) {
  for (const auto& pts : {testing::grid(5), testing::sphere_lattice(41),
                          testing::cube_surface(3, 10, 2), testing::random_cube(200, 5)}) {
    BulkOptions plain;
    plain.spatial_sort = false;
    const auto a = canonical_tets(build(pts));
    EXPECT_EQ(a, canonical_tets(build(testing::shuffled(pts, 11), plain)));
    EXPECT_EQ(a, canonical_tets(build(testing::shuffled(pts, 12))));
  }
}

TEST(Delaunay, DegenerateInputsAreReported) {
  Delaunay none;
  EXPECT_EQ(bulk_insert(none).status, BulkStatus::TooFewPoints);
  Delaunay same({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}});
  EXPECT_EQ(bulk_insert(same).status, BulkStatus::TooFewPoints);
  Delaunay line({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {0.5, 0.5, 0.5}});
  EXPECT_EQ(bulk_insert(line).status, BulkStatus::AllCollinear);
  Delaunay plane({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.3, 0.7, 1}});
  const BulkResult r = bulk_insert(plane);
  EXPECT_EQ(r.status, BulkStatus::AllCoplanar);
  EXPECT_EQ(r.message.rfind("all-coplanar", 0), 0u);
  EXPECT_TRUE(plane.empty());
}

// One point at a time from a hint, including points outside the hull, on hull faces, on
// hull edges and duplicates, with the whole audit after every insertion.
TEST(Delaunay, IncrementalInsertionAuditedAfterEachStep) {
  Delaunay dt({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}});
  dt.init(0, 1, 2, 3);
  expect_valid(dt);
  const std::vector<Point> more{
      {1, 1, 1},   {2, 0, 0},  {0, 2, 2},   {1, 1, 0},  {8, 8, 8},  {-1, -1, -1},
      {2, 2, 0},   {4, 4, 0},  {2, 0, 0},   {0, 0, 4},  {2, 2, 2},  {-1, 5, 0},
      {3, 3, 3},   {0.5, 0.5, 0.5}, {4, 4, 4}, {6, 6, 6}, {-2, -2, -2}};
  TetId hint = dt.last_tet();
  for (const Point& p : more) {
    bool dup = false;
    for (const Point& q : dt.points()) dup = dup || q == p;
    const VertexId v = dt.add_point(p);
    const InsertResult r = dt.insert(v, hint);
    SCOPED_TRACE(v);
    EXPECT_EQ(r.outcome, dup ? Outcome::Duplicate : Outcome::Inserted);
    ASSERT_TRUE(dt.store().is_alive(r.tet));
    const VertexId* tv = dt.store().vertices(r.tet);
    EXPECT_TRUE(tv[0] == r.vertex || tv[1] == r.vertex || tv[2] == r.vertex ||
                tv[3] == r.vertex);
    expect_valid(dt);
    hint = r.tet;
  }
}

// The cavity is a value: building it leaves the store untouched; its conflict set is the
// set of all tets in conflict (brute force); boundary and ring are its face-neighbourhood.
TEST(Cavity, IsTheConflictRegionAndChangesNothing) {
  Delaunay dt = build(testing::cube_surface(3, 20, 4));
  const TetStore before = dt.store();
  for (const Point& p : {Point{1.5, 1.5, 1.5}, Point{1, 1.5, 3}, Point{0, 0.5, 0.5},
                         Point{5, 5, 5}, Point{1.5, 1.5, 3}, Point{0.25, 1, 2}}) {
    SCOPED_TRACE(p[0] + 10 * p[1] + 100 * p[2]);
    const Location loc = dt.locate(p);
    ASSERT_NE(loc.kind, Location::Kind::OnVertex);
    Cavity c;
    dt.build_cavity(p, loc.tet, c);
    const TetStore& s = dt.store();
    std::vector<char> in(s.slots(), 0);
    for (TetId t : c.conflict) in[t] = 1;
    for (TetId t = 0; t < s.slots(); ++t) {
      if (!s.is_alive(t)) continue;
      EXPECT_EQ(bool(in[t]), in_conflict(s, dt.points(), t, p)) << "tet " << t;
    }
    std::vector<char> ring(s.slots(), 0);
    for (TetId t : c.ring) {
      EXPECT_FALSE(in[t]);
      EXPECT_FALSE(ring[t]) << "ring lists tet " << t << " twice";
      ring[t] = 1;
    }
    for (HalfFace h : c.boundary) {
      EXPECT_TRUE(in[tet_of(h)]);
      EXPECT_TRUE(ring[s.neighbour(tet_of(h), face_of(h))]);
    }
    for (TetId t = 0; t < s.slots(); ++t) {
      if (!s.is_alive(t)) continue;
      EXPECT_EQ(s.vertex(t, 0), before.vertex(t, 0));
      for (int f = 0; f < 4; ++f) EXPECT_EQ(s.opposite(t, f), before.opposite(t, f));
    }
  }
}

TEST(Walk, ReportsInsideOutsideAndDuplicate) {
  Delaunay dt = build(testing::grid(3));  // the cube [0,2]^3
  for (TetId hint = 0; hint < dt.store().slots(); hint += 7) {
    if (!dt.store().is_alive(hint)) continue;
    const Location in = dt.locate({0.5, 1.25, 1.75}, hint);
    EXPECT_EQ(in.kind, Location::Kind::InTet);
    EXPECT_FALSE(dt.store().is_ghost(in.tet));
    const Location face = dt.locate({0, 0.5, 0.25}, hint);  // on a hull face: closed tet
    EXPECT_EQ(face.kind, Location::Kind::InTet);
    const Location out = dt.locate({3, 1, 1}, hint);
    ASSERT_EQ(out.kind, Location::Kind::OutsideHull);
    const VertexId* g = dt.store().vertices(out.tet);
    EXPECT_EQ(g[3], kGhostVertex);
    EXPECT_EQ(exact::orient3d(dt.point(g[0]), dt.point(g[1]), dt.point(g[2]), {3, 1, 1}),
              Sign::Positive);
    const Location dup = dt.locate({2, 0, 1}, hint);
    ASSERT_EQ(dup.kind, Location::Kind::OnVertex);
    EXPECT_EQ(dt.point(dup.vertex), (Point{2, 0, 1}));
  }
}

// The refinement path: locate from a known tet, inspect the cavity, commit or drop it.
TEST(Delaunay, TwoPhaseInsertionFromAKnownTet) {
  Delaunay dt = build(testing::random_cube(40, 8));
  const std::size_t before = dt.num_points();
  Cavity c;
  const Point p{0.5, 0.5, 0.5};
  const Location loc = dt.locate(p, dt.last_tet());
  ASSERT_NE(loc.kind, Location::Kind::OnVertex);
  dt.build_cavity(p, loc.tet, c);
  EXPECT_EQ(dt.num_points(), before);  // dropping the cavity here would change nothing
  const InsertResult r = dt.commit(c);
  EXPECT_EQ(r.outcome, Outcome::Inserted);
  EXPECT_EQ(r.vertex, before);
  EXPECT_EQ(dt.point(r.vertex), p);
  expect_valid(dt);
  const InsertResult again = dt.insert(p, r.tet);
  EXPECT_EQ(again.outcome, Outcome::Duplicate);
  EXPECT_EQ(again.vertex, r.vertex);
  EXPECT_EQ(dt.num_points(), before + 1);
  const InsertResult outside = dt.insert(Point{2, -1, 0.5});
  EXPECT_EQ(outside.outcome, Outcome::Inserted);
  expect_valid(dt);
}

TEST(Export, TetsArePositiveAndFacesAreTheHull) {
  const Delaunay dt = build(testing::grid(3));
  const MeshData m = to_mesh_data(dt);
  EXPECT_EQ(m.points.size(), 27u);
  EXPECT_EQ(m.tets.size(), dt.count_finite_tets());
  mpq_class vol = 0;
  for (const Tet& t : m.tets) {
    EXPECT_EQ(exact::orient3d(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]),
              Sign::Positive);
    vol += exact::volume6(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
  }
  EXPECT_EQ(vol, 6 * 8);
  EXPECT_EQ(m.faces.size(), 6u * 8u);  // 6 sides of 2x2 squares, 2 triangles each
  const Point inside{1, 1, 1};
  for (const Tri& f : m.faces)
    EXPECT_EQ(exact::orient3d(m.points[f[0]], m.points[f[1]], m.points[f[2]], inside),
              Sign::Negative);
  // A keep mask: only tets touching vertex 0 (the corner (0,0,0)).
  std::vector<std::uint8_t> keep(dt.store().slots(), 0);
  for (TetId t = 0; t < dt.store().slots(); ++t)
    if (dt.store().is_alive(t) && !dt.store().is_ghost(t))
      for (int i = 0; i < 4; ++i) keep[t] |= dt.store().vertex(t, i) == 0;
  const MeshData part = to_mesh_data(dt, keep);
  EXPECT_GT(part.tets.size(), 0u);
  EXPECT_LT(part.tets.size(), m.tets.size());
  EXPECT_EQ(part.faces.size() % 2, 0u);  // a closed triangulated surface has an even count
}

}  // namespace
}  // namespace pdr
