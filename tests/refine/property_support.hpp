// What the mesher's property tests share (property_test.cpp, outside_property_test.cpp):
// size control as `pdr mesh` options, read back from a regress file's comments and drawn at
// random; the counterexample path; a RapidCheck runner with a required number of cases.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include "mesh/plc.hpp"

namespace pdr::refine::test {

// Size control, as `pdr mesh` options.
struct Sizing {
  std::optional<double> max_volume, size;
  std::string options() const {
    std::ostringstream s;
    s.precision(17);
    if (max_volume) s << " --max-volume " << *max_volume;
    if (size) s << " --size " << *size;
    return s.str();
  }
};

inline void showValue(const Sizing& z, std::ostream& os) { os << "options:" << z.options(); }

// "# options: --max-volume V --size L" in a regress file's comments.
inline Sizing sizing_of_file(const std::string& path) {
  Sizing z;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# options:", 0) != 0) continue;
    std::istringstream s(line.substr(10));
    for (std::string key; s >> key;) {
      double v = 0;
      s >> v;
      if (key == "--max-volume") z.max_volume = v;
      if (key == "--size") z.size = v;
    }
  }
  return z;
}

// None, or a volume or circumradius bound that splits the bounding box into a few to a
// few hundred pieces.
inline rc::Gen<Sizing> gen_sizing(const Plc& plc) {
  Point lo = plc.points[0], hi = plc.points[0];
  for (const Point& p : plc.points)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  const double vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  const double diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return rc::gen::exec([vol, diag] {
    Sizing z;
    const int kind = *rc::gen::inRange(0, 3), k = *rc::gen::inRange(1, 5);
    if (kind == 1) z.max_volume = vol / (k * k * k * 4);
    if (kind == 2) z.size = diag / (2 * k);
    return z;
  });
}

inline std::string counterexample_path() {
  const char* env = std::getenv("PDR_REFINE_COUNTEREXAMPLE");
  return env ? env : "refine-counterexample.poly";
}

// Runs a property with `n` successes required (RC_PARAMS still sets the seed and size);
// `seed`, when given and RC_PARAMS is not set, fixes the cases.
template <class F>
void check_property(const std::string& name, int n, F property,
                    std::optional<std::uint64_t> seed = std::nullopt) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = n;
  if (seed && !std::getenv("RC_PARAMS")) params.seed = *seed;
  rc::detail::TestMetadata meta;
  meta.id = "RefineProperty/" + name;
  meta.description = name;
  const auto result = rc::detail::checkTestable(property, meta, params);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream s;
    rc::detail::printResultMessage(result, s);
    ADD_FAILURE() << s.str();
  }
}

}  // namespace pdr::refine::test
