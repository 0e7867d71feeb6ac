// The property of issue #11 on one `pdr mesh` run outside the theory, from its exit code and
// summary: exit 0 or 3, some tets, no "conformity" note (the run's own NOT CONFORMING), and
// every failing exact check one that small input angles may leave (quality.ratio and
// encroachment.*, with exit 3 only). Shared by tests/refine/outside_property_test.cpp and
// fuzz/fuzz_outside_pipeline.cpp.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace pdr::test {

// "" when the run ends as the property says, else why not (with the summary).
inline std::string outside_verdict(int code, const nlohmann::json& summary) {
  std::string why;
  if (code != 0 && code != 3) why += "exit code " + std::to_string(code) + "; ";
  if (summary.value("tets", 0) == 0) why += "no tets; ";
  if (summary.contains("conformity"))
    why += "the run says: " + summary["conformity"].get<std::string>() + "; ";
  if (summary.contains("check_failed"))
    for (const auto& c : summary["check_failed"]) {
      const std::string id = c.get<std::string>();
      const bool allowed = id == "quality.ratio" || id.rfind("encroachment.", 0) == 0;
      if (!allowed || code != 3) why += "check " + id + " fails; ";
    }
  if (!why.empty()) why += "\n" + summary.dump(1);
  return why;
}

}  // namespace pdr::test
