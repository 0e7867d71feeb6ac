// The kernel's Delaunay tetrahedralizations (src/delaunay) pass every mesh check, including
// the listed hull faces; a planted corruption of one of them is caught. Degenerate inputs
// (grids: cospherical and coplanar points) exercise the exact paths.
#include <gtest/gtest.h>

#include <random>

#include "check_test_util.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/export.hpp"

namespace pdr::check::test {
namespace {

MeshData triangulate(std::vector<Point> pts) {
  Delaunay dt(std::move(pts));
  const BulkResult b = bulk_insert(dt);
  EXPECT_EQ(b.status, BulkStatus::Ok) << b.message;
  return to_mesh_data(dt);
}

std::vector<Point> random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> p(n);
  for (Point& x : p) x = {u(rng), u(rng), u(rng)};
  return p;
}

TEST(Kernel, RandomPointsPass) {
  const MeshData m = triangulate(random_points(3000, 7));
  const Report r = run(m);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(result(r, "validity.faces").status, Status::Pass);
  EXPECT_EQ(result(r, "delaunay.empty_sphere").status, Status::Pass);
}

TEST(Kernel, GridPointsPassWithTies) {
  std::vector<Point> pts;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) pts.push_back({i * 0.5, j * 0.5, k * 0.5});
  const MeshData m = triangulate(pts);
  const Report r = run(m);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_GT(count(r, "delaunay.empty_sphere", "cospherical"), 0u);
}

TEST(Kernel, SwappedPointIsCaught) {
  MeshData m = triangulate(random_points(500, 11));
  std::swap(m.points[3], m.points[400]);  // same point set, wrong tets
  const Report r = run(m);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(failed(r).count("delaunay.empty_sphere") || failed(r).count("validity.orientation"));
}

}  // namespace
}  // namespace pdr::check::test
