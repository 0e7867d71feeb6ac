// The distance d of paper §2.1: branch and bound over the hierarchy (feature_size) equals
// the all-pairs reference over all six kinds of component pairs (feature_size_brute) on
// random domains: disjoint boxes, boxes with voids, orthogonal ("skyline") prisms, which
// are admissible, and star-shaped prisms, which need not be.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "domain/distance.hpp"
#include "domain/validate.hpp"
#include "geom/predicates.hpp"
#include "support/plc_fixtures.hpp"

namespace pdr::domain::test {
using namespace pdr::test;
namespace {

void expect_fast_equals_brute(const Plc& plc) {
  const PlcDomain dom = build_domain(plc);
  const FeatureSize fast = feature_size(dom), brute = feature_size_brute(dom);
  RC_ASSERT(std::isfinite(brute.min_distance));
  RC_ASSERT(std::fabs(fast.min_distance - brute.min_distance) <= 1e-12 * brute.min_distance);
  RC_ASSERT(fast.d == fast.min_distance / std::sqrt(2.0));
  // Per component (the graded surface mesh's sizes): the hierarchy's answer equals the
  // all-pairs one, and the smallest is d.
  const LocalFeatureSizes local = local_feature_sizes(dom), ref = local_feature_sizes_brute(dom);
  RC_ASSERT(local.segment_d.size() == dom.segments.size());
  RC_ASSERT(local.facet_d.size() == dom.facets.size());
  const auto near = [](double a, double b) {
    return a == b || std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b));
  };
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < dom.segments.size(); ++s) {
    RC_ASSERT(near(local.segment_d[s], ref.segment_d[s]));
    smallest = std::min(smallest, local.segment_d[s]);
  }
  for (std::size_t f = 0; f < dom.facets.size(); ++f) {
    RC_ASSERT(near(local.facet_d[f], ref.facet_d[f]));
    RC_ASSERT(local.facet_d[f] >= fast.d * (1 - 1e-12));
    smallest = std::min(smallest, local.facet_d[f]);
  }
  // Each local size is a minimum over some of the unrelated pairs d minimises over (not the
  // pairs of two vertices, e.g. a segment's own ends): never below d.
  RC_ASSERT(smallest >= fast.d * (1 - 1e-12));
}

// A coordinate in a cell of width 16 starting at `cell`: cell*16 + k/7 for k in [lo, hi].
double coord(int cell, int k) { return 16.0 * cell + k / 7.0; }

// Up to `n` boxes in distinct cells of a 3x3x2 grid of cells (disjoint, closed).
std::vector<std::array<Point, 2>> random_boxes(int n, int margin) {
  std::vector<int> cells(18);
  for (int i = 0; i < 18; ++i) cells[i] = i;
  std::vector<std::array<Point, 2>> boxes;
  for (int i = 0; i < n; ++i) {
    const int pick = *rc::gen::inRange(0, static_cast<int>(cells.size()));
    const int c = cells[pick];
    cells.erase(cells.begin() + pick);
    const int cx = c % 3, cy = (c / 3) % 3, cz = c / 9;
    std::array<Point, 2> b;
    const int cell[3] = {cx, cy, cz};
    for (int k = 0; k < 3; ++k) {
      const int lo = *rc::gen::inRange(margin, 60);
      const int hi = *rc::gen::inRange(lo + 1, 112 - margin);
      b[0][k] = coord(cell[k], lo);
      b[1][k] = coord(cell[k], hi);
    }
    boxes.push_back(b);
  }
  return boxes;
}

RC_GTEST_PROP(PlcFeatureSize, DisjointBoxes, ()) {
  const auto boxes = random_boxes(*rc::gen::inRange(1, 6), 0);
  Plc plc = box(boxes[0][0], boxes[0][1]);
  for (std::size_t i = 1; i < boxes.size(); ++i) plc = merge(plc, box(boxes[i][0], boxes[i][1]));
  expect_fast_equals_brute(plc);
}

RC_GTEST_PROP(PlcFeatureSize, BoxWithVoids, ()) {
  const auto voids = random_boxes(*rc::gen::inRange(1, 5), 1);
  Plc plc = box({-1, -1, -1}, {49, 49, 33});
  for (const auto& v : voids) {
    plc = merge(plc, box(v[0], v[1]));
    plc.holes.push_back({(v[0][0] + v[1][0]) / 2, (v[0][1] + v[1][1]) / 2, (v[0][2] + v[1][2]) / 2});
  }
  relabel(plc);
  expect_fast_equals_brute(plc);
  // Orientation: the outer walls face their box's centre, the voids' walls face away.
  const PlcDomain dom = build_domain(plc);
  RC_ASSERT(dom.shells == voids.size() + 1);
  for (std::size_t f = 0; f < dom.facets.size(); ++f) {
    const Point c = f < 6 ? Point{24, 24, 16} : plc.holes[f / 6 - 1];
    const int expected = f < 6 ? 1 : -1;
    for (const FacetTri& t : dom.facets[f].tris)
      RC_ASSERT(to_int(orient3d(plc.points[t.v[0]], plc.points[t.v[1]], plc.points[t.v[2]], c)) *
                    t.inward == expected);
  }
}

RC_GTEST_PROP(PlcFeatureSize, SkylinePrisms, ()) {
  // An orthogonal polygon: columns of random widths and heights over the x axis.
  const int n = *rc::gen::inRange(1, 7);
  std::vector<double> xs{0};
  std::vector<double> hs;
  for (int i = 0; i < n; ++i) {
    xs.push_back(xs.back() + *rc::gen::inRange(1, 20) / 3.0);
    hs.push_back(*rc::gen::inRange(1, 20) / 5.0);
  }
  std::vector<P2d> poly{{xs.back(), 0}, {0, 0}};
  for (int i = 0; i < n; ++i) {
    poly.push_back({xs[i], hs[i]});
    poly.push_back({xs[i + 1], hs[i]});
  }
  // Drop repeated points where neighbouring columns have equal heights.
  std::vector<P2d> clean;
  for (const P2d& p : poly)
    if (clean.empty() || clean.back() != p) clean.push_back(p);
  if (clean.back() == clean.front()) clean.pop_back();
  const Plc plc = prism(clean, 0, *rc::gen::inRange(1, 20) / 4.0);
  expect_fast_equals_brute(plc);
}

RC_GTEST_PROP(PlcFeatureSize, StarPrisms, ()) {
  const int n = *rc::gen::inRange(3, 12);
  std::vector<std::pair<double, P2d>> pts;
  std::set<std::pair<int, int>> seen;
  for (int i = 0; i < 60 && static_cast<int>(pts.size()) < n; ++i) {
    const int x = *rc::gen::inRange(-9, 10), y = *rc::gen::inRange(-9, 10);
    if ((x == 0 && y == 0) || !seen.insert({x, y}).second) continue;
    bool clash = false;
    for (auto& [a, q] : pts) clash = clash || (q[0] * y - q[1] * x == 0 && q[0] * x + q[1] * y > 0);
    if (!clash) pts.push_back({std::atan2(double(y), double(x)), {double(x), double(y)}});
  }
  RC_PRE(pts.size() >= 3u);
  std::sort(pts.begin(), pts.end());
  std::vector<P2d> poly;
  for (auto& [a, q] : pts) poly.push_back(q);
  double area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2d &p = poly[i], &q = poly[(i + 1) % poly.size()];
    area += p[0] * q[1] - p[1] * q[0];
  }
  RC_PRE(area > 0);
  const Plc plc = prism(poly, 0, *rc::gen::inRange(1, 10) / 3.0);
  RC_PRE(error_of(plc).empty());  // a star whose edge passes through a vertex is not simple
  expect_fast_equals_brute(plc);
}

// A box with a rectangular tunnel along z: caps with facet holes, a genus-one shell.
Plc frame(const Point& lo, const Point& hi, double x0, double x1, double y0, double y1) {
  std::vector<Point> p{{lo[0], lo[1], lo[2]}, {hi[0], lo[1], lo[2]}, {hi[0], hi[1], lo[2]},
                       {lo[0], hi[1], lo[2]}, {lo[0], lo[1], hi[2]}, {hi[0], lo[1], hi[2]},
                       {hi[0], hi[1], hi[2]}, {lo[0], hi[1], hi[2]}, {x0, y0, lo[2]},
                       {x1, y0, lo[2]},       {x1, y1, lo[2]},       {x0, y1, lo[2]},
                       {x0, y0, hi[2]},       {x1, y0, hi[2]},       {x1, y1, hi[2]},
                       {x0, y1, hi[2]}};
  Plc plc = make_plc(p, {{{0, 1, 2, 3}, {8, 9, 10, 11}}, {{4, 5, 6, 7}, {12, 13, 14, 15}},
                         {{0, 1, 5, 4}}, {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}},
                         {{8, 9, 13, 12}}, {{9, 10, 14, 13}}, {{10, 11, 15, 14}},
                         {{11, 8, 12, 15}}});
  plc.facets[0].holes = {{(x0 + x1) / 2, (y0 + y1) / 2, lo[2]}};
  plc.facets[1].holes = {{(x0 + x1) / 2, (y0 + y1) / 2, hi[2]}};
  return plc;
}

RC_GTEST_PROP(PlcFeatureSize, Frames, ()) {
  const int w = *rc::gen::inRange(3, 30), h = *rc::gen::inRange(3, 30);
  const int x0 = *rc::gen::inRange(1, w - 1), x1 = *rc::gen::inRange(x0 + 1, w);
  const int y0 = *rc::gen::inRange(1, h - 1), y1 = *rc::gen::inRange(y0 + 1, h);
  const double s = 1.0 / 3;
  expect_fast_equals_brute(frame({0, 0, 0}, {w * s, h * s, *rc::gen::inRange(1, 30) * s}, x0 * s,
                                 x1 * s, y0 * s, y1 * s));
}

TEST(PlcFeatureSize, ManyBoxesAgreeWithTheReference) {
  Plc plc = box({0, 0, 0}, {1, 1, 1});
  for (int i = 1; i < 60; ++i) {
    const double x = (i % 6) * 1.5 + 0.01 * i, y = ((i / 6) % 5) * 1.7, z = (i / 30) * 2.1;
    plc = merge(plc, box({x, y, z}, {x + 1 + 0.003 * i, y + 1.2, z + 1.5}));
  }
  const PlcDomain dom = build_domain(plc);
  const FeatureSize fast = feature_size(dom), brute = feature_size_brute(dom);
  EXPECT_NEAR(fast.min_distance, brute.min_distance, 1e-12);
  EXPECT_NEAR(fast.min_distance, 0.51 - 0.003 * 58, 1e-9);  // boxes 58 and 59, side by side
}

}  // namespace
}  // namespace pdr::domain::test
