// The domain report (paper §1.1, §2.1) as text and JSON.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "domain/analysis.hpp"
#include "io/error.hpp"
#include "support/outside_fixtures.hpp"
#include "support/plc_fixtures.hpp"

namespace pdr::domain::test {
using namespace pdr::test;
namespace {

TEST(PlcReport, TextAndJsonCarryCountsViolationsAndD) {
  const DomainReport r = analyze_domain(read_data("wedge60.poly"));
  const std::string text = render_text(r);
  EXPECT_NE(text.find("admissible (paper 1.1, related components at 90..270 deg): no"), std::string::npos) << text;
  EXPECT_NE(text.find("facet-facet 60.0000 deg"), std::string::npos) << text;
  EXPECT_NE(text.find("d (paper 2.1) = "), std::string::npos) << text;
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["counts"]["facets"], 6);
  EXPECT_EQ(j["counts"]["segments"], 12);
  EXPECT_EQ(j["admissibility"]["admissible"], false);
  EXPECT_EQ(j["admissibility"]["violations"].size(), 7u);
  EXPECT_GT(j["feature_size"]["d"].get<double>(), 0);
  EXPECT_EQ(j["bounding_box"]["max"][0], 10.0);
}

// A torus of triangle facets violates at every corner of every triangle: the report lists
// the kListedViolations angles farthest from 90..270 degrees and counts them all.
TEST(PlcReport, ListsTheViolationsFarthestFromTheRangeAndCountsThemAll) {
  const DomainReport r = analyze_domain(torus_of_triangles(16, 10, 0.35));
  ASSERT_GT(r.violations.size(), kListedViolations);
  const auto beyond = [](double deg) { return deg < 90 ? 90 - deg : std::max(0.0, deg - 270); };
  const std::vector<const AngleRecord*> listed = listed_violations(r);
  ASSERT_EQ(listed.size(), kListedViolations);
  double least = 1e9;
  for (const AngleRecord* v : listed) least = std::min(least, beyond(v->degrees));
  for (const AngleRecord& v : r.violations) {
    if (std::find(listed.begin(), listed.end(), &v) == listed.end()) {
      EXPECT_LE(beyond(v.degrees), least) << v.degrees;
    }
  }
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["admissibility"]["violation_count"], r.violations.size());
  ASSERT_EQ(j["admissibility"]["violations"].size(), kListedViolations);
  EXPECT_EQ(j["admissibility"]["violations"][0]["degrees"].get<double>(), listed[0]->degrees);
  EXPECT_NE(render_text(r).find("... and " + std::to_string(r.violations.size() - kListedViolations) +
                                " more"),
            std::string::npos);
}

TEST(PlcReport, ToleranceFacetsAreListed) {
  Plc near = box({0, 0, 0}, {1, 1, 1});
  for (double& c : near.points[6]) c += 1e-13;
  const DomainReport r = analyze_domain(near);
  EXPECT_EQ(r.tolerance_facets.size(), 3u);
  EXPECT_EQ(to_json(r)["planarity"]["tolerance_facets"].size(), 3u);
  EXPECT_NE(render_text(r).find("3 facet(s) planar only within the relative tolerance 1e-09"),
            std::string::npos)
      << render_text(r);
}

// Voids are the shells enclosed an even number of times; those no hole point marks are
// listed (TetGen would mesh them as regions). Three nested boxes and a box beside them:
// only the middle box encloses a void.
TEST(PlcReport, VoidsWithoutHolePointsAreListed) {
  const Plc nested = merge(merge(box({0, 0, 0}, {10, 10, 10}), box({2, 2, 2}, {8, 8, 8})),
                           box({4, 4, 4}, {6, 6, 6}));
  Plc plc = merge(nested, box({20, 0, 0}, {21, 1, 1}));
  DomainReport r = analyze_domain(plc);
  EXPECT_EQ(r.shells, 4u);
  EXPECT_EQ(r.voids, 1u);
  ASSERT_EQ(r.unmarked_voids.size(), 1u);
  EXPECT_EQ(r.unmarked_voids[0].first, 6u);  // the middle box's first facet
  EXPECT_NE(render_text(r).find("the void bounded by facet 6"), std::string::npos) << render_text(r);
  EXPECT_EQ(to_json(r)["unmarked_voids"].size(), 1u);
  plc.holes.push_back({3, 3, 3});  // in the void, outside the innermost box
  r = analyze_domain(plc);
  EXPECT_EQ(r.voids, 1u);
  EXPECT_TRUE(r.unmarked_voids.empty());
  EXPECT_EQ(analyze_domain(read_data("cube-in-cube.poly")).voids, 1u);
  EXPECT_TRUE(analyze_domain(read_data("cube-in-cube.poly")).unmarked_voids.empty());
  EXPECT_EQ(analyze_domain(read_data("box.poly")).voids, 0u);
}

// Unrelated components closer than double coordinates resolve touch or cross to within
// rounding: a box stacked on another, rotated, its bottom corners a few ulps off the
// other's top face. Refused (exit 2), naming the pair; a small gap is a small feature and
// meshes, and so does a short edge, or a part far from another.
TEST(PlcReport, ComponentsCloserThanDoublesResolveAreRefused) {
  const auto stacked = [](double gap) {
    Plc plc = merge(box({0, 0, 0}, {2, 2, 1}), box({0.5, 0.5, 1 + gap}, {1.5, 1.5, 2}));
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (Point& p : plc.points) p = {c * p[0] - s * p[2], p[1], s * p[0] + c * p[2]};
    return plc;
  };
  std::string error;
  try {
    analyze(stacked(0));
  } catch (const InputError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("components apart:"), std::string::npos) << error;
  EXPECT_NE(error.find("closer than double coordinates of this magnitude resolve"), std::string::npos) << error;
  EXPECT_GT(analyze(stacked(1e-6)).report.feature.d, 0);
  Plc edge = box({0, 0, 0}, {1, 1, 1});  // its top face's front edge split 1e-9 from a corner
  edge.points.push_back({1 - 1e-9, 0, 1});
  for (PlcFacet& f : edge.facets)
    for (auto& poly : f.polygons)
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Point &a = edge.points[poly[i]], &b = edge.points[poly[(i + 1) % poly.size()]];
        if (a[1] == 0 && b[1] == 0 && a[2] == 1 && b[2] == 1) {
          poly.insert(poly.begin() + static_cast<std::ptrdiff_t>(i) + 1, static_cast<std::uint32_t>(edge.points.size() - 1));
          break;
        }
      }
  relabel(edge);
  EXPECT_NEAR(analyze(edge).report.feature.min_distance, 1e-9, 1e-15);
  const Plc far = merge(box({0, 0, 0}, {1, 1, 1}), box({2e9, 0, 0}, {2e9 + 1, 1, 1}));
  EXPECT_EQ(analyze(far).report.feature.min_distance, 1.0);
}

}  // namespace
}  // namespace pdr::domain::test
