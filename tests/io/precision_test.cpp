// The coordinates' precision read off their values (io/precision.hpp): short decimals are
// exact, 6 to 15 digits and floats give the rounding of that writer, full doubles none; and
// the surface reader merges the two triangles of each side of a rotated box written with
// 7 digits into one facet, where the relative tolerance alone leaves them apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "io/precision.hpp"
#include "io/surface.hpp"

namespace pdr::io {
namespace {

std::vector<Point> rotated_points(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Point> pts;
  for (int i = 0; i < n; ++i) pts.push_back({u(rng), u(rng), u(rng)});
  return pts;
}

double printed(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return std::strtod(buf, nullptr);
}

double largest(const std::vector<Point>& pts) {
  double c = 0;
  for (const Point& p : pts)
    for (double x : p) c = std::max(c, std::fabs(x));
  return c;
}

TEST(Precision, ShortDecimalsAreExact) {
  const std::vector<Point> pts{{0, 0, 0}, {0.5, 2.25, -3}, {1.125, 10, 0.1}};
  const CoordinatePrecision p = infer_precision(pts);
  EXPECT_LE(p.digits, kExactDigits);
  EXPECT_EQ(p.uncertainty, 0.0);
}

TEST(Precision, FullDoublesHaveTheirOwnRounding) {
  const std::vector<Point> pts = rotated_points(50, 1);
  const CoordinatePrecision p = infer_precision(pts);
  EXPECT_GE(p.digits, 16);
  EXPECT_FALSE(p.float32);
  EXPECT_DOUBLE_EQ(p.uncertainty, kComputedRounding * std::sqrt(3.0) * largest(pts));
}

// How far a point moved (the distance between its exact and its stored coordinates).
double moved(const Point& a, const Point& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The uncertainty is the rounding of the largest coordinate, half a unit in its last place
// (sqrt(3) for a point): it bounds how far every point moved, and is no coarser than that
// place (it was 5 * 10^-digits times the largest coordinate, up to 10 times the rounding
// of coordinates below 1, which read a scanned model's real bends of a degree as
// rounding).
TEST(Precision, PrintedDigitsGiveTheirRounding) {
  for (const double scale : {1.0, 0.95, 0.12, 37.0})
    for (const int digits : {6, 7, 9, 12, 15}) {
      const std::vector<Point> exact = rotated_points(50, 2);
      std::vector<Point> pts = exact;
      double moved_most = 0;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        Point e = exact[i];
        for (int k = 0; k < 3; ++k) e[k] *= scale, pts[i][k] = printed(e[k], digits);
        moved_most = std::max(moved_most, moved(e, pts[i]));
      }
      const CoordinatePrecision p = infer_precision(pts);
      EXPECT_EQ(p.digits, digits);
      EXPECT_FALSE(p.float32);
      const double place = std::pow(10.0, std::floor(std::log10(largest(pts))));
      EXPECT_DOUBLE_EQ(p.uncertainty, 5 * std::pow(10.0, -digits) * place * std::sqrt(3.0))
          << scale << " " << digits;
      EXPECT_LE(moved_most, p.uncertainty) << scale << " " << digits;
    }
}

TEST(Precision, FloatsAreFloat32) {
  const std::vector<Point> exact = rotated_points(50, 3);
  std::vector<Point> pts = exact;
  double moved_most = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (double& x : pts[i]) {
      // Through a volatile: GCC 12 at -O2 and above vectorizes this round trip away.
      const volatile float f = static_cast<float>(x);
      x = f;
    }
    moved_most = std::max(moved_most, moved(exact[i], pts[i]));
  }
  const CoordinatePrecision p = infer_precision(pts);
  EXPECT_TRUE(p.float32);
  EXPECT_DOUBLE_EQ(p.uncertainty,
                   std::ldexp(1.0, std::ilogb(largest(pts)) - 24) * std::sqrt(3.0));
  EXPECT_LE(moved_most, p.uncertainty);
}

TEST(Precision, ExactClassificationInfersNothing) {
  std::vector<Point> pts = rotated_points(10, 4);
  for (Point& p : pts)
    for (double& x : p) x = printed(x, 7);
  EXPECT_EQ(planarity_tolerance_of(pts, 0).uncertainty(), 0.0);
  const PlanarityTolerance t = planarity_tolerance_of(pts, 1e-9);
  EXPECT_GT(t.uncertainty(), 0.0);
  EXPECT_EQ(t.precision.digits, 7);
  EXPECT_DOUBLE_EQ(t.admitted(1.0), PlanarityTolerance::kPlanarShare * t.uncertainty());
  EXPECT_DOUBLE_EQ(t.admitted(1e9), 1.0);  // the relative part, for a huge face
}

// Exact integers with six digits look like a 6-digit print of a part at 1e5: read as
// rounded they would make the part uncertain by 0.87 of its 10 units. The uncertainty is
// at most kMaxUncertainty of the domain's diameter.
TEST(Precision, UncertaintyIsSmallNextToTheDomain) {
  std::vector<Point> pts;
  for (int i = 0; i <= 10; i += 5)
    for (int j = 0; j <= 10; j += 5) pts.push_back({100000.0 + i, 100000.0 + j, 100001.0 + i});
  const CoordinatePrecision p = infer_precision(pts);
  EXPECT_EQ(p.digits, 6);
  const double diagonal = std::sqrt(300.0);
  EXPECT_GT(p.uncertainty, 0.0);
  EXPECT_LE(p.uncertainty, kMaxUncertainty * diagonal * (1 + 1e-12));
}

// A point no face uses says nothing of the surface's precision: the reader infers it from
// the points its faces use, as the domain analysis does from the domain's.
TEST(Precision, SurfaceReaderIgnoresUnusedPoints) {
  Surface s;
  s.source = "cube.off";
  for (int k = 0; k < 8; ++k)
    s.add_point({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}, 0, k);
  s.add_point({1000000.5, 0.123456789, 0}, 0, 8);  // used by no face
  for (const std::vector<std::uint32_t>& f : {std::vector<std::uint32_t>{0, 2, 3, 1},
                                             {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2},
                                             {1, 3, 7, 5}})
    s.add_face(f, 0, 0);
  const Plc plc = surface_to_plc(s, 1e-9);
  EXPECT_LE(plc.precision.digits, kExactDigits);
  EXPECT_EQ(plc.precision.uncertainty, 0.0);
  EXPECT_EQ(planarity_tolerance_of(plc, 1e-9).uncertainty(), 0.0);
}

// A box of 2 x 2 grids of squares on each side, each square as two triangles, turned by
// a rotation and written with `digits` digits: the facets the surface reader makes.
std::size_t facets_of_rotated_box(int digits, double relative) {
  Surface s;
  s.source = "box.off";
  const double c = std::cos(0.7), d = std::sin(0.7), e = std::cos(1.1), g = std::sin(1.1);
  auto id = [&](int i, int j, int k) { return static_cast<std::uint32_t>(9 * i + 3 * j + k); };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double x = 0.5 * i, y = 0.5 * j, z = 0.5 * k;
        const Point r{c * x - d * y, e * (d * x + c * y) - g * z, g * (d * x + c * y) + e * z};
        s.add_point({printed(r[0], digits), printed(r[1], digits), printed(r[2], digits)}, 0,
                    static_cast<std::int64_t>(s.points.size()));
      }
  // The six sides: the grid's cells on i, j or k = 0 or 2, outward.
  auto square = [&](std::uint32_t a, std::uint32_t b, std::uint32_t cc, std::uint32_t dd) {
    s.add_face(std::vector<std::uint32_t>{a, b, cc}, 0, 0);
    s.add_face(std::vector<std::uint32_t>{a, cc, dd}, 0, 0);
  };
  for (int u = 0; u < 2; ++u)
    for (int v = 0; v < 2; ++v) {
      square(id(0, u, v), id(0, u, v + 1), id(0, u + 1, v + 1), id(0, u + 1, v));
      square(id(2, u, v), id(2, u + 1, v), id(2, u + 1, v + 1), id(2, u, v + 1));
      square(id(u, 0, v), id(u + 1, 0, v), id(u + 1, 0, v + 1), id(u, 0, v + 1));
      square(id(u, 2, v), id(u, 2, v + 1), id(u + 1, 2, v + 1), id(u + 1, 2, v));
      square(id(u, v, 0), id(u, v + 1, 0), id(u + 1, v + 1, 0), id(u + 1, v, 0));
      square(id(u, v, 2), id(u + 1, v, 2), id(u + 1, v + 1, 2), id(u, v + 1, 2));
    }
  return surface_to_plc(s, relative).facets.size();
}

TEST(Precision, SurfaceReaderMergesSidesWithinTheRounding) {
  EXPECT_EQ(facets_of_rotated_box(17, 1e-9), 6u);
  EXPECT_EQ(facets_of_rotated_box(7, 1e-9), 6u);
  EXPECT_EQ(facets_of_rotated_box(6, 1e-9), 6u);
  // Classified exactly (tolerance 0), the 7-digit sides stay apart: of the 48 triangles,
  // only pairs that happen to stay exactly coplanar merge.
  EXPECT_GT(facets_of_rotated_box(7, 0), 40u);
}

}  // namespace
}  // namespace pdr::io
