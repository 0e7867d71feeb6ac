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
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "mesh/plc.hpp"
#include "support/admissible_fixtures.hpp"

namespace pdr::refine::test {

// Size control, as `pdr mesh` options.
struct Sizing {
  std::optional<double> max_volume, size;
  bool graded = false;  // --surface-sizing graded (else auto)
  std::size_t max_vertices = 0;  // --max-vertices (0: derived)
  std::string options() const {
    std::ostringstream s;
    s.precision(17);
    if (max_volume) s << " --max-volume " << *max_volume;
    if (max_vertices != 0) s << " --max-vertices " << max_vertices;
    if (size) s << " --size " << *size;
    if (graded) s << " --surface-sizing graded";
    return s.str();
  }
};

inline void showValue(const Sizing& z, std::ostream& os) { os << "options:" << z.options(); }

// "# options: --max-volume V --size L [--surface-sizing graded]" in a regress file's comments.
inline Sizing sizing_of_file(const std::string& path) {
  Sizing z;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# options:", 0) != 0) continue;
    std::istringstream s(line.substr(10));
    for (std::string key; s >> key;) {
      if (key == "--surface-sizing") {
        std::string v;
        s >> v;
        z.graded = v == "graded";
        continue;
      }
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
// The extent of the PLC's bounding box per axis.
inline Point box_extent(const Plc& plc) {
  Point lo = plc.points[0], hi = plc.points[0];
  for (const Point& p : plc.points)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
}

inline rc::Gen<Sizing> gen_sizing(const Plc& plc) {
  const Point e = box_extent(plc);
  const double vol = e[0] * e[1] * e[2], diag = std::hypot(e[0], e[1], e[2]);
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

// One case of property `name` (Suite.Test): written to <counterexample>.running before it
// runs (a crash or a kill leaves it behind), then `failure()` ("" when the case holds); a
// failing case is written to the counterexample path after every shrinking step, and the
// property fails with `what`.
template <class Failure>
void judge_case(const std::string& name, const Plc& plc, const Sizing& z, const std::string& what,
                Failure&& failure) {
  std::ofstream(counterexample_path() + ".running")
      << pdr::test::poly_text(plc, "the case " + name + " was running\noptions:" + z.options());
  const std::string why = failure();
  if (why.empty()) return;
  const std::string path = counterexample_path();
  std::ofstream(path) << pdr::test::poly_text(
      plc, "shrunk counterexample of " + name + "\noptions:" + z.options());
  RC_LOG() << "options:" << z.options() << "\nwritten to " << path << "\n" << why;
  RC_FAIL(what);
}

// Runs a property with `n` successes required (RC_PARAMS still sets the seed and size);
// `seed`, when given and RC_PARAMS is not set, fixes the cases.
template <class F>
void check_property(const std::string& name, int n, F property,
                    std::optional<std::uint64_t> seed = std::nullopt) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = n;
  if (seed && !std::getenv("RC_PARAMS")) params.seed = *seed;
  // Every run says how to repeat it (RapidCheck prints its configuration only once).
  std::cout << name << ": " << n << " cases, seed " << params.seed << " (RC_PARAMS=\"seed="
            << params.seed << "\" repeats it)" << std::endl;
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

// Registers one gtest per file `prefix`*.poly of tests/regress in suite `suite`, each
// running `failure(path)` ("" when it passes); a file listed in known_bugs is registered
// DISABLED_ (gtest lists it) with the bug named in the file; one listed in `slow` (a replay
// of more than about ten seconds) DISABLED_SLOW_, which a CTest test labelled slow runs
// (--gtest_also_run_disabled_tests --gtest_filter=*.DISABLED_SLOW_*), the sanitizer pass not.
template <class Failure>
bool register_replays(const char* suite, const std::string& prefix,
                      const std::vector<std::string>& known_bugs, Failure failure,
                      const std::vector<std::string>& slow = {}) {
  class Replay : public ::testing::Test {
   public:
    Replay(std::string path, Failure f) : path_(std::move(path)), f_(f) {}
    void TestBody() override {
      const std::string why = f_(path_);
      EXPECT_TRUE(why.empty()) << path_ << ": " << why;
    }

   private:
    std::string path_;
    Failure f_;
  };
  const auto dir = std::filesystem::path(PDR_SOURCE_DIR) / "tests" / "regress";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    const auto ext = e.path().extension();
    if (name.rfind(prefix, 0) == 0 && (ext == ".poly" || ext == ".off")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& p : files) {
    std::string name = p.stem().string();
    if (std::find(known_bugs.begin(), known_bugs.end(), p.filename().string()) != known_bugs.end())
      name = "DISABLED_" + name;
    else if (std::find(slow.begin(), slow.end(), p.filename().string()) != slow.end())
      name = "DISABLED_SLOW_" + name;
    std::replace(name.begin(), name.end(), '-', '_');
    ::testing::RegisterTest(suite, name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [p, failure]() -> ::testing::Test* {
                              return new Replay(p.string(), failure);
                            });
  }
  return true;
}

// The `pdr mesh` pipeline on plc with the sizing z (ratio 2, no files written, the Lemma 1
// audit when `audit`): its exit code and summary, or the exception it threw (its text in
// *error, code -1).
inline int run_mesh(const Plc& plc, const Sizing& z, bool audit, nlohmann::json& summary,
                    std::string* error) {
  app::MeshArgs args;
  args.prefix = "unused";
  args.formats.clear();
  args.options.ratio = 2.0;
  args.options.audit = audit;
  args.options.max_volume = z.max_volume;
  args.options.size = z.size;
  args.options.max_vertices = z.max_vertices;
  if (z.graded) args.surface_sizing = surface::SurfaceSizing::Graded;
  app::Summary s;
  try {
    const int code = app::mesh_plc(plc, args, s);
    summary = s.to_json();
    return code;
  } catch (const std::exception& e) {
    *error = std::string("exception: ") + e.what();
    return -1;
  }
}

}  // namespace pdr::refine::test
