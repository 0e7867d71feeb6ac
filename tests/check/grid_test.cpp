// The checker's candidate grids (src/check/grid.hpp) against brute force: a point query
// visits every stored point inside its box exactly once, and the box-pair enumeration
// reports every intersecting pair exactly once, on clouds graded over many scales (the
// shape of a mesh refined to a small gap), with coincident points and empty boxes; a ball
// query visits every point in the closed ball once, and few far from it. A query inside a
// crowded patch visits few points: the grid nests where points crowd.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "check/grid.hpp"
#include "check/parallel.hpp"

namespace pdr::check {
namespace {

// Points: a coarse cloud over [0, 1]^3 and clusters of `fine` points each at scales
// 10^-s around random centres, some repeated exactly; `scale` is each point's spacing.
std::vector<Point> graded_cloud(std::vector<double>* spacing = nullptr) {
  const auto coarse = *rc::gen::inRange(0, 200);
  const auto clusters = *rc::gen::inRange(1, 4);
  std::vector<Point> p;
  auto unit = [] { return *rc::gen::inRange(0, 1 << 20) / double(1 << 20); };
  std::vector<double> h;
  for (int i = 0; i < coarse; ++i) p.push_back({unit(), unit(), unit()}), h.push_back(0.1);
  for (int c = 0; c < clusters; ++c) {
    const Point centre{unit(), unit(), unit()};
    const double scale = std::pow(10.0, -*rc::gen::inRange(2, 12));
    const bool flat = *rc::gen::arbitrary<bool>();  // a patch of one plane, as on a facet
    const int fine = *rc::gen::inRange(50, 900);
    for (int i = 0; i < fine; ++i) {
      p.push_back({centre[0] + scale * unit(), centre[1] + scale * unit(),
                   flat ? centre[2] : centre[2] + scale * unit()});
      h.push_back(scale / (flat ? std::sqrt(fine) : std::cbrt(fine)));
    }
  }
  const int copies = *rc::gen::inRange(0, 40);
  for (int i = 0; i < copies && !p.empty(); ++i) {
    const std::size_t k = *rc::gen::inRange<std::size_t>(0, p.size());
    p.push_back(p[k]), h.push_back(h[k]);
  }
  if (spacing) *spacing = std::move(h);
  return p;
}

bool inside(const Point& p, const Box& b) {
  for (int i = 0; i < 3; ++i)
    if (p[i] < b.lo[i] || p[i] > b.hi[i]) return false;
  return true;
}

Box box_around(const std::vector<Point>& p, std::size_t i, double r) {
  return {{p[i][0] - r, p[i][1] - r, p[i][2] - r}, {p[i][0] + r, p[i][1] + r, p[i][2] + r}};
}

RC_GTEST_PROP(Grid, PointQueriesVisitEveryPointInTheBoxOnce, ()) {
  const std::vector<Point> p = graded_cloud();
  RC_PRE(!p.empty());
  const PointGrid grid(p);
  for (int q = 0; q < 40; ++q) {
    const std::size_t i = *rc::gen::inRange<std::size_t>(0, p.size());
    const double r = std::pow(10.0, -*rc::gen::inRange(0, 14));
    const Box b = box_around(p, i, r);
    std::map<std::uint32_t, int> seen;
    grid.query(b, [&](std::uint32_t id, const Point& x) {
      RC_ASSERT(x == p[id]);
      ++seen[id];
    });
    for (const auto& [id, n] : seen) RC_ASSERT(n == 1);
    for (std::uint32_t id = 0; id < p.size(); ++id)
      if (inside(p[id], b)) RC_ASSERT(seen.count(id) == 1u);
  }
}

// Deterministic uniform doubles in [0, 1) for the fixed clouds (a 64-bit LCG's top bits).
struct Lcg {
  std::uint64_t s;
  double operator()() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) / double(1ull << 53);
  }
};

// Whether p lies in the closed ball (centre c, squared radius r2), in exact rationals: the
// oracle shares no arithmetic with the grid's outward rounding.
bool in_ball_exact(const Point& p, const Point& c, double r2) {
  mpq_class d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const mpq_class d = mpq_class(p[i]) - mpq_class(c[i]);
    d2 += d * d;
  }
  return d2 <= mpq_class(r2);
}

// Balls from tiny to far larger than the cloud, some centred far away so that only a cap
// reaches it (a flat tet's circumball), some with a radius exactly a point's distance.
RC_GTEST_PROP(Grid, BallQueriesVisitEveryPointInTheBallOnce, ()) {
  const std::vector<Point> p = graded_cloud();
  RC_PRE(!p.empty());
  const PointGrid grid(p);
  for (int q = 0; q < 40; ++q) {
    const std::size_t i = *rc::gen::inRange<std::size_t>(0, p.size());
    const double r = std::pow(10.0, *rc::gen::inRange(-14, 6));
    Point c = p[i];
    const int away = *rc::gen::inRange(0, 3);
    if (away > 0) {  // the centre r (or r and a bit) away from p[i]: a cap of the ball
      const double u = *rc::gen::inRange(-1000, 1000) / 1000.0;
      const double w = *rc::gen::inRange(-1000, 1000) / 1000.0;
      const double n = std::sqrt(1 + u * u + w * w);
      c = {p[i][0] + r / n, p[i][1] + r * u / n, p[i][2] + r * w / n};
    }
    double r2 = r * r;
    if (away == 2) {  // the ball's sphere through p[i], as far as doubles allow
      r2 = 0;
      for (int a = 0; a < 3; ++a) r2 += (p[i][a] - c[a]) * (p[i][a] - c[a]);
    }
    const IVec centre = ivec(c);
    std::map<std::uint32_t, int> seen;
    grid.query_ball(centre, r2, [&](std::uint32_t id, const Point& x) {
      RC_ASSERT(x == p[id]);
      ++seen[id];
    });
    for (const auto& [id, n] : seen) RC_ASSERT(n == 1);
    for (std::uint32_t id = 0; id < p.size(); ++id)
      if (in_ball_exact(p[id], c, r2)) RC_ASSERT(seen.count(id) == 1u);
  }
}

TEST(Grid, ABallQueryVisitsWhatLiesNearTheBall) {
  // 20,000 points in the unit cube and a ball of radius 100 that cuts a cap 0.3 deep off
  // the corner (1, 1, 1): its box holds the whole cube, the ball about 2% of it.
  std::vector<Point> p;
  Lcg unit{777};
  for (int i = 0; i < 20000; ++i) p.push_back({unit(), unit(), unit()});
  const PointGrid grid(p);
  const double t = 100, k = t / std::sqrt(3.0);
  const Point c{1 + k, 1 + k, 1 + k};
  const double r2 = (t + 0.3) * (t + 0.3);
  std::size_t visited = 0, inside = 0;
  grid.query_ball(ivec(c), r2, [&](std::uint32_t, const Point&) { ++visited; });
  for (const Point& x : p) inside += in_ball_exact(x, c, r2) ? 1 : 0;
  std::size_t boxed = 0;
  grid.query(Box{{c[0] - t, c[1] - t, c[2] - t}, {c[0] + t, c[1] + t, c[2] + t}},
             [&](std::uint32_t, const Point&) { ++boxed; });
  EXPECT_EQ(boxed, p.size());
  EXPECT_GT(inside, 100u);
  EXPECT_LE(visited, 8 * inside) << inside << " inside";  // 2,721 visited for 487 inside
}

TEST(Grid, AQueryInACrowdedPatchVisitsFewPoints) {
  // 100,000 points in a patch 1e-6 wide inside a unit cube of 2,000: a uniform grid puts the
  // patch in one cell.
  std::vector<Point> p;
  Lcg unit{12345};
  for (int i = 0; i < 2000; ++i) p.push_back({unit(), unit(), unit()});
  for (int i = 0; i < 100000; ++i) p.push_back({0.5 + 1e-6 * unit(), 0.5 + 1e-6 * unit(), 0.5 + 1e-6 * unit()});
  const PointGrid grid(p);
  EXPECT_GT(grid.depth(), 0);
  std::size_t worst = 0;
  for (std::size_t i = 2000; i < p.size(); i += 997) {
    std::size_t visited = 0;
    grid.query(box_around(p, i, 1e-9), [&](std::uint32_t, const Point&) { ++visited; });
    worst = std::max(worst, visited);
  }
  EXPECT_LE(worst, 8 * PointGrid::kLeafPoints);
}

// Boxes around the graded cloud's points, sized by their spacing; a third of the cases
// snapped to a dyadic lattice of the spacing, so that boxes often touch exactly (the
// normal case in a mesh: tets sharing a vertex); one in 50 empty on a random axis.
std::vector<Box> graded_boxes() {
  std::vector<double> h;
  const std::vector<Point> p = graded_cloud(&h);
  const bool snap = *rc::gen::inRange(0, 3) == 0;
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = h[i] * std::ldexp(1.0, *rc::gen::inRange(-4, 3));
    Box b = box_around(p, i, r);
    if (snap) {
      const double q = std::ldexp(1.0, std::ilogb(h[i]) - 1);
      for (int a = 0; a < 3; ++a) b.lo[a] = std::floor(b.lo[a] / q) * q, b.hi[a] = std::ceil(b.hi[a] / q) * q;
    }
    if (*rc::gen::inRange(0, 50) == 0) {
      const int a = *rc::gen::inRange(0, 3);
      std::swap(b.lo[a], b.hi[a]);
    }
    boxes.push_back(b);
  }
  return boxes;
}

// Closed boxes meet, written apart from grid.hpp's boxes_meet (the oracle must not share
// the code it judges): each axis's intervals overlap, an empty box meets nothing.
bool meet_oracle(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    if (!(a.lo[i] <= a.hi[i]) || !(b.lo[i] <= b.hi[i])) return false;
    if (std::max(a.lo[i], b.lo[i]) > std::min(a.hi[i], b.hi[i])) return false;
  }
  return true;
}

RC_GTEST_PROP(Grid, BoxPairsAreEveryIntersectingPairOnce, ()) {
  const std::vector<Box> boxes = graded_boxes();
  const unsigned threads = *rc::gen::inRange(1u, 3u);
  std::vector<std::map<std::pair<std::uint32_t, std::uint32_t>, int>> found(threads);
  auto loop = [&](std::size_t n, auto&& body) { parallel_blocks(n, threads, 7, body); };
  for_each_box_pair(boxes, 4, loop, [&](unsigned w, std::uint32_t s, std::uint32_t t) {
    RC_ASSERT(s != t);
    ++found[w][{std::min(s, t), std::max(s, t)}];
  });
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> all;
  for (const auto& f : found)
    for (const auto& [k, n] : f) all[k] += n;
  std::size_t expected = 0;
  for (std::uint32_t s = 0; s < boxes.size(); ++s)
    for (std::uint32_t t = s + 1; t < boxes.size(); ++t) {
      if (!meet_oracle(boxes[s], boxes[t])) continue;
      ++expected;
      const auto it = all.find({s, t});
      RC_ASSERT(it != all.end());
      RC_ASSERT(it->second == 1);
    }
  RC_ASSERT(all.size() == expected);
}

// BoxCells (the Delaunay check's boundary faces): whether a query box meets a stored box,
// against brute force, on frames of a few to thousands of cells (some flat on an axis),
// with sparse boxes (most cells far from any: the clearance answers) and boxes reaching
// outside the frame (clamped into its edge cells).
RC_GTEST_PROP(Grid, BoxCellsSayWhetherABoxMeetsAStoredOne, ()) {
  auto unit = [] { return *rc::gen::inRange(-64, 1024 + 64) / 1024.0; };
  const bool flat = *rc::gen::arbitrary<bool>();
  const Box extent{{0, 0, 0}, {1, 1, flat ? 0.0 : 1.0}};
  const GridFrame frame(extent, *rc::gen::element(1.0, 30.0, 500.0, 8000.0));
  const auto box_at = [&](double size) {
    const Point a{unit(), unit(), flat ? 0.0 : unit()};
    Point b = a;
    for (int i = 0; i < 3; ++i) b[i] += size * *rc::gen::inRange(0, 100) / 100.0;
    return Box{a, b};
  };
  std::vector<Box> stored;
  const int n = *rc::gen::inRange(0, 12);
  for (int i = 0; i < n; ++i) stored.push_back(box_at(*rc::gen::element(0.0, 0.01, 0.2)));
  const BoxCells cells(frame, stored);
  int met = 0;
  for (int q = 0; q < 400; ++q) {
    const Box query = box_at(*rc::gen::element(0.0, 0.02, 0.1, 0.5));
    bool brute = false;
    for (const Box& b : stored) brute = brute || boxes_meet(query, b);
    RC_ASSERT(cells.meets(query) == brute);
    met += brute ? 1 : 0;
  }
  RC_TAG(met == 0 ? "none met" : "some met");
}

}  // namespace
}  // namespace pdr::check
