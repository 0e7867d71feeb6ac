// The domain report (paper §1.1, §2.1) as text and JSON.
#include <gtest/gtest.h>

#include "domain/analysis.hpp"
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

}  // namespace
}  // namespace pdr::domain::test
